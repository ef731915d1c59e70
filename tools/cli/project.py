"""./facet setup, build, test and fuzz: the packages, the presets, every test, long fuzz runs."""
import datetime
import glob
import os
import shutil
import subprocess
import sys

from common import MODELS, ROOT, Failure, build, jobs, presets, run, say, setup, tool


def add(sub):
    p = sub.add_parser('setup', help='install missing Debian packages (apt-get, as root); run and test do it',
                       description='Install the Debian packages the project needs that are missing (apt-get, as '
                       'root; otherwise the command to run is printed and the exit code is 1).')
    p.set_defaults(run=lambda args, parser: setup() or 0)

    p = sub.add_parser('build', help='configure and build presets (default: all of them)',
                       description='Configure (once) and build CMake presets (CMakePresets.json): ' +
                       ', '.join(presets()) + '. Default: all of them.')
    p.add_argument('presets', nargs='*', metavar='PRESET')
    p.set_defaults(run=cmd_build)

    p = sub.add_parser('test', help='build every preset and run every test (what CI runs)',
                       description='Set up, build every preset and run every test through ctest: host unit tests, '
                       'ASan/UBSan, reference images, QEMU on the boards, the simulator headless, link-time guards, '
                       'the layers of DEVELOPERS.md.')
    p.add_argument('-R', '--only', metavar='REGEX', help="only the tests whose names match (ctest's -R)")
    p.add_argument('--quick', action='store_true',
                   help='the edit loop: the host build and its own tests only (no ARM builds, QEMU, sanitizers, '
                   'fuzzing or the corpus-wide sweeps); ./facet test before saying a change is done')
    p.set_defaults(run=cmd_test)

    p = sub.add_parser('fuzz', help='a long fuzz run (libFuzzer: cdt, pack, storage, tessellate, api; facet-pack on mutated STEP: step)',
                       description='A long libFuzzer run (ASan + UBSan; default 10,000,000 executions over every core), '
                       'the corpus kept in out/fuzz/TARGET. Exit 1 if anything was found.')
    p.add_argument('target', choices=['cdt', 'pack', 'storage', 'tessellate', 'api', 'step'])
    p.add_argument('--runs', type=positive, default=10_000_000, metavar='N')
    p.add_argument('--jobs', type=positive, default=int(jobs()), metavar='J')
    p.add_argument('--seed', type=positive, default=None, metavar='S',
                   help='the mutations\' seed (step: 1 unless given, each seed a new set of runs; the libFuzzer targets: '
                   'their own unless given)')
    p.add_argument('--no-trace-cmp', action='store_true',
                   help='no comparison tracing: ~4x the executions of tessellate (docs/reliability.md)')
    p.set_defaults(run=cmd_fuzz)


def positive(text):
    import argparse
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f'not a count: {text}')
    if n < 1:
        raise argparse.ArgumentTypeError(f'not a count: {text}')
    return n


def cmd_build(args, parser):
    known = presets()
    for p in args.presets:
        if p not in known:
            parser.error(f'no preset {p!r} (presets: {", ".join(known)})')
    setup()
    build(*args.presets)
    return 0


# What --quick leaves out: everything that needs the ARM builds or the fuzzers, and the host
# tests that run over the whole corpus (each a minute or more of a 2-core machine).
QUICK_EXCLUDES = r'^(qemu\.|guard\.|fuzz\.|mimxrt1060-evkb\.|cdt\.no_floating_point|docs\.budgets|mesh\.|pack\.every|' \
                 r'reliability\.large|module\.model_needs_keeps)'


def cmd_test(args, parser):
    setup()
    if args.quick:
        build('host')
        only = ['-R', args.only] if args.only else []
        say('host: unit tests and the quick host checks (--quick: no QEMU, sanitizers or fuzzing)')
        return 0 if run(['ctest', '--test-dir', 'build/host', '-j', jobs(), '--output-on-failure', '--timeout', '600',
                         '-E', QUICK_EXCLUDES] + only) == 0 else 1
    build()
    only = ['-R', args.only] if args.only else []
    status = 0
    for preset, what in (('host-asan', 'unit tests under AddressSanitizer + UBSan'),
                         ('host', 'unit tests, reference images, QEMU tests on the boards, link-time guards')):
        say(f'{preset}: {what}')
        if run(['ctest', '--test-dir', f'build/{preset}', '-j', jobs(), '--output-on-failure', '--timeout', '600'] + only) != 0:
            status = 1
    return status


