#pragma once
// Which faces the view wants now: a face is worth its triangles when some instance of its part
// shows it at least kMinPixels across (its sphere, bounded by its edges' samples, at its nearest
// point), on the screen, and (a closed part's plane, cylinder or cone face, no section on)
// facing the eye. The rest wait (FaceState::Deferred), drawn by their edges, and are judged
// again once the view changes. A part whose every instance is off the screen or under
// kMinPixels is judged once for all its faces (a blocked pack's: its index has the part's box).
// Its own state: the spheres' view from the camera (taken again when the view, the section or
// the model's radius changed) and the part last asked about: its faces, its instances, and
// whether it shows at all in this view.
#include "camera.h"
#include "painter.h"
#include "scene.h"
#include "scheduler.h"

#include <cstdint>

namespace facet::module {

class FaceJudge {
public:
    static constexpr float kMinPixels = float(kFacePixels);

    // Judges by the scene, the camera, the pass's tolerance and the configuration's screen
    // (its size and screen error: none, and every face is wanted).
    FaceJudge(const Scene& scene, const Camera& camera, const Scheduler& scheduler, const Config& config)
        : scene_(scene), camera_(camera), scheduler_(scheduler), config_(config) {}

    // The scheduler's filter (self: the FaceJudge): whether face f is worth its triangles now.
    static bool wants(void* self, uint32_t f);
    // The spheres' view from the camera's, if it moved: true then.
    bool update();
    // Parts judged first (the default), or every face alone (tests: the same verdicts).
    void judge_parts(bool on) { by_parts_ = on, ++views_; }
    // Judged afresh (a new model).
    void reset() { part_ = kNone, part_end_ = 0, radius_ = 0, ++views_; }
    const SphereView& view() const { return view_; }

private:
    bool shows(uint32_t f); // wants()'s judgement
    void take_part(uint32_t f); // the part of face f: its faces, the instances that show it (any?)
    const Scene& scene_;
    const Camera& camera_;
    const Scheduler& scheduler_;
    const Config& config_;
    SphereView view_{};
    View camera_view_{};
    float radius_ = 0;
    bool section_ = false; // a section was on: every back face may show
    static constexpr uint32_t kInstances = 8; // a part's instances that show it, kept for its faces (count_: all of them)
    uint32_t part_ = kNone, count_ = 0, instances_[kInstances] = {};
    uint32_t part_first_ = 0, part_end_ = 0; // its faces
    bool part_closed_ = false, part_shown_ = true;
    uint32_t views_ = 0, part_view_ = 0; // views taken (update()); the view the part was judged in
    bool by_parts_ = true;
};

} // namespace facet::module
