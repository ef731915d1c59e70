// Blocks brought in as the view comes near them (swap.h).
#include "swap.h"

namespace facet::module {

using Scale = DetailScale; // (detail_scale.h)

uint32_t Swapper::block_samples(uint32_t b) const {
    const Block& block = scene_.block(b);
    uint32_t n = 0;
    for (uint32_t e = block.first_edge; e < block.first_edge + block.edges; ++e) n += scene_.samples().count[e];
    return n;
}

bool Swapper::begin() {
    if (!pending() || scheduler_.busy()) return false;
    check_ = false;
    // Every block's size on the screen, once (Block::pixels); the largest left out first.
    uint32_t best = kNone;
    float best_pixels = kBackPixels;
    for (uint32_t b = 0; b < scene_.block_count(); ++b) {
        Block& block = scene_.block(b);
        block.pixels = detail_.block_pixels(b);
        if (block.left_out && !block.refused && !block.broken && block.pixels >= best_pixels && !detail_.served_by_proxies(b)) {
            best = b, best_pixels = block.pixels;
        }
    }
    if (best == kNone) return false;
    check_ = true; // the next one at the next moment nothing else is under way (this one in or not)
    return bring_in(best);
}

bool Swapper::bring_in(uint32_t best) {
    const uint32_t blocks = scene_.block_count();
    const float best_pixels = scene_.block(best).pixels;
    // The room it needs: its decoded pack's, and its samples' (as load plans a block: six an
    // edge; the pool compacted first if short). Held blocks under half its size make it, the
    // least seen first, for a block at least kSwapPixels across; under that, only room free.
    const uint32_t need = block_memory(unpacked_, best), stage = block_staging(unpacked_, best);
    const uint32_t need_samples = Scheduler::kNewBlockSamplesPerEdge * scene_.block(best).edges + 2;
    (void)scheduler_.make_sample_room(need_samples);
    uint64_t room = free_block_memory(unpacked_), samples = scene_.samples_room();
    // The victims chosen first (Block::leaving), left out only if together they make the room.
    uint32_t victims = 0;
    while ((room < need + stage || samples < need_samples) && best_pixels >= kSwapPixels) {
        uint32_t victim = kNone;
        float least = 0.5f * best_pixels;
        for (uint32_t b = 0; b < blocks; ++b) {
            const Block& block = scene_.block(b);
            if (block.left_out || block.leaving) continue;
            if (block.pixels <= least && (victim == kNone || block.pixels < least)) victim = b, least = block.pixels;
        }
        if (victim == kNone) break;
        scene_.block(victim).leaving = true;
        room += block_memory(unpacked_, victim), samples += block_samples(victim);
        ++victims;
    }
    const bool fits = room >= need + stage && samples >= need_samples;
    for (uint32_t b = 0; b < blocks && victims; ++b) {
        Block& block = scene_.block(b);
        if (!block.leaving) continue;
        block.leaving = false;
        if (fits) scene_.drop_block(b);
    }
    if (!fits) { // it stays a box until the view changes
        scene_.block(best).refused = true;
        return false;
    }
    // Parts left out change from their faces to their proxies (or boxes); with none, nothing
    // on the screen changes (the block chosen stays as it is drawn, left out, until its edges
    // are sampled: Core::run_tessellation).
    if (victims) told_left_out(), presenter_.invalidate();
    compact_blocks(unpacked_); // (the free room after the blocks held)
    block_ = best, decoded_ = false;
    const Result r = start_block(unpacked_, best, decoder_);
    reading_ = unpacked_.reader && unpacked_.reader->reading();
    if (!r.ok() && r.status != Status::Busy) return failed(best, r);
    if (need == 0 || (r.ok() && stage == 0)) finish(nullptr); // read in place, or read to its place
    return true;
}

// A piece of decoding (LZMA: kSwapBytes; DEFLATE: the block at once, up to about 64 KB), then
// in a piece of its own the block opened (checked) and begun.
void Swapper::step() {
    if (reading_) { // from storage: the read ended, then its decoding begun
        Result r = unpacked_.reader->poll();
        if (r.status == Status::Busy) return;
        reading_ = false;
        if (r.ok()) r = decode_block(unpacked_, block_, decoder_);
        if (r.ok()) {
            finish(nullptr); // (a plain block: read to its place)
        } else if (r.status != Status::Busy) {
            (void)failed(block_, r.within({"block", block_}));
        }
        return;
    }
    if (decoded_) {
        finish(&decoder_);
        return;
    }
    const Result r = decoder_.run(kSwapBytes);
    if (r.status == Status::Busy) return;
    if (!r.ok()) {
        (void)failed(block_, r.within({"block", block_}));
        return;
    }
    decoded_ = true;
}

void Swapper::finish(const geom::PackDecoder* decoder) {
    const uint32_t b = block_;
    if (Result r = finish_block(unpacked_, b, decoder, scene_); !r.ok()) {
        (void)failed(b, r);
        return;
    }
    block_ = kNone;
    check_ = true; // (the next one, once this one is in)
    // (Its parts are drawn as they were while left out, their proxies or boxes, until their
    // edges are sampled: the frames change then, Core::run_tessellation.)
    if (!scheduler_.begin_refine(b, detail_.wanted_tolerance(b, scheduler_.tolerance(), Scale::kRefineFinest, nullptr))) {
        // No room for its samples even after the caches made some: a box again until the view changes.
        scene_.drop_block(b);
        scene_.block(b).refused = true;
    }
}

void Swapper::storage_back() {
    for (uint32_t b = 0; b < scene_.block_count(); ++b) scene_.block(b).refused = false;
    check_ = true;
}

bool Swapper::leave_out_unseen(uint32_t keep) {
    if (!unpacked_.memory || scheduler_.busy() || block_ != kNone) return false;
    uint32_t dropped = 0;
    for (uint32_t b = 0; b < scene_.block_count(); ++b) {
        if (b == keep || scene_.block(b).left_out || detail_.block_pixels(b) > 0) continue;
        scene_.drop_block(b);
        ++dropped;
    }
    if (!dropped) return false;
    told_left_out();
    presenter_.invalidate();
    return true;
}

// A block that could not come in: said by a PassFailed event naming it, and left out (a box)
// until the view changes, or for good when it is corrupt (anything but a want of room).
bool Swapper::failed(uint32_t b, const Result& why) {
    block_ = kNone;
    scene_.block(b).refused = true;
    // (a storage that failed, or went away, may be back: Io is not for good)
    scene_.block(b).broken = scene_.block(b).broken || (why.status != Status::Full && why.status != Status::Io);
    Event e{};
    e.kind = Event::Kind::PassFailed;
    e.pass = {scheduler_.pass(), scheduler_.tolerance(), scene_.samples().used};
    e.why = why;
    emit_(e);
    return true;
}

} // namespace facet::module
