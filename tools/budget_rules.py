"""The handheld's budgets, and how a QEMU run's log and instruction-count regions are measured
against them: one definition of each, imported by tools/budgets.py (the budget report), the QEMU
tests (tests/qemu/) and the benches (bench/).

Budgets: all RAM <= 32 MiB; CPU time in exact guest instructions at 600 MHz, one instruction per
cycle. None grows with the model past a bound (issue 52: a larger model is not allowed to be
slower). The first view (every piece of work from load to the first frame after the first pass)
<= 1.2 G (2 s), whatever the model's size; within it the first pass's tessellation <= 600 M (1 s)
for a model of up to 5,000 faces, beyond that 120 k a face up to the first view's 1.2 G; one
frame <= 20 M instructions per 10,000 triangles in view, at least 20 M (30 frames/s), at most
40 M (15 frames/s) whatever the triangles; a frame at rest (the last before the viewer is idle)
<= 20 M; a zoom's last step to its view's faces in at their level <= 600 M (1 s); the on-screen
interface <= 500 k instructions a frame.
"""
import protocol

MHZ = 600
RAM_BUDGET = 32 << 20
PEAK_RAM_GOAL = 8 << 20  # issue 5's goal for the largest test model, display buffers included

TESSELLATION_BUDGET = 600_000_000  # the first pass's tessellation, 1 s, for a model of up to TESSELLATION_FACES
TESSELLATION_FACES = 5_000
FRAME_BUDGET_PER_10K = 20_000_000
FRAME_BUDGET_MOST = 40_000_000  # issue 52: every frame, whatever the model (15 frames/s)
REST_FRAME_BUDGET = 20_000_000  # issue 52: a frame at rest, whatever the model
ZOOM_DETAIL_BUDGET = 600_000_000  # issue 52: a zoom's last step to its full detail, 1 s


def peak_ram(rep):
    """RAM the model needed at its peak: code, data, display and depth buffers, MMU table as
    reserved; the stack's high-water; the pack, with the viewer's storage at its peak or (while
    a deflated pack is inflated, before any storage is used) with the file it came from (the
    rest of the arena and pack regions is capacity for larger models). None without the
    firmware's @memory line."""
    mem, ram = rep.get('memory'), rep.get('ram', {})
    if not mem or 'storage_peak_bytes' not in mem or rep.get('stack_used') is None:
        return None
    fixed = sum(v for k, v in ram.items() if k not in ('arena', 'pack', 'stack', 'total'))
    pack = mem.get('pack_bytes', 0)
    file = mem.get('pack_file_bytes', 0) if mem.get('pack_file_bytes', 0) != pack else 0
    return fixed + rep['stack_used'] + pack + max(mem['storage_peak_bytes'], file)


def unpack_instructions(regions):
    """Instructions to inflate a deflated pack at load (the 'unpack' region), or None."""
    counts = [r['instructions'] for r in regions if r['name'] == 'unpack']
    return counts[0] if counts else None


OVERLAY_BUDGET = 500_000  # instructions a frame for the on-screen interface (issue 11)


FIRST_VIEW_BUDGET = 1_200_000_000  # issues 25 and 52: load to the first view, 2 s, whatever the model's size
WORK_REGIONS = ('unpack', 'edges', 'face', 'fit', 'frame', 'update', 'overlay')  # every piece of the viewer's work


def by_model(uart, regions):
    """The log's records with their regions (protocol.with_regions), model by model: a library's
    models opened in turn, each after the first from the unpack that opened it (the last
    '@begin unpack' before its '@model'), the first from the log's start. One list for one model."""
    pairs = list(protocol.with_regions(uart, regions))
    cuts, seen = [0], False
    for i, (r, _) in enumerate(pairs):
        if r.name != 'model':
            continue
        if seen:
            j = i
            while j > cuts[-1] and not (pairs[j][0].name == 'begin' and pairs[j][0].values()['region'] == 'unpack'):
                j -= 1
            cuts.append(j if j > cuts[-1] else i)
        seen = True
    return [pairs[a:b] for a, b in zip(cuts, cuts[1:] + [len(pairs)])]


