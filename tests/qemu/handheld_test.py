#!/usr/bin/env python3
"""The handheld's features in a scripted QEMU session on versatilepb (640x480), against the
desktop simulator running the same script (the module's own host build): the isometric view,
hidden-line mode, a section moved by its slider, the parts list and a picked face on the sample
part, see-through mode with a part chosen on an assembly, an AP242 part's PMI (drawn, listed,
one chosen, a kind hidden); each screenshot pixel-identical but
for the status bar's frame time (the simulator runs without a clock); the picked face's exact
values as facet-measure gives them; every frame of the session within the frame budget (the viewer's
budget rule); the board's frame times (the status bar's) those of a 600 MHz core.

  handheld_test.py --elf facet-viewer.elf --sim facet-sim --packer P --measure M --sample S
                   --assembly as1_oc_214.stp --pmi-model nist_ctc_02_ap242.stp --work DIR
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import board as boards  # noqa: E402
import protocol  # noqa: E402
import img  # noqa: E402
from budget_rules import analyse, frame_budget  # noqa: E402

# The sessions (tests/sessions): the handheld's features on the sample part, and see-through on
# an assembly, on the board and in the simulator.
def sessions(board):
    """(the features session, the see-through one, the PMI one), for this board's screen (refused otherwise)."""
    return (protocol.read_session(protocol.session_path('handheld'), board),
            protocol.read_session(protocol.session_path('handheld-assembly'), board),
            protocol.read_session(protocol.session_path('handheld-pmi'), board))


SHOTS = ['views', 'hidden-line', 'section', 'parts', 'measure']





