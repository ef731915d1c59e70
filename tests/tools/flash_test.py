#!/usr/bin/env python3
"""./facet flash without a board: the images it writes (firmware and pack at their addresses in
one Intel HEX, the pack alone in another), the copy onto a probe's drive (a fake DAPLink drive:
a folder with DETAILS.TXT, named or found in the mount table), the probe's refusal (FAIL.TXT),
bad inputs, and no board at all: exit 3 with what to do.

  flash_test.py --image facet-viewer.bin --pack MODEL.fpk --work DIR
"""
import argparse
import os
import shutil
import subprocess
import sys
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402


def read_hex(path):
    mem, base = {}, 0
    for line in open(path):
        line = line.strip()
        if not line.startswith(':'):
            continue
        rec = bytes.fromhex(line[1:])
        assert sum(rec) & 0xFF == 0, f'bad checksum in {path}: {line}'
        n, addr, kind, data = rec[0], (rec[1] << 8) | rec[2], rec[3], rec[4:4 + rec[0]]
        if kind == 0:
            for i, v in enumerate(data):
                mem[base + addr + i] = v
        elif kind == 4:
            base = int.from_bytes(data, 'big') << 16
    return mem


def holds(mem, address, data):
    return all(mem.get(address + i) == v for i, v in enumerate(data))


