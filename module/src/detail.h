#pragma once
// The level of detail the view asks for, block by block: a block's tolerance in a pass (from
// how large it shows), the order a pass takes the blocks in (largest on the screen first), and
// a block made again at another level once the view has moved far enough from the one it was
// made for (refine()). Which faces of a block are worth their triangles is the FaceJudge's.
#include "detail_scale.h"
#include "face_judge.h"
#include "scene.h"
#include "scheduler.h"

#include <cstdint>

namespace facet::module {

class Swapper;

class Detail {
public:
    // `screen_error_px`: Config::screen_error_px (none: every block takes the pass's tolerance).
    Detail(Scene& scene, Scheduler& scheduler, FaceJudge& judge, float screen_error_px)
        : scene_(scene), scheduler_(scheduler), judge_(judge), screen_error_px_(screen_error_px) {}

    // A new model, whose default tolerance is `mm` (geom::default_tolerance): judged afresh.
    void reset(float mm) {
        default_tolerance_ = mm;
        crowd_ = 1, crowded_ = false, judged_crowd_ = false, judged_held_ = 0, judged_us_ = 0, over_crowd_ = 0;
        judge_.reset();
    }
    float default_tolerance() const { return default_tolerance_; }
    // The pass's tolerance as a factor of the default (Viewer::detail()), and a pass at another.
    float factor() const { return default_tolerance_ > 0 ? scheduler_.tolerance() / default_tolerance_ : 1.0f; }
    [[nodiscard]] Result set_factor(float factor);

    // The scheduler's callbacks (self: the Detail): a block's tolerance in a pass; the blocks'
    // order (the first, the rest chained by Block::next).
    static float block_tolerance(void* self, uint32_t block, float pass_tolerance);
    static uint32_t block_order(void* self);

    // The tolerance the view asks of block b (mm): between the finer of pass_tolerance / finest
    // and the block's own share of it (its size over the model's) and DetailScale::kBlockCoarsest
    // times it; on_screen (if given): whether its box shows.
    float wanted_tolerance(uint32_t b, float pass_tolerance, float finest, bool* on_screen);
    bool block_sphere(uint32_t b, float centre[3], float& radius) const; // around its box (mm); false: empty
    // Whether every part of block b is drawn as its proxy wherever the view shows it: the view
    // is crowded, and each part's finest proxy strays by no more than the crowd's screen error
    // at the block's nearest point (Painter::proxy_level asks it of each instance, at its own,
    // farther). Such a block is neither brought in nor made again for the view.
    bool served_by_proxies(uint32_t b);
    float block_pixels(uint32_t b);                                      // its box's sphere across on the screen

    // The view may have moved: when it has (true), the faces left to their edges and the
    // blocks' levels are looked at again.
    bool view_changed();
    // With nothing else under way (the caller's to know: no framing, glide or drag): the block
    // furthest from its level begun again at it, the room made by `room` if short. True when
    // one was begun (or tried).
    bool refine(Swapper& room);
    // The screen error's factor the triangles' bound asks for now (1: none; DetailScale).
    float crowd() const { return crowd_; }
    uint32_t triangle_bound() const;
    // crowd() set from the triangles in view (every instance's, as the last whole frame took
    // them: `in_view`; without proxies, those held if more: blocks come in between whole
    // frames), against triangle_bound(), and from that frame's time (`frame_us`) against
    // `frame_budget_us` (0: none): true while either is over (the blocks are then made coarser
    // before any other comes in).
    bool bound_triangles(uint32_t in_view, uint32_t frame_us, uint32_t frame_budget_us);
    // Before the first frame: a model whose faces pass the bound at two triangles each starts
    // crowded (once a model; bound_triangles() does it too).
    void look_first();

private:
    uint32_t sort_blocks(uint32_t& head, uint32_t count);
    Scene& scene_;
    Scheduler& scheduler_;
    FaceJudge& judge_;
    float screen_error_px_;
    float default_tolerance_ = 0;
    bool check_ = false; // the view moved since the blocks' levels were last looked at
    float crowd_ = 1;    // crowd(): the screen error times this
    bool crowded_ = false; // over the bound when last looked: blocks are only made coarser
    bool judged_crowd_ = false; // bound_triangles() has looked since reset()
    uint32_t judged_held_ = 0, judged_us_ = 0; // at the triangles and the frame's time it last looked at
    float over_crowd_ = 0;      // the largest crowd this view was over the bound at (0: none)
};

} // namespace facet::module
