#!/usr/bin/env python3
"""A board's one description (boards/<board>/board.json), for the scripts and tests.

  board.py BOARD KEY[.KEY...]   prints one value (e.g. 'pack.address', 'display.width')
  board.py --list               the boards

From Python: board.load('qemu-versatilepb') -> dict, with 'pack_address' and 'pack_bytes' as
integers and 'size' as 'WxH'; board.can('qemu-versatilepb', 'mouse') -> what it can do (its
"capabilities": card, card_swap (a card pulled and put back), screenshots, mouse, touch, bench,
flash_runner); board.qemu_boards() -> the boards QEMU runs (those with a "qemu" machine).
"""
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BOARDS = os.path.join(ROOT, 'boards')


def bytes_of(text):
    """'4M', '256K', '0x1000', '4096' -> int."""
    t = str(text).strip()
    scale = {'K': 1 << 10, 'M': 1 << 20}.get(t[-1:].upper(), 1)
    if scale > 1:
        t = t[:-1]
    return int(t, 0) * scale


def names():
    return sorted(d for d in os.listdir(BOARDS) if os.path.exists(os.path.join(BOARDS, d, 'board.json')))


def load(name):
    path = os.path.join(BOARDS, name, 'board.json')
    if not os.path.exists(path):
        raise SystemExit(f'board.py: no board {name!r} (boards: {", ".join(names())})')
    with open(path) as f:
        b = json.load(f)
    b['pack_address'] = bytes_of(b['pack']['address'])
    b['pack_bytes'] = bytes_of(b['pack']['bytes'])
    b['size'] = f'{b["display"]["width"]}x{b["display"]["height"]}'
    return b


def can(name, capability):
    """A board's capability (board.json "capabilities"): True/False, or a flash runner's name."""
    caps = load(name).get('capabilities', {})
    if capability not in caps:
        raise SystemExit(f'board.py: {name} does not say whether it has {capability!r} (board.json "capabilities")')
    return caps[capability]


def qemu_boards():
    return [n for n in names() if 'qemu' in load(n)]


def main():
    if len(sys.argv) == 2 and sys.argv[1] == '--list':
        print('\n'.join(names()))
        return 0
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    v = load(sys.argv[1])
    for key in sys.argv[2].split('.'):
        if not isinstance(v, dict) or key not in v:
            print(f'board.py: {sys.argv[1]} has no {sys.argv[2]}', file=sys.stderr)
            return 2
        v = v[key]
    print(' '.join(v) if isinstance(v, list) else v)
    return 0


if __name__ == '__main__':
    sys.exit(main())
