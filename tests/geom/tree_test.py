#!/usr/bin/env python3
"""The assembly tree in the pack (issue 53): on the shared assemblies and on assemblies
facet-assembly makes of them, whole and blocked, facet-pack's tree is the product structure
Open CASCADE reads (tests/geom/product_reference.cpp, written apart from facet-pack's reader):
the same sub-assemblies in the same depth-first order, each at its depth, with its name and
as many parts under it.

  tree_test.py --packer facet-pack --reference facet-product-reference --assembly facet-assembly
               --models DIR --work DIR
"""
import argparse
import json
import os
import re
import subprocess
import sys

NODE = re.compile(r'^  ( *)node (\d+) "((?:[^"\\]|\\.)*)"(?: as "(?:[^"\\]|\\.)*")?: instances (\d+)-(-?\d+)$')


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f'FAIL: {" ".join(cmd)}: exit {r.returncode}\n{r.stderr[-2000:]}')
    return r.stdout


def tree_of(packer, pack):
    nodes = []
    for line in run([packer, '--check', pack]).splitlines():
        m = NODE.match(line)
        if m:
            nodes.append([len(m.group(1)) // 2, m.group(3), int(m.group(5)) - int(m.group(4)) + 1])
    return nodes


def main():
    ap = argparse.ArgumentParser()
    for a in ('--packer', '--reference', '--assembly', '--models', '--work'):
        ap.add_argument(a, required=True)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    m = lambda name: os.path.join(args.models, name)  # noqa: E731
    steps = [m('as1_oc_214.stp'), m('tail_section_asm.stp')]
    for name, extra in (('distinct', []), ('instances', ['--instances'])):
        out = os.path.join(args.work, name + '.step')
        run([args.assembly, out, '--faces', '400'] + extra + [m('as1_oc_214.stp'), m('nist_ctc_01.stp')])
        steps.append(out)
    failures = []
    for step in steps:
        ref = json.loads(run([args.reference, step]))
        want = ref['assemblies']
        if ref['roots'] != 1 and want:  # several top products: one node for the model over them
            want = [[0, None, sum(p for d, _, p in want if d == 0)]] + [[d + 1, n, p] for d, n, p in want]
        for form in ('whole', 'blocked'):
            pack = os.path.join(args.work, os.path.basename(step) + f'.{form}.fpk')
            run([args.packer, step, '-o', pack, '--quiet', '--' + form])
            got = tree_of(args.packer, pack)
            if len(got) != len(want):
                failures.append(f'{os.path.basename(step)} ({form}): {len(got)} nodes, Open CASCADE reads {len(want)} assemblies')
                continue
            for k, (g, w) in enumerate(zip(got, want)):
                if g[0] != w[0] or g[2] != w[2] or (w[1] is not None and g[1] != w[1]):
                    failures.append(f'{os.path.basename(step)} ({form}): node {k} is {g}, Open CASCADE says {w}')
                    break
            print(f'{os.path.basename(step)} ({form}): {len(got)} nodes, '
                  f'{max((g[0] for g in got), default=0)} levels deep, as Open CASCADE reads them')
    for f in failures:
        print('FAIL:', f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
