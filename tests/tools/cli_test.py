#!/usr/bin/env python3
"""./facet's contract with the command line (tools/cli/): every subcommand (and every bench)
answers --help with its usage and exit 0; an unknown subcommand or option, a missing value and a
file that does not exist are usage errors: exit 2 with the usage on stderr, before anything is
set up or built (this test runs in seconds, with no package installed by it).

  cli_test.py ROOT
"""
import os
import subprocess
import sys


def main():
    root = os.path.abspath(sys.argv[1])
    sys.path.insert(0, os.path.join(root, 'tools', 'cli'))
    import main as cli  # tools/cli/main.py: its parser names every subcommand

    facet = os.path.join(root, 'facet')
    ap = cli.parser()
    sub = next(a for a in ap._actions if a.dest == 'command')
    commands = [[c] for c in sub.choices if c != 'help']
    commands += [['bench', b] for b in next(a for a in sub.choices['bench']._actions if a.dest == 'bench').choices]
    problems = []

    def check(args, code, text_in):
        r = subprocess.run([facet] + args, capture_output=True, text=True, timeout=60, cwd=root)
        out = r.stdout + r.stderr
        if r.returncode != code or text_in not in out:
            problems.append(f'./facet {" ".join(args)}: exit {r.returncode} (expected {code}), '
                            f'{"no " + repr(text_in) if text_in not in out else "output"}: {out.strip()[-200:]!r}')
        if 'building' in out or 'configuring' in out:
            problems.append(f'./facet {" ".join(args)}: built something before answering')

    for c in commands:
        check(c + ['--help'], 0, 'usage')
    for c in commands:
        if c[0] in ('mesh', 'measure', 'qemu', 'setup'):
            continue  # their options go to their tools, which check them
        check(c + ['--no-such-option'], 2, 'usage')
    check(['no-such-command'], 2, 'invalid choice')
    check(['test', '--bogus'], 2, 'unrecognized arguments')
    for c in (['run'], ['pack'], ['sim'], ['example'], ['flash'], ['bench', 'mesh'], ['bench', 'device'], ['bench', 'sweep']):
        check(c + ['/no/such/model.step'], 2, 'no such file')
    check(['pack'], 2, 'usage')  # MODEL.step is required
    check(['build', 'no-such-preset'], 2, 'no preset')
    check(['fuzz', 'cdt', '--runs', '0'], 2, 'not a count')
    check(['fuzz', 'nonsense'], 2, 'invalid choice')
    check([], 0, 'usage')
    for p in problems:
        print('FAIL', p)
    if not problems:
        print(f'{len(commands)} subcommands: --help, usage errors exit 2 before any build')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
