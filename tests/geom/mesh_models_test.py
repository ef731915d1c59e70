#!/usr/bin/env python3
"""Packs and tessellates every shared model with facet-pack + facet-mesh (the device's geom/
and cdt/ code) at the default tolerance (0.1% of the bounding-box diagonal).

Asserted for every model that packs: facet-mesh completes with a report, every face either
yields triangles or is reported with a reason, and the measured deviation is within the
tolerance (but for the known exceptions listed below). Watertight (no free or non-manifold
edges, no failed face) is asserted for the models listed in WATERTIGHT: what holds today. Prints one line per model and writes WORK/mesh-models.json.
"""
import argparse
import json
import os
import subprocess
import sys

# Closed solids that tessellate with no free and no non-manifold edge today.
WATERTIGHT = ['anc101.stp', 'base_plate.stp', 'dm1_id_214.stp', 'house_walls.stp', 'io1_cm_214.stp', 'linkrods.step', 'm6_screw.step', 'mic6_bed.step', 'ndr_pivot_pin.stp', 'nist_ftc_11.stp', 'screw.step', 'sg1_c5_214.stp', 'tie_rod.step']
# Every model's measured deviation is within the tolerance, except these known cases (open
# problems, see docs/geom.md).
DEVIATION_EXCEPTIONS = ['nist_ctc_02_ap242.stp']


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--packer', required=True)
    ap.add_argument('--mesher', required=True)
    ap.add_argument('--models', required=True)
    ap.add_argument('--work', required=True)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows, bad = [], []
    for f in sorted(x for x in os.listdir(args.models) if x.lower().endswith(('.stp', '.step'))):
        fpk = os.path.join(args.work, os.path.splitext(f)[0] + '.fpk')
        p = subprocess.run([args.packer, os.path.join(args.models, f), '-o', fpk, '--quiet'], capture_output=True, text=True, timeout=600)
        if p.returncode != 0:
            print(f'skip    {f}: not packed ({p.stderr.strip().splitlines()[-1] if p.stderr.strip() else p.returncode})')
            continue
        rep = os.path.join(args.work, os.path.splitext(f)[0] + '.json')
        m = subprocess.run([args.mesher, fpk, '--json', rep, '--quiet'], capture_output=True, text=True, timeout=600)
        if m.returncode != 0 or not os.path.exists(rep):
            bad.append(f'{f}: facet-mesh exit {m.returncode}: {m.stderr.strip()[-300:]}')
            continue
        r = json.load(open(rep))
        r['model'] = f
        rows.append(r)
        print(f"{f}: {r['faces']} faces, {r['faces_failed']} failed, {r['triangles']} triangles, deviation "
              f"{r['max_deviation']:.4f} / {r['tolerance']:.4f} mm, free {r['free_edges']}, non-manifold "
              f"{r['nonmanifold_edges']}, thin {100 * r['small_angle_share']:.1f}%, {r['ms']:.0f} ms")
        if r['faces'] - r['faces_failed'] > 0 and r['triangles'] == 0:
            bad.append(f'{f}: faces triangulated but no triangles')
        if f in WATERTIGHT and (r['free_edges'] or r['nonmanifold_edges'] or r['faces_failed']):
            bad.append(f"{f}: expected watertight, got {r['free_edges']} free / {r['nonmanifold_edges']} non-manifold edges")
        if f not in DEVIATION_EXCEPTIONS and r['max_deviation'] > r['tolerance']:
            bad.append(f"{f}: deviation {r['max_deviation']:.4f} over the tolerance {r['tolerance']:.4f}")
    json.dump(rows, open(os.path.join(args.work, 'mesh-models.json'), 'w'), indent=2)
    faces = sum(r['faces'] for r in rows)
    failed = sum(r['faces_failed'] for r in rows)
    print(f'{len(rows)} models meshed: {faces - failed} of {faces} faces triangulated; '
          f'{sum(1 for r in rows if not r["free_edges"] and not r["nonmanifold_edges"] and not r["faces_failed"])} watertight; '
          f'{sum(1 for r in rows if r["max_deviation"] <= r["tolerance"])} within tolerance')
    for b in bad:
        print('FAIL', b)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
