"""The benches' one way to show a pack on a board in QEMU: the viewer firmware booted with the
pack at the board's pack address, a scripted session, exact instruction counts (facet-icount),
and what the run left: its report, its UART log, its exit code. Used by device.py and scale.py."""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def last_error(r):
    """A tool's last line on stderr (its message), or its exit code."""
    return (r.stderr.strip().splitlines() or [f'exit {r.returncode}'])[-1]


def boot(board, elf, fpk, out, session, timeout, card=None):
    """(report, uart log, exit code) of the run, or (None, None, why) when there is none: a pack
    over the board's pack region, a runner that wrote no report. `board` as tools/board.py loads it.
    card: a memory card image holding the pack instead (the board's SD slot; nothing loaded)."""
    size = os.path.getsize(fpk)
    if card is None and size > board['pack_bytes']:
        return None, None, f'pack file {size:,} B > the board\'s pack region {board["pack_bytes"]:,} B'
    sends = [x for s in session for x in ('--send', s)]
    source = ['--card', card] if card else ['--load', f'{fpk}@{board["pack"]["address"]}']
    r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', board['name'],
                        '--elf', elf, '--out', out, '--icount', '--timeout', str(timeout), '--quiet'] + source + sends,
                       capture_output=True, text=True)
    rep_path = os.path.join(out, 'report.json')
    if not os.path.exists(rep_path):
        return None, None, f'the runner wrote no report (exit {r.returncode})'
    return json.load(open(rep_path)), open(os.path.join(out, 'uart.log'), errors='replace').read(), r.returncode


def exit_note(code):
    return f'exit {code}' + (' (timeout)' if code == 124 else '')
