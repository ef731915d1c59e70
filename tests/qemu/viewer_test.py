#!/usr/bin/env python3
"""The viewer on the target, model by model: packs a model on the host, boots facet-viewer in
QEMU with the pack at the board's pack address and plays a scripted session (turn with keys,
drag with the PS/2 mouse on versatilepb, zoom, fit, finer level of detail, quit). Checks:

  * the device validated the pack, reported every face (none failed for these models), and
    printed its report: faces, triangles, arena high-water, mesh bytes;
  * every screenshot (wireframe, half, done, turned, dragged, zoomed, lod) is pixel-identical
    to the one facet-sim --headless renders on the host with the same code and the same session;
    the session changed the picture (done, turned, zoomed and lod all differ);
  * exact instruction counts: tessellation = every 'edges' and 'face' region (pieces of work) of
    the first pass, up to its @tessellation line (what the views bring in after it, sweeps and
    refinements of blocks, is counted apart); the first view = every piece of work from load to the first frame after the
    first pass (<= 1.2 G per 10,000 faces, at least 1.2 G); a frame = the 'frame' pieces of one full redraw (up to its '@frame' line). Budgets: tessellation <= 600 M
    instructions (1 s at 600 MHz), a frame <= 20 M per 10,000 triangles in view (30 frames/s;
    views under 10k triangles get the full 20 M). Printed for every run; asserted with
    --assert-budgets (the ctest runs on the ARM926 do).

  viewer_test.py --board B --elf ELF --packer facet-pack --ref facet-sim --work DIR [--plain]
                 [--sample facet-sample-model] [--markdown FILE] MODEL.step...
"""
import argparse
import hashlib
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import img  # noqa: E402
import protocol  # noqa: E402
from budget_rules import (OVERLAY_BUDGET, ZOOM_DETAIL_BUDGET, analyse, first_view, first_view_budget, frame_budget, peak_ram,  # noqa: E402
                          tessellation_budget, unpack_instructions, zoom_detail)

def session(board):
    """tests/sessions/viewer.session for this board (the drag only where it has a mouse)."""
    return protocol.read_session(protocol.session_path('viewer'), board)



