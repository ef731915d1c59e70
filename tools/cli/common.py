"""What every subcommand of ./facet shares: the tree's paths, messages and exit codes, the Debian
packages and the builds, the host tools' paths, a model made ready for the viewer."""
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = os.path.normpath(os.path.join(ROOT, '..', 'shared', 'models'))
sys.path.insert(0, os.path.join(ROOT, 'tools'))

# Exit codes (docs/reliability.md lists them per command).
OK, ERROR, USAGE, NO_BOARD, OVER_BUDGET, INCOMPLETE_MESH, OVER_TOLERANCE = 0, 1, 2, 3, 4, 5, 6

# The Debian 12 packages the project needs, in one place.
PACKAGES = [
    'cmake', 'ninja-build', 'g++', 'python3',
    'gcc-arm-none-eabi', 'binutils-arm-none-eabi', 'libnewlib-arm-none-eabi', 'libstdc++-arm-none-eabi-newlib',
    'qemu-system-arm',
    'mtools', 'dosfstools',  # the memory card's images (FAT), as a PC makes them
    'libgtest-dev', 'libbenchmark-dev', 'libgmp-dev', 'zlib1g-dev', 'liblzma-dev',
    'clang', 'libclang-rt-14-dev',
    'libcgal-dev', 'gnuplot-nox', 'libsdl2-dev',
    'xfonts-base',  # the X11 misc-fixed 5x8 font: tools/font/make_font.py's letters beyond ASCII
    'libocct-data-exchange-dev', 'libocct-modeling-algorithms-dev', 'libocct-modeling-data-dev',
    'libocct-foundation-dev', 'libocct-ocaf-dev', 'libocct-visualization-dev', 'libtbb-dev',
]


class Failure(Exception):
    """A command that cannot go on: its message and exit code (1 unless said)."""

    def __init__(self, message, code=ERROR):
        super().__init__(message)
        self.code = code


def say(text):
    print(f'\033[1mfacet:\033[0m {text}', flush=True)


def rel(path):
    return os.path.relpath(path, ROOT)


def jobs():
    return os.environ.get('FACET_JOBS', str(os.cpu_count() or 1))


def presets():
    """The CMake presets (CMakePresets.json), in order: the ARM boards' first, then the host's."""
    data = json.load(open(os.path.join(ROOT, 'CMakePresets.json')))
    names = [p['name'] for p in data['configurePresets'] if not p.get('hidden')]
    arm = [n for n in names if n.startswith(('qemu-', 'evkb'))]
    return arm + [n for n in names if n not in arm]


def preset_of(board):
    """The preset that builds a board (its FACET_BOARD in CMakePresets.json)."""
    data = json.load(open(os.path.join(ROOT, 'CMakePresets.json')))
    for p in data['configurePresets']:
        if p.get('cacheVariables', {}).get('FACET_BOARD') == board:
            return p['name']
    raise Failure(f'no preset builds {board} (CMakePresets.json)')


def missing_packages():
    """The packages not installed: one dpkg-query for all of them (cheap when none is missing)."""
    if not shutil.which('dpkg-query'):
        raise Failure('this script sets up Debian 12; install: ' + ' '.join(PACKAGES))
    r = subprocess.run(['dpkg-query', '-W', '-f', '${Package} ${db:Status-Abbrev}\\n'] + PACKAGES,
                       capture_output=True, text=True)
    installed = {w[0] for w in (line.split() for line in r.stdout.splitlines()) if len(w) > 1 and w[1].startswith('ii')}
    return [p for p in PACKAGES if p not in installed]


def setup():
    """Installs what is missing (apt-get, as root), or says the command to run."""
    missing = missing_packages()
    if not missing:
        return
    if os.geteuid() != 0:
        raise Failure(f'missing packages: {" ".join(missing)} -- run as root, or: sudo apt-get install -y {" ".join(missing)}')
    say(f'installing: {" ".join(missing)}')
    env = dict(os.environ, DEBIAN_FRONTEND='noninteractive')
    subprocess.run(['apt-get', 'update', '-qq'], check=True, env=env)
    r = subprocess.run(['apt-get', 'install', '-y', '-qq', '--no-install-recommends'] + missing, env=env,
                       stdout=subprocess.DEVNULL)
    still = missing_packages()
    if r.returncode != 0 or still:
        raise Failure(f'still missing after apt-get: {" ".join(still) or "(apt-get failed)"}')


