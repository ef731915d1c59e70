#!/usr/bin/env python3
"""An example on a QEMU board: examples/minimal (bands of 16 lines, copied into the board's
frame) shows the sample part and ends; examples/own-ui (facet in a viewport beside the product's
own buttons and text line, driven by its demo's taps through the C API) ends with a measurement
and a section on the screen. Either picture is pixel-identical to the same example built for
the host (examples/port/host_port.cpp) at the board's screen size.

  example_test.py --board B --elf ELF --host-example EXE --packer facet-pack
                  --sample facet-sample-model --work DIR [--example minimal|own-ui]
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import img  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    for a in ('--board', '--elf', '--host-example', '--packer', '--sample', '--work'):
        ap.add_argument(a, required=True)
    ap.add_argument('--example', default='minimal', choices=('minimal', 'own-ui'))
    args = ap.parse_args()
    name = args.example
    os.makedirs(args.work, exist_ok=True)
    board = boards.load(args.board)
    step = os.path.join(args.work, 'sample.step')
    fpk = os.path.join(args.work, 'sample.fpk')
    occt = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')  # Open CASCADE's allocations are not ours to check
    subprocess.run([args.sample, step], check=True, capture_output=True, env=occt)
    subprocess.run([args.packer, step, '-o', fpk, '--quiet'], check=True, capture_output=True, env=occt)
    out = os.path.join(args.work, 'qemu')
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board,
                        '--elf', args.elf, '--out', out, '--load', f'{fpk}@{board["pack"]["address"]}',
                        '--timeout', '300', '--quiet'], capture_output=True, text=True)
    host = os.path.join(args.work, 'host.f565')
    h = subprocess.run([args.host_example, fpk, host, board['size']], capture_output=True, text=True)
    problems = []
    if r.returncode != 0:
        problems.append(f'the example on the board: exit {r.returncode}: {r.stderr.strip()[-300:]}')
    if h.returncode != 0:
        problems.append(f'the example on the host: exit {h.returncode}: {h.stderr.strip()[-300:]}')
    uart = open(os.path.join(out, 'uart.log')).read() if os.path.exists(os.path.join(out, 'uart.log')) else ''
    said = {'minimal': 'every face is in', 'own-ui': 'idle'}[name]
    if not re.search(rf'^{name}: {said}$', uart, re.M):
        problems.append(f'the board never said "{said}"')
    shot = os.path.join(out, f'{name}.png')
    if not os.path.exists(shot) or not os.path.exists(host):
        problems.append('a picture is missing')
    else:
        w0, h0, _ = img.load_565(host)
        n, msg = img.compare(host, shot, os.path.join(args.work, 'diff.png'), ignore=[img.frame_time_field(w0, h0)] if name == 'minimal' else [])  # (own-ui: facet's status line is off)
        if n:
            problems.append(f'board and host differ: {msg}')
        w, hgt, px = img.load_565(host)
        if len(set(px)) < 50:
            problems.append(f'the picture shows next to nothing ({len(set(px))} colours)')
    if problems:
        print(f'FAIL {args.board} examples/{name}: ' + '; '.join(problems))
        print(uart[-1500:])
        return 1
    print(f'{args.board} examples/{name}: the sample part in bands of 16 lines, pixel-identical to the host build')
    return 0


if __name__ == '__main__':
    sys.exit(main())
