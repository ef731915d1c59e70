#!/usr/bin/env python3
"""./facet bench scale: assemblies of 1 k to 100 k faces through the viewer firmware in QEMU.

Each assembly is made with Open CASCADE (tools/assembly: copies of shared models on a grid,
`distinct` copies, `instances` of each model, or `mixed`: distinct copies up to 30 k faces
and instances of them beyond: a machine of many parts, some repeated), packed (facet-pack's default: blocked, LZMA),
loaded at the board's pack address and shown; then turned (four key turns), zoomed in on the
centre (six steps) and quit (tests/sessions/scale.session). With --sources ram,card each pack
also comes from a memory card image (tools/card.py) in the board's SD slot, nothing loaded into
RAM (boards with capabilities.card). One CSV row per board, assembly and source:

  board,kind,source,faces,pack_faces,step_bytes,pack_bytes,first_frame_instructions,first_view_instructions,
  frame_rest_instructions,frame_rest_sharp_instructions,frame_turning_max_instructions,
  frame_zoomed_instructions,frame_dragging_max_instructions,frame_max_instructions,zoom_detail_instructions,
  triangles,deferred_faces,left_out_faces,peak_ram_bytes,note

  faces: the assembly's size as asked (its placed faces are a little over); pack_faces: the
  faces the pack holds (for instances, those of the parts once each);

  first frame: every piece of work from load to the end of the first frame (the parts' boxes
  of a blocked pack while its edges are sampled, or the wireframe);
  first view: to the end of the first frame after the first pass (every face the view wants
  in); a frame at rest: the largest full frame drawn at a view at rest (once the faces are in
  at the fitted view, if the framing then moves it; when the drag ends); at rest, sharp: the
  same fitted view with tangent edges left out (key t: the edges between faces that meet
  smoothly, which the pack marks; a pack made before it marked them has none); turning: the
  largest frame while the view turns by keys; dragging: the largest frame while the mouse drags
  it (a board with a mouse; the frames a drag draws lighter); zoomed: the frame once the zoomed
  view's faces are in; worst: the largest full frame of the session after the first view
  (what ./facet run holds to a frame's budget); zoom to detail: every piece of work from the
  zoom's last step to the zoomed view at its level of detail (budget_rules.zoom_detail); left out: the faces of the parts the memory
  left out at load (drawn as their parts' proxies, or boxes from a pack without them).

The markdown table and a PNG plot (cost against faces, log-log) go beside the CSV. Exact guest
instruction counts (the facet-icount plugin); 600 M = 1 s at 600 MHz. A run that fails says why
in the note; nothing is left out silently.

  scale.py --assembly facet-assembly --packer facet-pack --build build --work DIR --csv FILE
           [--faces 1000,3000,10000,30000,100000] [--kinds distinct,instances,mixed]
           [--boards qemu-versatilepb,qemu-mps2-evkb] MODEL.step...
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import card  # noqa: E402
import img  # noqa: E402
import protocol  # noqa: E402
from budget_rules import first_view, peak_ram, zoom_detail  # noqa: E402
from boot import boot, exit_note, last_error  # noqa: E402  (bench/boot.py: the benches' one run)

COLUMNS = ['board', 'kind', 'source', 'faces', 'pack_faces', 'step_bytes', 'pack_bytes', 'first_frame_instructions', 'first_view_instructions',
           'frame_rest_instructions', 'frame_rest_sharp_instructions', 'frame_turning_max_instructions', 'frame_zoomed_instructions',
           'frame_dragging_max_instructions', 'frame_max_instructions', 'zoom_detail_instructions', 'triangles',
           'deferred_faces', 'left_out_faces', 'peak_ram_bytes', 'note']
MIXED_DISTINCT_FACES = 30_000  # kind mixed: distinct copies up to these faces, instances of them beyond


def measure(uart, regions):
    """The run's figures from its log and regions: the first frame and view (as ./facet run
    budgets them), then the frames of each phase of the session, split by its screenshots."""
    out = {'turning': [], 'dragging': [], 'all': []}
    out['first_frame'], out['first_view'] = first_view(uart, regions)
    pieces = []               # the pieces of the frame under way
    phase = 'load'            # load, rest (after the first shot), sharp, edges, turned, dragged, zoomed
    tessellated = False
    since_turned, last = [], None  # frames after the 'turned' shot; the last frame's cost
    for r, region in protocol.with_regions(uart, regions):
        if region and region['name'] in ('frame', 'update', 'overlay'):
            pieces.append(region['instructions'] or 0)
        elif r.name == 'tessellation':
            tessellated = True
        elif r.name == 'frame':
            n = r.values().get('pieces', 1)
            last = sum(pieces[-n:]) if len(pieces) >= n else None
            pieces = []
            if tessellated and last is not None:
                out['all'].append(last)
            if phase == 'load' and tessellated:
                out['rest'] = last
            elif phase == 'rest' and last is not None:
                out['sharp'] = last  # (tangent edges left out)
            elif phase == 'sharp' and last is not None:
                out['rest'] = max(out.get('rest') or 0, last)  # (the same view with them again)
            elif phase == 'edges' and last is not None:
                out['turning'].append(last)
            elif phase == 'turned' and last is not None:
                since_turned.append(last)
        elif r.name in ('shot', 'dump') and r.fields():  # a screenshot: over QMP, or a framebuffer the board wrote
            shot = r.values()['name']
            if shot == 'dragged':
                out['dragging'] = since_turned[:-1]  # (the last: the view at rest once the button is up)
                if since_turned:
                    out['rest'] = max(out.get('rest') or 0, since_turned[-1])
            elif shot == 'zoomed':
                out['zoomed'] = last
            phase = {'first': 'rest', 'sharp': 'sharp', 'edges': 'edges', 'turned': 'turned', 'dragged': 'dragged',
                     'zoomed': 'zoomed'}.get(shot, phase)
    out['zoom_detail'] = zoom_detail(uart, regions)
    stats = list(protocol.records(uart, 'stats'))  # the viewer's totals as it ends
    if stats and stats[-1].fields():
        out['deferred'], out['triangles'] = stats[-1].values()['deferred'], stats[-1].values()['triangles']
    return out


def make(tool, args, what):
    r = subprocess.run(tool + args, capture_output=True, text=True)
    return f'{what}: {last_error(r)}' if r.returncode != 0 else None


def run_one(board_name, elf, fpk, out, timeout, image=None):
    board = boards.load(board_name)
    row, notes = {}, []
    rep, uart, code = boot(board, elf, fpk, out, protocol.read_session(protocol.session_path('scale'), board_name), timeout, image)
    if rep is None:
        return row, [code]
    bad = protocol.first(uart, 'load_failed')
    if bad:
        notes.append(bad.fields().get('why', bad.text()))
    elif code != 0:
        notes.append(exit_note(code))
    model = protocol.first_fields(uart, 'model')
    if model.get('boxed_parts'):
        notes.append(f'larger than the memory: {model["boxed_parts"]:,} parts left out at load')
    row['left_out_faces'] = model.get('boxed_faces', 0) if model else ''
    m = measure(uart, rep.get('regions', []))
    for key, col in (('first_frame', 'first_frame_instructions'), ('first_view', 'first_view_instructions'),
                     ('rest', 'frame_rest_instructions'), ('sharp', 'frame_rest_sharp_instructions'),
                     ('zoomed', 'frame_zoomed_instructions'), ('zoom_detail', 'zoom_detail_instructions'),
                     ('triangles', 'triangles'), ('deferred', 'deferred_faces')):
        if m.get(key) is not None:
            row[col] = m[key]
    if m['turning']:
        row['frame_turning_max_instructions'] = max(m['turning'])
    if m['dragging']:
        row['frame_dragging_max_instructions'] = max(m['dragging'])
    if m['all']:
        row['frame_max_instructions'] = max(m['all'])
    peak = peak_ram(rep)
    if peak is not None:
        row['peak_ram_bytes'] = peak
    return row, notes


def markdown(rows, date):
    m = lambda v: f'{v / 1e6:,.1f}' if isinstance(v, int) else '-'
    lines = [f'Measured {date} by `./facet bench scale` (exact QEMU instruction counts, M = million instructions, '
             '600 M = 1 s at 600 MHz; the budgets, whatever the model (issue 52): first view 1,200 M, a frame at rest 20 M, '
             'every frame 40 M, a zoom to its detail 600 M).',
             '', '| board | kind | from | faces | faces in the pack | pack KB | first frame M | first view M | frame at rest M '
             '| at rest, tangent edges left out M | turning M | dragging M | zoomed M | worst frame M | zoom to detail M | triangles | deferred faces '
             '| faces left out | peak RAM MiB | note |',
             '|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|']
    for r in rows:
        peak = r.get('peak_ram_bytes')
        lines.append(f'| {r["board"]} | {r["kind"]} | {r.get("source", "ram")} | {r.get("faces", "-")} | {r.get("pack_faces", "-")} | '
                     f'{r["pack_bytes"] // 1024 if r.get("pack_bytes") else "-"} | '
                     f'{m(r.get("first_frame_instructions"))} | {m(r.get("first_view_instructions"))} | '
                     f'{m(r.get("frame_rest_instructions"))} | {m(r.get("frame_rest_sharp_instructions"))} | '
                     f'{m(r.get("frame_turning_max_instructions"))} | '
                     f'{m(r.get("frame_dragging_max_instructions"))} | '
                     f'{m(r.get("frame_zoomed_instructions"))} | {m(r.get("frame_max_instructions"))} | '
                     f'{m(r.get("zoom_detail_instructions"))} | {r.get("triangles", "-")} | '
                     f'{r.get("deferred_faces", "-")} | {r.get("left_out_faces", "-")} | '
                     f'{f"{peak / (1 << 20):.2f}" if peak else "-"} | {r.get("note", "")} |')
    return '\n'.join(lines) + '\n'


def plot(csv_path):
    """Cost against faces (log-log), a line per board, kind and measure, the packs loaded into RAM: the lines should be flat."""
    rows = [r for r in csv.DictReader(open(csv_path)) if r['first_view_instructions'] and r.get('source', 'ram') == 'ram']
    png = os.path.splitext(csv_path)[0] + '.png'
    series = []
    dats = []
    for b in sorted({r['board'] for r in rows}):
        for k in sorted({r['kind'] for r in rows}):
            mine = sorted((r for r in rows if r['board'] == b and r['kind'] == k), key=lambda r: int(r['faces']))
            if not mine:
                continue
            dat = os.path.join(os.path.dirname(csv_path), f'.scale-{b}-{k}.dat')
            with open(dat, 'w') as f:
                for r in mine:
                    f.write(' '.join([r['faces']] + [str(int(r[c]) / 1e6) if r.get(c) else 'NaN' for c in
                                                     ('first_view_instructions', 'frame_rest_instructions',
                                                      'frame_max_instructions')]) + '\n')
            dats.append(dat)
            for col, what in ((2, 'first view'), (3, 'frame at rest'), (4, 'worst frame')):
                series.append(f"'{dat}' using 1:{col} with linespoints title '{b} {k}: {what}'")
    if not series:
        return None
    script = f"""
