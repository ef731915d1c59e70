#pragma once
// Blocks brought in as the view comes near them: a model larger than the memory is opened with
// its largest blocks, the rest left out and drawn as their proxies, or boxes (loader.h). When the view has
// changed and nothing else is under way, the left-out block largest on the screen is brought
// in: where there is room for its decoded pack and its samples (kBackPixels across at least),
// or, for one kSwapPixels across or more, where held blocks under half its size on the screen
// (off it first, then the smallest) make the room when they are left out. The packs held are
// moved down over theirs, it is decoded at the end in pieces, and then sampled and its faces
// tessellated at the level the view asks, as a refinement is (Scheduler::begin_refine): each
// part stays at one level, watertight. Its parts' boxes stay until its edges are in.
#include "detail.h"
#include "loader.h"
#include "presenter.h"
#include "scene.h"
#include "scheduler.h"

#include <cstdint>

namespace facet::module {

class Swapper {
public:
    static constexpr float kSwapPixels = 32.0f;   // a left-out block this large on the screen comes in
    static constexpr float kBackPixels = 5.0f;    // one this large comes back where there is room (as tiny parts are boxes)
    static constexpr uint32_t kSwapBytes = 16384; // decoded a piece at a time

    // Told when blocks were left out to make room (the picks in them go).
    struct LeftOut {
        void (*fn)(void* user) = nullptr;
        void* user = nullptr;
    };
    // A block that cannot come in is said by a PassFailed event through `emit`.
    Swapper(Scene& scene, Scheduler& scheduler, Presenter& presenter, Detail& detail, const Emitter& emit)
        : scene_(scene), scheduler_(scheduler), presenter_(presenter), detail_(detail), emit_(emit) {}
    void set_left_out(const LeftOut& told) { left_out_ = told; }

    // A new model's blocks and pack memory (none: {}), nothing under way.
    void open(const Unpacked& unpacked) {
        unpacked_ = unpacked;
        block_ = kNone, check_ = false, reading_ = false;
    }
    // The storage came back: blocks it failed to give are looked at again.
    void storage_back();
    // The view changed: the left-out blocks are looked at again.
    void view_changed() { check_ = true; }
    // Blocks to look at, nothing decoding (the caller's to know: no drag).
    bool pending() const { return check_ && block_ == kNone && scene_.blocked() && scene_.left_out().blocks > 0 && unpacked_.memory; }
    // A block is being decoded: block() (kNone: none).
    bool decoding() const { return block_ != kNone; }
    uint32_t block() const { return block_; }

    // With nothing else under way (the caller's to know: no framing, glide or drag): the
    // left-out block largest on the screen begun, with the room made. True when begun.
    bool begin();
    // A piece of the block's decoding (from storage: its read looked at first), or, once decoded,
    // the block opened and its level begun.
    void step();
    // Room for a refinement of block `keep`: every held block off the screen left out. True
    // when some were.
    bool leave_out_unseen(uint32_t keep);

private:
    bool bring_in(uint32_t b); // block b (left out; Block::pixels set): true when begun
    void finish(const geom::PackDecoder* decoder);
    bool failed(uint32_t b, const Result& why);
    uint32_t block_samples(uint32_t b) const; // the samples its edges hold
    void told_left_out() const {
        if (left_out_.fn) left_out_.fn(left_out_.user);
    }

    Scene& scene_;
    Scheduler& scheduler_;
    Presenter& presenter_;
    Detail& detail_;
    Emitter emit_;
    LeftOut left_out_;
    Unpacked unpacked_;     // a blocked pack's blocks and pack memory
    bool check_ = false;    // the view changed since the left-out blocks were last looked at
    uint32_t block_ = kNone; // being decoded
    bool decoded_ = false;  // (opened and begun in the next piece)
    bool reading_ = false;  // its bytes being read from storage (Unpacked::reader)
    geom::PackDecoder decoder_;
};

} // namespace facet::module
