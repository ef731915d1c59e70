#!/usr/bin/env python3
"""Image helpers for facet (standard library only).

facet's raw frame format "F565": b'F565', u16 width, u16 height (little-endian), then
width*height RGB565 pixels, little-endian. The mps2 board dumps it over semihosting and the
host reference renderer writes it. RGB565 is widened to 8 bits per channel by shifting
(r<<3, g<<2, b<<3) -- what QEMU's PL110 does -- so comparisons are exact in RGB565 space.

  img.py topng IN.f565 OUT.png
  img.py compare A B [--diff DIFF.png]   (A, B: .png or .f565; exit 0 if identical in RGB565)
"""
import struct
import sys
import zlib


def read_f565(path):
    data = open(path, 'rb').read()
    if len(data) < 8 or data[:4] != b'F565':
        raise ValueError(f'{path}: not an F565 image')
    w, h = struct.unpack_from('<HH', data, 4)
    if len(data) != 8 + 2 * w * h:
        raise ValueError(f'{path}: size {len(data)} does not match {w}x{h}')
    px = struct.unpack_from(f'<{w * h}H', data, 8)
    return w, h, list(px)


def rgb565_to_rgb(p):
    return ((p >> 11) & 31) << 3, ((p >> 5) & 63) << 2, (p & 31) << 3


def rgb_to_rgb565(r, g, b):
    return ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3)


def write_png(path, w, h, rgb_rows):
    """rgb_rows: list of h bytes objects, 3*w each."""
    raw = b''.join(b'\x00' + row for row in rgb_rows)

    def chunk(tag, body):
        c = struct.pack('>I', len(body)) + tag + body
        return c + struct.pack('>I', zlib.crc32(tag + body) & 0xffffffff)

    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
    with open(path, 'wb') as f:
        f.write(png)


def read_png(path):
    """Returns (w, h, rows) with rows as lists of (r, g, b). 8-bit RGB or RGBA only."""
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError(f'{path}: not a PNG')
    pos, idat, w = 8, b'', None
    while pos < len(data):
        n, tag = struct.unpack_from('>I4s', data, pos)
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if tag == b'IHDR':
            w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError(f'{path}: unsupported PNG (depth {depth}, type {ctype})')
            bpp = 3 if ctype == 2 else 4
        elif tag == b'IDAT':
            idat += body
        elif tag == b'IEND':
            break
    raw = zlib.decompress(idat)
    stride = w * bpp
    prev = bytearray(stride)
    rows, i = [], 0
    for _ in range(h):
        f = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + ((a + b) >> 1)) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pr) & 255
        rows.append([(line[x], line[x + 1], line[x + 2]) for x in range(0, stride, bpp)])
        prev = line
    return w, h, rows


def load_565(path):
    """Any supported image as (w, h, flat list of RGB565)."""
    if path.endswith('.f565'):
        return read_f565(path)
    w, h, rows = read_png(path)
    return w, h, [rgb_to_rgb565(*p) for row in rows for p in row]


def f565_to_png(src, dst):
    w, h, px = read_f565(src)
    rows = []
    for y in range(h):
        rows.append(bytes(c for p in px[y * w:(y + 1) * w] for c in rgb565_to_rgb(p)))
    write_png(dst, w, h, rows)


def frame_time_field(w, h):
    """The status bar's frame-time field of facet's on-screen interface at w x h, as (x0, y0,
    x1, y1): the one place a board's frame and the host's differ (each shows its own clock).
    Mirrors module/src/overlay.cpp (layout, time_field); Overlay.TheFrameTimeFieldIsWhereImgPySaysItIs
    checks the two agree."""
    if w < 160 or h < 96:
        return None
    toolbar_x = w - (56 if w >= 600 else 44)
    x1 = toolbar_x - 3
    return (x1 - (9 * 6 - 1), 0, x1, 12)


def compare(a, b, diff=None, ignore=None):
    """Returns (different_pixels, message). ignore: rectangles (x0, y0, x1, y1) not compared."""
    wa, ha, pa = load_565(a)
    wb, hb, pb = load_565(b)
    if (wa, ha) != (wb, hb):
        return -1, f'size differs: {a} is {wa}x{ha}, {b} is {wb}x{hb}'
    skip = set()
    for r in ignore or []:
        if r:
            x0, y0, x1, y1 = r
            skip.update(y * wa + x for y in range(max(y0, 0), min(y1, ha)) for x in range(max(x0, 0), min(x1, wa)))
    bad = [i for i in range(len(pa)) if pa[i] != pb[i] and i not in skip]
    if diff and bad:
        badset = set(bad)
        rows = []
        for y in range(ha):
            row = bytearray()
            for x in range(wa):
                i = y * wa + x
                row += bytes((255, 0, 255)) if i in badset else bytes(c // 3 for c in rgb565_to_rgb(pa[i]))
            rows.append(bytes(row))
        write_png(diff, wa, ha, rows)
    if not bad:
        return 0, f'identical: {wa}x{ha}'
    x, y = bad[0] % wa, bad[0] // wa
    return len(bad), (f'{len(bad)} of {wa * ha} pixels differ; first at ({x},{y}): '
                      f'{pa[bad[0]]:#06x} vs {pb[bad[0]]:#06x}')


def main(argv):
    if len(argv) >= 3 and argv[0] == 'topng':
        f565_to_png(argv[1], argv[2])
        return 0
    if len(argv) >= 3 and argv[0] == 'compare':
        diff = argv[argv.index('--diff') + 1] if '--diff' in argv else None
        n, msg = compare(argv[1], argv[2], diff)
        print(msg)
        return 0 if n == 0 else 1
    print(__doc__)
    return 2


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