set terminal pngcairo noenhanced size 1100,650 font 'sans,10'
set output '{png}'
set title 'facet on large assemblies, the pack in RAM: instructions against faces (exact QEMU counts)'
set logscale xy
set xlabel 'faces of the assembly (as asked)'
set ylabel 'million instructions (600 = 1 s at 600 MHz)'
set key outside right
set grid
plot {', '.join(series)}, 1200 with lines dashtype 2 title 'first view budget', 20 with lines dashtype 3 title 'frame at rest budget', 40 with lines dashtype 4 title 'frame budget'
"""
    subprocess.run(['gnuplot'], input=script, text=True, check=True)
    for d in dats:
        os.unlink(d)
    return png


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--assembly', required=True, help='tools/assembly (facet-assembly)')
    ap.add_argument('--packer', required=True)
    ap.add_argument('--build', required=True, help='the build tree holding <board>/firmware/facet-viewer.elf')
    ap.add_argument('--work', required=True)
    ap.add_argument('--csv', required=True)
    ap.add_argument('--faces', default='1000,3000,10000,30000,100000')
    ap.add_argument('--kinds', default='distinct,instances,mixed', help='mixed: above 30 k faces only (at or below, it is distinct); '
                    'distinct above 30 k faces only when mixed is not asked')
    ap.add_argument('--boards', default='qemu-versatilepb,qemu-mps2-evkb')
    ap.add_argument('--sources', default='ram', help='ram, card (an SD card image in the slot of a board with one), or both')
    ap.add_argument('--timeout', type=int, default=3600, help='seconds of wall clock per run')
    ap.add_argument('--date', default='')
    ap.add_argument('--strict', action='store_true', help='exit 1 unless every figure of every row was measured')
    ap.add_argument('models', nargs='+')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board_names = [b for b in args.boards.split(',') if b]
    for b in board_names:
        boards.load(b)
        if not os.path.exists(os.path.join(args.build, b, 'firmware', 'facet-viewer.elf')):
            raise SystemExit(f'scale.py: no facet-viewer.elf for {b} under {args.build}')
    rows = []
    kinds = args.kinds.split(',')
    for kind in kinds:
        for faces in [int(f) for f in args.faces.split(',')]:
            if kind == 'mixed' and faces <= MIXED_DISTINCT_FACES:
                continue  # (the same assembly as distinct)
            if kind == 'distinct' and faces > MIXED_DISTINCT_FACES and 'mixed' in kinds:
                continue  # (mixed stands for it: distinct copies that large are gigabytes of STEP)
            name = f'{kind}-{faces}'
            step = os.path.join(args.work, name + '.step')
            fpk = os.path.join(args.work, name + '.fpk')
            why = None
            if not os.path.exists(step):  # made once (minutes for the largest); delete the folder to remake
                how = {'instances': ['--instances'], 'mixed': ['--distinct', str(min(faces, MIXED_DISTINCT_FACES))]}.get(kind, [])
                why = make([args.assembly], [step, '--faces', str(faces)] + how + args.models, 'facet-assembly')
            # Packed again when the packer is newer than the pack (what it writes may have grown).
            packer = shutil.which(args.packer) or args.packer
            stale = os.path.exists(packer) and os.path.exists(fpk) and os.path.getmtime(fpk) < os.path.getmtime(packer)
            if not why and (not os.path.exists(fpk) or stale):
                why = make([args.packer], [step, '-o', fpk, '--quiet'], 'facet-pack')
            for b, source in [(b, s) for b in board_names for s in args.sources.split(',')]:
                if source == 'card' and not boards.can(b, 'card'):
                    continue
                row = {'board': b, 'kind': kind, 'source': source, 'faces': faces}
                notes = []
                run_dir = os.path.join(args.work, b, name + ('-card' if source == 'card' else ''))
                if why:
                    notes.append(why)
                else:
                    row['step_bytes'], row['pack_bytes'] = os.path.getsize(step), os.path.getsize(fpk)
                    image = None
                    if source == 'card':
                        image = os.path.join(args.work, name + '.img')
                        if not os.path.exists(image) or os.path.getmtime(image) < os.path.getmtime(fpk):
                            card.make(image, [(fpk, name + '.fpk')])
                    got, notes = run_one(b, os.path.join(args.build, b, 'firmware', 'facet-viewer.elf'), fpk, run_dir, args.timeout, image)
                    row.update(got)
                    log = os.path.join(run_dir, 'uart.log')
                    text = open(log, errors='replace').read() if os.path.exists(log) else ''
                    stated = protocol.first_fields(text, 'model')
                    if stated:  # (the faces held, and those of the parts left out)
                        row['pack_faces'] = stated['faces'] + stated.get('boxed_faces', 0)
                row['note'] = '; '.join(notes)
                rows.append(row)
                fv = row.get('first_view_instructions')
                print(f'{b} {name} {source}: ' + (f'first view {fv / 1e6:,.0f} M, frame at rest '
                                         f'{(row.get("frame_rest_instructions") or 0) / 1e6:.1f} M'
                                         if fv else 'not measured') + (f' ({row["note"]})' if row['note'] else ''),
                      flush=True)
    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for row in rows:
            w.writerow([row.get(c, '') for c in COLUMNS])
    md = os.path.splitext(args.csv)[0] + '.md'
    with open(md, 'w') as f:
        f.write(markdown(rows, args.date))
    png = plot(args.csv)
    print(f'wrote {args.csv}, {md}' + (f', {png}' if png else ''))
    figures = ('first_frame_instructions', 'first_view_instructions', 'frame_rest_instructions',
               'frame_rest_sharp_instructions', 'frame_turning_max_instructions', 'frame_zoomed_instructions', 'peak_ram_bytes')
    if args.strict:  # (the test of this script) every figure of every row; a card's pictures those from RAM
        missing = [f'{r["board"]} {r["kind"]}-{r["faces"]} {r["source"]}: {c}' for r in rows for c in figures if r.get(c) in (None, '')]
        for r in rows:
            if r['source'] != 'card':
                continue
            name = f'{r["kind"]}-{r["faces"]}'
            for shot in ('first', 'zoomed'):
                a, b = (os.path.join(args.work, r['board'], name + end, shot + '.png') for end in ('', '-card'))
                if not (os.path.exists(a) and os.path.exists(b)):
                    missing.append(f'{r["board"]} {name}: the {shot} screenshot from RAM or the card')
                    continue
                w, h, _ = img.load_565(a)
                field = img.frame_time_field(w, h)  # (the status bar's text: the model's name as its source gives it, and the time)
                d, msg = img.compare(a, b, ignore=[(0, 0, field[2], field[3])] if field else [])
                if d:
                    missing.append(f'{r["board"]} {name}: the {shot} view from the card is not the one from RAM: {msg}')
        for m in missing:
            print(f'scale.py: not measured: {m}', file=sys.stderr)
        return 1 if missing else 0
    # A row the board could not take says why (its note); one with neither is a failure.
    return 0 if all('first_view_instructions' in r or r['note'] for r in rows) else 1


if __name__ == '__main__':
    sys.exit(main())