def session(args, env, fpk, board_dir, sim_dir, script, shots):
    """The script on the board and in the simulator: the problems found (screenshots that differ)."""
    board = boards.load(args.board)
    dev = os.path.join(args.work, board_dir)
    cmd = [sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board, '--elf', args.elf,
           '--out', dev, '--load', f'{fpk}@{board["pack"]["address"]}', '--icount', '--timeout', '600', '--quiet']
    for s in script:
        cmd += ['--send', s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    problems = []
    if r.returncode != 0:
        problems.append(f'the board session ({board_dir}): exit {r.returncode}: {r.stderr.strip()[-300:]}')
    host = os.path.join(args.work, sim_dir)
    os.makedirs(host, exist_ok=True)
    hcmd = [args.sim, '--pack', fpk, '--out', host, '--size', '640x480', '--headless', '--no-clock']
    for s in script:
        hcmd += ['--send', s]
    h = subprocess.run(hcmd, capture_output=True, text=True, env=env, timeout=300)
    if h.returncode != 0:
        problems.append(f'the simulator ({sim_dir}): exit {h.returncode}: {h.stderr.strip()[-300:]}')
    for s in shots:
        a, b = os.path.join(host, s + '.f565'), os.path.join(dev, s + '.png')
        if not (os.path.exists(a) and os.path.exists(b)):
            problems.append(f'screenshot {s} missing')
            continue
        n, msg = img.compare(a, b, os.path.join(args.work, s + '-diff.png'), ignore=[img.frame_time_field(640, 480)])
        if n:
            problems.append(f'{s}: board and host differ: {msg}')
    return problems


def main():
    ap = argparse.ArgumentParser()
    for a in ('--board', '--elf', '--sim', '--packer', '--measure', '--sample', '--assembly', '--pmi-model', '--work'):
        ap.add_argument(a, required=True)
    args = ap.parse_args()
    if not boards.can(args.board, 'mouse'):
        raise SystemExit(f'handheld_test.py: {args.board} has no mouse (board.json "capabilities"): the session drags one')
    os.makedirs(args.work, exist_ok=True)
    env = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')
    step, fpk = os.path.join(args.work, 'sample.step'), os.path.join(args.work, 'sample.fpk')
    subprocess.run([args.sample, step], check=True, capture_output=True, env=env)
    subprocess.run([args.packer, step, '-o', fpk, '--quiet'], check=True, capture_output=True, env=env)
    features, see_through, pmi = sessions(args.board)
    problems = session(args, env, fpk, 'board', 'sim', features, SHOTS)
    dev = os.path.join(args.work, 'board')
    # See-through on an assembly: a part chosen in the list drawn solid, the others a screen door.
    afpk = os.path.join(args.work, 'assembly.fpk')
    subprocess.run([args.packer, args.assembly, '-o', afpk, '--quiet'], check=True, capture_output=True, env=env)
    problems += session(args, env, afpk, 'assembly-board', 'assembly-sim', see_through, ['tree', 'see-through', 'exploded', 'exploded-more'])
    # An AP242 part's PMI: drawn over it, the annotations list, one chosen, a kind hidden.
    pfpk = os.path.join(args.work, 'pmi.fpk')
    subprocess.run([args.packer, args.pmi_model, '-o', pfpk, '--quiet'], check=True, capture_output=True, env=env)
    problems += session(args, env, pfpk, 'pmi-board', 'pmi-sim', pmi, ['pmi-view', 'pmi-list', 'pmi-kinds'])
    # The picked face's values, as the host's facet-measure states them.
    rep = json.load(open(os.path.join(dev, 'report.json'))) if os.path.exists(os.path.join(dev, 'report.json')) else {}
    picks = rep.get('picks', [])
    if len(picks) != 1 or not picks[0]['lines']:
        problems.append(f'one pick with its values expected, got {picks}')
    else:
        p = picks[0]
        m = subprocess.run([args.measure, fpk, '--face', str(p['face']), '--json'], capture_output=True, text=True)
        g = json.loads(m.stdout)['faces'][0]
        line = p['lines'][0]
        want = {'plane': f'offset {g["offset"]:.3f}', 'cylinder': f'D {2 * g["radius"]:.3f}', 'cone': f'R {g["radius"]:.3f}',
                'sphere': f'R {g["radius"]:.3f}', 'torus': f'R {g["radius"]:.3f}',
                'B-spline': f'degree {g["u_degree"]} x {g["v_degree"]}  {g["u_poles"]} x {g["v_poles"]} poles'}.get(g['type'])
        if not line.startswith(f'#{p["face"]} ') or (want and want not in line):
            problems.append(f'the board says {line!r}; facet-measure: {g["type"]} ({want})')
        else:
            print(f'picked face {p["face"]}: {line!r} (facet-measure agrees)')
    # Every frame of the session within the frame budget.
    uart = open(os.path.join(dev, 'uart.log')).read() if os.path.exists(os.path.join(dev, 'uart.log')) else ''
    _, frames = analyse(uart, rep.get('regions', []))
    over = [f for f in frames if f['instructions'] and f['instructions'] > frame_budget(f['triangles'], f['rest'])]
    if not frames or over:
        problems.append(f'{len(frames)} frames, {len(over)} over the frame budget')
    else:
        print(f'{len(frames)} frames, the largest {max(f["instructions"] for f in frames):,} instructions, all within budget')
    # The status bar's frame time is the 600 MHz target's: the firmware's clock (QEMU's virtual
    # clock, in target time) gives each frame the cost its counted instructions take at 600 MHz,
    # give or take the UART lines printed between a frame's pieces.
    off = [f for f in frames if f['instructions'] and abs(f['cost_us'] * 600 - f['instructions']) > f['instructions'] // 100 + 600]
    if off:
        f = off[0]
        problems.append(f'{len(off)} frames whose clock disagrees with 600 MHz: {f["cost_us"]} us for {f["instructions"]:,} instructions')
    elif frames:
        f = max(frames, key=lambda f: f['instructions'] or 0)
        print(f'frame times at 600 MHz: the largest frame {f["cost_us"] / 1000:.2f} ms by the clock, '
              f'{f["instructions"] / 600e3:.2f} ms by its instructions')
    for p in problems:
        print('FAIL', p)
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
