#!/usr/bin/env python3
"""The MIMXRT1060-EVKB flash image, read back as the i.MX RT1062 boot ROM reads it
(IMXRT1060RM, chapter "System Boot"), field by field against this test's own tables:

  * FlexSPI NOR configuration block at +0x0000: tag 'FCFB', version 1.4.0, quad pads, the
    IS25WP064A's size, the read sequence (0xEB, 24-bit address on 4 pads, 6 dummy, read on 4);
  * IVT at +0x1000: header (tag 0xD1, length 0x20, version 0x41), entry = the vector table,
    DCD and boot-data pointers, self, no CSF;
  * boot data at +0x1020: start = the flash base, size covering the whole image;
  * DCD at +0x1030: its header and every command (write, check) against the expected
    register/value table below, each with its reference-manual chapter;
  * vector table at +0x2000: initial SP in DTCM, 8-byte aligned; reset and every handler a
    Thumb address inside the image;
  * the .hex holds exactly the .bin's bytes at 0x60000000; the image ends before the pack region.

  evkb_image_test.py --elf facet-viewer.elf --bin facet-viewer.bin --hex facet-viewer.hex
"""
import argparse
import os
import struct
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402

FLASH = 0x60000000
CCM, ANALOG, IOMUXC, SEMC = 0x400FC000, 0x400D8000, 0x401F8000, 0x402F0000
RM_CCM = 'RM ch. Clock Controller Module (CCM)'
RM_IOMUXC = 'RM ch. IOMUX Controller (IOMUXC)'
RM_SEMC = 'RM ch. Smart External Memory Controller (SEMC)'


def expected_dcd():
    """(kind, register name, address, value, reference) in the order the ROM must run them:
    the SDRAM bring-up of NXP's SDK for this board (evkbmimxrt1060 dcd.c)."""
    w = []
    for n in range(7):
        w.append(('write', f'CCM_CCGR{n}', CCM + 0x68 + 4 * n, 0xFFFFFFFF, RM_CCM + ': all module clocks on'))
    w += [
        ('write', 'CCM_ANALOG_PLL_SYS', ANALOG + 0x30, 0x00002001, RM_CCM + ' (analog): PLL2 enabled, 528 MHz'),
        ('write', 'CCM_ANALOG_PFD_528', ANALOG + 0x100, 0x101D101B, RM_CCM + ' (analog): PFD2_FRAC 29 -> 327.7 MHz'),
        ('write', 'CCM_CBCDR', CCM + 0x14, 0x00010D40, RM_CCM + ': SEMC from PLL2 PFD2 / 2, AHB_PODF 3, IPG_PODF 1'),
    ]
    for n in range(40):
        w.append(('write', f'IOMUXC_SW_MUX_CTL_PAD_GPIO_EMC_{n:02d}', IOMUXC + 0x14 + 4 * n, 0x10 if n == 39 else 0,
                  RM_IOMUXC + (': SEMC_DQS, SION' if n == 39 else ': ALT0, SEMC')))
    for n in range(40):
        w.append(('write', f'IOMUXC_SW_PAD_CTL_PAD_GPIO_EMC_{n:02d}', IOMUXC + 0x204 + 4 * n, 0x110F9,
                  RM_IOMUXC + ': hysteresis, keeper, 200 MHz, R0/7, fast slew'))
    regs = [('SEMC_MCR', 0x00, 0x10000004), ('SEMC_BMCR0', 0x08, 0x81), ('SEMC_BMCR1', 0x0C, 0x81),
            ('SEMC_BR0', 0x10, 0x8000001B), ('SEMC_BR1', 0x14, 0x8200001B), ('SEMC_BR2', 0x18, 0x8400001B),
            ('SEMC_BR3', 0x1C, 0x8600001B), ('SEMC_BR4', 0x20, 0x90000021), ('SEMC_BR5', 0x24, 0xA0000019),
            ('SEMC_BR6', 0x28, 0xA8000017), ('SEMC_BR7', 0x2C, 0xA900001B), ('SEMC_BR8', 0x30, 0x21),
            ('SEMC_IOCR', 0x04, 0x79A8), ('SEMC_SDRAMCR0', 0x40, 0xF31), ('SEMC_SDRAMCR1', 0x44, 0x652922),
            ('SEMC_SDRAMCR2', 0x48, 0x10920), ('SEMC_SDRAMCR3', 0x4C, 0x50210A08), ('SEMC_DBICR0', 0x80, 0x21),
            ('SEMC_DBICR1', 0x84, 0x888888), ('SEMC_IPCR1', 0x94, 0x2), ('SEMC_IPCR2', 0x98, 0x0)]
    w += [('write', n, SEMC + o, v, RM_SEMC + ': SDRAM controller set-up') for n, o, v in regs]

    def ip(command, what):
        return [('write', 'SEMC_IPCR0', SEMC + 0x90, 0x80000000, RM_SEMC + ': IP command address 0x80000000'),
                ('write', 'SEMC_IPCMD', SEMC + 0x9C, 0xA55A0000 | command, RM_SEMC + ': ' + what),
                ('check', 'SEMC_INTR', SEMC + 0x3C, 0x1, RM_SEMC + ': wait for IPCMDDONE')]
    w += ip(0xF, 'SDRAM precharge all')
    w += ip(0xC, 'SDRAM auto-refresh')
    w += ip(0xC, 'SDRAM auto-refresh')
    w.append(('write', 'SEMC_IPTXDAT', SEMC + 0xA0, 0x33, RM_SEMC + ': mode register: burst 8, CAS latency 3'))
    w += ip(0xA, 'SDRAM mode register set')
    w.append(('write', 'SEMC_SDRAMCR3', SEMC + 0x4C, 0x50210A09, RM_SEMC + ': auto-refresh on (REN)'))
    return w


