#!/usr/bin/env python3
"""Names as the CAD system wrote them (issue 27): a STEP product named in Cyrillic and Greek
(written, as STEP does, in \\X2\\ hex) comes out of facet-pack as UTF-8 in the pack, where the
device's font draws it (render/text.h).

The shared model io1_cm_214.stp is copied into WORK with its product renamed (the shared file is
never touched), packed plain (its names readable in the file), and the pack searched for the
name's UTF-8 bytes; the '?' a byte an ASCII conversion would write must not be there.
"""
import argparse
import os
import subprocess
import sys

NAME = 'Деталь-Ω1'  # "part" in Russian, an omega, a digit


def step_hex(text):
    r"""STEP's \X2\ form: four hex digits a UTF-16 unit, ASCII as it is."""
    out, run = [], []
    for ch in text + '\0':
        if ch != '\0' and ord(ch) > 126:
            run.append(f'{ord(ch):04X}')
            continue
        if run:
            out.append('\\X2\\' + ''.join(run) + '\\X0\\')
            run = []
        if ch != '\0':
            out.append(ch)
    return ''.join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--packer', required=True)
    ap.add_argument('--models', required=True)
    ap.add_argument('--work', required=True)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    step = open(os.path.join(args.models, 'io1_cm_214.stp'), encoding='latin-1').read()
    before = "PRODUCT('io1','io1'"
    if before not in step:
        print(f'io1_cm_214.stp has no {before}: the test needs its product record')
        return 1
    renamed = os.path.join(args.work, 'renamed.stp')
    with open(renamed, 'w', encoding='latin-1') as f:
        f.write(step.replace(before, f"PRODUCT('{step_hex(NAME)}','{step_hex(NAME)}'"))
    pack = os.path.join(args.work, 'renamed.fpk')
    r = subprocess.run([args.packer, renamed, '-o', pack, '--plain', '--quiet'], capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        print(r.stdout + r.stderr)
        return 1
    data = open(pack, 'rb').read()
    want = NAME.encode('utf-8')
    ok = want in data and NAME.encode('ascii', 'replace') not in data
    print(f'{NAME!r} as UTF-8 in the pack: {"yes" if want in data else "no"}')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
