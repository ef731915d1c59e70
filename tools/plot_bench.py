#!/usr/bin/env python3
"""Plots a benchmark CSV as a PNG beside it (gnuplot, pngcairo).

  plot_bench.py cdt out/bench/cdt.csv     ns per vertex by input, facet vs CGAL (log scale)
  plot_bench.py mesh out/bench/mesh.csv   triangles and time per model, facet vs BRepMesh
  plot_bench.py mesh-table out/bench/mesh.csv   the same as a Markdown table (docs/geom.md)
  plot_bench.py render out/bench/render.csv   instructions a frame by view, facet vs tgx, per board
  plot_bench.py render-table out/bench/render.csv   the same as a Markdown table (docs/render.md)
"""
import csv
import os
import subprocess
import sys
import tempfile


def plot_cdt(path):
    rows = list(csv.DictReader(open(path)))
    inputs, table = [], {}
    for r in rows:
        if r['input'] not in table:
            inputs.append(r['input'])
            table[r['input']] = {}
        table[r['input']][r['impl']] = float(r['ns_per_vertex'])
    impls = [i for i in ('cgal', 'facet16', 'facet32') if any(i in t for t in table.values())]
    with tempfile.NamedTemporaryFile('w', suffix='.dat', delete=False) as dat:
        dat.write('input ' + ' '.join(impls) + '\n')
        for name in inputs:
            dat.write(f'"{name}" ' + ' '.join(str(table[name].get(i, 'NaN')) for i in impls) + '\n')
    png = os.path.splitext(path)[0] + '.png'
    cols = ', '.join(f"'{dat.name}' using {k + 2}:xtic(1) title columnheader" for k in range(len(impls)))
    script = f"""
set terminal pngcairo noenhanced size 1200,600 font 'sans,10'
set output '{png}'
set title 'Constrained Delaunay triangulation: ns per inserted vertex (lower is better)'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set logscale y
set ylabel 'ns per vertex'
set xtics rotate by -30
set key top left
set grid ytics
plot {cols}
"""
    subprocess.run(['gnuplot'], input=script, text=True, check=True)
    os.unlink(dat.name)
    print(f'plot: {png}')


def plot_mesh(path):
    rows = [r for r in csv.DictReader(open(path))]
    models = []
    tri, ms = {}, {}
    for r in rows:
        if r['model'] not in models:
            models.append(r['model'])
    smallest = {}
    for r in rows:  # the finer deflection of each model (0.1% of the diagonal)
        d = float(r['deflection'])
        if r['model'] not in smallest or d < smallest[r['model']]:
            smallest[r['model']] = d
    for r in rows:
        if float(r['deflection']) == smallest[r['model']]:
            tri[(r['model'], r['impl'])] = int(r['triangles'])
            ms[(r['model'], r['impl'])] = float(r['ms'])
    for (m, impl) in list(tri):  # facet@equal? (BRepMesh's deviation not reached) plots as facet@equal
        if impl == 'facet@equal?':
            tri[(m, 'facet@equal')] = tri[(m, impl)]
    with tempfile.NamedTemporaryFile('w', suffix='.dat', delete=False) as dat:
        dat.write('model facet_triangles equal_triangles brepmesh_triangles facet_ms brepmesh_ms\n')
        for m in models:
            dat.write(f'"{m}" {tri.get((m, "facet"), "NaN")} {tri.get((m, "facet@equal"), "NaN")} '
                      f'{tri.get((m, "brepmesh"), "NaN")} {ms.get((m, "facet"), "NaN")} {ms.get((m, "brepmesh"), "NaN")}\n')
    png = os.path.splitext(path)[0] + '.png'
    script = f"""
set terminal pngcairo noenhanced size 1400,900 font 'sans,9'
set output '{png}'
set multiplot layout 2,1 title 'Tessellation at 0.1% of the bounding-box diagonal: facet vs BRepMesh'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set logscale y
set xtics rotate by -35
set grid ytics
set key top left
set ylabel 'triangles'
plot '{dat.name}' using 2:xtic(1) title 'facet (same deflection)', '' using 3 title 'facet at BRepMesh measured deviation', '' using 4 title 'BRepMesh'
set ylabel 'ms (host)'
plot '{dat.name}' using 5:xtic(1) title 'facet', '' using 6 title 'BRepMesh'
unset multiplot
"""
    subprocess.run(['gnuplot'], input=script, text=True, check=True)
    os.unlink(dat.name)
    print(f'plot: {png}')


