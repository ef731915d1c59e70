#!/usr/bin/env python3
"""The EVKB's MPU, enforced: on its QEMU stand-in (the EVKB's start-up and memory plan on the
mps2's Cortex-M7), a store just past the SDRAM and a store into the flash (the pack region,
where QEMU itself has writable RAM) each end in a MemManage fault that names the address
(MMFAR), with a non-zero exit code; neither store completes.

  mpu_fault_test.py --elf facet-fault-test.elf --work DIR
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402

BOARD = 'qemu-mps2-evkb'


def run(elf, work, typed):
    cmd = [sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', BOARD, '--elf', elf,
           '--out', work, '--timeout', '60']
    if typed:
        cmd += ['--send', f'keys {typed}']
    return subprocess.run(cmd, capture_output=True, text=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--elf', required=True)
    ap.add_argument('--work', required=True)
    args = ap.parse_args()
    b = boards.load(BOARD)
    sdram_end = next(boards.bytes_of(m['origin']) + boards.bytes_of(m['bytes']) for m in b['memory'] if m['name'] == 'SDRAM')
    probe = boards.bytes_of(b['fault_probe'])
    # (Enter alone takes the default address at once: waiting for it is two seconds of the
    # guest's polling, billions of instructions, which a loaded machine may not run in a minute.)
    cases = [('past the SDRAM', '\\n', probe), ('into the flash (pack region)', f'{b["pack_address"]:x}\\n', b['pack_address'])]
    bad = []
    if probe != sdram_end:
        bad.append(f'the board\'s fault_probe {probe:#x} is not the end of its SDRAM {sdram_end:#x}')
    for i, (what, typed, address) in enumerate(cases):
        r = run(args.elf, os.path.join(args.work, str(i)), typed)
        print(r.stdout)
        print(r.stderr, file=sys.stderr)
        checks = [
            (r.returncode != 0, f'{what}: the exit code is non-zero ({r.returncode})'),
            (f'storing to {address:#010x}' in r.stdout, f'{what}: the store went to {address:#010x}'),
            ('*** fault: exception 4 ' in r.stdout, f'{what}: a MemManage fault (exception 4) is reported'),
            (f'MMFAR {address:#010x}' in r.stdout, f'{what}: MMFAR names {address:#010x}'),
            ('did not fault' not in r.stdout, f'{what}: the store did not complete'),
        ]
        bad += [w for ok, w in checks if not ok]
    for w in bad:
        print(f'FAIL: expected: {w}')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