def fake_drive(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    with open(os.path.join(path, 'DETAILS.TXT'), 'w') as fh:
        fh.write('# DAPLink Firmware - see https://mbed.com/daplink\nUnique ID: 0000000000000000\n'
                 'Board Name: MIMXRT1060-EVK (fake, for the test)\nInterface Version: 0254\n')
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--image', required=True)
    ap.add_argument('--pack', required=True)
    ap.add_argument('--work', required=True)
    ap.add_argument('--facet', help='also run ./facet flash itself (this script path) with no board and onto a fake drive')
    args = ap.parse_args()
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    b = boards.load('mimxrt1060-evkb')
    flash_base = boards.bytes_of(b['flash']['origin'])
    image, pack = open(args.image, 'rb').read(), open(args.pack, 'rb').read()
    empty_mounts = os.path.join(work, 'mounts-none')
    open(empty_mounts, 'w').close()
    bad = []

    def check(ok, what):
        print(('ok   ' if ok else 'FAIL ') + what)
        if not ok:
            bad.append(what)

    def flash(*extra, env_mounts=empty_mounts, out='out'):
        env = dict(os.environ, FACET_FLASH_MOUNTS=env_mounts)
        return subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'flash.py'), '--image', args.image,
                               '--pack', args.pack, '--out', os.path.join(work, out), '--wait', '0.6', *extra],
                              capture_output=True, text=True, env=env)

    # 1. No board: exit 3, the images written, and the steps to take.
    r = flash()
    check(r.returncode == 3, f'no board: exit code 3 ({r.returncode})')
    check('To flash the MIMXRT1060-EVKB' in r.stderr and 'facet-evkb.hex' in r.stderr and '--drive' in r.stderr,
          'no board: the steps are printed')
    mem = read_hex(os.path.join(work, 'out', 'facet-evkb.hex'))
    check(holds(mem, flash_base, image) and holds(mem, b['pack_address'], pack) and len(mem) == len(image) + len(pack),
          f'facet-evkb.hex: the firmware at {flash_base:#x} and the pack at {b["pack_address"]:#x}, nothing else')
    mem = read_hex(os.path.join(work, 'out', 'pack.hex'))
    check(holds(mem, b['pack_address'], pack) and len(mem) == len(pack), 'pack.hex: the pack alone at its address')
    check(open(os.path.join(work, 'out', 'facet-evkb.bin'), 'rb').read() == image, 'facet-evkb.bin: the firmware image')

    # 2. A drive named with --drive: the .hex lands on it.
    drive = fake_drive(os.path.join(work, 'DAPLINK'))
    r = flash('--drive', drive)
    check(r.returncode == 0, f'--drive: exit 0 ({r.returncode}) {r.stderr.strip()}')
    mem = read_hex(os.path.join(drive, 'FACET.HEX')) if os.path.exists(os.path.join(drive, 'FACET.HEX')) else {}
    check(holds(mem, flash_base, image) and holds(mem, b['pack_address'], pack), '--drive: FACET.HEX holds firmware and pack')

    # 3. A drive found in the mount table, and --pack-only: the pack alone goes onto it.
    drive = fake_drive(os.path.join(work, 'MOUNTED'))
    mounts = os.path.join(work, 'mounts-one')
    with open(mounts, 'w') as fh:
        fh.write(f'/dev/sdz1 {drive} vfat rw,nosuid,nodev 0 0\nproc /proc proc rw 0 0\n')
    r = flash('--pack-only', env_mounts=mounts)
    check(r.returncode == 0 and f'probe drive {drive}' in r.stdout, f'found in the mount table ({r.returncode})')
    mem = read_hex(os.path.join(drive, 'FACET.HEX')) if os.path.exists(os.path.join(drive, 'FACET.HEX')) else {}
    check(holds(mem, b['pack_address'], pack) and len(mem) == len(pack), '--pack-only: the pack alone onto the drive')

    # 4. The probe refuses (DAPLink writes FAIL.TXT after the copy): exit 4 with its reason.
    drive = fake_drive(os.path.join(work, 'REFUSING'))

    def refuse():
        for _ in range(100):
            if os.path.exists(os.path.join(drive, 'FACET.HEX')):
                with open(os.path.join(drive, 'FAIL.TXT'), 'w') as fh:
                    fh.write('The hex file cannot be decoded.\n')
                return
            time.sleep(0.05)
    t = threading.Thread(target=refuse)
    t.start()
    r = flash('--drive', drive)
    t.join()
    check(r.returncode == 4 and 'cannot be decoded' in r.stderr, f'a refusal: exit 4 with the reason ({r.returncode})')

    # 5. Bad inputs: exit 2, nothing copied.
    notpack = os.path.join(work, 'not-a-pack.fpk')
    with open(notpack, 'wb') as fh:
        fh.write(b'ISO-10303-21;\n')
    drive = fake_drive(os.path.join(work, 'UNTOUCHED'))
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'flash.py'), '--image', args.image, '--pack', notpack,
                        '--out', os.path.join(work, 'out-bad'), '--drive', drive], capture_output=True, text=True)
    check(r.returncode == 2 and 'no facet pack' in r.stderr and not os.path.exists(os.path.join(drive, 'FACET.HEX')),
          f'a file that is no pack: exit 2, nothing copied ({r.returncode})')
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'flash.py'), '--image', args.pack, '--pack', args.pack,
                        '--out', os.path.join(work, 'out-bad'), '--drive', drive], capture_output=True, text=True)
    check(r.returncode == 2 and 'no EVKB flash image' in r.stderr, f'an image that is no EVKB image: exit 2 ({r.returncode})')

    # 5b. A library larger than the pack region: refused with both sizes, nothing copied.
    big = os.path.join(work, 'big.flb')
    with open(big, 'wb') as fh:
        fh.write(b'FLB1' + bytes(b['pack_bytes'] - 3))
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'flash.py'), '--image', args.image, '--pack', big,
                        '--out', os.path.join(work, 'out-big'), '--drive', drive], capture_output=True, text=True)
    check(r.returncode == 2 and f'the library ({b["pack_bytes"] + 1:,} B) exceeds the {b["pack_bytes"]:,} B pack region' in r.stderr
          and not os.path.exists(os.path.join(drive, 'FACET.HEX')), f'a library over the pack region: exit 2 with both sizes ({r.returncode})')

    # 6. ./facet flash itself (it builds, packs the sample part plain, calls the tool).
    if args.facet:
        env = dict(os.environ, FACET_FLASH_MOUNTS=empty_mounts)
        r = subprocess.run([args.facet, 'flash'], capture_output=True, text=True, env=env)
        check(r.returncode == 3 and 'To flash the MIMXRT1060-EVKB' in r.stderr, f'./facet flash, no board: exit 3 and the steps ({r.returncode})')
        drive = fake_drive(os.path.join(work, 'FACET_FLASH'))
        r = subprocess.run([args.facet, 'flash', '--drive', drive, '--wait', '0.5'], capture_output=True, text=True, env=env)
        mem = read_hex(os.path.join(drive, 'FACET.HEX')) if os.path.exists(os.path.join(drive, 'FACET.HEX')) else {}
        packed = os.path.join(ROOT, 'out', 'flash', 'model.fpk')
        plain = open(packed, 'rb').read() if os.path.exists(packed) else b''
        check(r.returncode == 0 and plain[:4] == b'FPK1' and holds(mem, b['pack_address'], plain) and holds(mem, flash_base, image),
              f'./facet flash --drive: the firmware and the sample part\'s plain pack on the drive ({r.returncode}) {r.stderr[-300:]}')

        # Several models: a library of them where the pack goes, each model in it.
        drive = fake_drive(os.path.join(work, 'FACET_LIBRARY'))
        r = subprocess.run([args.facet, 'flash', args.pack, args.pack, '--drive', drive, '--wait', '0.5'], capture_output=True,
                           text=True, env=env)
        mem = read_hex(os.path.join(drive, 'FACET.HEX')) if os.path.exists(os.path.join(drive, 'FACET.HEX')) else {}
        lib_path = os.path.join(ROOT, 'out', 'flash', 'library.flb')
        lib = open(lib_path, 'rb').read() if os.path.exists(lib_path) else b''
        check(r.returncode == 0 and lib[:4] == b'FLB1' and holds(mem, b['pack_address'], lib) and lib.count(pack) == 2,
              f'./facet flash A B: a library of both where the pack goes ({r.returncode}) {r.stderr[-300:]}')

    print(f'flash: {len(bad)} problem(s)')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
