#!/usr/bin/env python3
"""The PMI of the shared AP242 models in their packs (issue 53): facet-pack's annotations are
the records Open CASCADE reads (tests/geom/product_reference.cpp, written apart from facet-pack's
reader): as many, the same semantic values, the same datum names; several known texts; and
each annotation's faces are what it says: a diameter's faces are cylinders of its diameter,
a flatness's faces are planes (facet-measure, the device's own exact geometry).

  pmi_test.py --packer facet-pack --reference facet-pmi-reference --measure facet-measure
              --models DIR --work DIR
"""
import argparse
import json
import os
import subprocess
import sys

KNOWN = {
    'nist_ctc_02_ap242.stp': ['\u230052 \u00B10.15', '\u230012 \u00B10.05', '\u23E5 0.05', '\u2316 \u23001.5 \u24C2 A B C',
                              '\u27C2 \u23000.1 \u24C1 G', '\u2313 2.5 A B C', 'K1', 'A2'],
    'nist_ctc_01_ap242.stp': ['60\u00B0 \u00B10.5', '\u230035 +0.2/-0', '\u230034.8-35.2', '\u230025 \u00B10.15', 'A'],
}
DIMENSION_DIAMETER, TOLERANCE_FLATNESS = 2, 7
OCCT_DIAMETER = 15  # XCAFDimTolObjects_DimensionType_Size_Diameter


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, encoding='utf-8')
    if r.returncode != 0:
        sys.exit(f'FAIL: {" ".join(cmd)}: exit {r.returncode}\n{r.stderr}')
    return r.stdout


def main():
    ap = argparse.ArgumentParser()
    for a in ('--packer', '--reference', '--measure', '--models', '--work'):
        ap.add_argument(a, required=True)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    failures = []
    for model, texts in KNOWN.items():
        step = os.path.join(args.models, model)
        pack = os.path.join(args.work, model + '.fpk')
        summary = run([args.packer, step, '-o', pack, '--quiet'])
        ref = json.loads(run([args.reference, step]))
        notes = [json.loads(line) for line in run([args.packer, '--annotations', pack]).splitlines()]
        said = f'{ref["dimension_labels"]} dimensions, {ref["tolerances"]} geometric tolerances, {ref["datums"]} datums'
        if said not in summary:
            failures.append(f'{model}: facet-pack does not say "{said}":\n{summary}')
        # As many records as Open CASCADE reads, the same values.
        total = ref['dimension_labels'] + ref['tolerances'] + ref['datums']
        if len(notes) != total:
            failures.append(f'{model}: {len(notes)} annotations, Open CASCADE reads {total}')
        semantic = [n for n in notes if n['semantic']]
        tolerances = sorted(round(n['value'], 6) for n in semantic if n['kind'] == 'tolerance')
        if tolerances != sorted(round(v, 6) for _, v in ref['tolerance_values']):
            failures.append(f'{model}: tolerance values {tolerances} are not Open CASCADE\'s {ref["tolerance_values"]}')
        dimensions = sorted(round(n['value'], 6) for n in semantic if n['kind'] == 'dimension')
        if dimensions != sorted(round(v, 6) for _, v in ref['semantic_dimensions']):
            failures.append(f'{model}: dimension values {dimensions} are not Open CASCADE\'s {ref["semantic_dimensions"]}')
        diameters = sum(1 for t, _ in ref['semantic_dimensions'] if t == OCCT_DIAMETER)
        if sum(1 for n in semantic if n['kind'] == 'dimension' and n['type'] == DIMENSION_DIAMETER) != diameters:
            failures.append(f'{model}: the diameters are not Open CASCADE\'s {diameters}')
        datums = sorted(n['text'] for n in semantic if n['kind'] == 'datum')
        if len(datums) != ref['datums']:
            failures.append(f'{model}: {len(datums)} datums, Open CASCADE reads {ref["datums"]}')
        if not all(any(d.startswith(name) for d in datums) for name in ref['datum_names']):
            failures.append(f'{model}: datum names {sorted(set(ref["datum_names"]))} not all among {sorted(set(datums))}')
        # A repeat (listed once) is one whose kind, text and faces an earlier one has; no other.
        for k, n in enumerate(notes):
            earlier = any(m['kind'] == n['kind'] and m['text'] == n['text'] and m['faces'] == n['faces'] for m in notes[:k])
            if n['repeat'] != earlier:
                failures.append(f'{model}: annotation {k} {n["text"]!r}: repeat {n["repeat"]}, an earlier one like it: {earlier}')
        for t in texts:
            if not any(n['text'] == t for n in notes):
                failures.append(f'{model}: no annotation reads {t!r}')
        # The faces are what the annotation says of them.
        checked = 0
        for n in semantic:
            if not n['faces'] or not ((n['kind'] == 'dimension' and n['type'] == DIMENSION_DIAMETER) or
                                      (n['kind'] == 'tolerance' and n['type'] == TOLERANCE_FLATNESS)):
                continue
            for f in n['faces']:
                g = json.loads(run([args.measure, pack, '--face', str(f), '--json']))['faces'][0]
                checked += 1
                if n['kind'] == 'tolerance' and g['type'] != 'plane':
                    failures.append(f'{model}: {n["text"]!r} on face {f}, a {g["type"]}, not a plane')
                if n['kind'] == 'dimension':
                    if g['type'] not in ('cylinder', 'cone', 'sphere') or abs(2 * g['radius'] - n['value']) > 1e-3 * max(1, n['value']):
                        failures.append(f'{model}: {n["text"]!r} on face {f}, a {g["type"]} of radius {g["radius"]}')
        if checked < 3:
            failures.append(f'{model}: only {checked} faces checked against their annotations')
        listed = sum(1 for n in semantic if not n['repeat'])
        print(f'{model}: {len(notes)} annotations ({len(semantic)} semantic, {listed} listed) as Open CASCADE reads them; '
              f'{checked} faces of diameters and flatness checked')
    for f in failures:
        print('FAIL:', f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