def build(*names, quiet=False, extra=()):
    """Configures (once) and builds presets; warnings, errors and the linkers' memory use shown,
    the per-file progress lines not. `extra`: targets left out of a preset's default build (the
    host's benches: no test uses them) built too."""
    for preset in names or presets():
        out = os.path.join(ROOT, 'build', preset)
        if not os.path.exists(os.path.join(out, 'build.ninja')):
            if not quiet:
                say(f'configuring {preset}')
            r = subprocess.run(['cmake', '--preset', preset], cwd=ROOT, capture_output=True, text=True)
            if r.returncode != 0:
                print(r.stdout + r.stderr, file=sys.stderr)
                raise Failure(f'configure {preset} failed')
        if not quiet:
            say(f'building {preset}')
        targets = ['--target', 'all', *extra] if extra else []
        p = subprocess.Popen(['cmake', '--build', out, '-j', jobs()] + targets, cwd=ROOT, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        for line in p.stdout:
            progress = line.startswith('[') and ('] Building' in line or '] Linking' in line)
            if not progress and not quiet:
                sys.stdout.write(line)
            elif not progress and ('error' in line.lower() or 'warning' in line.lower()):
                sys.stderr.write(line)
        if p.wait() != 0:
            raise Failure(f'build {preset} failed')


def tool(name):
    """A host tool built by the host preset (facet-pack, facet-mesh, facet-sim...)."""
    paths = {
        'facet-pack': 'tools/facet-pack/facet-pack', 'facet-mesh': 'tools/facet-mesh/facet-mesh',
        'facet-measure': 'tools/facet-measure/facet-measure', 'facet-sim': 'tools/sim/facet-sim',
        'facet-sample-model': 'tools/sample-model/facet-sample-model',
        'facet-stress-model': 'tools/stress-models/facet-stress-model',
        'facet-bench-mesh': 'bench/facet-bench-mesh', 'facet-bench-cdt': 'bench/facet-bench-cdt',
        'facet-render-views': 'bench/facet-render-views',
        'facet-example-minimal': 'examples/facet-example-minimal', 'facet-example-own-ui': 'examples/facet-example-own-ui',
        'facet-assembly': 'tools/assembly/facet-assembly',
    }
    return os.path.join(ROOT, 'build', 'host', paths[name])


def pack_address(board):
    import board as boards
    return boards.load(board)['pack']['address']


def run(cmd, **kw):
    """A command; its exit code."""
    return subprocess.run(cmd, cwd=kw.pop('cwd', ROOT), **kw).returncode


def model_pack(model, folder, plain=False, name='model'):
    """A model ready for the viewer, under `folder`: a pack as it is, a STEP file packed, or the
    sample part made and packed (model None). Returns the pack's path (a packed one: NAME.fpk)."""
    os.makedirs(folder, exist_ok=True)
    if model is None:
        model = os.path.join(folder, 'sample.step')
        if run([tool('facet-sample-model'), model], stdout=subprocess.DEVNULL) != 0:
            raise Failure('cannot make the sample part')
    if model.endswith('.fpk'):
        return model
    fpk = os.path.join(folder, f'{name}.fpk')
    if run([tool('facet-pack'), model, '-o', fpk, '--quiet'] + (['--plain'] if plain else []),
           stdout=subprocess.DEVNULL) != 0:
        raise Failure(f'cannot pack {model}')
    return fpk


def existing_file(parser, path):
    """The absolute path of a file named on the command line, or a usage error (exit 2)."""
    full = os.path.abspath(path)
    if not os.path.isfile(full):
        parser.error(f'no such file: {path}')
    return full


def shared_models(pattern_ends=('.stp', '.step')):
    return sorted(os.path.join(MODELS, f) for f in os.listdir(MODELS) if f.endswith(pattern_ends)) \
        if os.path.isdir(MODELS) else []


def fresh(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder, exist_ok=True)
    return folder


def library_of(models, folder, capacity, where, plain=False):
    """Several models packed and joined into one library file (facet-pack --library) under
    `folder`; a Failure naming both sizes when it is larger than `capacity` bytes (`where`)."""
    packs = [model_pack(m, folder, plain=plain, name=f'model-{i + 1}') for i, m in enumerate(models)]
    lib = os.path.join(folder, 'library.flb')
    if run([tool('facet-pack'), '--library', lib] + packs + ['--quiet']) != 0:
        raise Failure('cannot make the library of the models')
    size = os.path.getsize(lib)
    if size > capacity:
        raise Failure(f'the library of {len(models)} models is {size:,} bytes: larger than {where} ({capacity:,} bytes)')
    return lib
