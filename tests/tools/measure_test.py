#!/usr/bin/env python3
"""./facet measure against Open CASCADE's own values, on shared models.

Each model is packed with `facet-pack --reference` (Open CASCADE's surface parameters of every
packed face, in double, straight from the STEP file's B-rep) and measured with `facet-measure`
(the device's geom/measure.h on the pack's float32 parameters). Asserted, to 1e-6 relative:
  * every face: its surface type; radii (cylinder, cone, sphere, torus major and minor), cone
    half-angles; hole or boss; B-spline degrees and pole counts (exactly);
  * pairs of faces of one shell: the angle between two planes, the distance between parallel
    planes, the angle between a plane and an axis and the distance of a parallel axis, the
    angle and distance between two axes (cylinders, cones) — from Open CASCADE's planes and
    axes in double.
Relations are placement-invariant (both faces placed by one instance), so the reference stays
in the shells' own coordinates.

Radii and angles are held to 1e-6 of their value. Distances are held to 1e-6 of the larger of
the value and the faces' distance from the origin: the pack keeps positions in float32, whose
step at 400 mm from the origin is 3e-5 mm (tail_section_asm: planes 3 mm apart at x = 265,
y = 374 measure 3.00002 mm; facet-measure prints them to the digits float32 holds: 3.0000 mm).

  measure_test.py --packer P --measure M --models DIR --work DIR MODEL...
"""
import argparse
import itertools
import json
import math
import os
import subprocess
import sys

REL = 1e-6


def sub(a, b): return [x - y for x, y in zip(a, b)]
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def norm(a): return math.sqrt(dot(a, a))
def unit(a):
    n = norm(a)
    return [x / n for x in a]


def line_angle(a, b):
    return math.atan2(norm(cross(a, b)), abs(dot(a, b)))


def expected(ra, rb):
    """The relation of two faces from Open CASCADE's planes and axes: (kind, angle, distance)."""
    pa, pb = ra['type'] == 'plane', rb['type'] == 'plane'
    axial = ('cylinder', 'cone')
    if pa and pb:
        ang = line_angle(ra['normal'], rb['normal'])
        d = abs(dot(unit(ra['normal']), sub(rb['origin'], ra['origin']))) if ang < 1e-6 else None
        return 'planes', ang, d
    if pa or pb:
        plane, other = (ra, rb) if pa else (rb, ra)
        if other['type'] in axial:
            ang = math.pi / 2 - line_angle(plane['normal'], other['axis'])
            d = abs(dot(unit(plane['normal']), sub(other['origin'], plane['origin']))) if ang < 1e-6 else None
            return 'plane_axis', ang, d
        return None
    if ra['type'] in axial and rb['type'] in axial:
        a, b = unit(ra['axis']), unit(rb['axis'])
        ang = line_angle(a, b)
        w = sub(rb['origin'], ra['origin'])
        if ang < 1e-6:
            d = norm(cross(w, a))
        else:
            n = cross(a, b)
            d = abs(dot(w, n)) / norm(n)
        return 'axes', ang, d
    return None


def close(got, want, reach):
    """Within 1e-6 of the value, or of the positions' distance from the origin (float32)."""
    return abs(got - want) <= REL * max(abs(want), reach)


