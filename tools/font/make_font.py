#!/usr/bin/env python3
"""facet's bitmap font, 5 x 8 pixels a glyph (rows 0-6 the letter, row 7 the descender), written
as render/src/font_5x8.inc: one byte per row, bit 4 the leftmost pixel, and the ranges of code
points it covers.

- Printable ASCII (32-126): drawn here as pixel art (the source of those glyphs).
- Latin-1 Supplement and Latin Extended-A (U+00A0-U+017F), Greek (U+0370-U+03FF) and Cyrillic
  (U+0400-U+04FF): from the X11 misc-fixed 5x8 font Debian ships (xfonts-base,
  /usr/share/fonts/X11/misc/5x8.pcf.gz, public domain), read from its PCF file below. A code
  point of these ranges the font lacks takes the replacement mark.
- The symbols of dimensions and geometric tolerances (the diameter sign, flatness, position,
  perpendicularity, the circled M and L ...): drawn here, for the texts of a model's PMI.
- The replacement mark (U+FFFD), drawn here: what the screen shows for a character the font
  lacks, and for bytes that are no UTF-8.

`font.generated_file_is_current` checks the .inc matches what this writes.

  make_font.py [OUT.inc]     (default: print to stdout)
"""
import gzip
import struct
import sys

# Each glyph: 8 rows of 5 pixels, '#' set, '.' clear, rows separated by spaces.
GLYPHS = {
    ' ': '..... ..... ..... ..... ..... ..... ..... .....',
    '!': '..#.. ..#.. ..#.. ..#.. ..#.. ..... ..#.. .....',
    '"': '.#.#. .#.#. ..... ..... ..... ..... ..... .....',
    '#': '.#.#. .#.#. ##### .#.#. ##### .#.#. .#.#. .....',
    '$': '..#.. .#### #.#.. .###. ..#.# ####. ..#.. .....',
    '%': '##... ##..# ...#. ..#.. .#... #..## ...## .....',
    '&': '.##.. #..#. #.#.. .#... #.#.# #..#. .##.# .....',
    "'": '..#.. ..#.. ..... ..... ..... ..... ..... .....',
    '(': '...#. ..#.. .#... .#... .#... ..#.. ...#. .....',
    ')': '.#... ..#.. ...#. ...#. ...#. ..#.. .#... .....',
    '*': '..... ..#.. #.#.# .###. #.#.# ..#.. ..... .....',
    '+': '..... ..#.. ..#.. ##### ..#.. ..#.. ..... .....',
    ',': '..... ..... ..... ..... ..... .##.. ..#.. .#...',
    '-': '..... ..... ..... ##### ..... ..... ..... .....',
    '.': '..... ..... ..... ..... ..... .##.. .##.. .....',
    '/': '....# ...#. ...#. ..#.. .#... .#... #.... .....',
    '0': '.###. #...# #..## #.#.# ##..# #...# .###. .....',
    '1': '..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###. .....',
    '2': '.###. #...# ....# ...#. ..#.. .#... ##### .....',
    '3': '##### ...#. ..#.. ...#. ....# #...# .###. .....',
    '4': '...#. ..##. .#.#. #..#. ##### ...#. ...#. .....',
    '5': '##### #.... ####. ....# ....# #...# .###. .....',
    '6': '..##. .#... #.... ####. #...# #...# .###. .....',
    '7': '##### ....# ...#. ..#.. .#... .#... .#... .....',
    '8': '.###. #...# #...# .###. #...# #...# .###. .....',
    '9': '.###. #...# #...# .#### ....# ...#. .##.. .....',
    ':': '..... .##.. .##.. ..... .##.. .##.. ..... .....',
    ';': '..... .##.. .##.. ..... .##.. ..#.. .#... .....',
    '<': '...#. ..#.. .#... #.... .#... ..#.. ...#. .....',
    '=': '..... ..... ##### ..... ##### ..... ..... .....',
    '>': '.#... ..#.. ...#. ....# ...#. ..#.. .#... .....',
    '?': '.###. #...# ....# ...#. ..#.. ..... ..#.. .....',
    '@': '.###. #...# ....# .##.# #.#.# #.#.# .###. .....',
    'A': '.###. #...# #...# ##### #...# #...# #...# .....',
    'B': '####. #...# #...# ####. #...# #...# ####. .....',
    'C': '.###. #...# #.... #.... #.... #...# .###. .....',
    'D': '###.. #..#. #...# #...# #...# #..#. ###.. .....',
    'E': '##### #.... #.... ####. #.... #.... ##### .....',
    'F': '##### #.... #.... ####. #.... #.... #.... .....',
    'G': '.###. #...# #.... #.### #...# #...# .#### .....',
    'H': '#...# #...# #...# ##### #...# #...# #...# .....',
    'I': '.###. ..#.. ..#.. ..#.. ..#.. ..#.. .###. .....',
    'J': '..### ...#. ...#. ...#. ...#. #..#. .##.. .....',
    'K': '#...# #..#. #.#.. ##... #.#.. #..#. #...# .....',
    'L': '#.... #.... #.... #.... #.... #.... ##### .....',
    'M': '#...# ##.## #.#.# #.#.# #...# #...# #...# .....',
    'N': '#...# #...# ##..# #.#.# #..## #...# #...# .....',
    'O': '.###. #...# #...# #...# #...# #...# .###. .....',
    'P': '####. #...# #...# ####. #.... #.... #.... .....',
    'Q': '.###. #...# #...# #...# #.#.# #..#. .##.# .....',
    'R': '####. #...# #...# ####. #.#.. #..#. #...# .....',
    'S': '.#### #.... #.... .###. ....# ....# ####. .....',
    'T': '##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#.. .....',
    'U': '#...# #...# #...# #...# #...# #...# .###. .....',
    'V': '#...# #...# #...# #...# #...# .#.#. ..#.. .....',
    'W': '#...# #...# #...# #.#.# #.#.# #.#.# .#.#. .....',
    'X': '#...# #...# .#.#. ..#.. .#.#. #...# #...# .....',
    'Y': '#...# #...# .#.#. ..#.. ..#.. ..#.. ..#.. .....',
    'Z': '##### ....# ...#. ..#.. .#... #.... ##### .....',
    '[': '.###. .#... .#... .#... .#... .#... .###. .....',
    '\\': '#.... .#... .#... ..#.. ...#. ...#. ....# .....',
    ']': '.###. ...#. ...#. ...#. ...#. ...#. .###. .....',
    '^': '..#.. .#.#. #...# ..... ..... ..... ..... .....',
    '_': '..... ..... ..... ..... ..... ..... ..... #####',
    '`': '.#... ..#.. ..... ..... ..... ..... ..... .....',
    'a': '..... ..... .###. ....# .#### #...# .#### .....',
    'b': '#.... #.... #.##. ##..# #...# #...# ####. .....',
    'c': '..... ..... .###. #.... #.... #...# .###. .....',
    'd': '....# ....# .##.# #..## #...# #...# .#### .....',
    'e': '..... ..... .###. #...# ##### #.... .###. .....',
    'f': '..##. .#..# .#... ###.. .#... .#... .#... .....',
    'g': '..... ..... .#### #...# #...# .#### ....# .###.',
    'h': '#.... #.... #.##. ##..# #...# #...# #...# .....',
    'i': '..#.. ..... .##.. ..#.. ..#.. ..#.. .###. .....',
    'j': '...#. ..... ..##. ...#. ...#. ...#. #..#. .##..',
    'k': '#.... #.... #..#. #.#.. ##... #.#.. #..#. .....',
    'l': '.##.. ..#.. ..#.. ..#.. ..#.. ..#.. .###. .....',
    'm': '..... ..... ##.#. #.#.# #.#.# #...# #...# .....',
    'n': '..... ..... #.##. ##..# #...# #...# #...# .....',
    'o': '..... ..... .###. #...# #...# #...# .###. .....',
    'p': '..... ..... ####. #...# #...# ####. #.... #....',
    'q': '..... ..... .##.# #..## #...# .#### ....# ....#',
    'r': '..... ..... #.##. ##..# #.... #.... #.... .....',
    's': '..... ..... .###. #.... .###. ....# ####. .....',
    't': '.#... .#... ###.. .#... .#... .#..# ..##. .....',
    'u': '..... ..... #...# #...# #...# #..## .##.# .....',
    'v': '..... ..... #...# #...# #...# .#.#. ..#.. .....',
    'w': '..... ..... #...# #...# #.#.# #.#.# .#.#. .....',
    'x': '..... ..... #...# .#.#. ..#.. .#.#. #...# .....',
    'y': '..... ..... #...# #...# #...# .#### ....# .###.',
    'z': '..... ..... ##### ...#. ..#.. .#... ##### .....',
    '{': '...#. ..#.. ..#.. .#... ..#.. ..#.. ...#. .....',
    '|': '..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ..#.. .....',
    '}': '.#... ..#.. ..#.. ...#. ..#.. ..#.. .#... .....',
    '~': '..... ..... .#... #.#.# ...#. ..... ..... .....',
}


