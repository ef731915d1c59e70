"""./facet run, sim, example and flash: the viewer on QEMU, in the simulator's window, the C
example, and the evaluation board's image."""
import json
import os
import subprocess
import sys

from common import (INCOMPLETE_MESH, OVER_BUDGET, ROOT, Failure, build, existing_file, fresh, library_of, model_pack,
                    pack_address, preset_of, run, say, setup, tool)

RUN_BOARD = 'qemu-versatilepb'  # the main job's: an ARM926 without an FPU, like the paper's handheld
SHOTS = ['wireframe', 'half', 'done', 'turned', 'dragged', 'zoomed', 'views', 'hidden-line', 'section', 'parts',
         'measure']
LIBRARY_SHOTS = ['wireframe', 'half', 'done', 'turned', 'chooser', 'second']
CARD_ROW_Y, CARD_ROW_H = 42, 20  # the chooser's first row's middle and its rows' height (module/src/overlay.cpp)


def add(sub):
    p = sub.add_parser('run', help='set up, build and run the main job: the viewer in QEMU, screenshots, budgets',
                       description='Set up, build, and run the main job: make the sample part (or take MODEL.step), '
                       'pack it, boot the viewer in QEMU (versatilepb: ARM926EJ-S, 32 MiB), which shows the wireframe, '
                       'fills in the faces, then is turned, dragged, zoomed, put in the isometric view and in hidden '
                       'line, cut by a section, shown with its parts list and clicked, by the session '
                       'tests/sessions/run.session. Screenshots, uart.log, report.json and the budget report '
                       '(budgets.json, budgets.md) go to out/run/. Exit 4 over a budget, 5 when faces failed.')
    p.add_argument('model', nargs='*', metavar='MODEL.step', help='a STEP file (default: the sample part); several: '
                   'a library on the device, the chooser (key b) opening the second (tests/sessions/library.session)')
    p.add_argument('--window', action='store_true', help='a QEMU window to use yourself instead of the script '
                   '(keys on the terminal, the mouse in the window; h lists the keys, q quits)')
    p.add_argument('--card', action='store_true', help='the models on a memory card instead: each packed onto a FAT32 '
                   'image (out/run/card.img; the sample part and an assembly of it unless models are given) in the '
                   "SD slot; the viewer lists them and opens the first, the session opens each from the chooser")
    p.set_defaults(run=cmd_run)

    p = sub.add_parser('sim', help='the desktop simulator: the module in an SDL window',
                       description='The module in an SDL window: mouse (left drag orbits, right drag pans, wheel '
                       'zooms, a click picks), touch (one finger orbits, two pinch and pan), keys as on the boards '
                       '(h lists them). The sample part unless a model is given.')
    p.add_argument('model', nargs='*', metavar='MODEL.step|MODEL.fpk', help='several: a library (key b chooses)')
    p.add_argument('--size', metavar='WxH', help='the screen: 480x272 (the EVKB) or 640x480')
    p.add_argument('--bands', metavar='N', help='draw in bands of N lines')
    p.add_argument('--scale', metavar='K', help='window pixels per screen pixel')
    p.add_argument('--ram', metavar='MIB', help="the module in that much RAM, as a device (a model larger opens in "
                   'part; its other parts come in as the view nears them)')
    p.add_argument('--headless', action='store_true', help='no window: screenshots to out/sim')
    p.set_defaults(run=cmd_sim)

    p = sub.add_parser('example', help='a C example (examples/minimal or own-ui) in QEMU and on the host',
                       description='Build and run a C example in QEMU (versatilepb) and on the host: examples/minimal '
                       '(C99, bands of 16 lines) or examples/own-ui (a product screen with its own buttons, facet in '
                       'a viewport, driven through the C API); pictures under out/example/.')
    p.add_argument('model', nargs='?', metavar='MODEL.step')
    p.add_argument('--which', choices=('minimal', 'own-ui'), default='minimal', help='the example (default: minimal)')
    p.set_defaults(run=cmd_example)

    p = sub.add_parser('flash', help="the MIMXRT1060-EVKB's image and a model's pack onto the board",
                       description="Build the MIMXRT1060-EVKB image and the model's plain pack (the sample part "
                       'unless a model is given; read in place from flash), write out/flash/facet-evkb.hex (firmware '
                       "+ pack), .bin and pack.hex, and copy the .hex onto the board's debug-probe drive (found "
                       'mounted, or --drive). Several models: a library of them (the viewer lists them, key b), '
                       'refused with both sizes when larger than the pack region. With no board: exit 3 and what to '
                       'do (docs/boards.md).')
    p.add_argument('model', nargs='*', metavar='MODEL.step|MODEL.fpk')
    p.add_argument('--drive', metavar='DIR', help="the probe's drive (default: found mounted)")
    p.add_argument('--pack-only', action='store_true', help='the pack alone: a new model without a new firmware')
    p.add_argument('--wait', metavar='SECONDS', help='wait this long for the drive to appear')
    p.set_defaults(run=cmd_flash)


