"""./facet pack, mesh and measure: a STEP file into a pack, a pack into triangles with the
device's code, a face's exact values."""
import os
import subprocess

from common import ROOT, USAGE, build, existing_file, model_pack, setup, tool

MESH_HELP = '''usage: ./facet mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM | --finer N]
                   [--angle RAD] [--faces] [--pieces UNITS] [--face-points N] [--quiet]

A pack into triangles with the device's geom/ and cdt/ code: STL, OBJ or PLY and a report
(faces, triangles, the measured deviation, free and non-manifold edges). Exit 5: an incomplete
mesh (a face failed, a closed shell not watertight); 6: over the tolerance (outputs written).'''

MEASURE_HELP = '''usage: ./facet measure MODEL.fpk|MODEL.step --face N[@I] [--face M[@J]] [--all] [--json]

A face's exact surface (plane normal and offset, hole or boss diameter and axis, cone half-angle,
sphere and torus radii, B-spline degrees and poles) and, for two faces, the exact distance and
angle between them, in the file's unit (the viewer's pick and measure, for scripts). A STEP file
is packed first (under out/measure/).'''


def add(sub):
    p = sub.add_parser('pack', help='STEP -> pack (Open CASCADE), validated with the device\'s reader',
                       description='STEP -> pack with Open CASCADE (default output out/packs/NAME.fpk), LZMA unless '
                       '--plain, then validated with the device\'s reader.')
    p.add_argument('model', metavar='MODEL.step')
    p.add_argument('-o', dest='output', metavar='MODEL.fpk')
    p.add_argument('--plain', action='store_true', help='not compressed (read in place)')
    p.add_argument('--unit', choices=['mm', 'cm', 'm', 'in', 'ft'], help='for a file that gives no length unit')
    p.add_argument('--partial', action='store_true', help='pack what can be read when faces of the file cannot')
    p.add_argument('--quiet', action='store_true')
    p.set_defaults(run=cmd_pack)

    # mesh and measure hand their arguments to the tools, which check them (exit 2 with usage).
    p = sub.add_parser('mesh', help='pack -> triangles with the device\'s code, and a report', add_help=False)
    p.add_argument('args', nargs='*')
    p.set_defaults(run=cmd_mesh)
    p = sub.add_parser('measure', help='a face\'s exact surface; two faces\' exact distance and angle', add_help=False)
    p.add_argument('args', nargs='*')
    p.set_defaults(run=cmd_measure)


def cmd_pack(args, parser):
    model = existing_file(parser, args.model)
    out = os.path.abspath(args.output) if args.output else \
        os.path.join(ROOT, 'out', 'packs', os.path.splitext(os.path.basename(model))[0] + '.fpk')
    os.makedirs(os.path.dirname(out), exist_ok=True)
    setup()
    build('host', quiet=True)
    opts = [o for o, on in (('--plain', args.plain), ('--partial', args.partial), ('--quiet', args.quiet)) if on]
    if args.unit:
        opts += ['--unit', args.unit]
    rc = subprocess.run([tool('facet-pack'), model, '-o', out] + opts).returncode
    if rc != 0:
        return rc
    return subprocess.run([tool('facet-pack'), '--check', out]).returncode


def passthrough_help(argv, text):
    if any(a in ('-h', '--help') for a in argv):
        print(text)
        return True
    return False


def cmd_mesh(args, parser):
    if passthrough_help(args.args, MESH_HELP):
        return 0
    if not args.args:
        print(MESH_HELP)
        return USAGE
    setup()
    build('host', quiet=True)
    os.execv(tool('facet-mesh'), [tool('facet-mesh')] + args.args)


def cmd_measure(args, parser):
    if passthrough_help(args.args, MEASURE_HELP):
        return 0
    if not args.args:
        print(MEASURE_HELP)
        return USAGE
    model, rest = args.args[0], args.args[1:]
    if not model.startswith('-'):
        model = existing_file(parser, model)
    setup()
    build('host', quiet=True)
    if not model.startswith('-') and not model.endswith('.fpk'):
        model = model_pack(model, os.path.join(ROOT, 'out', 'measure'))
    os.execv(tool('facet-measure'), [tool('facet-measure'), model] + rest)
