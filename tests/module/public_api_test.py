#!/usr/bin/env python3
"""The module's boundary, checked on the sources:

  * the three hosts -- the QEMU viewer firmware (firmware/viewer), the simulator (tools/sim)
    and the example (examples/) -- include the module's public headers (facet/...), hal/ and
    their own platform's headers only: nothing of module/src, geom/, cdt/ or render/;
  * the public C++ header stays under 250 lines, every file of the module under 500.

  public_api_test.py ROOT
"""
import os
import re
import sys

HOSTS = ['firmware/viewer', 'tools/sim', 'examples']
# What a host may include besides the module's public headers and hal/: its platform's own.
PLATFORM = {'facet_board_config.h', 'qemu/capture.h', 'report.h', 'port.h', 'session.h', 'SDL.h'}
INTERNAL = ('geom/', 'cdt/', 'render/')
C_STANDARD = {'stddef.h', 'stdint.h', 'stdio.h', 'stdlib.h', 'string.h'}


def main():
    root = sys.argv[1]
    internal_headers = set(os.listdir(os.path.join(root, 'module', 'src')))
    problems = []
    checked = 0
    for host in HOSTS:
        for dirpath, _, files in os.walk(os.path.join(root, host)):
            for f in files:
                if not f.endswith(('.c', '.cpp', '.h')):
                    continue
                path = os.path.join(dirpath, f)
                for n, line in enumerate(open(path, encoding='utf-8'), 1):
                    m = re.match(r'\s*#\s*include\s*[<"]([^>"]+)[>"]', line)
                    if not m:
                        continue
                    inc = m.group(1)
                    checked += 1
                    standard = '/' not in inc and ('.' not in inc or inc in C_STANDARD)
                    ok = inc.startswith(('facet/', 'hal/')) or inc in PLATFORM or standard
                    if inc.startswith(INTERNAL) or inc in internal_headers or not ok:
                        problems.append(f'{os.path.relpath(path, root)}:{n}: includes "{inc}"')
    header = os.path.join(root, 'module', 'include', 'facet', 'viewer.h')
    lines = sum(1 for _ in open(header))
    if lines >= 250:
        problems.append(f'facet/viewer.h has {lines} lines (under 250)')
    for dirpath, _, files in os.walk(os.path.join(root, 'module')):
        for f in files:
            n = sum(1 for _ in open(os.path.join(dirpath, f)))
            if n > 500:
                problems.append(f'{os.path.relpath(os.path.join(dirpath, f), root)}: {n} lines (at most 500)')
    for p in problems:
        print('FAIL', p)
    if not problems:
        print(f'{checked} includes of the three hosts: public API, hal/ and their platform only; '
              f'facet/viewer.h {lines} lines; every module file under 500 lines')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
