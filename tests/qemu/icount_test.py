#!/usr/bin/env python3
"""The instruction counter is exact and repeatable.

Runs facet-icount-test twice under the facet-icount plugin. The firmware calls an assembly
loop that executes exactly 2n+1 instructions between the markers for several n and prints the
expected count ('@expect'); run.py fails if the plugin's count differs by even one. The two
runs must also report identical counts.
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(args, k):
    out = os.path.join(os.path.abspath(args.work), f'run{k}')
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'),
                        '--board', args.board, '--elf', args.elf, '--out', out, '--icount',
                        '--timeout', '120', '--quiet'])
    report = json.load(open(os.path.join(out, 'report.json')))
    return r.returncode, report


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--board', required=True)
    ap.add_argument('--elf', required=True)
    ap.add_argument('--work', required=True)
    args = ap.parse_args()
    code1, rep1 = run(args, 1)
    code2, rep2 = run(args, 2)
    ok = code1 == 0 and code2 == 0 and rep1['regions'] and rep1['regions'] == rep2['regions']
    for r in rep1['regions']:
        print(f"{r['name']}: {r['instructions']} (expected {rep1.get('expect', {}).get(r['name'])})")
    if not ok:
        print(f'FAIL: exit codes {code1}/{code2}; failures {rep1["failures"]} {rep2["failures"]}')
        print(f'run 1: {rep1["regions"]}\nrun 2: {rep2["regions"]}')
        return 1
    print('ok: counts exact and identical over two runs')
    return 0


if __name__ == '__main__':
    sys.exit(main())