def mesh_table(path):
    """One row per model at its finer deflection (0.1% of the diagonal)."""
    rows = list(csv.DictReader(open(path)))
    by = {}
    for r in rows:
        by.setdefault(r['model'], {}).setdefault(float(r['deflection']), {})[r['impl'].rstrip('?')] = r  # facet@equal? = not reached
    print('| model | BRepMesh triangles | BRepMesh deviation | facet triangles (same deflection) | facet deviation '
          '| facet at BRepMesh\'s deviation | ratio | facet ms | BRepMesh ms | speed-up '
          '| free / non-manifold / overlap edges: facet; BRepMesh |')
    print('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|')
    ratios, speed = [], []
    for model, per in by.items():
        d = min(per)
        f, b, e = per[d].get('facet'), per[d].get('brepmesh'), per[d].get('facet@equal')
        if not (f and b and e):
            continue
        bt, et = int(b['triangles']), int(e['triangles'])
        reached = not e['impl'].endswith('?')
        ratio = et / bt if bt and reached else None
        sp = float(b['ms']) / max(float(f['ms']), 1e-3)
        if ratio is not None:
            ratios.append(ratio)
        speed.append(sp)
        topo = lambda r: f"{r['free_edges']} / {r['nonmanifold_edges']} / {r.get('overlap_edges', '-')}"
        print(f"| {model} | {bt:,} | {float(b['max_deviation']):.4f} | {int(f['triangles']):,} | {float(f['max_deviation']):.4f} "
              f"| {str(et) + ' ' if not reached else f'{et:,}'}{'' if reached else '(not reached)'} "
              f"| {'-' if ratio is None else f'{ratio:.2f}'} | {float(f['ms']):.1f} | {float(b['ms']):.1f} "
              f"| {sp:.0f}x | {topo(f)}; {topo(b)} |")
    if ratios:
        ratios.sort()
        speed.sort()
        print(f'\nMedian ratio {ratios[len(ratios) // 2]:.2f} over {len(ratios)} models (range {ratios[0]:.2f}-{ratios[-1]:.2f}); '
              f'median speed-up {speed[len(speed) // 2]:.0f}x (range {speed[0]:.0f}x-{speed[-1]:.0f}x).')


def render_views(path):
    """{(board, model, view, size): {impl: row}} in the CSV's order."""
    views = {}
    for r in csv.DictReader(open(path)):
        views.setdefault((r['board'], r['model'], r['view'], f'{r["width"]}x{r["height"]}'), {})[r['impl']] = r
    return views


def plot_render(path):
    views = render_views(path)
    impls = ['facet', 'facet_shaded', 'tgx']
    png = os.path.splitext(path)[0] + '.png'
    boards = list(dict.fromkeys(k[0] for k in views))
    plots = []
    with tempfile.NamedTemporaryFile('w', suffix='.dat', delete=False) as dat:
        for b in boards:
            dat.write('view ' + ' '.join(impls) + '\n')
            for (board, model, view, size), row in views.items():
                if board == b:
                    dat.write(f'"{model} {view} {size}" ' + ' '.join(
                        str(int(row[i]['instructions']) / 1e6) if i in row else 'NaN' for i in impls) + '\n')
            dat.write('\n\n')
    for k, b in enumerate(boards):
        cols = ', '.join(f"'{dat.name}' index {k} using {j + 2}:xtic(1) title columnheader" for j in range(len(impls)))
        plots.append(f"set title '{b}: million instructions a frame (lower is better)'\nplot {cols}")
    script = f"""
set terminal pngcairo noenhanced size 1400,{420 * len(boards)} font 'sans,10'
set output '{png}'
set multiplot layout {len(boards)},1
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set logscale y
set ylabel 'M instructions'
set xtics rotate by -25
set key top left
""" + '\n'.join(plots) + '\nunset multiplot\n'
    subprocess.run(['gnuplot'], input=script, text=True, check=True)
    os.unlink(dat.name)
    print(f'plot: {png}')


def render_table(path):
    print('| board | model | view | screen | triangles drawn | pixels | facet M | facet without edges M | tgx M '
          '| facet / tgx |')
    print('|---|---|---|---|---:|---:|---:|---:|---:|---:|')
    for (board, model, view, size), row in render_views(path).items():
        f, s, t = row.get('facet'), row.get('facet_shaded'), row.get('tgx')
        if not (f and s and t):
            continue
        fi, si, ti = (int(x['instructions']) for x in (f, s, t))
        print(f'| {board} | {model} | {view} | {size} | {int(f["triangles"]):,} | {int(t["pixels"]):,} | {fi / 1e6:.2f} '
              f'| {si / 1e6:.2f} | {ti / 1e6:.2f} | {fi / ti:.2f} |')


def main():
    kinds = {'cdt': plot_cdt, 'mesh': plot_mesh, 'mesh-table': mesh_table, 'render': plot_render,
             'render-table': render_table}
    if len(sys.argv) != 3 or sys.argv[1] not in kinds:
        print(__doc__)
        return 2
    kinds[sys.argv[1]](sys.argv[2])
    return 0


if __name__ == '__main__':
    sys.exit(main())