def parse_dcd(data):
    """The DCD at `data` as (kind, address, value) commands; raises on a malformed one."""
    if data[0] != 0xD2:
        raise ValueError(f'DCD tag {data[0]:#x}, not 0xD2')
    length = struct.unpack('>H', data[1:3])[0]
    if data[3] not in (0x40, 0x41):
        raise ValueError(f'DCD version {data[3]:#x}')
    at, out = 4, []
    while at < length:
        tag, n, param = data[at], struct.unpack('>H', data[at + 1:at + 3])[0], data[at + 3]
        if tag == 0xCC:
            if param != 0x04:
                raise ValueError(f'write command at {at}: parameter {param:#x}, not 0x04 (32-bit writes)')
            for k in range(at + 4, at + n, 8):
                out.append(('write',) + struct.unpack('>II', data[k:k + 8]))
        elif tag == 0xCF:
            if n != 12 or param != 0x1C:
                raise ValueError(f'check command at {at}: length {n}, parameter {param:#x} (want 12, 0x1C)')
            out.append(('check',) + struct.unpack('>II', data[at + 4:at + 12]))
        else:
            raise ValueError(f'unknown DCD command tag {tag:#x} at {at}')
        at += n
    if at != length:
        raise ValueError(f'DCD commands end at {at}, header says {length}')
    return length, out


def symbols(elf):
    out = subprocess.run(['arm-none-eabi-nm', elf], capture_output=True, text=True, check=True).stdout
    return {p[2]: int(p[0], 16) for p in (l.split() for l in out.splitlines()) if len(p) == 3}


