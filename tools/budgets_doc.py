#!/usr/bin/env python3
"""docs/budgets.md from the last QEMU viewer tests of the boards.

  python3 tools/budgets_doc.py build/host/tests > docs/budgets.md
  python3 tools/budgets_doc.py build/host/tests --check docs/budgets.md

Reads <dir>/<board>-viewer/budgets.{md,json} (written by tests/qemu/viewer_test.py, i.e. by
./facet test) and adds issue 5's goals as measured. --check: exit 1 when the file is not what
the tests measured (the test docs.budgets_md_is_current): every word the same, and every number
too but for a figure with a decimal point, which may differ by one in its last place (a frame's
count jitters by a few hundred instructions with the status bar's frame time, which can move
its rounding). ./facet bench device's table of every shared model: docs/bench/.
"""
import argparse
import json
import os
import re
import sys

BOARDS = ['qemu-versatilepb', 'qemu-mps2-an500', 'qemu-mps2-evkb']
GOALS = {'anc101': 30e6, 'nist_ctc_02': 300e6}  # tessellation, instructions
FRAME_GOAL_PER_10K = 10e6
PEAK_RAM_GOAL = 8 << 20


def same(a, b):
    """Whether two texts say the same, a decimal figure allowed one in its last place."""
    ta, tb = re.findall(r'[0-9][0-9,]*(?:\.[0-9]+)?|[^0-9\s]+', a), re.findall(r'[0-9][0-9,]*(?:\.[0-9]+)?|[^0-9\s]+', b)
    if len(ta) != len(tb):
        return False
    for x, y in zip(ta, tb):
        if x == y:
            continue
        if '.' in x and '.' in y and len(x.split('.')[1]) == len(y.split('.')[1]):
            places = len(x.split('.')[1])
            if abs(float(x.replace(',', '')) - float(y.replace(',', ''))) <= 10 ** -places * 1.0001:
                continue
        return False
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('tests', help='build/host/tests')
    ap.add_argument('--check', metavar='FILE', help='compare with FILE instead of printing')
    args = ap.parse_args()
    base = args.tests
    out = ['# Budgets', '',
           'Made by `python3 tools/budgets_doc.py build/host/tests > docs/budgets.md` from the `qemu.<board>.viewer` tests of',
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
           '(link time and MMU), the first view (load to the first frame with the faces in) <= 1.2 G whatever the model\'s size, the first pass\'s tessellation within it <= 600 M (up to 5,000 faces; beyond, 120 k a face up to the first view\'s 1.2 G), a frame <= 20 M per 10,000 triangles in view and at most 40 M (none grows with the model past these: issue 52).',
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
    out += ['Every shared model on the boards (`./facet bench device`): `docs/bench/` (its README lists the runs).', '']
    text = '\n'.join(out)
    if args.check:
        if not same(open(args.check).read().rstrip('\n'), text.rstrip('\n')):
            print(f'budgets_doc: {args.check} is not what the viewer tests measured; make it again:\n'
                  f'  python3 tools/budgets_doc.py {base} > {args.check}', file=sys.stderr)
            return 1
        print(f'budgets_doc: {args.check} is what the viewer tests measured')
        return 0
    print(text)
    return 0


if __name__ == '__main__':
    sys.exit(main())
