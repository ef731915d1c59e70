#!/usr/bin/env python3
"""facet-sim, the desktop simulator: one scripted session (keys, left/right/middle drags, the
wheel, a one-finger drag, a pinch, taps and a click that pick, a finer level of detail) played
three ways on the sample part, at both screen sizes:

  * headless: the entries go to the module's API directly (the reference; the QEMU viewer
    tests compare the boards' screenshots with this same program's);
  * in an SDL window (SDL's dummy video driver, no display needed): every entry becomes the SDL
    events a user's hands would make and goes through the simulator's event handling;
  * headless in bands of 16 lines (partial rendering, one band-sized depth buffer).

And `--ram 4` (the module in 4 MiB, the pack at its end) gives the same pictures for the part.

Every screenshot must be pixel-identical across the three (bands: every full redraw; the
"half" screenshot is taken at a different moment when bands refresh progress every sixteenth
of the faces), the picks must name the same faces, and the session must change the picture.

  sim_test.py --sim facet-sim --packer facet-pack --sample facet-sample-model --work DIR
"""
import argparse
import hashlib
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import img  # noqa: E402
import protocol  # noqa: E402

# The taps come after a fit (f: framed again from the direction the session turned to): the
# one in the middle of the screen lands on the part, the one in the corner on nothing.
SESSION = ['keys dd!shot turned\\n', 'mouse 60 -30', 'keys !shot dragged\\n', 'mouse 30 20 right',
           'keys !shot panned\\n', 'mouse 0 -25 middle', 'keys !shot dollied\\n', 'wheel 2', 'keys !shot wheeled\\n',
           'drag 200 150 40 10', 'keys !shot fingerdrag\\n', 'pinch 240 130 100 160', 'keys !shot pinched\\n',
           'keys f', 'tap {mx} {my}', 'tap 5 5', 'click', 'keys ]', 'keys !shot lod\\n']
SHOTS = ['wireframe', 'half', 'done', 'turned', 'dragged', 'panned', 'dollied', 'wheeled', 'fingerdrag', 'pinched', 'lod']


def run(sim, fpk, out, size, mode):
    os.makedirs(out, exist_ok=True)
    # No clock: the status bar shows no frame times (they differ with the machine and the
    # mode), so the three modes must give the same pixels, interface included.
    cmd = [sim, '--pack', fpk, '--out', out, '--size', size, '--no-clock']
    env = dict(os.environ)
    if mode == 'window':
        env['SDL_VIDEODRIVER'] = 'dummy'
        env.pop('DISPLAY', None)
    else:
        cmd.append('--headless')
    if mode == 'bands':
        cmd += ['--bands', '16']
    w, h = (int(v) for v in size.split('x'))
    for s in SESSION:
        cmd += ['--send', s.format(mx=w // 2, my=h // 2)]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=300)
    picks = [p.values() for p in protocol.records(r.stdout, 'pick')]
    return r, picks


def main():
    ap = argparse.ArgumentParser()
    for a in ('--sim', '--packer', '--sample', '--work'):
        ap.add_argument(a, required=True)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    step = os.path.join(args.work, 'sample.step')
    fpk = os.path.join(args.work, 'sample.fpk')
    occt = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')  # Open CASCADE's allocations are not ours to check
    subprocess.run([args.sample, step], check=True, capture_output=True, env=occt)
    subprocess.run([args.packer, step, '-o', fpk, '--quiet'], check=True, capture_output=True, env=occt)
    failed = False
    for size in ('640x480', '480x272'):
        outs, problems = {}, []
        picks = {}
        for mode in ('headless', 'window', 'bands'):
            outs[mode] = os.path.join(args.work, f'{size}-{mode}')
            r, picks[mode] = run(args.sim, fpk, outs[mode], size, mode)
            if r.returncode != 0:
                problems.append(f'{mode}: exit {r.returncode}: {r.stderr.strip()[-300:]}')
        if [p['hit'] for p in picks['headless']][:2] != [1, 0] or len(picks['headless']) != 3:
            problems.append(f'the picks: {picks["headless"]} (the tap in the middle hits a face, the corner one nothing)')
        if picks['window'] != picks['headless']:
            problems.append(f'window picks {picks["window"]} vs headless {picks["headless"]}')
        digests = set()
        for shot in SHOTS:
            ref = os.path.join(outs['headless'], shot + '.f565')
            if not os.path.exists(ref):
                problems.append(f'{shot} missing (headless)')
                continue
            digests.add(hashlib.sha1(open(ref, 'rb').read()).hexdigest())
            for mode in ('window', 'bands'):
                if mode == 'bands' and shot == 'half':
                    continue
                got = os.path.join(outs[mode], shot + '.f565')
                if not os.path.exists(got):
                    problems.append(f'{shot} missing ({mode})')
                    continue
                n, msg = img.compare(ref, got, os.path.join(outs[mode], shot + '-diff.png'))
                if n:
                    problems.append(f'{shot}, {mode} vs headless: {msg}')
        if len(digests) < len(SHOTS) - 1:
            problems.append(f'only {len(digests)} different pictures in {len(SHOTS)} screenshots: the session did not move')
        if problems:
            failed = True
            print(f'FAIL facet-sim {size}: ' + '; '.join(problems))
        else:
            print(f'facet-sim {size}: {len(SHOTS)} screenshots identical headless, in an SDL window (dummy driver) '
                  f'and in bands of 16 lines; picks {picks["headless"]}')
    # --ram: the module in that much RAM, the pack decoded at its end (as the boards do): the
    # sample part fits 4 MiB, so the same pictures; out of range, a usage error.
    ram_out = os.path.join(args.work, 'ram')
    os.makedirs(ram_out, exist_ok=True)
    r = subprocess.run([args.sim, '--pack', fpk, '--out', ram_out, '--size', '640x480', '--no-clock', '--headless', '--ram', '4',
                        '--send', 'keys dd!shot turned\\n'], capture_output=True, text=True, timeout=300)
    ref = os.path.join(args.work, '640x480-headless', 'turned.f565')
    got = os.path.join(ram_out, 'turned.f565')
    n, msg = img.compare(ref, got) if r.returncode == 0 and os.path.exists(got) else (1, f'exit {r.returncode}: {r.stderr.strip()[-200:]}')
    if n:
        failed = True
        print(f'FAIL facet-sim --ram 4: {msg}')
    for bad in ('0', '5000', 'x'):
        r = subprocess.run([args.sim, '--pack', fpk, '--ram', bad, '--headless'], capture_output=True, text=True, timeout=60)
        if r.returncode != 2 or '--ram' not in r.stderr:
            failed = True
            print(f'FAIL facet-sim --ram {bad}: exit {r.returncode}, {r.stderr.strip()[-200:]} (a usage error, exit 2)')
    if not failed:
        print('facet-sim --ram 4: the same pictures; --ram 0, 5000 and x refused (exit 2)')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
