#!/usr/bin/env python3
"""Models on a memory card in QEMU (issue 51): two shared models packed onto a FAT32 card image
(tools/card.py: mkfs.fat and mcopy, as a PC makes it) with a truncated pack, a file that is no
pack and a subfolder beside them, in the board's SD slot, or read through semihosting on a
board without one (run.py --card).

  1. The viewer lists the card's pack files (@card: names, sizes, faces), opens the first and,
     with the library session's input, the second from the chooser: the same pixels as the same
     two packs loaded into RAM as a library (the status bar's frame time aside).
  2. The card pulled and put back (tests/sessions/card-swap.session; a board whose card QEMU
     can pull: board.json capabilities.card_swap): the model stays on screen, the chooser says
     the card is gone; back, the truncated file is said and the first model comes back, then the
     second opens.
  3. An exFAT card (its boot sector) with the models in RAM beside it: said ("format it FAT32"),
     and the models in RAM open.

  card_test.py --board B --elf ELF --packer facet-pack --work DIR MODEL.step MODEL.step
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import card  # noqa: E402
import img  # noqa: E402
import protocol  # noqa: E402


def faces_of(packer, fpk):
    out = subprocess.run([packer, '--check', fpk], capture_output=True, text=True, check=True).stdout
    return int(re.search(r'valid pack, (\d+) faces', out).group(1))


def boot(args, out, session, extra):
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board, '--elf', args.elf,
                        '--out', out, '--timeout', '600', '--quiet', '--session', session] + extra, capture_output=True, text=True)
    uart = open(os.path.join(out, 'uart.log')).read() if os.path.exists(os.path.join(out, 'uart.log')) else ''
    return r.returncode, uart, r.stdout + r.stderr


def same(problems, a_dir, b_dir, name, what):
    a, b = os.path.join(a_dir, name + '.png'), os.path.join(b_dir, name + '.png')
    if not (os.path.exists(a) and os.path.exists(b)):
        problems.append(f'{what}: a screenshot {name} is missing')
        return
    w, h, _ = img.load_565(a)
    d, msg = img.compare(a, b, os.path.join(os.path.dirname(a_dir), f'{name}-diff.png'), ignore=[img.frame_time_field(w, h)])
    if d:
        problems.append(f'{what}: {name} differs: {msg}')


def main():
    ap = argparse.ArgumentParser()
    for a in ('--board', '--elf', '--packer', '--work'):
        ap.add_argument(a, required=True)
    ap.add_argument('models', nargs=2)
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board = boards.load(args.board)
    packs = []
    for i, m in enumerate(args.models):
        fpk = os.path.join(args.work, f'model-{i + 1}.fpk')
        subprocess.run([args.packer, m, '-o', fpk, '--quiet'], check=True, capture_output=True,
                       env=dict(os.environ, ASAN_OPTIONS='detect_leaks=0'))
        packs.append(fpk)
    faces = [faces_of(args.packer, p) for p in packs]
    truncated = os.path.join(args.work, 'truncated.fpk')
    data = open(packs[1], 'rb').read()
    open(truncated, 'wb').write(data[:len(data) * 2 // 3])
    notes = os.path.join(args.work, 'notes.fpk')
    open(notes, 'w').write('not a pack: a technician\'s notes\n' * 40)
    names = [os.path.splitext(os.path.basename(m))[0] + '.fpk' for m in args.models]
    image = os.path.join(args.work, 'card.img')
    card.make(image, [(packs[0], names[0]), (packs[1], names[1]), (truncated, 'Truncated copy.fpk'), (notes, 'notes.fpk'),
                      (packs[0], 'old/' + names[0])])
    problems = []

    # 1. From the card, with the library session's input; then the same packs as a library in RAM.
    on_card = os.path.join(args.work, 'card')
    code, uart, said = boot(args, on_card, 'library', ['--card', image])
    listed = [(r.values()['name'], r.values()['faces']) for r in protocol.records(uart, 'card')]
    opened = [r.values()['faces'] for r in protocol.records(uart, 'model')]
    if code != 0:
        problems.append(f'from the card: the viewer exited {code}: {said.strip()[-300:]}')
    want = [(names[0], faces[0]), (names[1], faces[1]), ('Truncated copy.fpk', None), ('notes.fpk', 0)]
    if [n for n, _ in listed] != [n for n, _ in want] or [f for f, (_, w) in zip([f for _, f in listed], want) if w is not None and f != w]:
        problems.append(f'the card lists {listed}, not {want} (the truncated file\'s faces from its index)')
    if opened != faces:
        problems.append(f'from the card: models opened with {opened} faces, not {faces}')
    lib = os.path.join(args.work, 'library.flb')
    subprocess.run([args.packer, '--library', lib] + packs + ['--quiet'], check=True)
    in_ram = os.path.join(args.work, 'ram')
    code, uart_ram, said = boot(args, in_ram, 'library', ['--load', f'{lib}@{board["pack"]["address"]}'])
    if code != 0:
        problems.append(f'from RAM: the viewer exited {code}: {said.strip()[-300:]}')
    for n in ('turned', 'second'):
        same(problems, on_card, in_ram, n, 'card and RAM')

    # 2. Pulled and put back (a board whose card QEMU can pull: a semihosted image cannot be).
    swap = os.path.join(args.work, 'swap')
    if not boards.can(args.board, 'card_swap'):
        print(f'card_test: {args.board}\'s card cannot be pulled (board.json capabilities.card_swap): no swap')
    else:
        code, uart, said = boot(args, swap, 'card-swap', ['--card', image])
        changes = [r.values()['state'] for r in protocol.records(uart, 'card_changed')]
        failed = [r.values()['model'] for r in protocol.records(uart, 'model_failed')]
        opened = [r.values()['faces'] for r in protocol.records(uart, 'model')]
        if code != 0:
            problems.append(f'the swap: the viewer exited {code}: {said.strip()[-300:]}')
        if changes != ['removed', 'inserted']:
            problems.append(f'the swap: the card was seen {changes}, not removed then inserted')
        same(problems, swap, swap, 'before', 'the swap')
        a, b = os.path.join(swap, 'before.png'), os.path.join(swap, 'pulled.png')
        if os.path.exists(a) and os.path.exists(b):
            w, h, _ = img.load_565(a)
            d, msg = img.compare(a, b, ignore=[img.frame_time_field(w, h)])
            if d:
                problems.append(f'the model did not stay on screen when the card was pulled: {msg}')
        else:
            problems.append('the swap: a screenshot is missing (before, pulled)')
        if failed != [3]:
            problems.append(f'the swap: the truncated file was not said (model_failed {failed})')
        if opened != [faces[0], faces[0], faces[1]]:
            problems.append(f'the swap: models opened with {opened} faces, not the first, the first again, the second')
        for n in ('chooser-out', 'chooser-back', 'after'):
            if not os.path.exists(os.path.join(swap, n + '.png')):
                problems.append(f'the swap: no screenshot {n}')
    # 3. A card the reader cannot take: said, and the pack where the board loads it opens.
    exfat = os.path.join(args.work, 'exfat.img')
    with open(exfat, 'wb') as f:
        boot_sector = bytearray(512)
        boot_sector[0:3] = b'\xEB\x76\x90'
        boot_sector[3:11] = b'EXFAT   '
        boot_sector[510:512] = b'\x55\xAA'
        f.write(boot_sector)
        f.truncate(64 << 20)
    other = os.path.join(args.work, 'exfat')
    code, uart_x, said = boot(args, other, 'library', ['--card', exfat, '--load', f'{lib}@{board["pack"]["address"]}'])
    if 'the card cannot be read' not in uart_x or 'exFAT' not in uart_x:
        problems.append('an exFAT card was not said ("the card cannot be read ... exFAT")')
    if code != 0 or [r.values()['faces'] for r in protocol.records(uart_x, 'model')] != faces:
        problems.append(f'with an exFAT card in the slot the models in RAM did not open (exit {code})')
    if problems:
        print(f'FAIL {args.board} card: ' + '; '.join(problems))
        print(uart[-1500:])
        return 1
    print(f'{args.board} card: {len(listed)} files listed; two models opened from the card with the pixels they have from RAM; '
          f'pulled and put back: the model stayed, a truncated file said, the others opened; an exFAT card said '
          f'({faces} faces)')
    return 0


if __name__ == '__main__':
    sys.exit(main())
