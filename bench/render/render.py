#!/usr/bin/env python3
"""./facet bench render: facet's frames against tgx's (a peer, built only into the bench
firmware facet-render-bench) in QEMU on the boards, exact instruction counts in one run.

For each model: packed (deflated) and tessellated on the host by facet-mesh (the device's
code, the viewer's default tolerance) into an OBJ, which tgx_mesh.py makes tgx meshes of; the
bench firmware gets both, tessellates the pack with the module and, at 480x272 then 640x480,
draws the fitted view once every face is done ("full") and three steps closer ("zoomed"), with
B-rep edges ("facet") and without ("facet_shaded"); tgx draws each view with the module's
camera (Viewer::camera()). A frame of facet's is the sum of its pieces (the 'frame' regions up
to its '@bench_frame' line); tgx's is one 'tgx' region, its clears included (facet's frame includes
its background).

Writes CSV  board,model,view,width,height,impl,triangles,pixels,instructions
  (triangles: those facet drew in the view, after culling, the same mesh and camera for tgx;
  pixels: those the model covers, from each renderer's own depth buffer), a PNG plot beside it
  and, under WORK/BOARD/MODEL/, the pictures side by side (facet | tgx): side-*.png.
Checks, for every row: the bench firmware finished, both sides drew the same mesh (triangle
counts), and their covered pixels agree within 2% (the same view). With --host-views (the
facet-render-views program: the firmware's sequence of views drawn by the module on the host),
every picture of facet's on every board is the host's, byte for byte.

  render.py --packer P --mesher M [--host-views V] --build BUILD --work DIR --csv FILE [--boards A,B]
            MODEL.step[@finerN]...
  (@finerN: the viewer's level of detail N steps finer than its default, on both sides)
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import img  # noqa: E402
import protocol  # noqa: E402

COLUMNS = ['board', 'model', 'view', 'width', 'height', 'impl', 'triangles', 'pixels', 'instructions']
COVERAGE_TOLERANCE = 0.02


def analyse(uart, regions):
    """Rows from the firmware's lines and the plugin's regions, in order."""
    rows, problems, frames, last_frame, last_tgx, model = [], [], [], None, None, {}
    for r, region in protocol.with_regions(uart, regions):
        if region:
            if region['name'] == 'frame':
                frames.append(region['instructions'])
            elif region['name'] == 'tgx':
                last_tgx = region['instructions']
        elif r.name == 'bench_model':
            model = r.values()
            if model['triangles'] != model['peer_triangles']:
                problems.append(f'facet tessellated {model["triangles"]:,} triangles, the OBJ has {model["peer_triangles"]:,}')
        elif r.name == 'bench_frame':
            kv = r.values()
            n = kv['pieces']
            mine = frames[-n:] if n and len(frames) >= n else [None]
            last_frame = dict(kv, instructions=None if None in mine else sum(mine))
            frames = []
        elif r.name in ('bench_view', 'peer'):
            kv = r.values()
            view = kv['view']
            width, height = map(int, kv['size'].split('x'))
            if r.name == 'bench_view':
                impl = 'facet' if kv['mode'] == 'edges' else 'facet_shaded'
                rows.append({'view': view, 'width': width, 'height': height, 'impl': impl,
                             'triangles': last_frame['triangles'], 'pixels': int(kv['covered']),
                             'instructions': last_frame['instructions']})
            else:
                drawn = rows[-1]['triangles'] if rows else 0
                rows.append({'view': view, 'width': width, 'height': height, 'impl': 'tgx', 'triangles': drawn,
                             'pixels': int(kv['covered']), 'instructions': last_tgx})
    return rows, problems


def side_by_side(out, view, size):
    """facet | tgx, one picture (out/side-VIEW-SIZE.png)."""
    a = os.path.join(out, f'{view}-{size}-facet.f565')
    b = os.path.join(out, f'{view}-{size}-tgx.f565')
    if not (os.path.exists(a) and os.path.exists(b)):
        return None
    w, h, pa = img.read_f565(a)
    _, _, pb = img.read_f565(b)
    gap = 8
    rows = []
    for y in range(h):
        left = bytes(c for p in pa[y * w:(y + 1) * w] for c in img.rgb565_to_rgb(p))
        right = bytes(c for p in pb[y * w:(y + 1) * w] for c in img.rgb565_to_rgb(p))
        rows.append(left + b'\xff' * (3 * gap) + right)
    path = os.path.join(out, f'side-{view}-{size}.png')
    img.write_png(path, 2 * w + gap, h, rows)
    return path


def host_differences(out, host, view, size):
    """Where facet's pictures of a view on the board are not the host's (none: the same bytes)."""
    problems = []
    for mode in ('facet', 'facet-shaded'):
        name = f'{view}-{size}-{mode}.f565'
        a, b = os.path.join(out, name), os.path.join(host, name)
        if not (os.path.exists(a) and os.path.exists(b)):
            problems.append(f'{name}: no picture to compare with the host\'s')
            continue
        wa, ha, pa = img.read_f565(a)
        wb, hb, pb = img.read_f565(b)
        if (wa, ha) != (wb, hb):
            problems.append(f'{name}: {wa}x{ha} on the board, {wb}x{hb} on the host')
        elif pa != pb:
            problems.append(f'{name}: {sum(x != y for x, y in zip(pa, pb)):,} pixels differ from the host\'s')
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--packer', required=True)
    ap.add_argument('--mesher', required=True)
    ap.add_argument('--host-views', help='facet-render-views: compare every board\'s pictures with the host\'s')
    ap.add_argument('--build', required=True)
    ap.add_argument('--work', required=True)
    ap.add_argument('--csv', required=True)
    ap.add_argument('--boards', default='qemu-versatilepb,qemu-mps2-an500')
    ap.add_argument('--timeout', type=int, default=1800)
    ap.add_argument('models', nargs='+')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    all_rows, failed = [], False
    for spec in args.models:
        model, _, finer = spec.partition('@finer')
        finer = int(finer or 0)
        name = os.path.splitext(os.path.basename(model))[0] + (f'-finer{finer}' if finer else '')
        fpk, obj, blob = (os.path.join(args.work, name + e) for e in ('.fpk', '.obj', '.tgx'))
        for cmd in ([args.packer, model, '-o', fpk, '--quiet'],
                    [args.mesher, fpk, '--obj', obj, '--finer', str(finer), '--quiet'],
                    [sys.executable, os.path.join(ROOT, 'bench', 'render', 'tgx_mesh.py'), obj, blob]):
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                raise SystemExit(f'render.py: {" ".join(cmd)}: exit {r.returncode}\n{r.stderr[-2000:]}')
        host = None
        if args.host_views:
            host = os.path.join(args.work, 'host', name)
            os.makedirs(host, exist_ok=True)
            r = subprocess.run([args.host_views, fpk, str(finer), host], capture_output=True, text=True)
            if r.returncode != 0:
                raise SystemExit(f'render.py: {args.host_views} {name}: exit {r.returncode}\n{r.stderr[-2000:]}')
        for b in [x for x in args.boards.split(',') if x]:
            board = boards.load(b)
            elf = os.path.join(args.build, b, 'bench', 'facet-render-bench.elf')
            if not os.path.exists(elf):
                raise SystemExit(f'render.py: no {elf} (./facet build {b}; tgx at ../shared/peers/tgx)')
            packs = board['pack_address']
            if os.path.getsize(fpk) > board['pack_bytes'] // 2 or os.path.getsize(blob) > board['pack_bytes'] // 2:
                print(f'{b} {name}: the pack or the mesh is over half the board\'s pack region: not measured',
                      file=sys.stderr)
                failed = True
                continue
            out = os.path.join(args.work, b, name)
            r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', b, '--elf', elf,
                                '--out', out, '--load', f'{fpk}@{hex(packs)}',
                                '--load', f'{blob}@{hex(packs + board["pack_bytes"] // 2)}', '--icount',
                                '--type', f'{finer}\\n', '--timeout', str(args.timeout), '--quiet'],
                               capture_output=True, text=True)
            rep_path = os.path.join(out, 'report.json')
            uart = open(os.path.join(out, 'uart.log'), errors='replace').read() if os.path.exists(
                os.path.join(out, 'uart.log')) else ''
            if r.returncode != 0 or not os.path.exists(rep_path):
                print(f'FAIL {b} {name}: the bench firmware exit {r.returncode}\n{uart[-1500:]}{r.stderr[-1500:]}',
                      file=sys.stderr)
                failed = True
                continue
            rows, problems = analyse(uart, json.load(open(rep_path))['regions'])
            by_view = {}
            for row in rows:
                by_view.setdefault((row['view'], row['width'], row['height']), {})[row['impl']] = row
            for (view, w, h), impls in by_view.items():
                f, t = impls.get('facet_shaded'), impls.get('tgx')
                if not f or not t or None in (f['instructions'], t['instructions']):
                    problems.append(f'{view} {w}x{h}: a count is missing')
                    continue
                if abs(f['pixels'] - t['pixels']) > COVERAGE_TOLERANCE * max(f['pixels'], t['pixels']):
                    problems.append(f'{view} {w}x{h}: facet covers {f["pixels"]:,} pixels, tgx {t["pixels"]:,}: '
                                    'not the same view')
                side_by_side(out, view, f'{w}x{h}')
                if host:
                    problems += host_differences(out, host, view, f'{w}x{h}')
            if problems:
                failed = True
                print(f'FAIL {b} {name}: ' + '; '.join(problems), file=sys.stderr)
            for row in rows:
                all_rows.append(dict(row, board=b, model=name))
            for (view, w, h), impls in by_view.items():
                f, s, t = impls.get('facet'), impls.get('facet_shaded'), impls.get('tgx')
                if f and s and t and t['instructions']:
                    print(f'{b:17s} {name:14s} {view:6s} {w}x{h}: {f["triangles"]:6,} triangles, '
                          f'{t["pixels"]:7,} pixels; facet {f["instructions"] / 1e6:6.2f} M '
                          f'({s["instructions"] / 1e6:.2f} M without edges), tgx {t["instructions"] / 1e6:6.2f} M: '
                          f'facet/tgx {f["instructions"] / t["instructions"]:.2f}', flush=True)
    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, 'w', newline='') as fh:
        wr = csv.writer(fh)
        wr.writerow(COLUMNS)
        for row in all_rows:
            wr.writerow([row[c] for c in COLUMNS])
    print(f'wrote {args.csv}')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
