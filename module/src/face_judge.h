#pragma once
// Which faces the view wants now: a face is worth its triangles when some instance of its part
// shows it at least kMinPixels across (its sphere, bounded by its edges' samples, at its nearest
// point), on the screen, and (a closed part's plane, cylinder or cone face, no section on)
// facing the eye. The rest wait (FaceState::Deferred), drawn by their edges, and are judged
// again once the view changes. Its own state: the spheres' view from the camera (taken again
// when the view, the section or the model's radius changed) and the instances of the part last
// asked about.
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
    // Judged afresh (a new model).
    void reset() { part_ = kNone, radius_ = 0; }
    const SphereView& view() const { return view_; }

private:
    bool shows(uint32_t f); // wants()'s judgement
    const Scene& scene_;
    const Camera& camera_;
    const Scheduler& scheduler_;
    const Config& config_;
    SphereView view_{};
    View camera_view_{};
    float radius_ = 0;
    bool section_ = false; // a section was on: every back face may show
    static constexpr uint32_t kInstances = 8; // a part's instances kept for the next of its faces
    uint32_t part_ = kNone, count_ = 0, instances_[kInstances] = {};
};

} // namespace facet::module