def card_of(models, out):
    """The models packed onto a card image (the sample part and a few copies of it placed as an
    assembly when none are given), and a session that opens each from the chooser."""
    import card
    if not models:
        say('making the sample part and an assembly of it (Open CASCADE): out/run/sample.step, sample-assembly.step')
        sample = os.path.join(out, 'sample.step')
        if run([tool('facet-sample-model'), sample], stdout=subprocess.DEVNULL) != 0:
            raise Failure('cannot make the sample part')
        assembly = os.path.join(out, 'sample-assembly.step')
        if run([tool('facet-assembly'), assembly, '--faces', '600', sample], stdout=subprocess.DEVNULL) != 0:
            raise Failure('cannot make the sample assembly')
        models = [sample, assembly]
    files = []
    for i, m in enumerate(models):
        base = os.path.splitext(os.path.basename(m))[0]
        files.append((model_pack(m, out, name=f'card-{i + 1}'), f'{base}.fpk'))
    image = os.path.join(out, 'card.img')
    size = card.make(image, files)
    say(f'a {size >> 20} MiB FAT32 card: ' + ', '.join(f'{n} ({os.path.getsize(p):,} bytes)' for p, n in files))
    shots = ['wireframe', 'half', 'done', 'chooser']
    lines = ['# ./facet run --card: the first model opens; then the chooser (key b) opens each of the others', 'screen 640x480',
             'keys b', 'keys !shot chooser\\n', 'keys b']
    for i in range(1, len(files)):
        lines += ['keys b', f'point 60 {CARD_ROW_Y + CARD_ROW_H * i}', 'press left', 'release left', f'keys !shot model-{i + 1}\\n']
        shots.append(f'model-{i + 1}')
    lines.append('keys q')
    session = os.path.join(out, 'card.session')
    with open(session, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    return image, session, shots, ' + '.join(n for _, n in files)


def cmd_run(args, parser):
    models = [existing_file(parser, m) for m in args.model]
    setup()
    build(RUN_BOARD, 'host')
    out = fresh(os.path.join(ROOT, 'out', 'run'))
    if args.card:
        return run_card(args, models, out)
    if not models:
        say('making the sample part (Open CASCADE): out/run/sample.step')
    if len(models) > 1:  # a library: the device lists them, the session opens the second from its chooser
        import board as boards
        fpk = library_of(models, out, boards.load(RUN_BOARD)['pack_bytes'], f"{RUN_BOARD}'s pack region")
        name = ' + '.join(os.path.basename(m) for m in models)
        say(f'packed {len(models)} models into a library: {os.path.getsize(fpk):,} bytes')
    else:
        fpk = model_pack(models[0] if models else None, out)
        name = os.path.basename(models[0]) if models else 'sample.step'
        say(f'packed {name}: {os.path.getsize(fpk):,} bytes')
    say(f'booting the viewer in QEMU ({RUN_BOARD}: ARM926EJ-S, 32 MiB) with the pack loaded')
    cmd = [sys.executable, 'tools/qemu/run.py', '--board', RUN_BOARD,
           '--elf', f'build/{RUN_BOARD}/firmware/facet-viewer.elf', '--out', out,
           '--load', f'{fpk}@{pack_address(RUN_BOARD)}', '--icount', '--timeout', '900']
    cmd += ['--window'] if args.window else ['--quiet', '--session', 'library' if len(models) > 1 else 'run']
    return boot_and_report(cmd, out, name, LIBRARY_SHOTS if len(models) > 1 else SHOTS, args.window)


def boot_and_report(cmd, out, name, shots, window):
    """The viewer booted (cmd: run.py's), then the budget report and the screenshots said; a
    Failure when the run failed or a shot is missing, exit 4 over a budget, 5 when faces failed."""
    if run(cmd) != 0:
        log = os.path.join(out, 'uart.log')
        if os.path.exists(log):
            print(''.join(open(log).readlines()[-20:]), file=sys.stderr)
        raise Failure('the viewer run failed (out/run/uart.log)')
    if window:
        return 0
    rc = run([sys.executable, 'tools/budgets.py', os.path.join(out, 'report.json'), '--json', os.path.join(out, 'budgets.json'),
              '--markdown', os.path.join(out, 'budgets.md'), '--model', name, '--strict'])
    missing = [s for s in shots if not os.path.exists(os.path.join(out, f'{s}.png'))]
    if missing:
        raise Failure('screenshots missing: ' + ', '.join(missing) + ' (out/run/uart.log)')
    say('screenshots out/run/{' + ','.join(shots) + '}.png, budget report out/run/budgets.json (.md)')
    for p in json.load(open(os.path.join(out, 'report.json'))).get('picks', []):
        print(f'  picked face {p["face"]}: {"; ".join(p["lines"])}')
    if rc == OVER_BUDGET:
        raise Failure('OVER BUDGET (exit 4): out/run/budgets.md says where', OVER_BUDGET)
    if rc == INCOMPLETE_MESH:
        raise Failure('INCOMPLETE MESH (exit 5): faces failed on the device, out/run/uart.log says why', INCOMPLETE_MESH)
    if rc != 0:
        raise Failure(f'the budget report failed (exit {rc})')
    return 0


def run_card(args, models, out):
    image, session, shots, name = card_of(models, out)
    say(f'booting the viewer in QEMU ({RUN_BOARD}) with the card in its SD slot (PL181)')
    cmd = [sys.executable, 'tools/qemu/run.py', '--board', RUN_BOARD, '--elf', f'build/{RUN_BOARD}/firmware/facet-viewer.elf',
           '--out', out, '--card', image, '--icount', '--timeout', '900']
    cmd += ['--window'] if args.window else ['--quiet', '--session', session]
    return boot_and_report(cmd, out, name, shots, args.window)


def cmd_sim(args, parser):
    models = [existing_file(parser, m) for m in args.model]
    if not args.headless and not (os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY') or
                                  os.environ.get('SDL_VIDEODRIVER')):
        raise Failure("no display for the simulator's window: run it on a desktop, under xvfb-run, or with "
                      '--headless (screenshots to out/sim)')
    setup()
    build('host', quiet=True)
    folder = os.path.join(ROOT, 'out', 'sim')
    if len(models) > 1:
        fpk = library_of(models, folder, 1 << 30, 'any')  # (the simulator's memory: the model's needs)
    else:
        fpk = model_pack(models[0] if models else None, folder)
    extra = []
    for opt in ('size', 'bands', 'scale', 'ram'):
        if getattr(args, opt):
            extra += [f'--{opt}', getattr(args, opt)]
    if args.headless:
        extra.append('--headless')
    say(f'facet-sim: {os.path.basename(fpk)} (h lists the keys, Esc or q quits)')
    os.execv(tool('facet-sim'), [tool('facet-sim'), '--pack', fpk, '--out', os.path.join(ROOT, 'out', 'sim')] + extra)


def cmd_example(args, parser):
    model = existing_file(parser, args.model) if args.model else None
    setup()
    build('host', 'qemu-versatilepb', quiet=True)
    out = fresh(os.path.join(ROOT, 'out', 'example'))
    fpk = model_pack(model, out)
    name = args.which
    say(f'examples/{name} on the host (480x272): out/example/host.png')
    if run([tool(f'facet-example-{name}'), fpk, os.path.join(out, 'host.f565'), '480x272']) != 0:
        raise Failure('the example failed on the host')
    run([sys.executable, 'tools/img.py', 'topng', os.path.join(out, 'host.f565'), os.path.join(out, 'host.png')])
    say(f'examples/{name} in QEMU (versatilepb, 640x480, bands of 16 lines): out/example/qemu/{name}.png')
    return run([sys.executable, 'tools/qemu/run.py', '--board', 'qemu-versatilepb',
                '--elf', f'build/qemu-versatilepb/examples/facet-example-{name}.elf', '--out', os.path.join(out, 'qemu'),
                '--load', f'{fpk}@{pack_address("qemu-versatilepb")}', '--timeout', '300'])


def flash_board():
    """The board ./facet flash writes: the one whose board.json names a flash runner."""
    import board as boards
    found = [b for b in boards.names() if boards.can(b, 'flash_runner')]
    if len(found) != 1:
        raise Failure(f'./facet flash needs exactly one board with a flash_runner in its board.json (found {found})')
    return found[0]


def cmd_flash(args, parser):
    models = [existing_file(parser, m) for m in args.model]
    board = flash_board()
    preset = preset_of(board)
    setup()
    build('host', preset, quiet=True)
    out = os.path.join(ROOT, 'out', 'flash')
    os.makedirs(out, exist_ok=True)
    # A plain pack: the board reads it in place from flash (nothing to inflate at boot); a .fpk
    # as it is (a compressed one is decoded into SDRAM). Several: a library of plain packs.
    if len(models) > 1:
        import board as boards
        fpk = library_of(models, out, boards.load(board)['pack_bytes'], "the board's flash pack region", plain=True)
    else:
        fpk = model_pack(models[0] if models else None, out, plain=True)
    extra = []
    if args.drive:
        extra += ['--drive', args.drive]
    if args.pack_only:
        extra.append('--pack-only')
    if args.wait:
        extra += ['--wait', args.wait]
    return run([sys.executable, 'tools/flash.py', '--image', f'build/{preset}/firmware/facet-viewer.bin', '--pack', fpk,
                '--out', out] + extra)

