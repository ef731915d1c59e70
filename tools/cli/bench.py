"""./facet bench: the CDT against CGAL, the tessellation against BRepMesh, the tolerance sweep,
every model on the boards, frames against tgx, the EVKB's ITCM list."""
import datetime
import os
import subprocess
import sys

from common import (MODELS, ROOT, Failure, build, existing_file, fresh, model_pack, pack_address, rel, run, say,
                    setup, shared_models, tool)

BENCH_BOARDS = 'qemu-versatilepb,qemu-mps2-an500'
TGX = os.path.normpath(os.path.join(ROOT, '..', 'shared', 'peers', 'tgx'))


def add(sub):
    bench = sub.add_parser('bench', help='benchmarks, side by side with the peers (never timed tests)',
                           description='Benchmarks: facet and its peers measured in the same run.')
    kinds = bench.add_subparsers(dest='bench', metavar='KIND', required=True)
    _kinds.append(kinds)

    p = kinds.add_parser('cdt', help='the CDT against CGAL, and exact ARM instruction counts',
                         description='The CDT against CGAL in one run: ns per vertex and the ratio per input, a CSV '
                         '(default out/bench/cdt.csv) and a PNG plot beside it, then exact ARM instruction counts (QEMU) '
                         'for the paper face and the 10k plate on both boards (FILE-targets.csv).')
    p.add_argument('--csv', default=os.path.join(ROOT, 'out', 'bench', 'cdt.csv'))
    p.add_argument('--quick', action='store_true', help='fewer repetitions')
    p.add_argument('--inputs', metavar='A,B', help='only these inputs')
    p.set_defaults(run=cmd_cdt)

    p = kinds.add_parser('mesh', help="the tessellation against Open CASCADE BRepMesh",
                         description="facet's tessellation (the device's path) against Open CASCADE BRepMesh on the "
                         'same shapes at 0.1%% and 1%% of the diagonal (default: every shared model), the same '
                         'measuring code; a CSV (default out/bench/mesh.csv) and a PNG plot.')
    p.add_argument('--csv', default=os.path.join(ROOT, 'out', 'bench', 'mesh.csv'))
    p.add_argument('models', nargs='*', metavar='MODEL.step')
    p.set_defaults(run=cmd_mesh)

    p = kinds.add_parser('sweep', help='every model at 0.02 to 5%% of its diagonal: no face fails, watertight',
                         description='Every model (default: the shared ones and the stress parts) at 0.02, 0.05, 0.1, '
                         '0.2, 0.5, 1, 2 and 5%% of its diagonal: no face fails, closed shells watertight, deviation '
                         'within the tolerance; a table in out/bench/sweep.md.')
    p.add_argument('models', nargs='*', metavar='MODEL.step')
    p.set_defaults(run=cmd_sweep)

    p = kinds.add_parser('device', help='every model through the viewer in QEMU on both boards',
                         description='Every model (default: the shared ones) through the viewer in QEMU on the ARM926 '
                         'and the Cortex-M7: faces, triangles, inflating, tessellation, the largest face and frame '
                         '(exact instruction counts) and peak RAM; a CSV (default out/bench/device.csv) and a '
                         'markdown table beside it (docs/budgets.md).')
    p.add_argument('--csv', default=os.path.join(ROOT, 'out', 'bench', 'device.csv'))
    p.add_argument('--boards', default=BENCH_BOARDS, metavar='A,B')
    p.add_argument('--jobs', default=str(os.cpu_count() or 1), metavar='N')
    p.add_argument('models', nargs='*', metavar='MODEL.step')
    p.set_defaults(run=cmd_device)

    p = kinds.add_parser('render', help="facet's frames against tgx's on both boards",
                         description="facet's frames against tgx (../shared/peers/tgx, a peer built only here) in QEMU "
                         'on both boards: the same meshes and cameras, full and zoomed views, 480x272 and 640x480; '
                         'CSV out/bench/render.csv, a PNG plot, side-by-side shots.')
    p.add_argument('--csv', default=os.path.join(ROOT, 'out', 'bench', 'render.csv'))
    p.add_argument('--quick', action='store_true', help='anc101 alone')
    p.add_argument('models', nargs='*', metavar='MODEL.step[@finerN]')
    p.set_defaults(run=cmd_render)

    p = kinds.add_parser('scale', help='assemblies of 1 k to 100 k faces through the viewer in QEMU',
                         description='Assemblies made with Open CASCADE from shared models (nist_ctc_02, nist_ctc_04, '
                         'mechanism, tail_section_asm), as distinct copies and as instances, of 1 k, 3 k, 10 k and 30 k '
                         'faces, and mixed (distinct copies to 30 k faces, instances of them beyond) of 100 k, through the viewer in QEMU on the ARM926 and the EVKB\'s configuration: pack bytes, '
                         'first wireframe, first view, frames at rest, turning and zoomed, triangles, peak RAM; a CSV '
                         '(default out/bench/scale.csv), a markdown table and a PNG plot beside it. The assemblies are '
                         'made once into out/bench/scale/ (the largest takes minutes); long: not part of ./facet test.')
    p.add_argument('--csv', default=os.path.join(ROOT, 'out', 'bench', 'scale.csv'))
    p.add_argument('--faces', default='1000,3000,10000,30000,100000', metavar='N,M')
    p.add_argument('--kinds', default='distinct,instances,mixed', metavar='A,B',
                   help='mixed: distinct copies to 30 k faces, instances of them beyond (above 30 k faces only)')
    p.add_argument('--boards', default='qemu-versatilepb,qemu-mps2-evkb', metavar='A,B')
    p.add_argument('--sources', default='ram', metavar='ram,card', help='where the pack comes from: loaded into RAM, '
                   'and/or a memory card image (the SD slot, or on the mps2 boards a semihosted image: docs/storage.md)')
    p.set_defaults(run=cmd_scale)

    p = kinds.add_parser('itcm', help="profile the EVKB's configuration, rewrite its ITCM code list",
                         description="Profile the viewer on the EVKB's configuration in QEMU (three models) and "
                         'rewrite linker/mimxrt1060-evkb-itcm.ld: the code that runs from ITCM.')
    p.set_defaults(run=cmd_itcm)


