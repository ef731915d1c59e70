#!/usr/bin/env python3
"""The UART protocol between a board (or the simulator) and the host, read in one place
(docs/protocol.md says what each record means; firmware/viewer/main.cpp speaks it).

From the device, a line that starts with '@' is a record: its name, then its words. Most
records are `key value` pairs after their name (`@frame triangles 12 culled 3 ...`); a few have
fixed positions (`@ram NAME START BYTES`) or end in free text (`@measure TEXT`).

  for r in records(uart): ...            every record of a log, in order
  first(uart, 'tessellation')            the first record of a name, or None
  r.fields()                             its key/value pairs, values as ints where they are
  with_regions(uart, regions)            each record with the instruction-count region it opened
  read_session(path, board)              a scripted session's entries (tests/sessions/*.session)

From the host: keys as themselves; ENQ after each scripted entry (the device answers '@idle'
again once it has handled everything before it); ACK after a screenshot; '!shot NAME\\n' and
'!budget US\\n' as commands.
"""
import os

ENQ = b'\x05'  # after each scripted entry
ACK = b'\x06'  # a screenshot was taken
SHOT_COMMAND = '!shot {}\\n'  # as typed in a session's keys (escapes: run.py decodes them)

# Every record the device may print, with how its words are laid out: 'pairs' (key value ...
# after the name), or the names of its positional words. docs/protocol.md explains each.
RECORDS = {
    'board': ['name', 'size', 'scanout_key', 'scanout'],
    'ram': ['name', 'start', 'bytes'],
    'stack': ['used_key', 'used', 'of', 'size', 'bytes'],
    'model': 'pairs',
    'pass': ['pass', 'tolerance_key', 'tolerance_um'],
    'lod': 'pairs',
    'progress': ['done_total', 'triangles_key', 'triangles'],
    'face': ['face', 'failed:', 'why...'],
    'tessellation': 'pairs',
    'retessellation': 'pairs',
    'frame': 'pairs',
    'view': 'pairs',
    'pick': 'pairs',  # 'face N instance N shell N surface_type N at X Y', or 'none at X Y'
    'measure': ['text...'],
    'budget': ['kind', 'used_key', 'used_us', 'budget_key', 'budget_us'],
    'memory': 'pairs',
    'begin': ['region'],
    'end': ['region'],
    'shot': ['name'],
    'dump': ['name', 'file'],
    'idle': [],
    'expect': ['region', 'instructions'],
    'cdt': ['region', 'pairs...'],
    'peer': ['view', 'mode', 'pairs...'],
}


def _value(text):
    try:
        return int(text)
    except ValueError:
        return text


class Record:
    """One '@' line: name (without '@'), words (after the name), line (the whole line)."""

    def __init__(self, name, words, line):
        self.name, self.words, self.line = name, words, line

    def fields(self, start=0):
        """The key/value pairs from word `start` on (values as ints where they are)."""
        w = self.words[start:]
        return {k: _value(v) for k, v in zip(w[0::2], w[1::2])}

    def text(self):
        """Everything after the name (a record that ends in free text, like @measure)."""
        return self.line.split(' ', 1)[1].strip() if ' ' in self.line else ''

    def __repr__(self):
        return f'Record({self.line!r})'


def parse(line):
    """A device line as a Record, or None when it is not one."""
    line = line.rstrip('\r\n')
    words = line.split()
    if not words or not words[0].startswith('@') or len(words[0]) < 2:
        return None
    return Record(words[0][1:], words[1:], line)


def records(text, name=None):
    """Every record of a log (of one name, if given), in order."""
    for line in text.splitlines():
        r = parse(line)
        if r and (name is None or r.name == name):
            yield r


def first(text, name):
    return next(records(text, name), None)


def tessellation(text, name='tessellation'):
    """The first pass's totals (@tessellation: faces, failed, triangles, vertices, mesh_bytes,
    arena_peak, tolerance_um) as a dict, or None."""
    r = first(text, name)
    return r.fields() if r else None


def with_regions(text, regions):
    """Each record of a log, with the region it opened: the runner (tools/qemu/run.py --icount)
    names the plugin's numbered regions from the '@begin NAME' records, in order, into
    report.json's 'regions'; for a @begin record this is its dict ('instructions' None when the
    plugin has no such region: a run cut short), for others None."""
    i = 0
    for r in records(text):
        region = None
        if r.name == 'begin' and len(r.words) == 1:
            if i < len(regions) and regions[i]['name'] == r.words[0]:
                region = regions[i]
            i += 1
        yield r, region


def pointer_to(x, y):
    """Moves that put the pointer at screen pixel (x, y): to the top left corner first (three
    moves of -250: any screen the runner drives), then moves of at most 250 (QEMU's PS/2 mouse
    holds a few packets of at most 255 each)."""
    entries = ['move -250 -250'] * 3
    while x or y:
        dx, dy = min(x, 250), min(y, 250)
        entries.append(f'move {dx} {dy}')
        x, y = x - dx, y - dy
    return entries


QEMU_ENTRIES = ('keys', 'mouse', 'move', 'press', 'release')
SIM_ENTRIES = ('wheel', 'drag', 'pinch', 'tap', 'click')  # the simulator's own (tools/sim/session.h)


def read_session(path, board=None):
    """A scripted session (tests/sessions/*.session): its entries, one per line:

      keys TEXT            typed (C-style escapes: '!shot NAME\\n' asks for a screenshot)
      mouse DX DY [BUTTON] a drag with a button held (left, right, middle)
      move DX DY           the pointer alone (a drag when a button was pressed before)
      press [BUTTON]       a mouse button down (left, right, middle), held until 'release'
      release [BUTTON]     and up again
      point X Y            the pointer to screen pixel (X, Y) (moves from the corner)
      include NAME         tests/sessions/NAME.session's entries here
      screen WxH           the screen the pointer moves were written for
      [CAPABILITY] ENTRY   the entry only on a board that has it (board.json "capabilities")

    Comments (#) and blank lines are left out. With a board (its name), a session written for
    another screen is refused (ValueError: its pointer moves would land elsewhere)."""
    import board as boards  # tools/board.py, beside this module
    desc = boards.load(board) if board else None
    entries, screen = [], None
    for n, raw in enumerate(open(path, encoding='utf-8'), 1):
        line = raw.rstrip('\n').strip()
        if not line or line.startswith('#'):
            continue
        if line.startswith('['):
            cap, _, line = line[1:].partition(']')
            line = line.strip()
            if desc is None or not desc.get('capabilities', {}).get(cap):
                continue
        kind, _, rest = line.partition(' ')
        if kind == 'screen':
            screen = rest.strip()
        elif kind == 'include':
            entries += read_session(session_path(rest.strip()), board)
        elif kind == 'point':
            x, y = (int(v) for v in rest.split())
            entries += pointer_to(x, y)
        elif kind in QEMU_ENTRIES + SIM_ENTRIES:
            entries.append(line)
        else:
            raise ValueError(f'{path}:{n}: not a session entry: {line!r}')
    if screen and desc and screen != desc['size']:
        raise ValueError(f'{path}: written for a {screen} screen, not {board}\'s {desc["size"]}')
    return entries


SESSIONS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'tests', 'sessions')


def session_path(name):
    """tests/sessions/NAME.session."""
    return os.path.join(SESSIONS, name + '.session')
