#!/usr/bin/env python3
"""The foundation's end-to-end image test.

  scene_test.py host --scene-ref BIN --work DIR [--update]
      Renders the test scene on the host (same render/ code as the firmware) at every board
      geometry and compares it with tests/reference/*.png; --update rewrites the references
      (the only way they change).
  scene_test.py qemu --board B --elf ELF --work DIR
      Boots the scene firmware in QEMU, takes its screenshots (versatilepb: QMP screendump of
      the PL110; mps2: the framebuffer dumped over semihosting), and compares them pixel for
      pixel, in RGB565, with the same references. Also reports the draw's exact instruction
      count and the RAM used.
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import img  # noqa: E402
import protocol  # noqa: E402

REF = os.path.join(ROOT, 'tests', 'reference')
GEOMETRIES = [(640, 480), (480, 272)]
VIEWS = ['scene-a', 'scene-b']


def ref_path(view, w, h):
    return os.path.join(REF, f'{view}-{w}x{h}.png')


def host(args):
    os.makedirs(args.work, exist_ok=True)
    failed = 0
    for w, h in GEOMETRIES:
        prefix = os.path.join(args.work, f'{w}x{h}')
        subprocess.run([args.scene_ref, str(w), str(h), prefix], check=True)
        for view in VIEWS:
            got = f'{prefix}-{view}.f565'
            ref = ref_path(view, w, h)
            if args.update:
                img.f565_to_png(got, ref)
                print(f'updated {os.path.relpath(ref, ROOT)}')
                continue
            if not os.path.exists(ref):
                print(f'FAIL {view} {w}x{h}: no reference {ref} (run with --update once)')
                failed += 1
                continue
            n, msg = img.compare(got, ref, diff=f'{prefix}-{view}-diff.png')
            print(f'{"ok  " if n == 0 else "FAIL"} host {view} {w}x{h}: {msg}')
            failed += n != 0
    return 1 if failed else 0


def qemu(args):
    out = os.path.abspath(args.work)
    cmd = [sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board,
           '--elf', args.elf, '--out', out, '--icount', '--timeout', '240', '--quiet']
    r = subprocess.run(cmd)
    report = json.load(open(os.path.join(out, 'report.json')))
    uart = open(os.path.join(out, 'uart.log')).read()
    b = protocol.first(uart, 'board')  # @board NAME WxH scanout BOOL
    if r.returncode != 0 or not b or 'x' not in str(b.fields().get('size', '')):
        print(uart)
        print(f'FAIL: firmware exit {r.returncode}')
        return 1
    w, h = (int(v) for v in b.values()['size'].split('x'))
    failed = 0
    for view in VIEWS:
        shot = os.path.join(out, f'{view}.png')
        if not os.path.exists(shot):
            print(f'FAIL {view}: no screenshot')
            failed += 1
            continue
        n, msg = img.compare(shot, ref_path(view, w, h), diff=os.path.join(out, f'{view}-diff.png'))
        print(f'{"ok  " if n == 0 else "FAIL"} {args.board} {view} {w}x{h}: {msg}')
        failed += n != 0
    for region in report['regions']:
        n = region['instructions']
        if n is None:
            print(f'FAIL region {region["name"]}: not counted')
            failed += 1
        else:
            print(f'{args.board} {region["name"]}: {n:,} instructions '
                  f'({region["ms_at_600mhz"]} ms at 600 MHz)')
    print(f'{args.board} RAM in use: {report["ram"].get("total", 0):,} bytes; '
          f'stack used {report.get("stack_used")} of {report.get("stack_size")}')
    return 1 if failed else 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('mode', choices=['host', 'qemu'])
    ap.add_argument('--scene-ref')
    ap.add_argument('--board')
    ap.add_argument('--elf')
    ap.add_argument('--work', required=True)
    ap.add_argument('--update', action='store_true')
    args = ap.parse_args()
    return host(args) if args.mode == 'host' else qemu(args)


if __name__ == '__main__':
    sys.exit(main())