def read_hex(path):
    mem, base = {}, 0
    for line in open(path):
        line = line.strip()
        if not line.startswith(':'):
            continue
        rec = bytes.fromhex(line[1:])
        if sum(rec) & 0xFF:
            raise ValueError(f'bad checksum: {line}')
        n, addr, kind, data = rec[0], (rec[1] << 8) | rec[2], rec[3], rec[4:4 + rec[0]]
        if kind == 0:
            for i, b in enumerate(data):
                mem[base + addr + i] = b
        elif kind == 4:
            base = int.from_bytes(data, 'big') << 16
        elif kind == 2:
            base = int.from_bytes(data, 'big') << 4
    return mem


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--elf', required=True)
    ap.add_argument('--bin', required=True)
    ap.add_argument('--hex', required=True)
    args = ap.parse_args()
    img = open(args.bin, 'rb').read()
    b = boards.load('mimxrt1060-evkb')
    flash_room = next(boards.bytes_of(m['bytes']) for m in b['memory'] if m['name'] == 'FLASH')
    dtcm = next((boards.bytes_of(m['origin']), boards.bytes_of(m['bytes'])) for m in b['memory'] if m['name'] == 'DTCM')
    bad = []

    def check(ok, what):
        print(('ok   ' if ok else 'FAIL ') + what)
        if not ok:
            bad.append(what)

    u32 = lambda off: struct.unpack_from('<I', img, off)[0]  # noqa: E731
    # FlexSPI configuration block.
    check(img[0:4] == b'FCFB', 'FCB tag "FCFB"')
    check(u32(4) == 0x56010400, f'FCB version 0x56010400 (V1.4.0): {u32(4):#x}')
    check(img[0x0C] == 1, 'FCB readSampleClkSrc 1 (loopback from the DQS pad)')
    check(img[0x0D] == 3 and img[0x0E] == 3, 'FCB CS hold and setup times 3')
    check(img[0x44] == 1 and img[0x45] == 4, 'FCB device type 1 (serial NOR), 4 pads')
    check(1 <= img[0x46] <= 6, f'FCB serial clock code {img[0x46]} (at most 6: 100 MHz, the 6-dummy-cycle limit)')
    check(u32(0x50) == 8 << 20, f'FCB flash A1 size 8 MiB (IS25WP064A): {u32(0x50)}')

    def lut(word):
        return [((word >> s) >> 10 & 0x3F, (word >> s) >> 8 & 3, (word >> s) & 0xFF) for s in (0, 16)]
    seq0 = lut(u32(0x80)) + lut(u32(0x84))
    check(seq0 == [(0x01, 0, 0xEB), (0x02, 2, 0x18), (0x0C, 2, 6), (0x09, 2, 4)],
          f'FCB read sequence: CMD 0xEB (1 pad), 24-bit address (4 pads), 6 dummy cycles, read (4 pads): {seq0}')
    check(u32(0x1C0) == 256 and u32(0x1C4) == 4096, 'FCB page 256 B, sector 4 KiB')

    # IVT and boot data.
    syms = symbols(args.elf)
    vectors = syms.get('__vectors_start', 0)
    hdr, entry, r1, dcd, boot, self_, csf, r2 = struct.unpack_from('<8I', img, 0x1000)
    check(hdr == 0x412000D1, f'IVT header: tag 0xD1, length 0x0020, version 0x41: {hdr:#x}')
    check(entry == vectors == FLASH + 0x2000, f'IVT entry = the vector table at 0x60002000: {entry:#x}')
    check(r1 == 0 and r2 == 0 and csf == 0, 'IVT reserved words and CSF are 0')
    check(self_ == FLASH + 0x1000, f'IVT self 0x60001000: {self_:#x}')
    check(boot == FLASH + 0x1020, f'IVT boot data at 0x60001020: {boot:#x}')
    check(dcd == FLASH + 0x1030, f'IVT DCD at 0x60001030: {dcd:#x}')
    start, size, plugin = struct.unpack_from('<3I', img, 0x1020)
    check(start == FLASH, f'boot data start 0x60000000: {start:#x}')
    check(len(img) <= size <= flash_room, f'boot data size {size:,} covers the image ({len(img):,} B) within its 1 MiB')
    check(plugin == 0, 'boot data: not a plugin')

    # DCD.
    try:
        length, cmds = parse_dcd(img[0x1030:0x2000])
        check(0x1030 + length <= 0x2000, f'DCD ({length} B) ends before the vector table')
        want = expected_dcd()
        check(len(cmds) == len(want), f'DCD: {len(cmds)} commands, {len(want)} expected')
        for i, (got, exp) in enumerate(zip(cmds, want)):
            kind, name, address, value, ref = exp
            if got != (kind, address, value):
                check(False, f'DCD command {i}: {got[0]} {got[1]:#010x} = {got[2]:#x}; expected {kind} {name} '
                             f'({address:#010x}) = {value:#x} [{ref}]')
        if not any('DCD command' in b for b in bad):
            check(True, f'DCD: all {len(cmds)} writes and checks as expected (CCM, IOMUXC EMC pads, SEMC, SDRAM init)')
    except ValueError as e:
        check(False, f'DCD malformed: {e}')

    # Vector table.
    sp, *handlers = struct.unpack_from('<16I', img, 0x2000)
    check(dtcm[0] < sp <= dtcm[0] + dtcm[1] and sp % 8 == 0, f'initial SP {sp:#x} in DTCM, 8-byte aligned')
    image_end = FLASH + len(img)
    inside = lambda a: a & 1 and FLASH + 0x2000 <= (a & ~1) < image_end  # noqa: E731
    used = [h for i, h in enumerate(handlers) if i + 1 not in (7, 8, 9, 10, 13)]  # reserved slots
    check(inside(handlers[0]) and syms.get('Reset_Handler') == handlers[0] & ~1,
          f'reset handler {handlers[0]:#x}: Reset_Handler, Thumb, inside the image')
    check(all(inside(h) for h in used), 'every system handler is a Thumb address inside the image')

    # The .hex: the .bin's bytes at 0x60000000, nothing elsewhere; the pack region untouched.
    mem = read_hex(args.hex)
    # Between sections (alignment) the .bin has zeros and the .hex nothing: padding, never run.
    check(min(mem) == FLASH and max(mem) == image_end - 1 and all(mem.get(FLASH + i, 0) == img[i] for i in range(len(img))),
          '.hex holds exactly the .bin at 0x60000000 (its gaps: the .bin\'s zero padding between sections)')
    check(image_end <= b['pack_address'], f'the image ends ({image_end:#x}) before the pack region ({b["pack_address"]:#x})')
    print(f'evkb image: {len(img):,} bytes; {len(bad)} problem(s)')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
