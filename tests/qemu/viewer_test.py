#!/usr/bin/env python3
"""The viewer on the target: packs a model on the host, boots facet-viewer in QEMU with the pack
loaded at the board's pack address, and checks the device validated it, tessellated every face
(none failed), drew triangles, and captured a screenshot. Prints the exact instruction counts
for tessellation and one frame (600 M instructions = 1 s at 600 MHz).

  viewer_test.py --board B --elf ELF --packer facet-pack --work DIR MODEL.step...
                 [--sample facet-sample-model]   also the project's own sample part
"""
import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACK_ADDRESS = {'qemu-versatilepb': '0x01C00000', 'qemu-mps2-an500': '0x60C00000'}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--board', required=True)
    ap.add_argument('--elf', required=True)
    ap.add_argument('--packer', required=True)
    ap.add_argument('--sample')
    ap.add_argument('--work', required=True)
    ap.add_argument('models', nargs='*')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    models = list(args.models)
    if args.sample:
        step = os.path.join(args.work, 'sample.step')
        subprocess.run([args.sample, step], check=True, capture_output=True)
        models.append(step)
    failed = False
    for model in models:
        name = os.path.splitext(os.path.basename(model))[0]
        fpk = os.path.join(args.work, name + '.fpk')
        subprocess.run([args.packer, model, '-o', fpk, '--quiet'], check=True, capture_output=True)
        out = os.path.join(args.work, name)
        r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board,
                            '--elf', args.elf, '--out', out, '--load', f'{fpk}@{PACK_ADDRESS[args.board]}', '--icount',
                            '--timeout', '900', '--quiet'], capture_output=True, text=True)
        uart = open(os.path.join(out, 'uart.log')).read()
        rep = json.load(open(os.path.join(out, 'report.json')))
        m = re.search(r'^@tessellation faces (\d+) failed (\d+) triangles (\d+)', uart, re.M)
        counts = {x['name']: x['instructions'] for x in rep['regions']}
        problems = []
        if r.returncode != 0:
            problems.append(f'exit {r.returncode}')
        if not m:
            problems.append('no tessellation report')
        elif int(m.group(2)) != 0:
            problems.append(f'{m.group(2)} faces failed')
        elif int(m.group(3)) == 0:
            problems.append('no triangles')
        if not os.path.exists(os.path.join(out, 'model.png')):
            problems.append('no screenshot')
        if counts.get('tessellate') is None or counts.get('frame') is None:
            problems.append('instruction counts missing')
        if problems:
            failed = True
            print(f'FAIL {args.board} {name}: ' + '; '.join(problems))
            print(uart[-2000:])
            continue
        t, f = counts['tessellate'], counts['frame']
        print(f'{args.board} {name}: {m.group(1)} faces, {m.group(3)} triangles; tessellation {t:,} instructions '
              f'({t / 600e3:.0f} ms at 600 MHz), frame {f:,} ({f / 600e3:.1f} ms)')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
