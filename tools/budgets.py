#!/usr/bin/env python3
"""Turns a QEMU run report (tools/qemu/run.py's report.json) into the budget report.

The budgets and the measures: tools/budget_rules.py (one definition of each).
Tessellation = every 'edges' and 'face' region (the pieces of work) of the viewer's first pass
(uart.log beside the report). Prints a table, writes --json and --markdown (always, also when
over budget); with --strict, the exit code says what went wrong: 1 the run itself failed (its
exit code or the runner's failures), 4 over budget (RAM, tessellation, the first view or a frame), 5 incomplete
mesh (faces failed on the device: they stay wireframe). 0 otherwise, and without --strict.
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import protocol  # noqa: E402
from budget_rules import (MHZ, PEAK_RAM_GOAL, RAM_BUDGET, analyse, by_model, first_view, first_view_budget,  # noqa: E402
                          frame_budget, peak_ram, tessellation_budget, unpack_instructions, zoom_detail, FRAME_BUDGET_MOST,
                          REST_FRAME_BUDGET, ZOOM_DETAIL_BUDGET)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('report')
    ap.add_argument('--json', required=True)
    ap.add_argument('--model', default='')
    ap.add_argument('--markdown')
    ap.add_argument('--strict', action='store_true')
    args = ap.parse_args()
    rep = json.load(open(args.report))
    ram = {k: v for k, v in rep['ram'].items() if k != 'total'}
    total = rep['ram'].get('total', sum(ram.values()))
    uart_path = os.path.join(os.path.dirname(os.path.abspath(args.report)), 'uart.log')
    uart = open(uart_path).read() if os.path.exists(uart_path) else ''
    passes, frame_list = analyse(uart, rep['regions'])
    tess = passes.get(0)
    t = protocol.tessellation(uart) or {}
    frames = [{'name': f'frame {i + 1}', 'instructions': f['instructions'], 'triangles': f['triangles'], 'rest': bool(f['rest']),
               'ms_at_600mhz': None if f['instructions'] is None else round(f['instructions'] / 600e3, 2)}
              for i, f in enumerate(frame_list)]
    zoom = zoom_detail(uart, rep['regions'])
    first_frame, view = first_view(uart, rep['regions'])
    view_budget = first_view_budget(t['faces']) if t.get('faces') else None
    tess_budget = tessellation_budget(t.get('faces') or 0)
    out = {
        'board': rep['board'],
        'model': args.model,
        'ram_bytes': ram,
        'ram_total_bytes': total,
        'ram_budget_bytes': RAM_BUDGET,
        'ram_peak_bytes': peak_ram(rep),
        'ram_peak_goal_bytes': PEAK_RAM_GOAL,
        'stack_used_bytes': rep.get('stack_used'),
        'pack_file_bytes': rep.get('memory', {}).get('pack_file_bytes'),
        'pack_bytes': rep.get('memory', {}).get('pack_bytes'),
        'unpack_instructions': unpack_instructions(rep['regions']),
        'faces': t.get('faces'),
        'faces_failed': t.get('failed'),
        'triangles': t.get('triangles'),
        'mesh_bytes': t.get('mesh_bytes'),
        'arena_peak': t.get('arena_peak'),
        'tri_instructions': tess,
        'tri_ms_at_600mhz': None if tess is None else round(tess / 600e3, 1),
        'frame_instructions': max((f['instructions'] or 0 for f in frame_list
                                   if t and f['triangles'] == t['triangles']), default=None),
        'first_frame_instructions': first_frame,
        'first_view_instructions': view,
        'first_view_budget_instructions': None if view_budget is None else int(view_budget),
        'frames': frames,
        'frame_budget_instructions_per_10k_triangles': int(frame_budget(0)),
        'frame_budget_most_instructions': FRAME_BUDGET_MOST,
        'frame_at_rest_budget_instructions': REST_FRAME_BUDGET,
        'zoom_detail_instructions': zoom,
        'zoom_detail_budget_instructions': ZOOM_DETAIL_BUDGET,
        'tessellation_budget_instructions': int(tess_budget),
        'exit_code': rep['exit_code'],
    }
    # A library: each model opened after the first (the chooser's) has its own tessellation and
    # first view, measured from the unpack that opened it, under the same budgets.
    later = []
    for k, seg in enumerate(by_model(uart, rep['regions'])[1:], start=2):
        passes_k, _ = analyse(None, None, pairs=seg)
        rec = next((r for r, _ in seg if r.name == 'tessellation'), None)
        tk = rec.fields() if rec else {}
        _, view_k = first_view(None, None, pairs=seg)
        later.append({'opened': k, 'faces': tk.get('faces'), 'faces_failed': tk.get('failed'), 'triangles': tk.get('triangles'),
                      'tri_instructions': passes_k.get(0), 'tessellation_budget_instructions': int(tessellation_budget(tk.get('faces') or 0)),
                      'first_view_instructions': view_k,
                      'first_view_budget_instructions': int(first_view_budget(tk['faces'])) if tk.get('faces') else None})
    if later:
        out['models_opened_later'] = later
    run_failed = bool(rep['failures']) or rep['exit_code'] != 0
    fails = list(rep['failures'])
    over_before = len(fails)
    if total > RAM_BUDGET:
        fails.append(f'RAM {total} bytes > {RAM_BUDGET}')
    for f in out['frames']:
        if f['instructions'] is None or f['instructions'] > frame_budget(f['triangles'], f['rest']):
            fails.append(f'{f["name"]} ({f["triangles"]:,} triangles{", at rest" if f["rest"] else ""}): {f["instructions"]} '
                         f'instructions > {frame_budget(f["triangles"], f["rest"]):,.0f}')
    if zoom is not None and zoom > ZOOM_DETAIL_BUDGET:
        fails.append(f'zoomed in to its detail: {zoom:,} instructions > {ZOOM_DETAIL_BUDGET:,}')
    if tess is not None and tess > tess_budget:
        fails.append(f'tessellation: {tess:,} instructions > {tess_budget:,.0f}')
    if view is not None and view_budget is not None and view > view_budget:
        fails.append(f'first view: {view:,} instructions > {view_budget:,.0f}')
    for m in later:
        what = f'model opened {m["opened"]}'
        if m['tri_instructions'] is not None and m['tri_instructions'] > m['tessellation_budget_instructions']:
            fails.append(f'{what}: tessellation {m["tri_instructions"]:,} instructions > {m["tessellation_budget_instructions"]:,}')
        view_k, budget_k = m['first_view_instructions'], m['first_view_budget_instructions']
        if view_k is not None and budget_k is not None and view_k > budget_k:
            fails.append(f'{what}: first view {view_k:,} instructions > {budget_k:,}')
    over = len(fails) > over_before
    incomplete = bool(out['faces_failed']) or any(m['faces_failed'] for m in later)
    out['within_budget'] = not fails and rep['exit_code'] == 0
    out['incomplete_mesh'] = incomplete
    with open(args.json, 'w') as fh:
        json.dump(out, fh, indent=2)
    if args.markdown:
        with open(args.markdown, 'w') as fh:
            fh.write(f'# Budget report — {out["board"]} — {args.model}\n\n')
            fh.write('| measure | value | budget |\n|---|---:|---:|\n')
            if tess is not None:
                fh.write(f'| tessellation | {tess:,} instructions ({tess / 600e3:.0f} ms) | {tess_budget:,.0f} ({tess_budget / 600e6:.1f} s) |\n')
            if view is not None and view_budget is not None:
                fh.write(f'| first view (load to the first frame with the faces in) | {view:,} instructions '
                         f'({view / 600e3:.0f} ms) | {view_budget:,.0f} ({view_budget / 600e6:.1f} s) |\n')
            if zoom is not None:
                fh.write(f'| zoomed in: its last step to its detail | {zoom:,} instructions ({zoom / 600e3:.0f} ms) '
                         f'| {ZOOM_DETAIL_BUDGET:,} ({ZOOM_DETAIL_BUDGET / 600e6:.1f} s) |\n')
            for f in out['frames']:
                if f['instructions'] is not None:
                    fh.write(f'| {f["name"]} ({f["triangles"]:,} triangles{", at rest" if f["rest"] else ""}) | {f["instructions"]:,} '
                             f'({f["instructions"] / 600e3:.1f} ms) | {frame_budget(f["triangles"], f["rest"]):,.0f} |\n')
            for m in later:
                if m['tri_instructions'] is not None:
                    fh.write(f'| model opened {m["opened"]}: tessellation ({m["faces"]} faces) | {m["tri_instructions"]:,} '
                             f'instructions | {m["tessellation_budget_instructions"]:,} |\n')
                if m['first_view_instructions'] is not None and m['first_view_budget_instructions'] is not None:
                    fh.write(f'| model opened {m["opened"]}: first view (from its unpack) | {m["first_view_instructions"]:,} '
                             f'instructions | {m["first_view_budget_instructions"]:,} |\n')
            fh.write(f'| CDT arena peak | {out["arena_peak"]} bytes | |\n| mesh | {out["mesh_bytes"]} bytes | |\n')
            if out['pack_bytes']:
                fh.write(f'| pack as loaded / in place | {out["pack_file_bytes"]:,} / {out["pack_bytes"]:,} bytes | |\n')
            if out['unpack_instructions']:
                fh.write(f'| inflating the pack | {out["unpack_instructions"]:,} instructions '
                         f'({out["unpack_instructions"] / 600e3:.1f} ms) | |\n')
            fh.write('\n| RAM section | bytes |\n|---|---:|\n')
            for k, v in ram.items():
                fh.write(f'| {k} | {v:,} |\n')
            fh.write(f'| total | {total:,} (budget {RAM_BUDGET:,}) |\n')
            if out['ram_peak_bytes'] is not None:
                fh.write(f'\nPeak RAM this model needed (buffers, code, stack high-water, pack, viewer storage at '
                         f'its peak): {out["ram_peak_bytes"]:,} bytes (goal {PEAK_RAM_GOAL:,}).\n')

    print(f'\nBudget report — {rep["board"]}' + (f' — {args.model}' if args.model else ''))
    if out['faces'] is not None:
        print(f'  model: {out["faces"]} faces ({out["faces_failed"]} failed), {out["triangles"]:,} triangles, '
              f'mesh {out["mesh_bytes"]:,} bytes, CDT arena peak {out["arena_peak"]:,} bytes')
    if out['pack_bytes']:
        unpack = out['unpack_instructions']
        print(f'  pack: {out["pack_file_bytes"]:,} bytes as loaded, {out["pack_bytes"]:,} bytes in place'
              + (f' (inflated on the device in {unpack:,} instructions = {unpack / 600e3:.1f} ms)' if unpack else ''))
    if tess is not None:
        print(f'  tessellation on the device: {tess:,} instructions = {tess / 600e3:.0f} ms at 600 MHz '
              f'(budget {tess_budget:,.0f} = {tess_budget / 600e6:.1f} s)')
    if view is not None and view_budget is not None:
        print(f'  first view (load to the first frame with the faces in): {view:,} instructions = {view / 600e3:.0f} ms '
              f'(budget {view_budget:,.0f}); the first frame (boxes or wireframe) {first_frame:,}')
    for m in later:
        print(f'  model opened {m["opened"]}: {m["faces"]} faces ({m["faces_failed"]} failed), tessellation '
              f'{m["tri_instructions"] or 0:,} instructions, first view (from its unpack) {m["first_view_instructions"] or 0:,} '
              f'(budget {m["first_view_budget_instructions"] or 0:,})')
    print(f'  RAM by section (budget {RAM_BUDGET:,} bytes = 32 MiB):')
    for k, v in ram.items():
        print(f'    {k:<14} {v:>12,}')
    print(f'    {"total":<14} {total:>12,}  ({100.0 * total / RAM_BUDGET:.1f}% of the budget)')
    if rep.get('stack_used') is not None:
        print(f'  stack high-water: {rep["stack_used"]:,} of {rep["stack_size"]:,} bytes')
    if out['ram_peak_bytes'] is not None:
        print(f'  peak RAM this model needed: {out["ram_peak_bytes"]:,} bytes ({out["ram_peak_bytes"] / (1 << 20):.2f} MiB; '
              f'goal {PEAK_RAM_GOAL >> 20} MiB): display and depth buffers, code, stack high-water, the pack, '
              f'the viewer storage at its peak')
    if zoom is not None:
        print(f'  zoomed in, its last step to its detail: {zoom:,} instructions = {zoom / 600e3:.0f} ms (budget {ZOOM_DETAIL_BUDGET:,})')
    print(f'  full frames (budget {frame_budget(0):,.0f} instructions = 33.3 ms at {MHZ} MHz per 10k triangles, '
          f'at most {FRAME_BUDGET_MOST:,}; at rest at most {REST_FRAME_BUDGET:,}):')
    for f in out['frames']:
        n = f['instructions']
        print(f'    {f["name"]:<10} {f["triangles"]:>7,} triangles {n:>12,} instructions = {n / (MHZ * 1000):.2f} ms'
              f'{"  at rest" if f["rest"] else ""}' if n is not None else f'    {f["name"]:<10} not counted')
    for msg in fails:
        print(f'  OVER BUDGET / FAILED: {msg}')
    print(f'  within budget: {"yes" if out["within_budget"] else "NO"}')
    if incomplete:
        failed_faces = (out['faces_failed'] or 0) + sum(m['faces_failed'] or 0 for m in later)
        print(f'  INCOMPLETE MESH: {failed_faces} faces failed on the device (uart.log says why)')
    if not args.strict:
        return 0
    return 1 if run_failed else 4 if over else 5 if incomplete else 0


if __name__ == '__main__':
    sys.exit(main())
