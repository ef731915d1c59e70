#!/usr/bin/env python3
"""Flash the MIMXRT1060-EVKB: the firmware image and the model's pack, each at its own place in
the QSPI flash (boards/mimxrt1060-evkb/board.json: the firmware at the flash base, the pack at
its own offset, so a new model needs no new firmware).

  flash.py --image facet-viewer.bin --pack MODEL.fpk|LIBRARY.flb --out DIR [--drive DIR] [--pack-only] [--wait S]

Writes into DIR: facet-evkb.hex (firmware and pack, absolute addresses: what a probe or a
programming tool takes), facet-evkb.bin (the firmware from the flash base), pack.hex (the pack
alone) and pack.fpk. Then, if a probe's drag-and-drop drive is mounted (DAPLink: a FAT drive with
DETAILS.TXT; --drive names one), copies the .hex onto it and waits for the probe's verdict
(DAPLink writes FAIL.TXT when programming failed). With no drive it says exactly what to do and
exits 3. Exit codes: 0 flashed (or handed to the probe), 2 bad input, 3 no board, 4 the probe
refused the image.

No vendor download is involved; what Debian 12's own tools can and cannot do for this chip is in
docs/boards.md (none of them programs the i.MX RT1062's FlexSPI flash).
"""
import argparse
import os
import shutil
import struct
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402

BOARD = 'mimxrt1060-evkb'
NO_BOARD, BAD_INPUT, REFUSED = 3, 2, 4


def die(code, message):
    print(f'flash: {message}', file=sys.stderr)
    sys.exit(code)


def intel_hex(chunks):
    """Intel HEX (I8HEX with extended linear address records) of [(address, bytes)]."""
    lines = []

    def record(kind, address, data):
        body = bytes([len(data), (address >> 8) & 0xFF, address & 0xFF, kind]) + data
        lines.append(':' + body.hex().upper() + f'{(-sum(body)) & 0xFF:02X}')

    for base, data in chunks:
        upper = None
        for off in range(0, len(data), 16):
            a = base + off
            if a >> 16 != upper:
                upper = a >> 16
                record(4, 0, struct.pack('>H', upper))
            record(0, a & 0xFFFF, data[off:off + 16])
    record(1, 0, b'')
    return '\n'.join(lines) + '\n'


def mounted_drives():
    """Mount points that look like a debug probe's drag-and-drop drive (DAPLink's DETAILS.TXT)."""
    found = []
    try:  # FACET_FLASH_MOUNTS: another mount table (the tests' fake drives)
        mounts = open(os.environ.get('FACET_FLASH_MOUNTS', '/proc/mounts')).read().splitlines()
    except OSError:
        mounts = []
    for line in mounts:
        p = line.split()
        if len(p) < 3:
            continue
        point = p[1].replace('\\040', ' ')
        if os.path.isfile(os.path.join(point, 'DETAILS.TXT')) or os.path.isfile(os.path.join(point, 'MBED.HTM')):
            found.append(point)
    return found


def describe(drive):
    try:
        text = open(os.path.join(drive, 'DETAILS.TXT'), errors='replace').read()
    except OSError:
        return ''
    keep = [l.strip() for l in text.splitlines() if l.split(':')[0].strip() in ('Board Name', 'Interface Version', 'Unique ID')]
    return '; '.join(keep)


def probes_on_usb():
    """NXP (0x1FC9: MCU-Link, LPC-Link2) and Arm/DAPLink (0x0D28) USB devices, by sysfs."""
    out = []
    base = '/sys/bus/usb/devices'
    try:
        names = os.listdir(base)
    except OSError:
        return out
    for n in names:
        try:
            vid = open(os.path.join(base, n, 'idVendor')).read().strip()
            pid = open(os.path.join(base, n, 'idProduct')).read().strip()
        except OSError:
            continue
        if vid in ('1fc9', '0d28'):
            product = ''
            try:
                product = open(os.path.join(base, n, 'product')).read().strip()
            except OSError:
                pass
            out.append(f'{vid}:{pid} {product}'.strip())
    return out