_kinds = []


def own_parsers():
    """Each bench's parser for its own usage errors (after the top level set the bench's)."""
    for kinds in _kinds:
        for p in kinds.choices.values():
            p.set_defaults(parser=p)


def cmd_cdt(args, parser):
    setup()
    build('qemu-versatilepb', 'qemu-mps2-an500')
    build('host', extra=['facet-bench-cdt'])
    csv = os.path.abspath(args.csv)
    os.makedirs(os.path.dirname(csv), exist_ok=True)
    say('CDT: facet vs CGAL 5.5 (same inputs, same run)')
    extra = (['--quick'] if args.quick else []) + (['--inputs', args.inputs] if args.inputs else [])
    if run([tool('facet-bench-cdt'), '--csv', csv] + extra) != 0:
        raise Failure('the CDT bench failed')
    run([sys.executable, 'tools/plot_bench.py', 'cdt', csv])
    say('CDT on the targets: exact instruction counts (QEMU plugin, 600 MHz = 600 M/s)')
    targets = csv[:-4] + '-targets.csv'
    if os.path.exists(targets):
        os.remove(targets)
    for board in BENCH_BOARDS.split(','):
        if run([sys.executable, 'tests/qemu/cdt_target_test.py', '--board', board,
                '--elf', f'build/{board}/bench/facet-cdt-bench.elf', '--work', os.path.join(ROOT, 'out', 'bench', f'{board}-cdt'),
                '--csv', targets]) != 0:
            raise Failure(f'the CDT on {board} failed')
    say(f'CSV: {rel(csv)} (host), {rel(targets)} (targets), plot: {rel(csv[:-4])}.png')
    return 0


