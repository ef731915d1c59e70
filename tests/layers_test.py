#!/usr/bin/env python3
"""The tree's layers, checked on the sources: every #include of every C/C++ file of the project
against the table of DEVELOPERS.md ("Layers": folder, what it holds, what it may include), which
this test reads. Also: no source file over 600 lines (the module's over 500); the public C++ header under 250
lines.

  layers_test.py ROOT

A quoted include resolves next to the including file, or to the one file of the tree that ends
with it; an angle include is the standard library's (allowed everywhere), a host library's
(`(libraries)`) or, not found, the board's generated configuration (`(board config)`) or a peer's
(`(peer)`). Exit 1 with each offending include; 0 with a summary.
"""
import os
import re
import subprocess
import sys

SOURCE = ('.c', '.cpp', '.h', '.ipp', '.inc')
STD_C = {'assert.h', 'ctype.h', 'errno.h', 'float.h', 'limits.h', 'math.h', 'stdarg.h', 'stdbool.h', 'stddef.h',
         'stdint.h', 'stdio.h', 'stdlib.h', 'string.h', 'time.h', 'unistd.h', 'fcntl.h', 'signal.h', 'inttypes.h'}
BOARD_CONFIG = 'facet_board_config.h'
PEERS = {'tgx.h'}
DOC_MAX_BYTES = 16_500
MAX_LINES = 600
MODULE_MAX_LINES = 500 # the module's files, smaller still (the module issue's rule)


def table(root):
    """{folder prefix: [allowed]} from DEVELOPERS.md's Layers table."""
    text = open(os.path.join(root, 'DEVELOPERS.md'), encoding='utf-8').read()
    rules = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        if len(cells) != 3 or not cells[0].startswith('`'):
            continue
        folder = cells[0].strip('`')
        allowed = re.findall(r'`([^`]+)`', cells[2])
        rules[folder] = ['*'] if cells[2] == 'anything' else allowed
    if not rules:
        raise SystemExit('layers_test.py: no Layers table in DEVELOPERS.md')
    return rules


def rule_for(rules, path):
    best = None
    for folder in rules:
        if path.startswith(folder) and (best is None or len(folder) > len(best)):
            best = folder
    return best


def main():
    root = os.path.abspath(sys.argv[1])
    rules = table(root)
    files_all = [f for f in subprocess.run(['git', 'ls-files', '--cached', '--others', '--exclude-standard'], cwd=root,
                                            capture_output=True, text=True, check=True).stdout.split('\n')
                 if f and not f.startswith(('build/', 'out/')) and os.path.exists(os.path.join(root, f))]
    files = [f for f in files_all if f.endswith(SOURCE)]
    by_suffix = {}
    for f in files:
        parts = f.split('/')
        for i in range(len(parts)):
            by_suffix.setdefault('/'.join(parts[i:]), []).append(f)
    problems, checked, governed = [], 0, 0
    for f in files:
        path = os.path.join(root, f)
        lines = open(path, encoding='utf-8', errors='replace').read().splitlines()
        limit = MODULE_MAX_LINES if f.startswith('module/') else MAX_LINES
        if len(lines) > limit:
            problems.append(f'{f}: {len(lines)} lines (at most {limit}: split it by idea)')
        folder = rule_for(rules, f)
        if folder is None:
            continue
        governed += 1
        allowed = rules[folder]
        for n, line in enumerate(lines, 1):
            m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
            if not m:
                continue
            checked += 1
            angle, inc = m.group(1) == '<', m.group(2)
            if '*' in allowed:
                continue
            local = os.path.normpath(os.path.join(os.path.dirname(f), inc))
            target = local if local in files else None
            if target is None:
                found = by_suffix.get(inc, [])
                if len(found) > 1:  # which one the compiler takes depends on the include path: name one
                    problems.append(f'{f}:{n}: includes "{inc}", which names {len(found)} files of the tree '
                                    f'({", ".join(found)}): the layers cannot tell which')
                    continue
                target = found[0] if found else None
            if target is None:
                if inc == BOARD_CONFIG:
                    kind = '(board config)'
                elif inc in PEERS:
                    kind = '(peer)'
                elif angle and ('/' not in inc and ('.' not in inc or inc in STD_C)):
                    continue  # the C or C++ standard library
                else:
                    kind = '(libraries)'
                if kind not in allowed:
                    problems.append(f'{f}:{n}: includes <{inc}>: {kind} is not for {folder}')
                continue
            if os.path.dirname(target) == os.path.dirname(f):
                continue  # the file's own folder
            if not any(target.startswith(a) for a in allowed if not a.startswith('(')):
                problems.append(f'{f}:{n}: includes "{inc}" ({target}): {folder} may include {" ".join(allowed)}')
    # The docs: a page each idea, each under about 15 KB (docs/bench/ holds the benches' output).
    for page in sorted(f for f in files_all if f.startswith('docs/') and f.endswith('.md') and not f.startswith('docs/bench/')):
        size = os.path.getsize(os.path.join(root, page))
        if size > DOC_MAX_BYTES:
            problems.append(f'{page}: {size:,} bytes (a page under about 15 KB, at most {DOC_MAX_BYTES:,}: split it by idea, '
                            f'or keep what it says now and leave its history to git)')
    viewer_h = os.path.join(root, 'module', 'include', 'facet', 'viewer.h')
    n = sum(1 for _ in open(viewer_h))
    if n >= 250:
        problems.append(f'module/include/facet/viewer.h: {n} lines (the public header under 250)')
    for p in problems:
        print('FAIL', p)
    if not problems:
        print(f'{checked} includes in {governed} files follow DEVELOPERS.md\'s layers ({len(rules)} folders); '
              f'every source file under {MAX_LINES} lines')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
