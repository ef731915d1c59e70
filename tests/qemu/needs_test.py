#!/usr/bin/env python3
"""facet::model_needs() keeps its word on a QEMU board (firmware/selftest/needs_test.cpp): each
model packed, loaded where the board's pack goes, and viewed by the module twice, in a
workspace of exactly the least and exactly the roomy size model_needs() gives on the board
(its float and libm, not the host's): every part shows at the least, every face at the default
detail at the other. The host's facet-needs-check does the same on the host.

  needs_test.py --board B --elf facet-needs-test.elf --packer facet-pack --work DIR MODEL.step...
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    for a in ('--board', '--elf', '--packer', '--work'):
        ap.add_argument(a, required=True)
    ap.add_argument('models', nargs='+')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board = boards.load(args.board)
    occt = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')  # Open CASCADE's allocations are not ours to check
    bad = 0
    for m in args.models:
        name = os.path.splitext(os.path.basename(m))[0]
        fpk = os.path.join(args.work, name + '.fpk')
        p = subprocess.run([args.packer, m, '-o', fpk, '--quiet'], capture_output=True, text=True, env=occt)
        if p.returncode != 0:
            print(f'FAIL {name}: facet-pack exit {p.returncode}: {p.stderr.strip()[-400:]}')
            bad += 1
            continue
        out = os.path.join(args.work, name)
        r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board, '--elf', args.elf,
                            '--out', out, '--load', f'{fpk}@{board["pack"]["address"]}', '--timeout', '600', '--quiet'],
                           capture_output=True, text=True)
        log = os.path.join(out, 'uart.log')
        uart = open(log, errors='replace').read() if os.path.exists(log) else ''
        lines = [line for line in uart.splitlines() if line.startswith('@needs')]
        for line in lines:
            print(f'  {name}: {line}')
        kept = '@needs kept' in lines
        if r.returncode != 0 or not kept:
            print(f'FAIL {name}: exit {r.returncode}, {"kept" if kept else "not kept"}\n{r.stdout[-400:]}{r.stderr[-400:]}')
            bad += 1
        else:
            print(f'ok   {name}')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