def cmd_mesh(args, parser):
    models = [existing_file(parser, m) for m in args.models] or shared_models()
    setup()
    build('host', extra=['facet-bench-mesh'])
    csv = os.path.abspath(args.csv)
    os.makedirs(os.path.dirname(csv), exist_ok=True)
    say('tessellation: facet (geom/ + cdt/) vs Open CASCADE BRepMesh, same shapes, same measurements')
    if run([tool('facet-bench-mesh')] + models + ['--csv', csv]) != 0:
        raise Failure('the mesh bench failed')
    run([sys.executable, 'tools/plot_bench.py', 'mesh', csv])
    say(f'CSV: {rel(csv)}, plot: {rel(csv[:-4])}.png')
    return 0


def stress_models(folder):
    """The parts no shared model has (tools/stress-models), made once under `folder`."""
    os.makedirs(folder, exist_ok=True)
    for name, what in (('fillets.step', ['fillets']), ('lenses.step', ['lenses']), ('machined.step', ['machined']),
                       ('holes1600.step', ['holes', '1600'])):
        path = os.path.join(folder, name)
        if not os.path.exists(path) and run([tool('facet-stress-model')] + what + [path], stdout=subprocess.DEVNULL) != 0:
            raise Failure(f'cannot make the stress part {name}')


def cmd_sweep(args, parser):
    files = [existing_file(parser, m) for m in args.models]
    setup()
    build('host')
    if files:
        folders = sorted({os.path.dirname(f) for f in files})
    else:
        stress = os.path.join(ROOT, 'out', 'bench', 'stress')
        stress_models(stress)
        folders = [MODELS, stress]
    cmd = [sys.executable, 'bench/sweep.py', '--packer', tool('facet-pack'), '--mesher', tool('facet-mesh'),
           '--work', os.path.join(ROOT, 'out', 'bench', 'sweep'), '--markdown', os.path.join(ROOT, 'out', 'bench', 'sweep.md'),
           '--csv', os.path.join(ROOT, 'out', 'bench', 'sweep.csv')]
    for f in folders:
        cmd += ['--models', f]
    if files:
        cmd += ['--only', ','.join(os.path.basename(f) for f in files)]
    say('tolerance sweep: every model at 0.02 to 5% of its diagonal (facet-pack + facet-mesh)')
    return run(cmd)


def cmd_device(args, parser):
    models = [existing_file(parser, m) for m in args.models] or shared_models()
    boards = args.boards.split(',')
    setup()
    build('host', *boards, quiet=True)
    csv = os.path.abspath(args.csv)
    say(f'every model through the viewer on {" and ".join(boards)} (QEMU, exact instruction counts)')
    return run([sys.executable, 'bench/device.py', '--packer', tool('facet-pack'), '--build', 'build', '--boards', args.boards,
                '--jobs', args.jobs, '--work', os.path.join(ROOT, 'out', 'bench', 'device'), '--csv', csv,
                '--markdown', csv[:-4] + '.md', '--date', datetime.date.today().isoformat()] + models)


def cmd_scale(args, parser):
    boards = args.boards.split(',')
    setup()
    build('host', *boards, quiet=True)
    csv = os.path.abspath(args.csv)
    models = [os.path.join(MODELS, m) for m in ('nist_ctc_02.stp', 'nist_ctc_04.stp', 'mechanism.stp', 'tail_section_asm.stp')]
    say(f'assemblies of {args.faces} faces ({args.kinds}) through the viewer on {" and ".join(boards)} '
        '(QEMU, exact instruction counts; the assemblies are made once, the largest in minutes)')
    return run([sys.executable, 'bench/scale.py', '--assembly', tool('facet-assembly'), '--packer', tool('facet-pack'),
                '--build', 'build', '--work', os.path.join(ROOT, 'out', 'bench', 'scale'), '--csv', csv,
                '--faces', args.faces, '--kinds', args.kinds, '--boards', args.boards, '--sources', args.sources,
                '--date', datetime.date.today().isoformat()] + models)


