#!/usr/bin/env python3
"""./facet: the one entry point (like idf.py or west). `./facet help`, and `--help` on every
subcommand. The shell bootstrap (../../facet) makes sure Python is there and hands over here."""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bench  # noqa: E402
import models  # noqa: E402
import project  # noqa: E402
import viewer  # noqa: E402
from common import ROOT, Failure  # noqa: E402

EPILOG = '''exit codes: 0 done; 1 error (the reason on stderr); 2 usage (a wrong option or argument, a file
that does not exist); 3 no board (flash); 4 over budget (run); 5 incomplete mesh (run, mesh);
6 mesh over its tolerance (mesh); 124 a QEMU run's timeout. docs/reliability.md lists them per
command.

presets: CMakePresets.json (host, host-asan, fuzz, and one per board). Environment: FACET_JOBS
(parallel jobs, default: the cores).'''

# Subcommands whose arguments go to a tool as they are (it checks them: exit 2 with its usage).
PASSTHROUGH = {'mesh': models.cmd_mesh, 'measure': models.cmd_measure}


def parser():
    ap = argparse.ArgumentParser(prog='./facet', formatter_class=argparse.RawDescriptionHelpFormatter,
                                 description='facet: CAD models from their exact geometry on a 600 MHz, 32 MiB '
                                 'ARM handheld. On a fresh machine: ./facet run, ./facet test.', epilog=EPILOG)
    sub = ap.add_subparsers(dest='command', metavar='COMMAND')
    viewer.add(sub)
    project.add(sub)
    models.add(sub)
    bench.add(sub)
    q = sub.add_parser('qemu', help='boot any firmware ELF in QEMU by hand (tools/qemu/run.py; --help for its options)',
                       add_help=False)
    h = sub.add_parser('help', help='this text')
    h.set_defaults(run=lambda args, parser: ap.print_help() or 0)
    for p in sub.choices.values():  # each subcommand's own parser, for its usage errors
        p.set_defaults(parser=p)
    bench.own_parsers()
    return ap


class Args:
    def __init__(self, rest):
        self.args = rest


def main(argv):
    ap = parser()
    if not argv:
        ap.print_help()
        return 0
    try:
        if argv[0] in PASSTHROUGH:
            return PASSTHROUGH[argv[0]](Args(argv[1:]), ap) or 0
        if argv[0] == 'qemu':
            os.execv(sys.executable, [sys.executable, os.path.join(ROOT, 'tools', 'qemu', 'run.py')] + argv[1:])
        args = ap.parse_args(argv)
        if args.command is None:
            ap.print_help()
            return 0
        return args.run(args, args.parser) or 0
    except Failure as f:
        print(f'facet: error: {f}', file=sys.stderr)
        return f.code
    except KeyboardInterrupt:
        return 130


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
