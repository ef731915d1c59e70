#!/usr/bin/env python3
"""facet's mesh (an OBJ from ./facet mesh --obj: placed vertices in mm, a unit normal per vertex)
as tgx meshes, in a blob the render bench reads in place (bench/render/tgx_side.cpp).

tgx::Mesh3D takes at most 32,767 vertices and 65,535 face words a mesh, and its faces as chains
of triangles (each triangle after the first of a chain costs one element, not three): the
triangles are chained greedily across shared edges, the way tgx's own OBJ converter does, and
the chains are split over as many chained meshes as the limits need.

Blob (little-endian, 4-byte aligned):
  u32 'TGXM', u32 version 1, u32 meshes, u32 triangles, f32 centre[3], f32 radius
  per mesh: u32 vertices, u32 triangles, u32 face_words, u32 rgb (0x00BBGGRR)
            f32 position[3 * vertices], f32 normal[3 * vertices], u16 face[face_words] (+ pad)

  tgx_mesh.py MODEL.obj OUT.blob [--rgb 0xB4B4B4]
"""
import argparse
import math
import struct
import sys

MAX_VERTICES = 32767
MAX_WORDS = 65000
DBIT = 0x8000


def read_obj(path):
    pos, nrm, tris = [], [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == 'v':
                pos.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == 'vn':
                nrm.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == 'f':
                idx = [int(x.split('/')[0]) - 1 for x in w[1:]]
                for k in range(1, len(idx) - 1):  # a polygon as a fan
                    tris.append((idx[0], idx[k], idx[k + 1]))
    if len(nrm) != len(pos):
        raise SystemExit(f'tgx_mesh.py: {path}: {len(pos)} vertices but {len(nrm)} normals (one per vertex expected)')
    return pos, nrm, tris


def chains(tris):
    """Greedy chains: from triangle (v1, v2, v3) the next is (v1, v3, v4) [DBIT 0], the neighbour
    across v3-v1, or (v3, v2, v4) [DBIT 1], the neighbour across v2-v3 (tgx's Mesh3D format)."""
    by_edge = {}
    for t, (a, b, c) in enumerate(tris):
        for e in ((a, b, c), (b, c, a), (c, a, b)):
            by_edge.setdefault((e[0], e[1]), []).append((t, e[2]))
    used = [False] * len(tris)

    def take(u, v):
        for t, w in by_edge.get((u, v), ()):
            if not used[t]:
                used[t] = True
                return w
        return None

    out = []
    for t, (a, b, c) in enumerate(tris):
        if used[t]:
            continue
        used[t] = True
        chain = [a, b, c]
        v1, v2, v3 = a, b, c
        while len(chain) < 65000:
            w = take(v1, v3)  # the triangle across v3 -> v1 holds v1 -> v3
            if w is not None:
                chain.append(w)
                v2, v3 = v3, w
                continue
            w = take(v3, v2)
            if w is not None:
                chain.append(w | DBIT)
                v1, v3 = v3, w
                continue
            break
        out.append(chain)
    return out


def build(pos, nrm, tris, rgb):
    meshes, cur = [], None

    def start():
        return {'map': {}, 'pos': [], 'nrm': [], 'words': [], 'tris': 0}

    for chain in chains(tris):
        verts = {v & ~DBIT for v in chain}
        if cur is None or len(cur['map']) + len(verts) > MAX_VERTICES or \
                len(cur['words']) + 1 + 2 * len(chain) + 1 > MAX_WORDS:
            if cur is not None:
                meshes.append(cur)
            cur = start()
        cur['words'].append(len(chain) - 2)
        for v in chain:
            i = v & ~DBIT
            if i not in cur['map']:
                cur['map'][i] = len(cur['pos'])
                cur['pos'].append(pos[i])
                cur['nrm'].append(nrm[i])
            k = cur['map'][i]
            cur['words'] += [k | (v & DBIT), k]
        cur['tris'] += len(chain) - 2
    if cur is not None:
        meshes.append(cur)
    lo = [min(p[k] for p in pos) for k in range(3)]
    hi = [max(p[k] for p in pos) for k in range(3)]
    centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
    radius = math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3))) / 2
    blob = struct.pack('<4I4f', 0x4D584754, 1, len(meshes), len(tris), *centre, radius)
    for m in meshes:
        words = m['words'] + [0]  # the end tag
        blob += struct.pack('<4I', len(m['pos']), m['tris'], len(words), rgb)
        blob += struct.pack(f'<{3 * len(m["pos"])}f', *[c for p in m['pos'] for c in p])
        blob += struct.pack(f'<{3 * len(m["nrm"])}f', *[c for n in m['nrm'] for c in n])
        face = struct.pack(f'<{len(words)}H', *words)
        blob += face + b'\0' * (-len(face) % 4)
    return blob, len(meshes)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('obj')
    ap.add_argument('out')
    ap.add_argument('--rgb', type=lambda s: int(s, 0), default=0xB4B4B4)
    args = ap.parse_args()
    pos, nrm, tris = read_obj(args.obj)
    if not tris:
        raise SystemExit(f'tgx_mesh.py: {args.obj}: no triangles')
    blob, n = build(pos, nrm, tris, args.rgb)
    with open(args.out, 'wb') as f:
        f.write(blob)
    print(f'{args.out}: {len(tris):,} triangles, {len(pos):,} vertices, {n} tgx meshes, {len(blob):,} bytes')
    return 0


if __name__ == '__main__':
    sys.exit(main())
