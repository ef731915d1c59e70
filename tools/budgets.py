#!/usr/bin/env python3
"""Turns a QEMU run report (tools/qemu/run.py's report.json) into the budget report.

Budgets of the handheld: all RAM <= 32 MiB (33,554,432 bytes); CPU time in exact guest
instructions at 600 MHz, one instruction per cycle; tessellating a model <= 600 M instructions
(1 s); one frame <= 20 M instructions (30 frames/s). Prints a table and writes --json; with
--strict, exits non-zero if a budget is exceeded (the tests' use); otherwise it reports.
"""
import argparse
import json
import sys

RAM_BUDGET = 32 << 20
FRAME_BUDGET = 20_000_000
TESSELLATION_BUDGET = 600_000_000
MHZ = 600


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('report')
    ap.add_argument('--json', required=True)
    ap.add_argument('--model', default='')
    ap.add_argument('--strict', action='store_true')
    args = ap.parse_args()
    rep = json.load(open(args.report))
    ram = {k: v for k, v in rep['ram'].items() if k != 'total'}
    total = rep['ram'].get('total', sum(ram.values()))
    frames = [r for r in rep['regions'] if r['name'].startswith('draw') or r['name'] == 'frame']
    tess = next((r['instructions'] for r in rep['regions'] if r['name'] == 'tessellate'), None)
    model = rep.get('model', {})
    out = {
        'board': rep['board'],
        'ram_bytes': ram,
        'ram_total_bytes': total,
        'ram_budget_bytes': RAM_BUDGET,
        'stack_used_bytes': rep.get('stack_used'),
        'frames': [{'name': r['name'], 'frame_instructions': r['instructions'],
                    'ms_at_600mhz': r['ms_at_600mhz']} for r in frames],
        'frame_budget_instructions': FRAME_BUDGET,
        'exit_code': rep['exit_code'],
    }
    if args.model or tess is not None:
        out['model'] = args.model
        out.update({k: model.get(k) for k in ('faces', 'faces_failed', 'triangles', 'mesh_bytes')})
        out['tri_instructions'] = tess
        out['tri_ms_at_600mhz'] = None if tess is None else round(tess / 600e3, 1)
        out['frame_instructions'] = frames[0]['instructions'] if frames else None
    fails = list(rep['failures'])
    if total > RAM_BUDGET:
        fails.append(f'RAM {total} bytes > {RAM_BUDGET}')
    for f in out['frames']:
        if f['frame_instructions'] is None or f['frame_instructions'] > FRAME_BUDGET:
            fails.append(f'{f["name"]}: {f["frame_instructions"]} instructions > {FRAME_BUDGET}')
    if tess is not None and tess > TESSELLATION_BUDGET:
        fails.append(f'tessellation: {tess:,} instructions > {TESSELLATION_BUDGET:,}')
    out['within_budget'] = not fails and rep['exit_code'] == 0
    with open(args.json, 'w') as fh:
        json.dump(out, fh, indent=2)

    print(f'\nBudget report — {rep["board"]}' + (f' — {args.model}' if args.model else ''))
    if 'faces' in out and out['faces'] is not None:
        print(f'  model: {out["faces"]} faces ({out["faces_failed"]} failed), {out["triangles"]:,} triangles, '
              f'mesh {out["mesh_bytes"]:,} bytes')
    if tess is not None:
        print(f'  tessellation on the device: {tess:,} instructions = {tess / 600e3:.0f} ms at 600 MHz '
              f'(budget {TESSELLATION_BUDGET:,} = 1 s)')
    print(f'  RAM by section (budget {RAM_BUDGET:,} bytes = 32 MiB):')
    for k, v in ram.items():
        print(f'    {k:<14} {v:>12,}')
    print(f'    {"total":<14} {total:>12,}  ({100.0 * total / RAM_BUDGET:.1f}% of the budget)')
    if rep.get('stack_used') is not None:
        print(f'  stack high-water: {rep["stack_used"]:,} of {rep["stack_size"]:,} bytes')
    print(f'  frames (budget {FRAME_BUDGET:,} instructions = 33.3 ms at {MHZ} MHz):')
    for f in out['frames']:
        n = f['frame_instructions']
        print(f'    {f["name"]:<14} {n:>12,} instructions = {n / (MHZ * 1000):.2f} ms' if n is not None
              else f'    {f["name"]:<14} not counted')
    for msg in fails:
        print(f'  OVER BUDGET / FAILED: {msg}')
    print(f'  within budget: {"yes" if out["within_budget"] else "NO"}')
    return 0 if out['within_budget'] or not args.strict else 1


if __name__ == '__main__':
    sys.exit(main())