def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--board', required=True)
    ap.add_argument('--elf', required=True)
    ap.add_argument('--packer', required=True)
    ap.add_argument('--plain', action='store_true',
                    help='plain packs, read in place (what ./facet flash puts on the EVKB); default deflated')
    ap.add_argument('--ref', required=True)
    ap.add_argument('--sample')
    ap.add_argument('--work', required=True)
    ap.add_argument('--markdown', help='write the budget table (docs/budgets.md) here')
    ap.add_argument('--assert-budgets', action='store_true', help='fail a model over a budget')
    ap.add_argument('models', nargs='*')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board = boards.load(args.board)
    models = list(args.models)
    if args.sample:
        step = os.path.join(args.work, 'sample.step')
        subprocess.run([args.sample, step], check=True, capture_output=True)
        models.insert(0, step)
    failed = False
    rows = []
    ram = {}
    for model in models:
        name = os.path.splitext(os.path.basename(model))[0]
        fpk = os.path.join(args.work, name + '.fpk')
        subprocess.run([args.packer, model, '-o', fpk, '--quiet'] + (['--plain'] if args.plain else []),
                       check=True, capture_output=True)
        out = os.path.join(args.work, name)
        ref = os.path.join(args.work, name + '-ref')
        os.makedirs(ref, exist_ok=True)
        script = session(args.board)
        sends = [x for s in script for x in ('--send', s)]
        r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board,
                            '--elf', args.elf, '--out', out, '--load', f'{fpk}@{board["pack"]["address"]}', '--icount',
                            '--timeout', '900', '--quiet'] + sends, capture_output=True, text=True)
        h = subprocess.run([args.ref, '--headless', '--quiet', '--size', board['size'], '--pack', fpk, '--out', ref] + sends,
                           capture_output=True, text=True)
        if not os.path.exists(os.path.join(out, 'report.json')):
            failed = True
            print(f'FAIL {args.board} {name}: the runner wrote no report (exit {r.returncode})\n{r.stdout[-1500:]}\n'
                  f'{r.stderr[-3000:]}')
            continue
        uart = open(os.path.join(out, 'uart.log')).read()
        rep = json.load(open(os.path.join(out, 'report.json')))
        ram = rep.get('ram', ram)
        problems = []
        if r.returncode != 0:
            problems.append(f'exit {r.returncode}: {r.stderr.strip()[-300:]}')
        if h.returncode != 0:
            problems.append(f'facet-sim exit {h.returncode}: {h.stderr.strip()[-300:]}')
        t = protocol.tessellation(uart)
        if 'the rasterizer refused' in uart:
            problems.append('the rasterizer refused triangles or lines')
        if not t:
            problems.append('no tessellation report')
        elif t['failed'] != 0:
            problems.append(f'{t["failed"]} faces failed')
        elif t['triangles'] == 0:
            problems.append('no triangles')
        shots = ['wireframe', 'half', 'done', 'turned'] + (['dragged'] if boards.can(args.board, 'mouse') else []) + \
            ['zoomed', 'lod']
        digests = {}
        for s in shots:
            dev = os.path.join(out, s + '.png')
            host = os.path.join(ref, s + '.f565')
            if not os.path.exists(dev) or not os.path.exists(host):
                problems.append(f'screenshot {s} missing ({"device" if not os.path.exists(dev) else "host"})')
                continue
            # Every pixel but the status bar's frame time (each shows its own clock's).
            w, hh, _ = img.load_565(host)
            n, msg = img.compare(host, dev, os.path.join(out, s + '-diff.png'), ignore=[img.frame_time_field(w, hh)])
            if n != 0:
                problems.append(f'{s}: {msg}')
            digests[s] = hashlib.sha1(open(host, 'rb').read()).hexdigest()
        if len({digests.get(s) for s in ('done', 'turned', 'zoomed', 'lod')}) != 4:
            problems.append('the session did not change the picture (done/turned/zoomed/lod alike)')
        tess, frames = analyse(uart, rep['regions'])
        t0 = tess.get(0)
        if t0 is None or not frames or any(f['instructions'] is None for f in frames):
            problems.append('instruction counts missing')
        worst = max(frames, key=lambda f: f['instructions'] / frame_budget(f['triangles'], f['rest'])) if frames else None
        budget_notes = []
        if t0 is not None and t and t0 > tessellation_budget(t['faces']):
            budget_notes.append(f'tessellation {t0:,} > {tessellation_budget(t["faces"]):,.0f}')
        _, view = first_view(uart, rep['regions'])
        if view is None:
            problems.append('no first view (no frame after the first pass)')
        elif t and view > first_view_budget(t['faces']):
            budget_notes.append(f'first view {view:,} > {first_view_budget(t["faces"]):,.0f}')
        for f in frames:
            if f['instructions'] and f['instructions'] > frame_budget(f['triangles'], f['rest']):
                budget_notes.append(f'frame of {f["triangles"]:,} triangles{" at rest" if f["rest"] else ""}: {f["instructions"]:,} > '
                                    f'{frame_budget(f["triangles"], f["rest"]):,.0f}')
        zoom = zoom_detail(uart, rep['regions'])
        if zoom is not None and zoom > ZOOM_DETAIL_BUDGET:
            budget_notes.append(f'zoomed in to its detail: {zoom:,} > {ZOOM_DETAIL_BUDGET:,}')
        # The on-screen interface: at most 0.5 M instructions a frame.
        overlay_max = max((f.get('overlay', 0) for f in frames), default=0)
        if overlay_max > OVERLAY_BUDGET:
            budget_notes.append(f'the overlay took {overlay_max:,} instructions in a frame > {OVERLAY_BUDGET:,}')
        print(f'{args.board} {name}: overlay at most {overlay_max:,} instructions a frame')
        if args.assert_budgets:
            problems += budget_notes
        if problems:
            failed = True
            print(f'FAIL {args.board} {name}: ' + '; '.join(problems))
            print(uart[-1500:])
            continue
        big = max(frames, key=lambda f: f['triangles'])
        peak = peak_ram(rep)
        if peak is None:
            problems.append('no @memory report')
        row = {'model': name, 'faces': t['faces'], 'triangles': t['triangles'], 'mesh_bytes': t['mesh_bytes'],
               'peak_ram': peak,
               'arena_peak': t['arena_peak'], 'file_bytes': os.path.getsize(fpk),
               'pack_bytes': rep.get('memory', {}).get('pack_bytes', 0), 'unpack': unpack_instructions(rep['regions']),
               'tess': t0,
               'frame': max(f['instructions'] for f in frames if f['pass'] == 0 and f['triangles'] == t['triangles']),
               'big_frame': big, 'tess_lod': tess.get(max(k for k in tess if isinstance(k, int))), 'tess_view': tess.get('view', 0), 'notes': budget_notes}
        rows.append(row)
        print(f'{args.board} {name}: {row["faces"]} faces, {row["triangles"]:,} triangles, arena peak '
              f'{row["arena_peak"]:,} B, mesh {row["mesh_bytes"]:,} B; tessellation {t0:,} instructions '
              f'({t0 / 600e3:.0f} ms at 600 MHz), then {row["tess_view"]:,} for what the views brought in; '
              f'frame {row["frame"]:,} ({row["frame"] / 600e3:.1f} ms); '
              f'finest frame {big["instructions"]:,} for {big["triangles"]:,} triangles; '
              f'peak RAM {peak / (1 << 20):.2f} MiB; '
              f'{len(shots)} screenshots pixel-identical to the host'
              + (f'; OVER BUDGET: {"; ".join(budget_notes)}' if budget_notes else '; within budgets'))
    if args.markdown and rows:
        write_markdown(args.markdown, args.board, rows, ram)
        # The same rows for tools/budgets_doc.py (docs/budgets.md from both boards).
        with open(os.path.splitext(args.markdown)[0] + '.json', 'w') as f:
            json.dump({'board': args.board, 'rows': rows, 'ram': ram}, f, indent=1)
    return 1 if failed else 0


