#!/usr/bin/env python3
"""./facet bench device: every model through the viewer firmware on the boards in QEMU, with
exact instruction counts (the facet-icount plugin), one CSV row per board and model:

  board,model,faces,triangles,inflate_instructions,tessellation_instructions,
  max_face_instructions,max_frame_instructions,peak_ram_bytes

and a markdown table (for docs/budgets.md). Each model is packed once on the host (LZMA,
what ./facet run loads), booted at the board's pack address and shown: the first pass is
tessellated, the finished model drawn, then zoomed in three times and quit. The counts are the
ones tests/qemu/viewer_test.py takes (the same analysis): tessellation = edge sampling and every
face piece of the first pass; a face's instructions = its pieces, up to its '@progress' line;
a frame = the pieces of one full redraw of the finished mesh (the fitted and the zoomed views);
peak RAM as in docs/budgets.md. A model the board cannot take (a pack over the board's pack
region, a model over the default capacities, faces that fail) gets its row with what was
measured and a note saying why, in the markdown and on stderr: never a silent gap.

  device.py --packer facet-pack --build build --csv out/bench/device.csv --markdown FILE
            [--boards qemu-versatilepb,qemu-mps2-an500] [--jobs N] MODEL.step...
"""
import argparse
import concurrent.futures
import csv
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import protocol  # noqa: E402
from budget_rules import analyse, peak_ram, tessellation_budget, unpack_instructions  # noqa: E402
from boot import boot, exit_note, last_error  # noqa: E402  (bench/boot.py: the benches' one run)

COLUMNS = ['board', 'model', 'faces', 'triangles', 'inflate_instructions', 'tessellation_instructions',
           'max_face_instructions', 'max_frame_instructions', 'peak_ram_bytes']
SESSION = protocol.read_session(protocol.session_path('device'))


def face_instructions(uart, regions):
    """Instructions per face of the first pass: its 'face' pieces up to its '@progress' line."""
    faces, now, pass_no = [], 0, -1
    for r, region in protocol.with_regions(uart, regions):
        if r.name == 'pass':
            pass_no = r.values()['pass']
        elif r.name == 'progress' and pass_no == 0:
            faces.append(now)
            now = 0
        elif region and region['name'] == 'face' and pass_no == 0:
            now += region['instructions'] or 0
    return faces


def pack(packer, model, fpk):
    r = subprocess.run([packer, model, '-o', fpk, '--quiet'], capture_output=True, text=True)
    return last_error(r) if r.returncode != 0 else None


def run_one(board_name, elf, fpk, out, timeout):
    board = boards.load(board_name)
    name = os.path.basename(out)
    row = {'board': board_name, 'model': name}
    notes = []
    rep, uart, code = boot(board, elf, fpk, out, SESSION, timeout)
    if rep is None:
        return row, [code]
    if code != 0:
        notes.append(exit_note(code))
    bad = protocol.first(uart, 'load_failed')
    if bad:
        notes.append(bad.fields().get('why', bad.text()))
    t = protocol.tessellation(uart)
    tess, frames = analyse(uart, rep.get('regions', []))
    faces = face_instructions(uart, rep.get('regions', []))
    if t:
        row['faces'], row['triangles'] = t['faces'], t['triangles']
        if t['failed']:
            notes.append(f'{t["failed"]} faces failed')
        full = [f['instructions'] for f in frames
                if f['pass'] == 0 and f['triangles'] == row['triangles'] and f['instructions'] is not None]
        if full:
            row['max_frame_instructions'] = max(full)
    elif not bad:
        notes.append('no tessellation report')
    row['inflate_instructions'] = unpack_instructions(rep.get('regions', [])) or 0
    if 0 in tess and t:
        row['tessellation_instructions'] = tess[0]
        if tess[0] > tessellation_budget(t['faces']):
            notes.append(f'tessellation over its {tessellation_budget(t["faces"]) / 1e6:,.0f} M budget')
    if faces:
        row['max_face_instructions'] = max(faces)
    peak = peak_ram(rep)
    if peak is not None:
        row['peak_ram_bytes'] = peak
    return row, notes


