#!/usr/bin/env python3
"""The UART protocol from one source: the module's record writer (facet/records.h) and the
host's reader (tools/protocol.py) agree, and every record the tree prints is in the reader's
table.

  * facet-records-check prints every record the writer makes, with the largest values each
    field holds; each must read back through RECORDS' layout with those values;
  * every '@name' a C++ source of the tree prints (firmware, boards, hal, benches, the writer)
    is a record of RECORDS, and the firmware and the simulator print the viewer's events
    through the writer only (no event record of their own).

  protocol_test.py --check BUILD/facet-records-check ROOT
"""
import argparse
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import protocol  # noqa: E402

MAX = 0xFFFFFFFF
REASON = 'section Faces record 4294967294, loop 4294967294: the loop\'s points are not all in the surface\'s domain'
EXPECTED = [
    ('model', {'faces': MAX, 'edges': MAX, 'shells': MAX, 'instances': MAX, 'bytes': MAX, 'file_bytes': MAX,
               'boxed_parts': MAX, 'boxed_faces': MAX}),
    ('pass', {'pass': MAX, 'tolerance_um': 4000000}),
    ('lod', {'tolerance_um': 4000000, 'samples': MAX}),
    ('progress', {'finished': MAX - 1, 'total': MAX, 'triangles': MAX}),
    ('face', {'face': MAX, 'why': f'{REASON} (OutOfRange); it stays wireframe'}),
    ('pass_failed', {'tolerance_um': 4000000, 'status': 'OutOfRange', 'why': REASON}),
    ('tessellation', {'faces': MAX, 'failed': MAX, 'triangles': MAX, 'vertices': MAX, 'mesh_bytes': MAX, 'arena_peak': MAX,
                      'tolerance_um': 4000000}),
    ('retessellation', {'faces': MAX, 'failed': MAX, 'triangles': MAX, 'vertices': MAX, 'mesh_bytes': MAX,
                        'arena_peak': MAX, 'tolerance_um': 4000000}),
    ('frame', {'triangles': MAX, 'culled': MAX, 'pixels': MAX, 'pieces': MAX, 'cost_us': MAX}),
    ('budget', {'kind': 'step', 'used_us': MAX, 'budget_us': MAX}),
    ('pick', {'hit': 1, 'face': MAX, 'instance': MAX, 'shell': MAX, 'surface_type': 255, 'x': -32768, 'y': -32768}),
    ('pick', {'hit': 0, 'x': -32768, 'y': -32768}),
    ('view', {'yaw': -180, 'pitch': 90, 'zoom_pct': 2000}),
    ('model_failed', {'model': MAX, 'status': 'OutOfRange', 'why': REASON}),
    ('memory', {'pack_bytes': MAX, 'pack_file_bytes': MAX, 'storage_peak_bytes': MAX}),
    ('stats', {'faces': MAX, 'done': MAX, 'failed': MAX, 'deferred': MAX, 'triangles': MAX, 'refused': MAX}),
    ('load_failed', {'status': 'OutOfRange', 'why': REASON}),
]
# Where C++ sources print records (the tests print what they check, not records).
SOURCES = ('firmware', 'boards', 'hal', 'bench', 'module', 'tools/sim')
PRINTED = re.compile(r'"@([a-z_]+)[ \\{"]')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--check', required=True)
    ap.add_argument('root')
    args = ap.parse_args()
    problems = []
    r = subprocess.run([args.check], capture_output=True, text=True)
    if r.returncode != 0:
        problems.append(f'facet-records-check: exit {r.returncode}: {r.stderr.strip()}')
    got = list(protocol.records(r.stdout))
    if len(got) != len(EXPECTED):
        problems.append(f'{len(got)} records written, {len(EXPECTED)} expected:\n{r.stdout}')
    for rec, (name, values) in zip(got, EXPECTED):
        try:
            v = rec.values()
        except ValueError as e:
            problems.append(str(e))
            continue
        if rec.name != name or v != values:
            problems.append(f'{rec.line!r} reads as @{rec.name} {v}, not @{name} {values}')
    # Every record printed anywhere in the tree is in the table.
    for folder in SOURCES:
        for path in glob.glob(os.path.join(args.root, folder, '**', '*.[ch]*'), recursive=True):
            text = open(path, errors='replace').read()
            for m in PRINTED.finditer(text):
                if m.group(1) not in protocol.RECORDS:
                    problems.append(f'{os.path.relpath(path, args.root)}: prints @{m.group(1)}, which tools/protocol.py '
                                    f'RECORDS does not list')
    # The viewer's event records are written in one place.
    events = {name for name, _ in EXPECTED}
    for path in ('firmware/viewer/main.cpp', 'tools/sim/session.cpp', 'tools/sim/main.cpp'):
        text = open(os.path.join(args.root, path)).read()
        own = sorted({m.group(1) for m in PRINTED.finditer(text)} & events)
        if own:
            problems.append(f'{path} writes event records of its own ({", ".join(own)}): facet/records.h writes them')
    for p in problems:
        print(f'FAIL {p}')
    if not problems:
        print(f'protocol: {len(got)} records written by facet/records.h read back through tools/protocol.py; every '
              f'record printed in {", ".join(SOURCES)} is in its table')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