def write_markdown(path, board, rows, ram):
    ms = lambda n: f'{n / 600e3:.1f}'
    lines = [f'### {board}', '',
             '| model | faces | triangles | pack file / inflated B | inflating (M instr) | mesh B | arena peak B '
             '| peak RAM MiB | tessellation (M instr / ms) | frame (M instr / ms) | finest view: triangles, frame (M / ms) '
             '| budgets |',
             '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|']
    for r in rows:
        b = r['big_frame']
        inflating = f'{r["unpack"] / 1e6:.1f}' if r['unpack'] else '-'
        lines.append(f'| {r["model"]} | {r["faces"]} | {r["triangles"]:,} | {r["file_bytes"]:,} / {r["pack_bytes"]:,} '
                     f'| {inflating} | {r["mesh_bytes"]:,} '
                     f'| {r["arena_peak"]:,} | {r["peak_ram"] / (1 << 20):.2f} | {r["tess"] / 1e6:.1f} / {ms(r["tess"])} '
                     f'| {r["frame"] / 1e6:.1f} / {ms(r["frame"])} '
                     f'| {b["triangles"]:,}: {b["instructions"] / 1e6:.1f} / {ms(b["instructions"])} '
                     f'| {"; ".join(r["notes"]) if r["notes"] else "within"} |')
    lines += ['', 'RAM by section (static; the same for every model):', '', '| section | bytes |', '|---|---:|']
    for k, v in ram.items():
        lines.append(f'| {k} | {v:,} |')
    lines.append('')
    with open(path, 'w') as f:
        f.write('\n'.join(lines))


if __name__ == '__main__':
    sys.exit(main())
