// The level of detail the view asks for: which faces are worth their triangles now.
//
// A face is tessellated when some instance of its part shows it at least FaceJudge::kMinPixels across
// (its sphere, bounded by its edges' samples, at its nearest point), on the screen, and (a
// closed part's plane, cylinder or cone face, no section on) facing the eye; the rest are
// deferred (FaceState::Deferred): drawn by their edges, and judged again once the view changes
// (the scheduler's sweep), so zooming in brings in what grew and turning what came round. Each
// block's level follows the view too: set as a pass reaches it, and refined or coarsened when
// the view has moved far enough (refine_for_view).
#include "detail.h"
#include "swap.h"
#include "geom/fmath.h"
#include "geom/params.h"

#include <algorithm>
#include <cmath>

namespace facet::module {

using Scale = DetailScale; // (detail_scale.h)
// A block's tolerance: the pass's (the default, or the bias the user chose) scaled by how far
// the block lies: Config::screen_error_px (half a pixel) at its nearest point in the view the
// pass starts from (before the first pass is framed: the whole model's sphere fitted), never
// finer than the pass's and at most Scale::kBlockCoarsest times it. A part near the eye gets the pass's
// own; a far one coarser.
float Detail::block_tolerance(void* self, uint32_t b, float pass_tolerance) {
    return static_cast<Detail*>(self)->wanted_tolerance(b, pass_tolerance, 1, nullptr);
}

float Detail::wanted_tolerance(uint32_t b, float pass_tolerance, float finest, bool* on_screen) {
    if (on_screen) *on_screen = true;
    if (default_tolerance_ <= 0 || !(screen_error_px_ > 0)) return pass_tolerance;
    float centre[3], r;
    if (!block_sphere(b, centre, r)) return pass_tolerance;
    (void)judge_.update();
    if (on_screen) *on_screen = judge_.view().pixels(centre, r) > 0;
    const float bias = pass_tolerance / default_tolerance_;
    const float crowd = std::min(crowd_, Scale::kCrowdMeshCoarsest);
    float t = bias * screen_error_px_ * crowd * judge_.view().mm_per_pixel(centre, r);
    // Never finer than the block would take as a model of its own (its share of the model's
    // size: a part of a large assembly zoomed into gets its own detail, a one-block model
    // keeps the pass's), nor than `finest` times the pass's.
    const float own = scene_.radius() > 0 ? pass_tolerance * std::min(1.0f, r / scene_.radius()) : pass_tolerance;
    const float floor = std::max(own, pass_tolerance / finest);
    if (t < floor) t = floor;
    if (t > Scale::kBlockCoarsest * crowd * pass_tolerance) t = Scale::kBlockCoarsest * crowd * pass_tolerance;
    return t;
}

// When nothing else is under way and the view has changed: the block whose level is furthest
// from what the view now asks for (Scale::kStep times too coarse and on the screen, or as many
// times too fine) is tessellated again at that level, down to Scale::kRefineFinest times finer than the pass
// for a part of a large model zoomed into (wanted_tolerance). One at a time, largest gap first;
// none while a finger drags the view. Once at the view's level, a block moves again only when
// the view has moved by that factor.
bool Detail::refine(Swapper& room) {
    if (!check_ || scheduler_.busy()) return false;
    for (;;) { // (a block refused, for want of room, is passed over the next time round)
        uint32_t best = kNone;
        float best_gap = 1, best_tolerance = 0;
        for (uint32_t b = 0; b < scene_.block_count(); ++b) {
            const Block& block = scene_.block(b);
            if (!(block.tolerance > 0) || block.refused || served_by_proxies(b)) continue;
            bool on_screen = true;
            const float want = wanted_tolerance(b, scheduler_.tolerance(), Scale::kRefineFinest, &on_screen);
            const float finer = block.tolerance / want, coarser = want / block.tolerance;
            const float gap = finer >= Scale::kStep && on_screen && !crowded_ ? finer : coarser >= Scale::kStep ? coarser : 0;
            if (gap > best_gap) best = b, best_gap = gap, best_tolerance = want;
        }
        if (best == kNone) {
            check_ = false;
            return false;
        }
        if (scheduler_.begin_refine(best, best_tolerance)) return true;
        // No room: blocks off the screen make it, where they can come back (swap.cpp); short
        // of it still, a finer level part of the way (Scale::kStep at a time from the wanted).
        const float now = scene_.block(best).tolerance;
        const bool left = room.leave_out_unseen(best);
        for (float t = best_tolerance * (left ? 1 : Scale::kStep); t < now / Scale::kStep * 1.001f; t *= Scale::kStep) {
            scene_.block(best).refused = false;
            if (scheduler_.begin_refine(best, t)) return true;
        }
        scene_.block(best).refused = true; // (passed over the next time round, whatever refused it)
    }
}

uint32_t Detail::triangle_bound() const {
    const SphereView& v = judge_.view();
    const uint32_t pixels = uint32_t(4.0f * v.half_w * v.half_h);
    return std::max(pixels / Scale::kPixelsPerTriangle, Scale::kLeastTriangleBound);
}

// A blocked model's triangles bounded by the screen (issue 52): past the bound (the triangles a
// frame of the view takes, each instance's: what its cost follows), or where that frame took
// longer than `frame_budget_us` (a frame at rest's), every block's screen error is taken kStep
// times coarser (refine() then makes again the blocks now twice finer than the view asks,
// largest gap first, and more parts are drawn as their proxies); under a quarter of the bound
// (half, and half the time, where the parts have proxies: they cost little to change), kStep
// finer again, though never to a crowd this view was over at. Where the parts have no
// proxies, the triangles held count when they are more (a block brought in since that
// frame); where they have, what is held is not what is drawn.
bool Detail::bound_triangles(uint32_t in_view, uint32_t frame_us, uint32_t frame_budget_us) {
    if (!scene_.blocked() || scene_.block_count() < 2) return false; // (a part alone keeps the detail it was given)
    const bool proxies = scene_.index().proxy_levels() > 0;
    const uint32_t held = proxies ? in_view : std::max(in_view, scene_.totals().triangles), bound = triangle_bound();
    const bool slow = frame_budget_us && frame_us > frame_budget_us, quick = !frame_budget_us || frame_us < frame_budget_us / 2;
    if (!judged_crowd_) {
        look_first();
    } else if (held != judged_held_ || frame_us != judged_us_) { // (once a frame: the next one shows what this step did)
        if ((held > bound || slow) && crowd_ < (proxies ? Scale::kCrowdCoarsest : Scale::kCrowdMeshCoarsest)) {
            over_crowd_ = std::max(over_crowd_, crowd_);
            crowd_ *= Scale::kStep, check_ = true;
        } else if (held < bound / (proxies ? 2 : 4) && (!proxies || quick) && crowd_ > 1 && crowd_ / Scale::kStep > over_crowd_) {
            crowd_ /= Scale::kStep, check_ = true; // (never back to a crowd this view was over at)
        }
    }
    judged_held_ = held, judged_us_ = frame_us;
    crowded_ = held > bound || slow;
    return crowded_;
}

// The first look, before any frame has counted the view's triangles (the first frames draw the
// parts at their coarsest proxies, which say nothing of it): a view of a model with proxies
// where two triangles a face, every instance's, pass the bound starts as crowded as it can be
// (its parts as proxies, no block brought in for them), and is made finer as its frames show
// room.
void Detail::look_first() {
    if (judged_crowd_) return;
    judged_crowd_ = true;
    if (!scene_.blocked() || scene_.block_count() < 2 || scene_.index().proxy_levels() == 0) return;
    (void)judge_.update();
    uint64_t least = 0;
    for (const auto& i : scene_.instances()) least += 2 * uint64_t(scene_.index().parts()[i.shell].face_count); // (left out or not)
    if (least > triangle_bound()) crowd_ = Scale::kCrowdCoarsest, check_ = true;
}

// Work in screen order: a pass or a sweep takes the blocks largest on the screen first (their
// boxes' spheres; off the screen last), so what the view shows large is shaded first. A merge
// sort of the chain (Block::next), stable: equal ones keep the pack's order.
uint32_t Detail::block_order(void* self) {
    Detail& c = *static_cast<Detail*>(self);
    Scene& scene = c.scene_;
    const uint32_t n = scene.block_count();
    for (uint32_t b = 0; b < n; ++b) {
        Block& block = scene.block(b);
        block.pixels = block.left_out ? 0 : c.block_pixels(b);
        block.next = b + 1 < n ? b + 1 : kNone;
    }
    uint32_t head = n ? 0 : kNone;
    return n ? c.sort_blocks(head, n) : kNone;
}

// The first `count` blocks of the chain from `head` sorted (largest first); head moves past them.
uint32_t Detail::sort_blocks(uint32_t& head, uint32_t count) {
    if (count == 1) {
        const uint32_t one = head;
        head = scene_.block(one).next;
        scene_.block(one).next = kNone;
        return one;
    }
    uint32_t a = sort_blocks(head, count / 2), b = sort_blocks(head, count - count / 2);
    uint32_t first = kNone, *tail = &first;
    while (a != kNone && b != kNone) {
        uint32_t& take = scene_.block(b).pixels > scene_.block(a).pixels ? b : a;
        *tail = take, tail = &scene_.block(take).next, take = scene_.block(take).next;
    }
    *tail = a != kNone ? a : b;
    return first;
}

bool Detail::block_sphere(uint32_t b, float centre[3], float& radius) const {
    float lo[3], hi[3], r2 = 0;
    scene_.block_box(b, lo, hi);
    if (!(lo[0] <= hi[0])) return false;
    for (int k = 0; k < 3; ++k) centre[k] = 0.5f * (lo[k] + hi[k]), r2 += 0.25f * (hi[k] - lo[k]) * (hi[k] - lo[k]);
    radius = std::sqrt(r2);
    return true;
}

bool Detail::served_by_proxies(uint32_t b) {
    const geom::PackIndex& index = scene_.index();
    const uint32_t levels = scene_.blocked() ? index.proxy_levels() : 0;
    float centre[3], r;
    if (levels == 0 || !(crowd_ > 1) || !(screen_error_px_ > 0) || !block_sphere(b, centre, r)) return false;
    (void)judge_.update();
    const float allowed_mm = screen_error_px_ * crowd_ * judge_.view().mm_per_pixel(centre, r);
    const Block& block = scene_.block(b);
    for (uint32_t p = block.first_part; p < scene_.part_count() && scene_.part(p).block == b; ++p) {
        const pack::ProxyPart& finest = index.proxy(p, levels - 1);
        if (finest.triangle_count == 0 || !(finest.error_mm <= allowed_mm)) return false;
    }
    return true;
}

float Detail::block_pixels(uint32_t b) {
    float centre[3], r;
    if (!block_sphere(b, centre, r)) return 0;
    (void)judge_.update();
    return judge_.view().pixels(centre, r);
}

bool Detail::view_changed() {
    if (!judge_.update()) return false;
    check_ = true, over_crowd_ = 0;
    for (uint32_t b = 0; b < scene_.block_count(); ++b) scene_.block(b).refused = false; // (the room may differ now)
    if (scene_.totals().deferred > 0) scheduler_.revisit();
    return true;
}

Result Detail::set_factor(float factor) {
    if (!(factor >= Scale::kUserFinest && factor <= Scale::kUserCoarsest)) { // (NaN too)
        return Result::fail(Status::OutOfRange, "the detail factor is outside 1/8 to 16");
    }
    if (factor == this->factor()) return {};
    scheduler_.begin_pass(default_tolerance_ * factor);
    return {};
}

} // namespace facet::module
