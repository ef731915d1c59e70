#!/usr/bin/env python3
"""Plots a benchmark CSV as a PNG beside it (gnuplot, pngcairo).

  plot_bench.py cdt out/bench/cdt.csv     ns per vertex by input, facet vs CGAL (log scale)
  plot_bench.py mesh out/bench/mesh.csv   triangles and time per model, facet vs BRepMesh
  plot_bench.py mesh-table out/bench/mesh.csv   the same as a Markdown table (docs/geom.md)
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


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ('cdt', 'mesh', 'mesh-table'):
        print(__doc__)
        return 2
    {'cdt': plot_cdt, 'mesh': plot_mesh, 'mesh-table': mesh_table}[sys.argv[1]](sys.argv[2])
    return 0


if __name__ == '__main__':
    sys.exit(main())
