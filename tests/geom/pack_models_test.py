#!/usr/bin/env python3
"""Every STEP file in ../shared/models packs.

For each model: facet-pack must exit 0 and write a pack that the device's reader (facet-pack
--check) validates, with every face of the file's shells (ndr_part01 too: no product structure,
no unit, read as metres), and no larger than 10% of its STEP file (blocked or whole), its tangent edges (SmoothEdges: faces
meeting with G1 continuity, Open CASCADE's regularity) marked: none more than the edges, and on
the machined parts with fillets (nist_ctc_02, nist_ctc_04) between a quarter and two thirds. A refusal (exit 1 with its 'facet-pack: error: ...' line, printed), a
crash, a signal, a timeout, or a pack the reader refuses fails the test. Prints one line per model
(faces by surface type, pack file size as % of the STEP file) and the counts, and writes them to
WORK/pack-models.json.
"""
import argparse
import json
import os
import re
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--packer', required=True)
    ap.add_argument('--models', required=True)
    ap.add_argument('--work', required=True)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    files = sorted(f for f in os.listdir(args.models) if f.lower().endswith(('.stp', '.step')))
    if not files:
        print(f'no STEP files in {args.models}')
        return 1
    rows, bad = [], []
    for f in files:
        out = os.path.join(args.work, os.path.splitext(f)[0] + '.fpk')
        try:
            r = subprocess.run([args.packer, os.path.join(args.models, f), '-o', out, '--quiet'],
                               capture_output=True, text=True, timeout=600)
        except subprocess.TimeoutExpired:
            bad.append(f'{f}: timed out')
            continue
        if r.returncode == 0:
            c = subprocess.run([args.packer, '--check', out], capture_output=True, text=True)
            if c.returncode != 0:
                bad.append(f'{f}: packed, but the reader refuses it: {c.stderr.strip()}')
                continue
            m = re.search(r'pack (\d+) bytes = ([\d.]+)% of the STEP', r.stdout)
            inflated = re.search(r'(\d+) bytes decoded', r.stdout)
            summary = r.stdout.strip().splitlines()[0].split(': ', 1)[1]
            rows.append({'model': f, 'status': 'packed', 'bytes': int(m.group(1)), 'percent_of_step': float(m.group(2)),
                         'inflated_bytes': int(inflated.group(1)) if inflated else int(m.group(1)), 'summary': summary})
            print(f'packed  {f}: {summary}; {m.group(2)}% of the STEP file')
            if float(m.group(2)) > 10.0:
                bad.append(f'{f}: the pack is {m.group(2)}% of the STEP file (at most 10%)')
            t = re.search(r'(\d+) edges \((\d+) tangent\)', r.stdout)
            if not t:
                bad.append(f'{f}: the summary does not say its tangent edges')
                continue
            edges, tangent = int(t.group(1)), int(t.group(2))
            rows[-1]['edges'], rows[-1]['tangent_edges'] = edges, tangent
            if tangent > edges:
                bad.append(f'{f}: {tangent} tangent edges of {edges}')
            if f in ('nist_ctc_02.stp', 'nist_ctc_04.stp') and not edges / 4 <= tangent <= 2 * edges / 3:
                bad.append(f'{f}: {tangent} tangent edges of {edges}: a machined part with fillets has more, and its '
                           'planes\' edges are sharp')
        elif r.returncode == 1 and 'facet-pack: error:' in r.stderr:
            reason = r.stderr.strip().splitlines()[-1]
            rows.append({'model': f, 'status': 'refused', 'reason': reason})
            print(f'refused {f}: {reason}')
            bad.append(f'{f}: refused: {reason}')
        else:
            bad.append(f'{f}: exit {r.returncode} without a clear message: {r.stderr.strip()[-300:]}')
    packed = sum(r['status'] == 'packed' for r in rows)
    print(f'{packed} of {len(files)} models packed, {len(rows) - packed} refused with a reason, {len(bad)} failed')
    json.dump(rows, open(os.path.join(args.work, 'pack-models.json'), 'w'), indent=2)
    for b in bad:
        print('FAIL', b)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