def first_view(uart, regions, pairs=None):
    """(first frame, first view): every piece of work from load to the end of the first frame
    (a blocked pack's parts as boxes, or the wireframe), and to the end of the first frame after the first pass's faces are in (the
    view at its level of detail); None where the log has no such frame. `pairs`: one model's
    records and regions (by_model) instead of the log's."""
    spent, first, tessellated = 0, None, False
    for r, region in (pairs if pairs is not None else protocol.with_regions(uart, regions)):
        if region and region['name'] in WORK_REGIONS:
            spent += region['instructions'] or 0
        elif r.name == 'tessellation':
            tessellated = True
        elif r.name == 'frame':
            first = spent if first is None else first
            if tessellated:
                return first, spent
    return first, None


def first_view_budget(faces):
    return FIRST_VIEW_BUDGET


def tessellation_budget(faces):
    """The first pass's tessellation: 1 s for a part or a small assembly; beyond
    TESSELLATION_FACES faces 120 k a face, up to the first view's budget, which holds it (so
    that for a large model the first view is what binds)."""
    return min(TESSELLATION_BUDGET * max(1.0, faces / TESSELLATION_FACES), FIRST_VIEW_BUDGET)


def frame_budget(triangles, rest=False):
    return min(FRAME_BUDGET_PER_10K * max(1.0, triangles / 10_000), REST_FRAME_BUDGET if rest else FRAME_BUDGET_MOST)


def zoom_detail(uart, regions, shot='zoomed', pairs=None):
    """Every piece of work from a zoom's last step (the last '@view' before the screenshot
    `shot`, which a session takes once the viewer is idle) to that screenshot: the zoomed view
    brought to its level of detail (blocks brought in and made again, faces the view now wants,
    frames). None where the log has no such screenshot after a view change."""
    spent = None
    for r, region in (pairs if pairs is not None else protocol.with_regions(uart, regions)):
        if r.name == 'view':
            spent = 0
        elif region and region['name'] in WORK_REGIONS:
            spent = None if spent is None else spent + (region['instructions'] or 0)
        elif r.name in ('shot', 'dump') and r.fields() and r.values().get('name') == shot:
            return spent
    return None


def analyse(uart, regions, pairs=None):
    """Per pass: tessellation instructions (its pieces of sampling and faces); per full frame:
    its pieces' instructions (the last 'pieces' frame and overlay regions before its '@frame'
    line: a frame the view outdated while it was drawn is not one), the overlay's part of them,
    the mesh's triangles then, the cost the firmware's own clock gave it (us at 600 MHz) and
    whether it is a frame at rest (the last before an '@idle': what the screen then shows).
    `pairs`: one model's records and regions (by_model) instead of the log's."""
    tess, frames, tri_now, pass_no, pieces, overlay, closed = {}, [], 0, -1, [], [], False
    models = 0  # a library's models opened in turn: the passes of the first keyed by number, the others' by model too
    for r, region in (pairs if pairs is not None else protocol.with_regions(uart, regions)):
        if r.name == 'model':
            models += 1
        elif r.name == 'pass':
            pass_no = r.values()['pass']
            tri_now, closed = 0, False
        elif r.name in ('tessellation', 'retessellation'):
            closed = True  # the pass is in: what follows is the view's (sweeps, refinements)
        elif r.name == 'progress':
            tri_now = r.values()['triangles']
        elif r.name == 'idle' and frames and frames[-1]['rest'] is None:
            frames[-1]['rest'] = True
        elif r.name == 'frame':
            kv = r.values()
            n = kv.get('pieces', 1)
            mine = pieces[-n:] if len(pieces) >= n else [None]
            frames.append({'instructions': None if None in mine else sum(mine), 'triangles': tri_now, 'pass': pass_no,
                           'overlay': overlay[-1] if overlay else 0, 'cost_us': int(kv.get('cost_us', 0)), 'rest': None})
            pieces, overlay = [], []
        elif region:
            n = region['instructions']
            if region['name'] in ('edges', 'face'):
                key = 'view' if closed else pass_no
                key = key if models <= 1 else f'model {models} {key}'
                tess[key] = tess.get(key, 0) + (n or 0)
            elif region['name'] in ('frame', 'overlay'):
                pieces.append(n)  # a frame's cost: its pieces, the overlay's included
            if region['name'] == 'overlay':
                overlay.append(n or 0)
    return tess, frames
