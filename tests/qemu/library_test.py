#!/usr/bin/env python3
"""Several models on a QEMU board: a library (facet-pack --library) of the sample part and two
shared models loaded where the pack goes. The viewer lists them, opens the first, and the
scripted session opens the second from the chooser (tests/sessions/library.session, ./facet
run's): two models opened, each with its own face count, the chooser and the second model in
their screenshots, pixel-identical to the desktop simulator's given the same library and input. Then the same library with its second model damaged
(tests/sessions/library-walk.session): opening it is said ("model 2 of the library: ...") and
the first opens again, and the third still opens.

  library_test.py --board B --elf ELF --sim facet-sim --packer facet-pack --sample facet-sample-model --work DIR
                  MODEL.step MODEL.step
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
import protocol  # noqa: E402


def faces_of(packer, fpk):
    out = subprocess.run([packer, '--check', fpk], capture_output=True, text=True, check=True).stdout
    return int(re.search(r'valid pack, (\d+) faces', out).group(1))


def boot(args, board, lib, out, session):
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board, '--elf', args.elf,
                        '--out', out, '--load', f'{lib}@{board["pack"]["address"]}', '--timeout', '600', '--quiet',
                        '--session', session], capture_output=True, text=True)
    uart = open(os.path.join(out, 'uart.log')).read() if os.path.exists(os.path.join(out, 'uart.log')) else ''
    return r.returncode, uart


def main():
    ap = argparse.ArgumentParser()
    for a in ('--board', '--elf', '--sim', '--packer', '--sample', '--work'):
        ap.add_argument(a, required=True)
    ap.add_argument('models', nargs=2)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board = boards.load(args.board)
    occt = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')  # Open CASCADE's allocations are not ours to check
    step = os.path.join(args.work, 'sample.step')
    subprocess.run([args.sample, step], check=True, capture_output=True, env=occt)
    packs = []
    for i, m in enumerate([step] + args.models):
        fpk = os.path.join(args.work, f'model-{i + 1}.fpk')
        subprocess.run([args.packer, m, '-o', fpk, '--quiet'], check=True, capture_output=True, env=occt)
        packs.append(fpk)
    faces = [faces_of(args.packer, p) for p in packs]
    lib = os.path.join(args.work, 'library.flb')
    subprocess.run([args.packer, '--library', lib] + packs + ['--quiet'], check=True)
    problems = []

    # The library as ./facet run shows it: the first model, the chooser, the second.
    out = os.path.join(args.work, 'good')
    code, uart = boot(args, board, lib, out, 'library')
    opened = [r.values()['faces'] for r in protocol.records(uart, 'model')]
    if code != 0:
        problems.append(f'the viewer exited {code}')
    if len(list(protocol.records(uart, 'library'))) != 3:
        problems.append('the viewer did not list the three models')
    if opened != faces[:2]:
        problems.append(f'the models opened have {opened} faces, not the first two ({faces[:2]})')
    shots = {n: os.path.join(out, f'{n}.png') for n in ('done', 'chooser', 'second')}
    if not all(os.path.exists(p) for p in shots.values()):
        problems.append('a screenshot is missing: ' + ', '.join(n for n, p in shots.items() if not os.path.exists(p)))
    elif img.compare(shots['done'], shots['second'])[0] == 0:
        problems.append('the second model looks like the first')
    # The simulator given the library and the session's input (a pointer at the row, a click).
    sim = os.path.join(args.work, 'sim')
    os.makedirs(sim, exist_ok=True)
    entries = ['keys d', 'keys !shot turned\n', 'keys b', 'keys !shot chooser\n', 'move -1000 -1000', 'move 60 66', 'click',
               'keys !shot second\n']
    h = subprocess.run([args.sim, '--pack', lib, '--out', sim, '--size', board['size'], '--headless', '--no-clock', '--quiet']
                       + [a for e in entries for a in ('--send', e)], capture_output=True, text=True, timeout=300)
    if h.returncode != 0:
        problems.append(f'the simulator: exit {h.returncode}: {h.stderr.strip()[-300:]}')
    for n in ('turned', 'chooser', 'second'):
        a, b = os.path.join(sim, n + '.f565'), os.path.join(out, n + '.png')
        if os.path.exists(a) and os.path.exists(b):
            w, hgt, _ = img.load_565(a)
            d, msg = img.compare(a, b, os.path.join(args.work, n + '-diff.png'), ignore=[img.frame_time_field(w, hgt)])
            if d:
                problems.append(f'{n}: the board and the simulator differ: {msg}')
        else:
            problems.append(f'{n}: a screenshot is missing')

    # Its second model damaged in the middle of its file: said, the first back, the third opens.
    data = bytearray(open(lib, 'rb').read())
    offset, size = int.from_bytes(data[16 + 64:20 + 64], 'little'), int.from_bytes(data[20 + 64:24 + 64], 'little')
    data[offset + size // 2] ^= 0x5A
    bad = os.path.join(args.work, 'damaged.flb')
    open(bad, 'wb').write(data)
    out = os.path.join(args.work, 'damaged')
    code, uart = boot(args, board, bad, out, 'library-walk')
    opened = [r.values()['faces'] for r in protocol.records(uart, 'model')]
    if code != 0:
        problems.append(f'the damaged library: the viewer exited {code}')
    if [r.values()['model'] for r in protocol.records(uart, 'model_failed')] != [2]:
        problems.append('the damaged model was not said')
    if opened != [faces[0], faces[0], faces[2]]:
        problems.append(f'the damaged library: models opened with {opened} faces, not the first, the first again, the third '
                        f'({[faces[0], faces[0], faces[2]]})')
    if not os.path.exists(os.path.join(out, 'third.png')):
        problems.append('the damaged library: no screenshot of the third model')
    if problems:
        print(f'FAIL {args.board} library: ' + '; '.join(problems))
        print(uart[-1500:])
        return 1
    print(f'{args.board} library: three models listed; the second opened from the chooser; a damaged one said, the first '
          f'back, the third opened ({faces} faces)')
    return 0


if __name__ == '__main__':
    sys.exit(main())