def markdown(rows, date):
    by_board = {}
    for row, notes in rows:
        by_board.setdefault(row['board'], []).append((row, notes))
    m = lambda v: f'{v / 1e6:.1f}' if isinstance(v, int) else '-'
    lines = [f'Measured {date} by `./facet bench device` (exact QEMU instruction counts; LZMA packs, default '
             'tolerance; M = million instructions, 600 M = 1 s at 600 MHz).', '']
    for board_name, items in by_board.items():
        lines += [f'#### {board_name}', '',
                  '| model | faces | triangles | inflating M | tessellation M | largest face M | largest frame M '
                  '| peak RAM MiB | notes |',
                  '|---|---:|---:|---:|---:|---:|---:|---:|---|']
        for row, notes in items:
            peak = row.get('peak_ram_bytes')
            lines.append(f'| {row["model"]} | {row.get("faces", "-")} | '
                         f'{format(row["triangles"], ",") if "triangles" in row else "-"} | '
                         f'{m(row.get("inflate_instructions")) if row.get("inflate_instructions") else "-"} | '
                         f'{m(row.get("tessellation_instructions"))} | {m(row.get("max_face_instructions"))} | '
                         f'{m(row.get("max_frame_instructions"))} | '
                         f'{f"{peak / (1 << 20):.2f}" if peak else "-"} | {"; ".join(notes)} |')
        lines.append('')
    return '\n'.join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--packer', required=True)
    ap.add_argument('--build', required=True, help='the build tree holding <board>/firmware/facet-viewer.elf')
    ap.add_argument('--work', required=True)
    ap.add_argument('--csv', required=True)
    ap.add_argument('--markdown')
    ap.add_argument('--boards', default='qemu-versatilepb,qemu-mps2-an500')
    ap.add_argument('--jobs', type=int, default=os.cpu_count() or 1)
    ap.add_argument('--timeout', type=int, default=900, help='seconds of wall clock per run')
    ap.add_argument('--date', default='')
    ap.add_argument('--strict', action='store_true',
                    help='exit 1 unless every model was measured on every board (the test of this script)')
    ap.add_argument('models', nargs='+')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board_names = [b for b in args.boards.split(',') if b]
    for b in board_names:
        boards.load(b)
        elf = os.path.join(args.build, b, 'firmware', 'facet-viewer.elf')
        if not os.path.exists(elf):
            raise SystemExit(f'device.py: no {elf} (./facet build {b})')
    packs, failed_packs = {}, {}
    for model in sorted(args.models):
        name = os.path.splitext(os.path.basename(model))[0]
        fpk = os.path.join(args.work, name + '.fpk')
        why = pack(args.packer, model, fpk)
        if why:
            failed_packs[name] = why
            print(f'{name}: the packer refused it: {why}', file=sys.stderr)
        else:
            packs[name] = fpk
    jobs = [(b, name) for name in packs for b in board_names]
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futs = {pool.submit(run_one, b, os.path.join(args.build, b, 'firmware', 'facet-viewer.elf'), packs[name],
                            os.path.join(args.work, b, name), args.timeout): (b, name) for b, name in jobs}
        for fut in concurrent.futures.as_completed(futs):
            b, name = futs[fut]
            row, notes = fut.result()
            results[(b, name)] = (row, notes)
            t = row.get('tessellation_instructions')
            print(f'{b} {name}: ' + (f'{row.get("triangles", 0):,} triangles, tessellation {t / 1e6:.1f} M, '
                                     f'largest face {row.get("max_face_instructions", 0) / 1e6:.1f} M, largest frame '
                                     f'{row.get("max_frame_instructions", 0) / 1e6:.1f} M' if t else 'not measured')
                  + (f' ({"; ".join(notes)})' if notes else ''), flush=True)
    rows = []
    for b in board_names:
        for name in sorted(set(packs) | set(failed_packs)):
            if name in failed_packs:
                rows.append(({'board': b, 'model': name}, [f'not packed: {failed_packs[name]}']))
            else:
                rows.append(results[(b, name)])
    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for row, _ in rows:
            w.writerow([row.get(c, '') for c in COLUMNS])
    print(f'wrote {args.csv}')
    if args.markdown:
        with open(args.markdown, 'w') as f:
            f.write(markdown(rows, args.date))
        print(f'wrote {args.markdown}')
    unmeasured = [f'{r["board"]} {r["model"]}' for r, n in rows if 'tessellation_instructions' not in r]
    if unmeasured:
        print(f'not measured ({len(unmeasured)}): {", ".join(unmeasured)}', file=sys.stderr)
    incomplete = [f'{r["board"]} {r["model"]}' for r, n in rows if any(c not in r for c in COLUMNS)]
    if args.strict and (unmeasured or incomplete):
        print(f'device.py: incomplete rows: {", ".join(incomplete)}', file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
