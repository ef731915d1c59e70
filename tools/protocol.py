#!/usr/bin/env python3
"""The UART protocol between a board (or the simulator) and the host, read in one place
(docs/protocol.md says what each record means; firmware/viewer/main.cpp speaks it).

From the device, a line that starts with '@' is a record: its name, then its words, laid out as
RECORDS says. Most are `key value` pairs after their name (`@frame triangles 12 culled 3 ...`);
a few have fixed positions (`@ram NAME START BYTES`) or end in free text (`@measure TEXT`). Every
reader takes them through this module: no reader parses a line itself.

  for r in records(uart): ...            every record of a log, in order
  first(uart, 'tessellation')            the first record of a name, or None
  first_fields(uart, 'model')            its fields, or {} when the log has none
  r.values()                             its words by RECORDS' layout (ints where they are)
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

# Every record a device may print and how its words are laid out, in order: a name takes one
# word (an int where it is one); '=word' is that literal word; 'a/b' one word 'A/B', two values;
# 'pairs...' the rest as key value pairs; 'text...' the rest of the line. docs/protocol.md says
# what each means; module/src/records.cpp writes the viewer's.
RECORDS = {
    # the boards (hal/src/report.cpp, boards/)
    'board': ('name', 'size', 'pairs...'),
    'ram': ('name', 'start', 'bytes'),
    'stack': ('=used', 'used', '=of', 'size', '=bytes'),
    'exit': ('code',),
    'halt': ('code', 'text...'),
    'mpu': ('text...',),
    'touch': ('text...',),
    'shot': ('name',),
    'dump': ('name', 'file'),
    'begin': ('region',),
    'end': ('region',),
    # the viewer (facet/records.h), and the firmware around it (firmware/viewer/main.cpp)
    'library': ('index', '=bytes', 'bytes', 'name...'),
    'card': ('index', '=bytes', 'bytes', '=faces', 'faces', 'name...'),
    'card_changed': ('state',),
    'card_slot': ('controller', 'text...'),
    'model': ('pairs...',),
    'load_failed': ('status', 'why...'),
    'model_failed': ('model', 'status', 'why...'),
    'pass_failed': ('=tolerance_um', 'tolerance_um', 'status', 'why...'),
    'pass': ('pass', 'pairs...'),
    'lod': ('pairs...',),
    'progress': ('finished/total', 'pairs...'),
    'face': ('face', '=failed:', 'why...'),
    'tessellation': ('pairs...',),
    'retessellation': ('pairs...',),
    'frame': ('pairs...',),
    'view': ('pairs...',),
    'pick': ('pairs...',),
    'measure': ('text...',),
    'budget': ('kind', 'pairs...'),
    'memory': ('pairs...',),
    'stats': ('pairs...',),
    'idle': (),
    'step_budget_us': ('us',),
    # the self-tests and benches (firmware/selftest, bench/)
    'expect': ('region', 'instructions'),
    'needs': ('text...',),
    'cdt': ('region', '=points', 'points', '=segments', 'segments', '=vertices', 'vertices', '=triangles', 'triangles',
            '=inner', 'inner', '=flips', 'flips', '=walk', 'walk', '=checker', 'checker...'),
    'vertices': ('region', 'points'),
    'bench_model': ('pairs...',),
    'bench_frame': ('pairs...',),
    'bench_view': ('view', 'size', 'pairs...'),
    'peer': ('view', 'size', 'pairs...'),
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

    def values(self):
        """The record's words by RECORDS' layout, as a dict (ints where they are). ValueError for a
        record that is not in the table or not laid out as it says."""
        layout = RECORDS.get(self.name)
        if layout is None:
            raise ValueError(f'not a record of the protocol: {self.line!r}')
        out, words = {}, self.words
        for i, part in enumerate(layout):
            if part == 'pairs...':
                rest = words[i:]
                if len(rest) % 2:
                    raise ValueError(f'@{self.name}: its key value pairs are uneven: {self.line!r}')
                out.update({k: _value(v) for k, v in zip(rest[0::2], rest[1::2])})
                return out
            if part.endswith('...'):  # the rest of the line as it is (its spacing kept)
                rest = self.line.split(None, i + 1)
                out[part[:-3]] = rest[i + 1].strip() if len(rest) > i + 1 else ''
                return out
            if i >= len(words):
                raise ValueError(f'@{self.name}: {part} missing: {self.line!r}')
            if part.startswith('='):
                if words[i] != part[1:]:
                    raise ValueError(f'@{self.name}: {part[1:]!r} expected, not {words[i]!r}: {self.line!r}')
            elif '/' in part:
                names, got = part.split('/'), words[i].split('/')
                if len(got) != 2:
                    raise ValueError(f'@{self.name}: {part} expected, not {words[i]!r}: {self.line!r}')
                out.update({k: _value(v) for k, v in zip(names, got)})
            else:
                out[part] = _value(words[i])
        if len(words) > len(layout):
            raise ValueError(f'@{self.name}: {len(words) - len(layout)} words too many: {self.line!r}')
        return out

    def fields(self):
        """values(), or {} for a record not laid out as RECORDS says (a reader's lenient form)."""
        try:
            return self.values()
        except ValueError:
            return {}

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


def first_fields(text, name):
    """The first record of a name's fields (Record.fields()), or {} when the log has none."""
    r = first(text, name)
    return r.fields() if r else {}


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


QEMU_ENTRIES = ('keys', 'mouse', 'move', 'press', 'release', 'card')
SIM_ENTRIES = ('wheel', 'drag', 'pinch', 'tap', 'click')  # the simulator's own (tools/sim/session.h)


def read_session(path, board=None):
    """A scripted session (tests/sessions/*.session): its entries, one per line:

      keys TEXT            typed (C-style escapes: '!shot NAME\\n' asks for a screenshot)
      mouse DX DY [BUTTON] a drag with a button held (left, right, middle)
      move DX DY           the pointer alone (a drag when a button was pressed before)
      press [BUTTON]       a mouse button down (left, right, middle), held until 'release'
      release [BUTTON]     and up again
      point X Y            the pointer to screen pixel (X, Y) (moves from the corner)
      card out|in          the memory card pulled from its slot, or put back (run.py --card)
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