def rows(art):
    r = art.split()
    assert len(r) == 8 and all(len(x) == 5 and set(x) <= set('.#') for x in r), art
    return [sum(1 << (4 - i) for i, ch in enumerate(x) if ch == '#') for x in r]


# The symbols of dimensions and geometric tolerances (ISO 1101, ASME Y14.5) that PMI texts use
# (tools/facet-pack/pmi.cpp), drawn here: each its code point's glyph.
SYMBOLS = {
    0x00B1: '..#.. ..#.. ##### ..#.. ..#.. ..... ##### .....',  # plus-minus (over Latin-1's own)
    0x2197: '..### ...## ..#.# .#... #.... ..... ..... .....',  # circular runout (an arrow)
    0x2220: '..... ....# ...#. ..#.. .#... ##### ..... .....',  # angularity
    0x2225: '..#.# ..#.# .#.#. .#.#. #.#.. #.#.. ..... .....',  # parallelism
    0x2300: '....# .###. #..## #.#.# ##..# .###. #.... .....',  # diameter
    0x2312: '..... .###. #...# #...# ..... ..... ..... .....',  # profile of a line (an arc)
    0x2313: '..... .###. #...# #...# ##### ..... ..... .....',  # profile of a surface (a segment)
    0x2316: '..#.. .###. #.#.# ##### #.#.# .###. ..#.. .....',  # position
    0x232D: '...## .##.# #...# #...# #...# #.##. ##... .....',  # cylindricity
    0x232F: '..... .###. ..... ##### ..... .###. ..... .....',  # symmetry
    0x2330: '.#.#. ##.## .#.#. .#.#. .#.#. ##### ..... .....',  # total runout (two arrows on a base)
    0x23E4: '..... ..... ..... ##### ..... ..... ..... .....',  # straightness
    0x23E5: '..... ..... .#### .#..# #..#. ####. ..... .....',  # flatness
    0x24C1: '.###. ##..# ##..# ##..# ###.# .###. ..... .....',  # least material (circled L)
    0x24C2: '.###. ##.## ##### ##.## ##.## .###. ..... .....',  # maximum material (circled M)
    0x24C5: '.###. ###.# ##.## ###.# ##..# .###. ..... .....',  # projected zone (circled P)
    0x25CB: '..... .###. #...# #...# #...# .###. ..... .....',  # circularity
    0x25CE: '.###. #...# #.#.# #...# .###. ..... ..... .....',  # concentricity, coaxiality
    0x27C2: '..... ..#.. ..#.. ..#.. ..#.. ##### ..... .....',  # perpendicularity
}
SYMBOL_RANGES = [(0x2197, 0x2197), (0x2220, 0x2225), (0x2300, 0x2330), (0x23E4, 0x23E5), (0x24C1, 0x24C5), (0x25CB, 0x25CE),
                 (0x27C2, 0x27C2)]