def check_model(args, name, problems, stats):
    step = os.path.join(args.models, name)
    base = os.path.join(args.work, os.path.splitext(name)[0])
    fpk, ref_path = base + '.fpk', base + '.faces.json'
    env = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')
    r = subprocess.run([args.packer, step, '-o', fpk, '--reference', ref_path, '--quiet'], capture_output=True, text=True, env=env)
    if r.returncode != 0:
        problems.append(f'{name}: facet-pack exit {r.returncode}: {r.stderr[-300:]}')
        return
    ref = json.load(open(ref_path))['faces']
    r = subprocess.run([args.measure, fpk, '--all'], capture_output=True, text=True)
    if r.returncode != 0:
        problems.append(f'{name}: facet-measure --all exit {r.returncode}: {r.stderr[-300:]}')
        return
    got = {g['face']: g for g in map(json.loads, r.stdout.splitlines())}
    worst = stats.setdefault('worst', [0.0, ''])
    for f in ref:
        g = got.get(f['face'])
        if g is None:
            continue  # a shell no instance places
        t = f['type']
        if t == 'other':
            continue
        if g['type'] != t:
            problems.append(f'{name} face {f["face"]}: {g["type"]}, Open CASCADE: {t}')
            continue
        stats['faces'] = stats.get('faces', 0) + 1
        for key in ('radius', 'minor_radius', 'half_angle'):
            if key in f:
                err = abs(g[key] - f[key]) / max(abs(f[key]), 1e-300)
                if err > worst[0]:
                    worst[:] = [err, f'{name} face {f["face"]} {key}']
                if err > REL:
                    problems.append(f'{name} face {f["face"]} {t} {key}: {g[key]!r}, Open CASCADE {f[key]!r} ({err:.2e} relative)')
        if 'hole' in f and g['hole'] != f['hole']:
            problems.append(f'{name} face {f["face"]} {t}: hole {g["hole"]}, Open CASCADE {f["hole"]}')
        if t == 'B-spline':
            for key in ('u_degree', 'v_degree', 'u_poles', 'v_poles', 'rational', 'u_periodic', 'v_periodic'):
                if g[key] != f[key]:
                    problems.append(f'{name} face {f["face"]} B-spline {key}: {g[key]}, Open CASCADE {f[key]}')
    # Pairs of one instance: every relation kind, up to args.pairs of each.
    faces = [f for f in ref if f['face'] in got and f['type'] in ('plane', 'cylinder', 'cone')]
    by_kind = {}
    for a, b in itertools.combinations(faces, 2):
        if got[a['face']]['instance'] != got[b['face']]['instance']:
            continue
        e = expected(a, b)
        if e is None:
            continue
        kind = e[0] + (' parallel' if e[2] is not None and e[1] < 1e-6 else '')
        lst = by_kind.setdefault(kind, [])
        if len(lst) < args.pairs:
            lst.append((a, b, e))
    for kind, lst in sorted(by_kind.items()):
        for a, b, (k, ang, dist) in lst:
            r = subprocess.run([args.measure, fpk, '--face', str(a['face']), '--face', str(b['face']), '--json'], capture_output=True, text=True)
            if r.returncode != 0:
                problems.append(f'{name} faces {a["face"]}, {b["face"]}: exit {r.returncode}: {r.stderr[-200:]}')
                continue
            rel = json.loads(r.stdout)['relation']
            stats['pairs'] = stats.get('pairs', 0) + 1
            if rel['kind'] != k:
                problems.append(f'{name} faces {a["face"]}, {b["face"]}: {rel["kind"]}, expected {k}')
                continue
            if abs(rel['angle'] - ang) > REL:
                problems.append(f'{name} faces {a["face"]}, {b["face"]} ({kind}): angle {rel["angle"]!r}, Open CASCADE {ang!r}')
            if dist is not None:
                # How far from the origin the two faces' positions lie (the float32 step scales with it).
                reach = max(norm(a['origin']), norm(b['origin']), 1e-9)
                if rel['distance'] is None or not close(rel['distance'], dist, reach):
                    problems.append(f'{name} faces {a["face"]}, {b["face"]} ({kind}): distance {rel["distance"]!r}, Open CASCADE {dist!r}')
                else:
                    err = abs(rel['distance'] - dist) / max(abs(dist), reach)
                    if err > worst[0]:
                        worst[:] = [err, f'{name} faces {a["face"]}, {b["face"]} distance']
    print(f'{name}: {len(got)} faces, pairs: ' + ', '.join(f'{len(v)} {k}' for k, v in sorted(by_kind.items())))


def main():
    ap = argparse.ArgumentParser()
    for a in ('--packer', '--measure', '--models', '--work'):
        ap.add_argument(a, required=True)
    ap.add_argument('--pairs', type=int, default=12, help='pairs of each relation kind per model')
    ap.add_argument('models_list', nargs='+')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    problems, stats = [], {}
    for name in args.models_list:
        check_model(args, name, problems, stats)
    # Misuse: a face or instance that does not exist, text for a number, no pack.
    fpk = os.path.join(args.work, os.path.splitext(args.models_list[0])[0] + '.fpk')
    for cmd, code, needle in (([fpk, '--face', '999999'], 2, 'the pack has'), ([fpk, '--face', 'x'], 2, 'a face index'),
                              ([fpk, '--face', '0@77'], 2, 'does not place'), ([fpk], 2, 'one or two --face'),
                              ([os.path.join(args.work, 'none.fpk'), '--face', '0'], 1, 'cannot read')):
        r = subprocess.run([args.measure, *cmd], capture_output=True, text=True)
        if r.returncode != code or needle not in r.stderr:
            problems.append(f'facet-measure {" ".join(cmd[1:])}: exit {r.returncode} (expected {code}), {r.stderr.strip()[-200:]!r}')
    for p in problems[:40]:
        print('FAIL', p)
    w = stats.get('worst', [0, ''])
    print(f'{stats.get("faces", 0)} faces and {stats.get("pairs", 0)} pairs against Open CASCADE; '
          f'largest relative difference {w[0]:.2e} ({w[1]}); {len(problems)} problems')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
