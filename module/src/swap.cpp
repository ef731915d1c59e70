// Blocks brought in as the view comes near them (issue 25): a model larger than the memory is
// opened with its largest blocks, the rest left out and drawn as their boxes (loader.h). When
// the view has changed and nothing else is under way, the left-out block largest on the screen
// is brought in: where there is room for its decoded pack and its samples (kBackPixels across
// at least), or, for one kSwapPixels across or more, where held blocks under half its size on
// the screen (off it first, then the smallest) make the room when they are left out. The packs
// held are moved down over theirs, it is decoded at the end in pieces, and then sampled and its
// faces tessellated at the level the view asks, as a refinement is (Scheduler::begin_refine):
// each part stays at one level, watertight. Its parts' boxes stay until its edges are in.
#include "core.h"

#include <cmath>

namespace facet {

using Scale = module::DetailScale; // (detail_scale.h)

bool Core::block_sphere(uint32_t b, float centre[3], float& radius) const {
    float lo[3], hi[3], r2 = 0;
    scene_.block_box(b, lo, hi);
    if (!(lo[0] <= hi[0])) return false;
    for (int k = 0; k < 3; ++k) centre[k] = 0.5f * (lo[k] + hi[k]), r2 += 0.25f * (hi[k] - lo[k]) * (hi[k] - lo[k]);
    radius = std::sqrt(r2);
    return true;
}

float Core::block_pixels(uint32_t b) {
    float centre[3], r;
    if (!block_sphere(b, centre, r)) return 0;
    (void)judge_with_view();
    return judge_.view().pixels(centre, r);
}

uint32_t Core::block_samples(uint32_t b) const {
    const module::Block& block = scene_.block(b);
    uint32_t n = 0;
    for (uint32_t e = block.first_edge; e < block.first_edge + block.edges; ++e) n += scene_.samples().count[e];
    return n;
}

// The choice and the room made (blocks left out, the pack memory compacted) as a piece of
// unpacking work, when there is a choice to make.
bool Core::swap_piece() {
    if (!swap_pending() || swap_.block != kNone) return false;
    work(Event::Kind::WorkBegin, Work::Unpack, 0);
    const bool begun = swap_for_view();
    work(Event::Kind::WorkEnd, Work::Unpack, 0);
    return begun;
}

bool Core::swap_for_view() {
    if (!swap_pending() || swap_.block != kNone || scheduler_.busy() || scene_.bounding() || framer_.busy() ||
        !glide_.idle()) {
        return false;
    }
    swap_check_ = false;
    // Every block's size on the screen, once (Block::pixels); the largest left out first.
    uint32_t best = kNone;
    float best_pixels = kBackPixels;
    for (uint32_t b = 0; b < scene_.block_count(); ++b) {
        module::Block& block = scene_.block(b);
        block.pixels = block_pixels(b);
        if (block.left_out && !block.refused && !block.broken && block.pixels >= best_pixels) best = b, best_pixels = block.pixels;
    }
    if (best == kNone) return false;
    swap_check_ = true; // the next one at the next moment nothing else is under way (this one in or not)
    return swap_in(best);
}

bool Core::swap_in(uint32_t best) {
    const uint32_t blocks = scene_.block_count();
    const float best_pixels = scene_.block(best).pixels;
    // The room it needs: its decoded pack's, and its samples' (as load plans a block: six an
    // edge; the pool compacted first if short). Held blocks under half its size make it, the
    // least seen first, for a block at least kSwapPixels across; under that, only room free.
    const uint32_t need = module::block_memory(unpacked_, best);
    const uint32_t need_samples = module::Scheduler::kNewBlockSamplesPerEdge * scene_.block(best).edges + 2;
    (void)scheduler_.make_sample_room(need_samples);
    uint64_t room = module::free_block_memory(unpacked_), samples = scene_.samples_room();
    // The victims chosen first (Block::leaving), left out only if together they make the room.
    uint32_t victims = 0;
    while ((room < need || samples < need_samples) && best_pixels >= kSwapPixels) {
        uint32_t victim = kNone;
        float least = 0.5f * best_pixels;
        for (uint32_t b = 0; b < blocks; ++b) {
            const module::Block& block = scene_.block(b);
            if (block.left_out || block.leaving) continue;
            if (block.pixels <= least && (victim == kNone || block.pixels < least)) victim = b, least = block.pixels;
        }
        if (victim == kNone) break;
        scene_.block(victim).leaving = true;
        room += module::block_memory(unpacked_, victim), samples += block_samples(victim);
        ++victims;
    }
    const bool fits = room >= need && samples >= need_samples;
    for (uint32_t b = 0; b < blocks && victims; ++b) {
        module::Block& block = scene_.block(b);
        if (!block.leaving) continue;
        block.leaving = false;
        if (fits) scene_.drop_block(b);
    }
    if (!fits) { // it stays a box until the view changes
        scene_.block(best).refused = true;
        return false;
    }
    if (victims) forget_left_out_picks();
    presenter_.invalidate();
    module::compact_blocks(unpacked_); // (the free room after the blocks held)
    swap_.block = best, swap_.decoded = false;
    if (Result r = module::start_block(unpacked_, best, swap_.decoder); !r.ok() && r.status != Status::Busy) return swap_failed(best, r);
    if (need == 0) swap_finish(nullptr); // read in place
    return true;
}

// A piece of decoding (LZMA: kSwapBytes; DEFLATE: the block at once, up to about 64 KB), then
// in a piece of its own the block opened (checked) and begun.
void Core::swap_step() {
    if (swap_.decoded) {
        swap_finish(&swap_.decoder);
        return;
    }
    const Result r = swap_.decoder.run(kSwapBytes);
    if (r.status == Status::Busy) return;
    if (!r.ok()) {
        (void)swap_failed(swap_.block, r.within({"block", swap_.block}));
        return;
    }
    swap_.decoded = true;
}

void Core::swap_finish(const geom::PackDecoder* decoder) {
    const uint32_t b = swap_.block;
    if (Result r = module::finish_block(unpacked_, b, decoder, scene_); !r.ok()) {
        (void)swap_failed(b, r);
        return;
    }
    swap_.block = kNone;
    swap_check_ = true; // (the next one, once this one is in)
    presenter_.invalidate();
    if (!scheduler_.begin_refine(b, wanted_tolerance(b, scheduler_.tolerance(), Scale::kRefineFinest, nullptr))) {
        // No room for its samples even after the caches made some: a box again until the view changes.
        scene_.drop_block(b);
        scene_.block(b).refused = true;
    }
}

bool Core::leave_out_unseen(uint32_t keep) {
    if (!unpacked_.memory || scheduler_.busy() || swap_.block != kNone) return false;
    uint32_t dropped = 0;
    for (uint32_t b = 0; b < scene_.block_count(); ++b) {
        if (b == keep || scene_.block(b).left_out || block_pixels(b) > 0) continue;
        scene_.drop_block(b);
        ++dropped;
    }
    if (!dropped) return false;
    forget_left_out_picks();
    presenter_.invalidate();
    return true;
}

// A face picked in a block left out is no longer there to describe or highlight: the
// selection and the measurement go (as after a tap on nothing).
void Core::forget_left_out_picks() {
    if (!selection_.forget([&](const Picked& p) { return scene_.block_of_face(p.face).left_out; })) return;
    highlight();
    show_measurement();
}

// A block that could not come in: said by a PassFailed event naming it, and left out (a box)
// until the view changes, or for good when it is corrupt (anything but a want of room).
bool Core::swap_failed(uint32_t b, const Result& why) {
    swap_.block = kNone;
    scene_.block(b).refused = true;
    scene_.block(b).broken = scene_.block(b).broken || why.status != Status::Full;
    Event e{};
    e.kind = Event::Kind::PassFailed;
    e.pass = {scheduler_.pass(), scheduler_.tolerance(), scene_.samples().used};
    e.why = why;
    emit(e);
    return true;
}

} // namespace facet
