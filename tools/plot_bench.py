#!/usr/bin/env python3
"""Plots a benchmark CSV as a PNG beside it (gnuplot, pngcairo).

  plot_bench.py cdt out/bench/cdt.csv     ns per vertex by input, facet vs CGAL (log scale)
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
set terminal pngcairo size 1200,600 font 'sans,10'
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


def main():
    if len(sys.argv) != 3 or sys.argv[1] != 'cdt':
        print(__doc__)
        return 2
    plot_cdt(sys.argv[2])
    return 0


if __name__ == '__main__':
    sys.exit(main())
