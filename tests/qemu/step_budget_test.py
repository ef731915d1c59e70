#!/usr/bin/env python3
"""The module's time slicing on the target, measured exactly: how far a step(budget) runs past
its budget.

QEMU runs with a virtual clock (-icount shift=0: the guest's timers advance 1 ns per executed
instruction) and the boards report its ticks in the 600 MHz target's time, so the firmware's
clock, and with it the module's decision to end a step, is repeatable for the same input at the
same moments (the session's keys, and '!budget' itself, arrive when the host sends them: how many
steps a run takes varies). The firmware is told '!budget US': every step(US) is then an
instruction-count region 'step'. A step's overrun is its instructions beyond the budget (US
microseconds at 600 MHz = US x 600 instructions), less the screenshots taken inside it (regions
'shot' nested in it: the firmware waits there for the host, as long as the host takes).

Asserted for each model: the session completes (every face in, a view change and a finer
level of detail drawn), no step runs more than --bound instructions past its budget, and
steps that ran out of work (idle) are not counted as overruns. Prints the figures:

  step_budget_test.py --board B --elf ELF --packer facet-pack --work DIR [--budget-us 4000]
                      [--bound 1500000] MODEL.step...
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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--board', required=True)
    ap.add_argument('--elf', required=True)
    ap.add_argument('--packer', required=True)
    ap.add_argument('--work', required=True)
    ap.add_argument('--budget-us', type=int, default=4000)
    ap.add_argument('--bound', type=int, default=1_500_000, help='instructions a step may run past its budget')
    ap.add_argument('models', nargs='+')
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    board = boards.load(args.board)
    budget = args.budget_us * 600  # instructions: 600 a microsecond at 600 MHz
    failed = False
    for model in args.models:
        name = os.path.splitext(os.path.basename(model))[0]
        fpk = os.path.join(args.work, name + '.fpk')
        subprocess.run([args.packer, model, '-o', fpk, '--quiet'], check=True, capture_output=True)
        out = os.path.join(args.work, name)
        r = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py'), '--board', args.board,
                            '--elf', args.elf, '--out', out, '--load', f'{fpk}@{board["pack"]["address"]}', '--icount',
                            '--timeout', '900', '--quiet', '--type', f'!budget {args.budget_us}\\n',
                            '--session', 'step-budget'], capture_output=True, text=True)
        problems = []
        report = os.path.join(out, 'report.json')
        if r.returncode != 0 or not os.path.exists(report):
            print(f'FAIL {args.board} {name}: exit {r.returncode}\n{r.stderr[-2000:]}')
            failed = True
            continue
        rep = json.load(open(report))
        uart = open(os.path.join(out, 'uart.log')).read()
        again = protocol.tessellation(uart, 'retessellation')
        if not again or again['failed'] != 0:
            problems.append('the session did not finish its finer level of detail')
        regions = rep['regions']
        # A step's own instructions: the screenshots taken inside it (regions 'shot' nested in
        # it) wait for the host as long as the host takes, which is no work of the module's.
        waits = {}
        for r in regions:
            if r['name'] == 'shot' and r.get('parent') is not None and r['instructions'] is not None:
                waits[r['parent']] = waits.get(r['parent'], 0) + r['instructions']
        steps = [None if x['instructions'] is None else x['instructions'] - waits.get(i, 0)
                 for i, x in enumerate(regions) if x['name'] == 'step']
        if not steps or None in steps:
            problems.append('no step counted')
            steps = [0]
        over = [s - budget for s in steps if s > budget]
        worst = max(over) if over else 0
        if worst > args.bound:
            problems.append(f'a step ran {worst:,} instructions past its budget (bound {args.bound:,})')
        line = (f'{args.board} {name}: {len(steps)} steps of {args.budget_us:,} us ({budget:,} instructions); '
                f'{len(over)} ran past it, by {worst:,} instructions at most = {worst / 600e3:.2f} ms at 600 MHz '
                f'(bound {args.bound:,}); longest step {max(steps):,}')
        if problems:
            failed = True
            print(f'FAIL {line}: ' + '; '.join(problems))
        else:
            print(line)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