def cmd_render(args, parser):
    models = []
    for spec in args.models:
        path, at, finer = spec.partition('@finer')
        models.append(existing_file(parser, path) + (at + finer if at else ''))
    if args.quick:
        models = [os.path.join(MODELS, 'anc101.stp')]
    if not os.path.exists(os.path.join(TGX, 'src', 'tgx.h')):
        raise Failure('no tgx at ../shared/peers/tgx: the render bench needs its peer')
    # nist_ctc_02 and anc101 at the default level of detail, nist_ctc_02 two steps finer (13,106 triangles).
    models = models or [os.path.join(MODELS, 'nist_ctc_02.stp'), os.path.join(MODELS, 'anc101.stp'),
                        os.path.join(MODELS, 'nist_ctc_02.stp') + '@finer2']
    setup()
    build('host', 'qemu-versatilepb', 'qemu-mps2-an500', quiet=True)
    say('frames: facet vs tgx on the ARM926 and the Cortex-M7 (QEMU, exact instruction counts, same meshes and cameras)')
    fresh(os.path.join(ROOT, 'out', 'bench', 'render'))
    csv = os.path.abspath(args.csv)
    rc = run([sys.executable, 'bench/render/render.py', '--packer', tool('facet-pack'), '--mesher', tool('facet-mesh'),
              '--host-views', tool('facet-render-views'), '--build', 'build', '--work', os.path.join(ROOT, 'out', 'bench', 'render'), '--csv', csv] + models)
    run([sys.executable, 'tools/plot_bench.py', 'render', csv])
    with open(csv[:-4] + '.md', 'w') as md:
        run([sys.executable, 'tools/plot_bench.py', 'render-table', csv], stdout=md)
    say(f'table: {rel(csv[:-4])}.md; pictures side by side (facet | tgx): out/bench/render/BOARD/MODEL/side-*.png')
    return rc


def cmd_itcm(args, parser):
    setup()
    build('host', 'qemu-mps2-evkb', 'evkb', quiet=True)
    out = fresh(os.path.join(ROOT, 'out', 'bench', 'itcm'))
    sample = os.path.join(out, 'sample.step')
    run([tool('facet-sample-model'), sample], stdout=subprocess.DEVNULL)
    profiles = []
    for model in (sample, os.path.join(MODELS, 'anc101.stp'), os.path.join(MODELS, 'nist_ctc_02_ap242.stp')):
        name = os.path.splitext(os.path.basename(model))[0]
        fpk = model_pack(model, os.path.join(out, name))
        say(f"profiling the viewer on {name} (the EVKB's configuration, QEMU)")
        if run([sys.executable, 'tools/qemu/run.py', '--board', 'qemu-mps2-evkb',
                '--elf', 'build/qemu-mps2-evkb/firmware/facet-viewer.elf', '--out', os.path.join(out, name),
                '--load', f'{fpk}@{pack_address("qemu-mps2-evkb")}', '--icount', '--profile', '--timeout', '900',
                '--quiet', '--session', 'itcm'], stdout=subprocess.DEVNULL) != 0:
            raise Failure(f'profiling {name} failed')
        profiles.append(os.path.join(out, name, 'profile.raw'))
    run([sys.executable, 'tools/hot_code.py', 'pick', 'build/qemu-mps2-evkb/firmware/facet-viewer.elf'] + profiles +
        ['--out', 'linker/mimxrt1060-evkb-itcm.ld'])
    build('qemu-mps2-evkb', 'evkb', quiet=True)
    return run([sys.executable, 'tools/hot_code.py', 'check', 'build/evkb/firmware/facet-viewer.elf',
                'linker/mimxrt1060-evkb-itcm.ld'])
