#!/usr/bin/env python3
"""A store past the 32 MiB budget on versatilepb aborts with a clear message and a non-zero
exit code (the MMU maps only the budget)."""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--elf', required=True)
    ap.add_argument('--work', required=True)
    args = ap.parse_args()
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'),
                        '--board', 'qemu-versatilepb', '--elf', args.elf, '--out', args.work,
                        '--timeout', '60', '--send', 'keys \\n'],  # Enter: the default address at once (no
                       capture_output=True, text=True)                # two seconds of the guest's polling)
    print(r.stdout)
    print(r.stderr, file=sys.stderr)
    checks = [
        (r.returncode != 0, f'exit code is non-zero ({r.returncode})'),
        ('*** data abort' in r.stdout, 'a data abort is reported'),
        ('translation fault' in r.stdout, 'the fault status names a translation fault'),
        ('0x02000000 is past the 32 MiB RAM budget' in r.stdout, 'the message names the budget'),
        ('did not fault' not in r.stdout, 'the store did not complete'),
    ]
    bad = [what for good, what in checks if not good]
    for what in bad:
        print(f'FAIL: expected: {what}')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
