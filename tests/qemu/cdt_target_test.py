#!/usr/bin/env python3
"""cdt/ on the target: runs facet-cdt-bench in QEMU under the instruction counter. The firmware
triangulates the paper's face and the 10k plate in the 16-bit device arena and runs the
independent checker on the device; this test requires the checker to pass for both, the exact
instruction counts to be present, and prints them per inserted vertex. --csv FILE appends one
row per face (board,input,vertices,instructions,per_vertex; the header if FILE is new)."""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import protocol  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--board', required=True)
    ap.add_argument('--elf', required=True)
    ap.add_argument('--work', required=True)
    ap.add_argument('--csv', help='append the target rows to this CSV')
    args = ap.parse_args()
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board,
                        '--elf', args.elf, '--out', args.work, '--icount', '--timeout', '600', '--quiet'])
    rep = json.load(open(os.path.join(args.work, 'report.json')))
    uart = open(os.path.join(args.work, 'uart.log')).read()
    failed = r.returncode != 0
    rows = []
    for name, region in (('paper', 'cdt_paper'), ('plate10k', 'cdt_plate10k'),
                         ('paper, paper order', 'cdt_paper_paper_order'),
                         ('plate10k, paper order', 'cdt_plate10k_paper_order')):
        cdt = next((c for c in protocol.records(uart, 'cdt') if c.fields().get('region') == region), None)
        kv = cdt.fields() if cdt else {}  # @cdt REGION points N ... checker VERDICT
        verdict = kv.get('checker')
        n = next((x['instructions'] for x in rep['regions'] if x['name'] == region), None)
        if not cdt or verdict != 'ok' or n is None:
            print(f'FAIL {name}: {verdict if cdt else "no result"}; instructions {n}')
            failed = True
            continue
        pts = kv['points']
        rows.append((args.board, name.replace(', ', '/').replace(' ', '-'), pts, n, n / pts))
        print(f'{args.board} {name}: {pts} points, checker ok, {n:,} instructions '
              f'({n / pts:,.0f} per inserted vertex, {n / 600e3:.2f} ms at 600 MHz)')
    if args.csv and rows:
        new = not os.path.exists(args.csv) or os.path.getsize(args.csv) == 0
        with open(args.csv, 'a') as f:
            if new:
                f.write('board,input,vertices,instructions,per_vertex\n')
            for b, name, pts, n, per in rows:
                f.write(f'{b},{name},{pts},{n},{per:.0f}\n')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