def cmd_fuzz(args, parser):
    setup()
    if args.target == 'step': # facet-pack (Open CASCADE) on mutated STEP text: a process a run
        build('host')
        out = os.path.join(ROOT, 'out', 'fuzz', 'step')
        say(f'fuzzing step: {args.runs} runs of facet-pack on mutated STEP text, {args.jobs} jobs, findings in out/fuzz/step')
        if run([sys.executable, 'tests/fuzz/step_fuzz.py', '--packer', tool('facet-pack'), '--models', MODELS, '--out', out,
                '--runs', str(args.runs), '--jobs', str(args.jobs), '--seed', str(args.seed or 1)]) != 0:
            raise Failure('step: facet-pack failed on mutated STEP text (out/fuzz/step: each finding and its command)')
        return 0
    folder = os.path.join(ROOT, 'build', 'fuzz')
    if args.no_trace_cmp:
        folder = os.path.join(ROOT, 'build', 'fuzz-no-trace-cmp')
        if run(['cmake', '--preset', 'fuzz', '-B', folder, '-DFACET_FUZZ_TRACE_CMP=OFF'], stdout=subprocess.DEVNULL) != 0 or \
                run(['cmake', '--build', folder, '-j', jobs()]) != 0:
            raise Failure('the fuzz build failed')
    else:
        build('fuzz')
    t = args.target
    out = os.path.join(ROOT, 'out', 'fuzz', t)
    corpus, artifacts, logs = (os.path.join(out, d) for d in ('corpus', 'artifacts', 'logs'))
    for d in (corpus, artifacts, logs):
        os.makedirs(d, exist_ok=True)
    for seed in glob.glob(os.path.join(ROOT, 'tests', 'fuzz', 'corpus', 'pack' if t == 'storage' else t, '*')):  # (storage: the pack seeds, as files)
        dest = os.path.join(corpus, os.path.basename(seed))
        if not os.path.exists(dest):
            shutil.copy(seed, dest)
    for old in glob.glob(os.path.join(logs, 'fuzz-*.log')):
        os.remove(old)
    per = (args.runs + args.jobs - 1) // args.jobs
    say(f'fuzzing {t}: {args.jobs} x {per} executions, corpus out/fuzz/{t}/corpus, logs out/fuzz/{t}/logs')
    start = datetime.datetime.utcnow().strftime('%Y-%m-%dT%H:%M:%SZ')
    max_len = 512 if t in ('cdt', 'api') else 32768
    seed = [f'-seed={args.seed}'] if args.seed else []
    subprocess.run([os.path.join(folder, 'tests', 'fuzz', f'facet-{t}-fuzz'), f'-jobs={args.jobs}', f'-workers={args.jobs}',
                    f'-runs={per}', f'-max_len={max_len}', '-timeout=30', '-rss_limit_mb=4096', '-print_final_stats=1', *seed,
                    f'-artifact_prefix={artifacts}/', corpus], cwd=logs, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    total = 0
    for log in glob.glob(os.path.join(logs, 'fuzz-*.log')):
        for line in open(log, errors='replace'):
            if line.startswith('stat::number_of_executed_units:'):
                total += int(line.split(':')[-1])
    say(f'{t}: {total} executions from {start} to {datetime.datetime.utcnow().strftime("%Y-%m-%dT%H:%M:%SZ")}')
    found = sorted(os.listdir(artifacts))
    if found:
        for f in found:
            print(f'  found: {f}')
        raise Failure(f'{t}: the fuzzer found inputs that fail (out/fuzz/{t}/artifacts): reproduce with '
                      f'{folder}/tests/fuzz/facet-{t}-fuzz FILE')
    return 0
