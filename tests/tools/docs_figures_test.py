#!/usr/bin/env python3
"""The storage plan's figures in the docs are the code's: each place a page states one (the
workspace's least and default bytes, the LZMA decoder's state) says what facet-doc-figures,
built from the plan itself, prints.

  docs_figures_test.py --figures BUILD/facet-doc-figures ROOT
"""
import argparse
import os
import re
import subprocess
import sys

# (page, a pattern whose group is the figure, the figure's name in facet-doc-figures' output)
PLACES = [
    ('docs/module.md', r'`FACET_WORKSPACE_BASE_BYTES` \(([0-9,]+)', 'workspace_base_bytes'),
    ('docs/module.md', r'`FACET_WORKSPACE_BYTES_DEFAULT` \(([0-9,]+)\)', 'workspace_default_bytes'),
    ('docs/module.md', r'LZMA: plus ([0-9,]+) bytes of decoder state', 'lzma_state_bytes'),
    ('docs/pack-format.md', r'\n?([0-9,]+) bytes at the very end\)', 'lzma_state_bytes'),
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--figures', required=True)
    ap.add_argument('root')
    args = ap.parse_args()
    out = subprocess.run([args.figures], capture_output=True, text=True, check=True).stdout
    figures = {k: int(v) for k, v in (line.split() for line in out.splitlines())}
    problems = []
    for page, pattern, name in PLACES:
        text = open(os.path.join(args.root, page)).read()
        found = re.findall(pattern, text)
        want = f'{figures[name]:,}'
        if not found:
            problems.append(f'{page}: no {pattern!r} (the page no longer states {name}: drop it from this test)')
        for got in found:
            if got != want:
                problems.append(f'{page}: says {got} for {name}; the plan gives {want}')
    for p in problems:
        print(f'FAIL {p}')
    if not problems:
        print(f'docs: {len(PLACES)} figures of the storage plan as the code gives them')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
