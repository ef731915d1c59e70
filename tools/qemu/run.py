#!/usr/bin/env python3
"""facet QEMU runner: boots a firmware ELF on a QEMU board, headless, and reports.

  run.py --board qemu-versatilepb --elf build/qemu-versatilepb/firmware/facet-scene.elf \
         --out out/scene [--load model.fpk@0x01000000] [--icount] [--budget draw=20000000]

What it does:
  * starts qemu-system-arm for the board (versatilepb: -m 32M; mps2-an500: -m 16M), headless
    (-display none, audio to a null backend), semihosting on so the firmware's exit code is
    QEMU's exit code;
  * logs the UART to OUT/uart.log and echoes it (unless --quiet);
  * '@shot NAME' from the firmware: takes a PNG screendump over QMP into OUT/NAME.png and
    acknowledges over the UART; '@dump NAME FILE': converts a framebuffer the board wrote via
    semihosting (F565) into OUT/NAME.png;
  * --type TEXT: types TEXT into the UART at boot (C-style escapes allowed, e.g. 'r\\n');
  * --session NAME|FILE, --send ENTRY (repeatable): a scripted session (a file of
    tests/sessions, by name or path; tools/protocol.py reads it), then the entries; each time the
    firmware prints '@idle' the next entry is sent: 'keys TEXT' types TEXT (escapes allowed),
    'mouse DX DY [BUTTON]' drags the PS/2 mouse over QMP (button left/right/middle held during
    the move), 'move DX DY' moves it, 'press [BUTTON]' and 'release [BUTTON]' hold a button over
    the entries between them (a drag in steps, a frame at each) (docs/protocol.md);
  * runs the guest on a virtual clock, the board description's qemu.clock (-icount shift=0:
    the guest's timers count executed instructions, 1 ns each), so a firmware's clock is
    deterministic: its time-sliced steps repeatable, its frame times those of the 600 MHz
    target (boards/qemu-common/include/qemu/virtual_clock.h); --real-clock runs on the host's;
  * --icount: loads the facet-icount TCG plugin and names its numbered regions from the
    firmware's '@begin NAME' lines; --limit N stops any region over N instructions;
    --budget NAME=N fails the run if region NAME used more than N instructions;
  * enforces --timeout seconds of wall clock (exit 124);
  * writes OUT/report.json (exit code, regions with the region each is nested in, RAM by
    section, stack, screenshots);
  * --window opens a QEMU window instead of running headless, when a display exists.
Exit status: the firmware's exit code, or non-zero for a timeout, a budget or a runner error.
"""
import argparse
import json
import os
import re
import queue
import socket
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import board as boards  # noqa: E402
import img  # noqa: E402
import protocol  # noqa: E402

MHZ = 600



def safe_name(name):
    """A screenshot's or dump's name from the firmware: letters, digits, - and _ (no path)."""
    return re.fullmatch(r'[A-Za-z0-9_-]{1,64}', name) is not None

def qemu_board(name):
    """The machine and its options, from the board's description (boards/<board>/board.json)."""
    b = boards.load(name)
    return ['-M', b['qemu']['machine']] + b['qemu']['args']


def find_plugin():
    for build in ('host', 'host-asan'):
        p = os.path.join(ROOT, 'build', build, 'tools', 'qemu', 'icount', 'facet-icount.so')
        if os.path.exists(p):
            return p
    return None


def symbol_address(elf, name):
    out = subprocess.run(['arm-none-eabi-nm', elf], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16)
    raise SystemExit(f'run.py: symbol {name} not found in {elf}')


