#!/usr/bin/env python3
"""The viewer's UART session and the device side of the reliability findings (issue 12), on a
QEMU board, one check per finding:

  * bang_then_quit: after '!', a byte no command starts with is a key again: '!q' quits (the
    session used to wait in command mode for a newline until the runner's timeout);
  * odd_bytes_and_an_overlong_command: NUL, bytes over 0x7F, '!' then a control byte and a
    command longer than the line are dropped with their reasons; the session goes on;
  * shot_name_with_a_path: '!shot ../../name' is refused by the firmware with its reason, and
    nothing is written outside the run's folder (run.py checks the names it is given too:
    tests/tools/reliability_test.py screenshot_names_stay_in_the_folder);
  * corrupt_pack: a pack that fails validation gets its reason and exit 1, and no word of
    'nothing was loaded' (one was);
  * plate_of_1600_holes: the plate with 1,600 holes in one face is shown whole: every face
    tessellated on the device (its big faces have 11,204 points and 1,601 loops).

  session_test.py --board B --elf facet-viewer.elf --packer P --stress S --sample M --work DIR [--plain]
"""
import argparse
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import protocol  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    for a in ('--board', '--elf', '--packer', '--stress', '--sample', '--work'):
        ap.add_argument(a, required=True)
    ap.add_argument('--plain', action='store_true', help='plain packs (a board that reads them in place from flash)')
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    board = boards.load(args.board)
    occt = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')
    plain = ['--plain'] if args.plain else []

    def pack(step, name):
        fpk = os.path.join(args.work, name)
        subprocess.run([args.packer, step, '-o', fpk, '--quiet', *plain], check=True, capture_output=True, env=occt)
        return fpk

    sample_step = os.path.join(args.work, 'sample.step')
    subprocess.run([args.sample, sample_step], check=True, capture_output=True, env=occt)
    sample = pack(sample_step, 'sample.fpk')

    def session(name, fpk, *send, timeout=300):
        out = os.path.join(args.work, name)
        cmd = [sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board, '--elf', args.elf,
               '--out', out, '--load', f'{fpk}@{board["pack"]["address"]}', '--timeout', str(timeout), '--quiet']
        for s in send:
            cmd += ['--send', s]
        r = subprocess.run(cmd, capture_output=True, text=True)
        uart = open(os.path.join(out, 'uart.log')).read() if os.path.exists(os.path.join(out, 'uart.log')) else ''
        return r.returncode, uart, out

    problems = []

    code, uart, _ = session('bang-q', sample, 'keys !q', timeout=120)
    if code != 0 or "'!q' is not a command" not in uart or 'bye' not in uart:
        problems.append(f'bang_then_quit: exit {code}; the viewer did not take q as a key after !: {uart[-400:]}')

    # Odd bytes (NUL, bytes over 0x7F, a lone '!'-then-control) and a command longer than the
    # line buffer: each dropped with its reason, and the session still takes its keys.
    code, uart, _ = session('odd-bytes', sample, 'keys \\x00\\xff\\x80!\\x01', 'keys !shot ' + 'a' * 200, 'keys q', timeout=120)
    if code != 0 or 'command dropped: longer than 47 bytes' not in uart or 'viewer: command dropped' not in uart or 'bye' not in uart:
        problems.append(f'odd_bytes_and_an_overlong_command: exit {code}: {uart[-600:]}')

    code, uart, out = session('shot-path', sample, 'keys !shot ../../escaped\n', 'keys q', timeout=120)
    escaped = [p for p in (os.path.join(args.work, 'escaped.png'), os.path.join(os.path.dirname(args.work), 'escaped.png'))
               if os.path.exists(p)]
    if code != 0 or "a screenshot's name is letters, digits, - and _ only" not in uart or escaped:
        problems.append(f'shot_name_with_a_path: exit {code}, written outside: {escaped}; {uart[-400:]}')

    data = bytearray(open(sample, 'rb').read())
    data[len(data) // 2] ^= 0x40  # a bit flipped in the middle: the deflate stream or the CRC says so
    corrupt = os.path.join(args.work, 'corrupt.fpk')
    open(corrupt, 'wb').write(data)
    code, uart, _ = session('corrupt', corrupt, timeout=120)
    if code != 1 or 'viewer: no valid pack:' not in uart or 'nothing was loaded' in uart:
        problems.append(f'corrupt_pack: exit {code} (expected 1), the reason and no "nothing was loaded": {uart[-400:]}')

    holes_step = os.path.join(args.work, 'holes1600.step')
    subprocess.run([args.stress, 'holes', '1600', holes_step], check=True, capture_output=True, env=occt)
    holes = pack(holes_step, 'holes1600.fpk')
    code, uart, _ = session('holes1600', holes, 'keys q', timeout=900)
    t = protocol.first(uart, 'tessellation')
    kv = t.fields() if t else {}
    if code != 0 or not t or kv.get('faces') != 1606 or kv.get('failed') != 0:
        problems.append(f'plate_of_1600_holes: exit {code}, {t.line if t else "no @tessellation line"}: '
                        f'{"; ".join(l for l in uart.splitlines() if "failed" in l)[:400]}')
    else:
        print(f'{args.board}: the 1,600-hole plate: 1606 faces, 0 failed, {kv["triangles"]} triangles')

    for p in problems:
        print(f'FAIL {args.board}: {p}')
    if not problems:
        print(f'{args.board}: session and device checks pass')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