def instructions(out, b):
    rel = os.path.relpath(out, os.getcwd())
    usb = probes_on_usb()
    seen = (f'A debug probe is on USB ({", ".join(usb)}) but it shows no drive.' if usb else
            'No debug probe is on USB and no probe drive is mounted.')
    return f"""{seen}
The images are ready in {rel}/:
  facet-evkb.hex  the firmware at {b['flash_origin']:#010x} and the pack at {b['pack_address']:#010x}: what to flash
  facet-evkb.bin  the firmware alone, from {b['flash_origin']:#010x}
  pack.hex        the pack alone: a new model without a new firmware
To flash the MIMXRT1060-EVKB:
  1. Connect the board's debug USB port (the on-board probe) to this computer.
  2. If the probe runs DAPLink firmware it shows a USB drive (check with 'lsblk' or a file manager;
     mount it if your desktop does not). Then run again:
         ./facet flash [MODEL.step]                 (it finds the drive)
         ./facet flash [MODEL.step] --drive /media/$USER/DRIVE
     The copy programs the QSPI flash; the probe's LED blinks while it writes.
  3. Without such a drive: Debian 12's openocd, pyocd and uuu cannot program this flash (see
     docs/boards.md). Any programmer that takes Intel HEX for the EVKB's QSPI flash (NXP's
     MCUXpresso / LinkServer, SEGGER J-Flash) takes {rel}/facet-evkb.hex as it is: its addresses
     are absolute.
  4. Boot from the QSPI flash (the boot-mode switches to internal boot), press RESET and watch
     the console: picocom -b 115200 /dev/ttyACM0 (docs/boards.md, "What you should see")."""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--image', required=True, help='the firmware image (.bin, from the flash base)')
    ap.add_argument('--pack', required=True, help='the model (.fpk), or several models (a library, .flb)')
    ap.add_argument('--out', required=True)
    ap.add_argument('--drive', help="the probe's mounted drive (default: look for one)")
    ap.add_argument('--pack-only', action='store_true', help='flash the pack alone (the firmware is already there)')
    ap.add_argument('--wait', type=float, default=15.0, help='seconds to wait for the probe to report')
    args = ap.parse_args()

    b = boards.load(BOARD)
    b['flash_origin'] = boards.bytes_of(b['flash']['origin'])
    room = next(boards.bytes_of(m['bytes']) for m in b['memory'] if m['name'] == 'FLASH')
    try:
        image = open(args.image, 'rb').read()
        pack = open(args.pack, 'rb').read()
    except OSError as e:
        die(BAD_INPUT, f'cannot read: {e}')
    if image[:4] != b'FCFB':
        die(BAD_INPUT, f'{args.image} is no EVKB flash image (no FlexSPI configuration block at its start)')
    if len(image) > room:
        die(BAD_INPUT, f'the firmware ({len(image):,} B) exceeds its {room:,} B of flash')
    if pack[:4] not in (b'FPK1', b'FPX1', b'FPZ1', b'FPB1', b'FLB1'):
        die(BAD_INPUT, f'{args.pack} is no facet pack nor library (facet-pack makes them from STEP files)')
    what = 'library' if pack[:4] == b'FLB1' else 'pack'
    if len(pack) > b['pack_bytes']:
        die(BAD_INPUT, f'the {what} ({len(pack):,} B) exceeds the {b["pack_bytes"]:,} B pack region')

    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    chunks = [(b['pack_address'], pack)] if args.pack_only else [(b['flash_origin'], image), (b['pack_address'], pack)]
    files = {'facet-evkb.hex': intel_hex([(b['flash_origin'], image), (b['pack_address'], pack)]),
             'pack.hex': intel_hex([(b['pack_address'], pack)])}
    try:
        for name, text in files.items():
            with open(os.path.join(out, name), 'w') as fh:
                fh.write(text)
        shutil.copyfile(args.image, os.path.join(out, 'facet-evkb.bin'))
        shutil.copyfile(args.pack, os.path.join(out, 'pack.fpk'))
    except OSError as e:
        die(BAD_INPUT, f'cannot write the images into {out}: {e}')
    print(f'flash: firmware {len(image):,} B at {b["flash_origin"]:#010x}, pack {len(pack):,} B at '
          f'{b["pack_address"]:#010x}; images in {os.path.relpath(out, os.getcwd())}/')

    drives = [args.drive] if args.drive else mounted_drives()
    if args.drive and not os.path.isdir(args.drive):
        die(NO_BOARD, f'no such drive: {args.drive}')
    if not drives:
        print(instructions(out, b), file=sys.stderr)
        die(NO_BOARD, 'no board to flash (exit 3)')
    if len(drives) > 1:
        die(NO_BOARD, f'several probe drives are mounted ({", ".join(drives)}): name one with --drive')
    drive = drives[0]
    what = describe(drive)
    print(f'flash: probe drive {drive}' + (f' ({what})' if what else ''))
    name = 'pack.hex' if args.pack_only else 'facet-evkb.hex'
    started = time.time()
    target = os.path.join(drive, 'FACET.HEX')
    try:
        with open(target, 'w') as fh:
            fh.write(intel_hex(chunks))
            fh.flush()
            os.fsync(fh.fileno())
    except OSError as e:
        die(REFUSED, f'cannot write onto {drive}: {e}')
    print(f'flash: {name} copied onto {drive}; waiting up to {args.wait:g} s for the probe')
    fail = os.path.join(drive, 'FAIL.TXT')
    deadline = started + args.wait
    while time.time() < deadline:
        try:
            if os.path.getmtime(fail) >= started - 1:
                reason = open(fail, errors='replace').read().strip()
                die(REFUSED, f'the probe refused the image: {reason}')
        except OSError:
            pass
        time.sleep(0.2)
    print('flash: done — press RESET on the board (boot-mode switches at internal boot); the console: '
          'picocom -b 115200 /dev/ttyACM0')
    return 0


if __name__ == '__main__':
    sys.exit(main())