class Qmp:
    def __init__(self, path, timeout=10.0):
        deadline = time.time() + timeout
        while True:
            try:
                self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                self.sock.connect(path)
                break
            except OSError:
                if time.time() > deadline:
                    raise
                time.sleep(0.05)
        self.file = self.sock.makefile('rwb')
        self._read()  # greeting
        self.command('qmp_capabilities')

    def _read(self):
        while True:
            line = self.file.readline()
            if not line:
                raise RuntimeError('QMP connection closed')
            msg = json.loads(line)
            if 'event' not in msg:
                return msg

    def command(self, name, **args):
        self.file.write(json.dumps({'execute': name, 'arguments': args}).encode() + b'\n')
        self.file.flush()
        reply = self._read()
        if 'error' in reply:
            raise RuntimeError(f'QMP {name}: {reply["error"]}')
        return reply.get('return')


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--board', required=True, choices=boards.qemu_boards())
    ap.add_argument('--elf', required=True)
    ap.add_argument('--out', required=True, help='directory for uart.log, screenshots, report.json')
    ap.add_argument('--load', action='append', default=[], metavar='FILE@ADDR')
    ap.add_argument('--card', metavar='IMAGE', help="a memory card image (FAT) in the board's SD slot (board.json capabilities.card)")
    ap.add_argument('--type', default='', help='text typed into the UART at boot')
    ap.add_argument('--session', action='append', default=[], metavar='NAME|FILE',
                    help='a scripted session: tests/sessions/NAME.session or a file (before the --send entries)')
    ap.add_argument('--send', action='append', default=[], metavar='ENTRY',
                    help="sent at each '@idle': 'keys TEXT', 'mouse DX DY [left|right|middle]' or 'move DX DY'")
    ap.add_argument('--timeout', type=float, default=120)
    ap.add_argument('--icount', action='store_true', help='count instructions between markers')
    ap.add_argument('--real-clock', action='store_true',
                    help="the guest's timers on the host's clock, not the board's virtual clock")
    ap.add_argument('--limit', type=int, default=0, help='fail any region above N instructions')
    ap.add_argument('--budget', action='append', default=[], metavar='REGION=N')
    ap.add_argument('--profile', action='store_true',
                    help='with --icount: write OUT/profile.txt, instructions per function in regions')
    ap.add_argument('--profile-regions', metavar='A-B,C-D',
                    help='with --profile: only these regions, numbered in the order they begin')
    ap.add_argument('--window', action='store_true', help='open a QEMU window if a display exists')
    ap.add_argument('--quiet', action='store_true')
    args = ap.parse_args()
    script = []
    for name in args.session:
        path = name if os.path.sep in name or name.endswith('.session') else protocol.session_path(name)
        try:
            script += protocol.read_session(path, args.board)
        except (OSError, ValueError) as e:
            ap.error(f'--session {name}: {e}')
    script += args.send

    elf = os.path.abspath(args.elf)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    qmp_path = os.path.join(out, 'qmp.sock')
    if os.path.exists(qmp_path):
        os.unlink(qmp_path)
    plugin_log = os.path.join(out, 'icount.log')
    if os.path.exists(plugin_log):
        os.unlink(plugin_log)

    cmd = ['qemu-system-arm'] + qemu_board(args.board) + [
        '-kernel', elf, '-serial', 'stdio', '-monitor', 'none',
        '-semihosting-config', 'enable=on,target=native',
        '-qmp', f'unix:{qmp_path},server=on,wait=off', '-no-reboot']
    window = args.window and (os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY'))
    if args.window and not window:
        print('run.py: no display found; running headless', file=sys.stderr)
    cmd += [] if window else ['-display', 'none']
    if not args.real_clock:
        cmd += boards.load(args.board)['qemu'].get('clock', [])
    for spec in args.load:
        path, _, addr = spec.rpartition('@')
        if not path or not addr:
            raise SystemExit(f'run.py: --load wants FILE@ADDR, got {spec}')
        cmd += ['-device', f'loader,file={os.path.abspath(path)},addr={addr},force-raw=on']
    card_at = os.path.join(out, 'facet-card.img')  # a semihosted card's image (an earlier run's removed)
    if os.path.lexists(card_at):
        os.remove(card_at)
    if args.card:
        if not boards.can(args.board, 'card'):
            raise SystemExit(f'run.py: {args.board} has no memory card slot (board.json capabilities.card)')
        if not os.path.isfile(args.card):
            raise SystemExit(f'run.py: no card image {args.card}')
        if boards.can(args.board, 'card_swap'):  # an SD slot QEMU emulates
            cmd += ['-drive', f'if=sd,format=raw,id=card,file={os.path.abspath(args.card)}']
        else:  # read through semihosting from QEMU's working directory (boards/qemu-common/card_semihosted.h)
            os.symlink(os.path.abspath(args.card), card_at)
    if args.icount:
        plugin = find_plugin()
        if not plugin:
            raise SystemExit('run.py: facet-icount.so not built (build the host preset first)')
        begin, end = symbol_address(elf, 'facet_mark_begin'), symbol_address(elf, 'facet_mark_end')
        parg = f'{plugin},begin={begin:#x},end={end:#x}'
        if args.limit:
            parg += f',limit={args.limit}'
        if args.profile:
            parg += f',profile={os.path.join(out, "profile.raw")}'
            if args.profile_regions:
                parg += ',profile_regions=' + args.profile_regions.replace(',', ':')
        cmd += ['-plugin', parg, '-d', 'plugin', '-D', plugin_log]

    budgets = {}
    for b in args.budget:
        name, _, n = b.partition('=')
        budgets[name] = int(n)

    proc = subprocess.Popen(cmd, cwd=out, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    lines = queue.Queue()

    def pump(stream, tag):
        for raw in iter(stream.readline, b''):
            lines.put((tag, raw.decode('utf-8', 'replace').rstrip('\r\n')))
        lines.put((tag, None))

    threading.Thread(target=pump, args=(proc.stdout, 'uart'), daemon=True).start()
    threading.Thread(target=pump, args=(proc.stderr, 'qemu'), daemon=True).start()
    if window and not script:
        # An interactive session: the terminal's keys go to the UART (the mouse is the window's).
        def forward():
            for chunk in iter(lambda: os.read(sys.stdin.fileno(), 64), b''):
                try:
                    proc.stdin.write(chunk)
                    proc.stdin.flush()
                except OSError:
                    return
        threading.Thread(target=forward, daemon=True).start()
    if args.type:
        proc.stdin.write(args.type.encode().decode('unicode_escape').encode('latin-1'))
        proc.stdin.flush()

    def send(data):
        # The firmware may exit on the input just sent (a quit key): QEMU then closes its end
        # of the pipe, and a write that was already on its way fails with EPIPE. That alone is
        # no failure -- QEMU's exit code and the script entries left unsent say what went wrong.
        try:
            proc.stdin.write(data)
            proc.stdin.flush()
        except OSError as e:
            report['uart_closed'] = str(e)

    qmp = None
    report = {'board': args.board, 'elf': os.path.relpath(elf, ROOT), 'regions': [], 'ram': {},
              'shots': [], 'exit_code': None, 'failures': []}
    begins, parents, open_regions = [], [], []  # region names in the order they begin; nesting
    log = open(os.path.join(out, 'uart.log'), 'w')
    deadline = time.time() + args.timeout
    open_streams, timed_out = 2, False
    while open_streams:
        remaining = deadline - time.time()
        if remaining <= 0:
            timed_out = True
            break
        try:
            tag, line = lines.get(timeout=min(remaining, 0.5))
        except queue.Empty:
            continue
        if line is None:
            open_streams -= 1
            continue
        if tag == 'qemu':
            print(f'[qemu] {line}', file=sys.stderr)
            log.write(f'[qemu] {line}\n')
            continue
        log.write(line + '\n')
        log.flush()
        if not args.quiet:
            print(line, flush=True)
        rec = protocol.parse(line)
        if rec is None:
            continue
        if rec.name == 'idle':
            # Each entry ends with ENQ (0x05) on the UART: the firmware says '@idle' again only
            # once it has handled everything before it (mouse packets are polled first).
            if script:
                entry = script.pop(0)
                kind, _, rest = entry.partition(' ')
                enq = protocol.ENQ
                if kind == 'keys':
                    # The keys and their ENQ in one write: a quit key may end QEMU at once.
                    send(rest.encode().decode('unicode_escape').encode('latin-1') + enq)
                    enq = b''
                elif kind == 'mouse':
                    p = rest.split()
                    button = p[2] if len(p) > 2 else 'left'
                    try:
                        if qmp is None:
                            qmp = Qmp(qmp_path)
                        press = lambda down: {'type': 'btn', 'data': {'down': down, 'button': button}}
                        qmp.command('input-send-event', events=[press(True)])
                        qmp.command('input-send-event', events=[
                            {'type': 'rel', 'data': {'axis': 'x', 'value': int(p[0])}},
                            {'type': 'rel', 'data': {'axis': 'y', 'value': int(p[1])}}])
                        qmp.command('input-send-event', events=[press(False)])
                    except (OSError, RuntimeError, IndexError, ValueError) as e:
                        report['failures'].append(f'mouse {rest}: {e}')
                elif kind in ('press', 'release'):  # a button held over the entries between (a drag in steps)
                    try:
                        if qmp is None:
                            qmp = Qmp(qmp_path)
                        qmp.command('input-send-event', events=[
                            {'type': 'btn', 'data': {'down': kind == 'press', 'button': rest.strip() or 'left'}}])
                    except (OSError, RuntimeError, ValueError) as e:
                        report['failures'].append(f'{kind} {rest}: {e}')
                elif kind == 'move':  # the pointer alone (a drag while a button is pressed)
                    p = rest.split()
                    try:
                        if qmp is None:
                            qmp = Qmp(qmp_path)
                        qmp.command('input-send-event', events=[
                            {'type': 'rel', 'data': {'axis': 'x', 'value': int(p[0])}},
                            {'type': 'rel', 'data': {'axis': 'y', 'value': int(p[1])}}])
                    except (OSError, RuntimeError, IndexError, ValueError) as e:
                        report['failures'].append(f'move {rest}: {e}')
                elif kind == 'card':  # the card pulled out or put back (QEMU's removable medium)
                    try:
                        if qmp is None:
                            qmp = Qmp(qmp_path)
                        if not args.card:
                            raise ValueError('no --card')
                        if not boards.can(args.board, 'card_swap'):
                            raise ValueError(f'the card of {args.board} cannot be pulled (board.json capabilities.card_swap)')
                        if rest.strip() == 'out':
                            qmp.command('eject', device='card', force=True)
                        else:
                            qmp.command('blockdev-change-medium', device='card', filename=os.path.abspath(args.card), format='raw')
                    except (OSError, RuntimeError, ValueError) as e:
                        report['failures'].append(f'card {rest}: {e}')
                else:
                    report['failures'].append(f'unknown script entry: {entry}')
                if enq:
                    send(enq)
            continue
        try:
            v = rec.values()  # (the table of tools/protocol.py)
        except ValueError as e:
            report['failures'].append(str(e))
            continue
        if rec.name in ('shot', 'dump') and not all(safe_name(w.removesuffix('.f565')) for w in rec.words):
            # The name becomes a file in OUT: never a path (a firmware could print anything).
            report['failures'].append(f'{rec.line!r}: not a file name (letters, digits, - and _ only); ignored')
            if rec.name == 'shot':
                send(protocol.ACK)
        elif rec.name == 'shot':
            name = v['name']
            try:
                if qmp is None:
                    qmp = Qmp(qmp_path)
                png = os.path.join(out, f'{name}.png')
                qmp.command('screendump', filename=png, format='png')
                report['shots'].append(os.path.relpath(png, ROOT))
            except (OSError, RuntimeError) as e:
                report['failures'].append(f'screendump {name}: {e}')
            send(protocol.ACK)
        elif rec.name == 'dump':
            png = os.path.join(out, f'{v["name"]}.png')
            try:
                img.f565_to_png(os.path.join(out, v['file']), png)
                report['shots'].append(os.path.relpath(png, ROOT))
            except (OSError, ValueError) as e:
                report['failures'].append(f'dump {v["name"]}: {e}')
        elif rec.name == 'begin':
            parents.append(open_regions[-1] if open_regions else None)
            open_regions.append(len(begins))
            begins.append(str(v['region']))
        elif rec.name == 'end' and open_regions:
            open_regions.pop()
        elif rec.name == 'ram':
            report['ram'][str(v['name'])] = v['bytes']
        elif rec.name == 'stack':
            report['stack_used'], report['stack_size'] = v['used'], v['size']
        elif rec.name == 'tessellation':
            report['model'] = {'faces': v['faces'], 'faces_failed': v['failed'], 'triangles': v['triangles'],
                               'mesh_bytes': v['mesh_bytes']}
        elif rec.name == 'pick' and v.get('hit') == 1:
            report.setdefault('picks', []).append({'face': v['face'], 'instance': v['instance'], 'lines': []})
        elif rec.name == 'measure' and report.get('picks'):
            report['picks'][-1]['lines'].append(v['text'])  # the picked faces' exact values
        elif rec.name == 'memory':
            report['memory'] = v
        elif rec.name == 'expect':
            report.setdefault('expect', {})[str(v['region'])] = v['instructions']

    if timed_out:
        proc.kill()
        report['failures'].append(f'timeout after {args.timeout:g} s')
    try:
        code = proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        code = proc.wait()
    report['exit_code'] = code
    if script and not timed_out:
        report['failures'].append(f'{len(script)} script entries never sent (the firmware stopped '
                                  f'asking for input): {script}')

    if args.icount:
        counts = {}
        if os.path.exists(plugin_log):
            for l in open(plugin_log):
                p = l.split()
                if l.startswith('facet-icount: region') and len(p) >= 7:
                    counts[int(p[2])] = int(p[6])
                elif l.startswith('facet-icount:'):
                    report['failures'].append(l.strip())
        for i, name in enumerate(begins):
            n = counts.get(i)
            report['regions'].append({'name': name, 'instructions': n, 'parent': parents[i],
                                      'ms_at_600mhz': None if n is None else round(n / (MHZ * 1000), 3)})
            if n is not None and name in budgets and n > budgets[name]:
                report['failures'].append(f'region {name}: {n} instructions, budget {budgets[name]}')
        for r in report['regions']:
            n = r['instructions']
            shown = 'not counted' if n is None else f'{n:,} instructions = {n / (MHZ * 1000):.3f} ms at {MHZ} MHz'
            print(f'icount {r["name"]}: {shown}')
    for k, v in report.get('expect', {}).items():
        got = next((r['instructions'] for r in report['regions'] if r['name'] == k), None)
        if got != v:
            report['failures'].append(f'region {k}: expected exactly {v} instructions, got {got}')
    if args.icount and args.profile and os.path.exists(os.path.join(out, 'profile.raw')):
        prof = subprocess.run([sys.executable, os.path.join(HERE, 'profile.py'), elf,
                               os.path.join(out, 'profile.raw')], capture_output=True, text=True).stdout
        with open(os.path.join(out, 'profile.txt'), 'w') as f:
            f.write(prof)
        print(f'profile: {os.path.relpath(os.path.join(out, "profile.txt"))}')
    if report['ram']:
        budget = boards.bytes_of(boards.load(args.board)['ram_budget'])
        print(f'RAM: {report["ram"].get("total", 0):,} bytes in use of the board\'s {budget:,}')
    if os.path.exists(qmp_path):
        os.unlink(qmp_path)
    with open(os.path.join(out, 'report.json'), 'w') as f:
        json.dump(report, f, indent=2)
    for msg in report['failures']:
        print(f'run.py: FAIL: {msg}', file=sys.stderr)
    if timed_out:
        return 124
    if report['failures'] and code == 0:
        return 1
    return code


if __name__ == '__main__':
    sys.exit(main())