# The replacement mark: a question mark in reverse video, filling the cell (reads apart from '?').
REPLACEMENT = '#...# .###. ####. ###.# ##.## ##### ##.## .....'

# The ranges taken from the Debian font, and where it lies.
FONT = '/usr/share/fonts/X11/misc/5x8.pcf.gz'
RANGES = [(0x00A0, 0x017F), (0x0370, 0x03FF), (0x0400, 0x04FF)]


def read_pcf(path):
    """{code point: 8 row bytes} of a PCF bitmap font of 5 x 8 cells (X11's own format: a table
    of contents, then metrics, bitmaps and encodings tables)."""
    data = gzip.open(path).read()
    if data[:4] != b'\x01fcp':
        raise SystemExit(f'{path}: not a PCF font')
    count = struct.unpack_from('<i', data, 4)[0]
    toc = {}
    for i in range(count):
        kind, fmt, size, offset = struct.unpack_from('<4i', data, 8 + 16 * i)
        toc[kind] = offset
    PROPERTIES, METRICS, BITMAPS, ENCODINGS = 1 << 0, 1 << 2, 1 << 3, 1 << 5

    def table(kind):
        offset = toc[kind]
        fmt = struct.unpack_from('<i', data, offset)[0]
        return offset + 4, fmt, '>' if fmt & (1 << 2) else '<'

    # The font's ascent (the cell's baseline: row 7 is the one row under it).
    at, fmt, e = table(METRICS)
    if fmt & 0x100:  # compressed: a byte each, offset by 0x80
        n = struct.unpack_from(e + 'h', data, at)[0]
        metrics = [tuple(b - 0x80 for b in data[at + 2 + 5 * i: at + 7 + 5 * i]) for i in range(n)]
    else:
        n = struct.unpack_from(e + 'i', data, at)[0]
        metrics = [struct.unpack_from(e + '5h', data, at + 4 + 12 * i) for i in range(n)]
    # (left bearing, right bearing, width, ascent, descent)
    at, fmt, e = table(BITMAPS)
    glyphs = struct.unpack_from(e + 'i', data, at)[0]
    offsets = struct.unpack_from(e + f'{glyphs}i', data, at + 4)
    bitmaps = at + 4 + 4 * glyphs + 16
    pad = 1 << (fmt & 3)             # bytes a row is padded to
    msb_bit = bool(fmt & (1 << 3))   # bit 7 of a byte the leftmost pixel
    unit = 1 << ((fmt >> 4) & 3)     # bytes swapped in units of this size when LSB byte first
    if unit != 1 and e == '<':
        raise SystemExit(f'{path}: byte swapping of {unit}-byte units is not read here')
    at, fmt, e = table(ENCODINGS)
    b2_min, b2_max, b1_min, b1_max, _default = struct.unpack_from(e + '5h', data, at)
    per_row = b2_max - b2_min + 1
    index = struct.unpack_from(e + f'{per_row * (b1_max - b1_min + 1)}H', data, at + 10)
    font = {}
    for b1 in range(b1_min, b1_max + 1):
        for b2 in range(b2_min, b2_max + 1):
            g = index[(b1 - b1_min) * per_row + (b2 - b2_min)]
            if g == 0xFFFF:
                continue
            left, right, width, ascent, descent = metrics[g]
            row_bytes = ((right - left + 7) // 8 + pad - 1) // pad * pad
            rows = [0] * 8
            for y in range(ascent + descent):
                cell_row = 7 - ascent + y
                line = data[bitmaps + offsets[g] + y * row_bytes: bitmaps + offsets[g] + (y + 1) * row_bytes]
                for x in range(right - left):
                    byte = line[x // 8]
                    bit = (byte >> (7 - x % 8)) & 1 if msb_bit else (byte >> (x % 8)) & 1
                    col = left + x
                    if bit and 0 <= col < 5 and 0 <= cell_row < 8:
                        rows[cell_row] |= 1 << (4 - col)
            font[(b1 << 8) | b2] = rows
    return font


def main():
    assert sorted(GLYPHS) == [chr(c) for c in range(32, 127)], 'every printable ASCII character once'
    try:
        fixed = read_pcf(FONT)
    except FileNotFoundError:
        raise SystemExit(f'make_font.py: {FONT} is missing (Debian package xfonts-base: ./facet setup installs it)')
    replacement = rows(REPLACEMENT)
    # (first, last, glyphs): ASCII, the font's ranges, the replacement mark last.
    ranges = [(32, 126, [rows(GLYPHS[chr(c)]) for c in range(32, 127)])]
    for first, last in RANGES:
        ranges.append((first, last, [rows(SYMBOLS[c]) if c in SYMBOLS else fixed.get(c, replacement)
                                     for c in range(first, last + 1)]))
    assert all(any(a <= c <= b for a, b in SYMBOL_RANGES + RANGES) for c in SYMBOLS), 'every symbol in a range'
    for first, last in SYMBOL_RANGES:
        ranges.append((first, last, [rows(SYMBOLS[c]) if c in SYMBOLS else fixed.get(c, replacement)
                                     for c in range(first, last + 1)]))
    ranges.append((0xFFFD, 0xFFFD, [replacement]))
    out = ['// Generated by tools/font/make_font.py (its pixel art, and the X11 misc-fixed 5x8 font',
           '// from Debian\'s xfonts-base): do not edit. 5 x 8 pixels a glyph, one byte per row (bit 4',
           '// the leftmost pixel); the ranges of code points it covers, their glyphs one after another.',
           f'constexpr GlyphRange kGlyphRanges[{len(ranges)}] = {{']
    at = 0
    for first, last, glyphs in ranges:
        out.append(f'    {{0x{first:04X}, 0x{last:04X}, {at}}},')
        at += len(glyphs)
    out.append('};')
    out.append(f'constexpr uint8_t kGlyphs[{at}][8] = {{')
    def row_bytes(g):
        return '{' + ', '.join(f'0x{b:02x}' for b in g) + '},'

    for first, last, glyphs in ranges:
        if first < 127:  # ASCII: a glyph a line, named
            for c, g in zip(range(first, last + 1), glyphs):
                out.append('    ' + row_bytes(g) + ' // ' + {'\\': 'backslash', "'": 'quote'}.get(chr(c), chr(c)))
            continue
        for c in range(first, last + 1, 4):  # the rest four a line, by code point
            line = glyphs[c - first: c - first + 4]
            out.append('    ' + ' '.join(row_bytes(g) for g in line) + f' // U+{c:04X}')
    out.append('};')
    text = '\n'.join(out) + '\n'
    if len(sys.argv) > 1:
        open(sys.argv[1], 'w').write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == '__main__':
    sys.exit(main())
