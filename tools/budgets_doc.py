#!/usr/bin/env python3
"""docs/budgets.md from the last QEMU viewer tests of both boards.

  python3 tools/budgets_doc.py build/host/tests [out/bench/device.md] > docs/budgets.md

Reads <dir>/<board>-viewer/budgets.{md,json} (written by tests/qemu/viewer_test.py, i.e. by
./facet test) and adds issue 5's goals as measured; with the table ./facet bench device
writes, adds it (every shared model on both boards).
"""
import csv
import json
import os
import sys
from datetime import date

BOARDS = ['qemu-versatilepb', 'qemu-mps2-an500', 'qemu-mps2-evkb']
GOALS = {'anc101': 30e6, 'nist_ctc_02': 300e6}  # tessellation, instructions
FRAME_GOAL_PER_10K = 10e6
PEAK_RAM_GOAL = 8 << 20


def device_goals(path):
    """Issue 13's tessellation goals on the ARM926, from bench device's CSV."""
    if not os.path.exists(path):
        return []
    rows = [r for r in csv.DictReader(open(path)) if r['board'] == 'qemu-versatilepb' and r['tessellation_instructions']]
    m = lambda r, k: int(r[k]) / 1e6
    over_300 = [f'{r["model"]} {m(r, "tessellation_instructions"):.0f} M' for r in rows
                if int(r['tessellation_instructions']) > 300e6]
    over_face = [f'{r["model"]} {m(r, "max_face_instructions"):.1f} M' for r in rows
                 if r['max_face_instructions'] and int(r['max_face_instructions']) > 30e6]
    inflate = [f'{r["model"]} {100 * int(r["inflate_instructions"]) / int(r["tessellation_instructions"]):.0f}%'
               for r in rows if r['inflate_instructions'] and
               int(r['inflate_instructions']) > 0.05 * int(r['tessellation_instructions'])]
    return ['Issue 13\'s goals on the ARM926, from these rows:', '',
            f'- every model tessellated in <= 300 M instructions: {len(rows) - len(over_300)} of {len(rows)}'
            + (f'; over: {", ".join(over_300)}' if over_300 else ''),
            f'- no face over 30 M instructions: {len(rows) - len(over_face)} of {len(rows)} models'
            + (f'; over: {", ".join(over_face)}' if over_face else ''),
            f'- decoding the pack (LZMA; the CSV\'s inflate_instructions) <= 5% of the tessellation: {len(rows) - len(inflate)} of {len(rows)} models'
            + (f'; over: {", ".join(inflate)}' if inflate else ''), '']


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__)
        return 2
    base = sys.argv[1]
    out = [f'# Budgets (generated {date.today().isoformat()})', '',
           'Made by `python3 tools/budgets_doc.py build/host/tests out/bench/device.md` from the `qemu.<board>.viewer` tests of',
           '`./facet test` (`tests/qemu/viewer_test.py`, which writes `build/host/tests/<board>-viewer/budgets.md`);',
           '`./facet run` writes `out/run/budgets.{json,md}` for its own model. Exact guest instruction counts',
           'from the QEMU plugin; ms at 600 MHz, one instruction per cycle. Default tolerance (0.1% of the',
           'diagonal). Tessellation = edge sampling + every face of the first pass (inflating the pack is',
           'apart: "inflating"). "frame" = the costliest full redraw of the finished model in the scripted',
           'session (the zoomed view fills the most pixels); "finest view" = the full redraw after one finer',
           'level of detail. Peak RAM = code, data, display and depth buffers, MMU table, stack high-water,',
           'the pack in place and the viewer storage at its peak (or the compressed file and the LZMA decoder\'s',
           'state while it is decoded). Budgets, asserted on the ARM926 and on the MIMXRT1060-EVKB\'s configuration (qemu-mps2-evkb:',
           'its memories, linker script and start-up on QEMU\'s Cortex-M7; docs/boards.md) and reported for the',
           'plain mps2 (code in RAM there, counted as RAM; on the EVKB it stays in flash): all RAM <= 32 MiB',
           '(link time and MMU), the first pass\'s tessellation <= 600 M (up to 5,000 faces; beyond, 120 k a face: the first view\'s rate, so that for a large model the first view binds), the first view (load to the first frame with the faces in) <= 1.2 G per 10,000 faces (at least 1.2 G), a frame <= 20 M per 10,000 triangles in view.',
           'With several models (`./facet run A.step B.step`: a library, the session opening the second from',
           'the chooser), each model opened is held to the tessellation and first-view budgets on its own, its',
           'first view counted from the unpack that opened it (`budgets.json`: `models_opened_later`).', '']
    data = {}
    for b in BOARDS:
        md = os.path.join(base, f'{b}-viewer', 'budgets.md')
        js = os.path.join(base, f'{b}-viewer', 'budgets.json')
        if not os.path.exists(md) or not os.path.exists(js):
            print(f'budgets_doc: {md} or its .json is missing: run ./facet test first', file=sys.stderr)
            return 1
        data[b] = json.load(open(js))
    out += ['## Goals (issue 5), as measured', '', '| goal | ' + ' | '.join(BOARDS) + ' |', '|---|' + '---|' * len(BOARDS)]
    for model, goal in GOALS.items():
        cells = []
        for b in BOARDS:
            r = next((r for r in data[b]['rows'] if r['model'] == model), None)
            cells.append('-' if r is None else f'{r["tess"] / 1e6:.1f} M {"met" if r["tess"] <= goal else "NOT met"}')
        out.append(f'| {model} tessellated in <= {goal / 1e6:.0f} M instructions | ' + ' | '.join(cells) + ' |')
    cells = []
    for b in BOARDS:
        per10k = [(r['model'], r['frame'] * 10_000 / max(r['triangles'], 10_000)) for r in data[b]['rows']]
        m, v = max(per10k, key=lambda x: x[1])
        cells.append(f'{v / 1e6:.1f} M ({m}) {"met" if v <= FRAME_GOAL_PER_10K else "NOT met"}')
    out.append('| a frame <= 10 M per 10,000 triangles in view (the costliest model\'s full frame) | ' + ' | '.join(cells) + ' |')
    cells = []
    for b in BOARDS:
        m = max(data[b]['rows'], key=lambda r: r['peak_ram'] or 0)
        cells.append(f'{m["peak_ram"] / (1 << 20):.2f} MiB ({m["model"]}) {"met" if m["peak_ram"] <= PEAK_RAM_GOAL else "NOT met"}')
    out.append('| peak RAM of the largest test model <= 8 MiB | ' + ' | '.join(cells) + ' |')
    out.append('')
    for b in BOARDS:
        out.append(open(os.path.join(base, f'{b}-viewer', 'budgets.md')).read().rstrip())
        out.append('')
    if len(sys.argv) == 3:
        out += ['## Every shared model (`./facet bench device`)', '',
                'The viewer firmware on every model of ../shared/models, loaded as facet-pack writes it (LZMA), tessellated at the '
                'default tolerance, drawn fitted then zoomed three steps (`./facet bench device`: CSV in '
                'out/bench/device.csv). "largest face" = the costliest face of the first pass (all its pieces); '
                '"largest frame" = the costliest full redraw of the finished model.', '',
                open(sys.argv[2]).read().rstrip(), '']
        out += device_goals(os.path.splitext(sys.argv[2])[0] + '.csv')
    print('\n'.join(out))
    return 0


if __name__ == '__main__':
    sys.exit(main())
