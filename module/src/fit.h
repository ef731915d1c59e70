#pragma once
// Framing: the placed model's outline as the camera sees it, and the pan and dolly that centre
// it and make it fill the screen's free area. The outline is what is drawn: every instance's
// tessellated faces and sampled edges, projected exactly as a frame projects them. A round
// projects every point once; rounds repeat until the outline sits (perspective makes neither
// step exact when the camera ends close). A tessellated face's vertices hold its loops' samples:
// its mesh alone is projected. The work is cut into pieces of about a million
// instructions on the ARM926, like a frame's, so a big model's fit never stalls a step.
#include "camera.h"
#include "overlay.h"
#include "scene.h"

#include <cstdint>

namespace facet::module {

// A rectangle of the screen, in 16ths of a pixel.
struct Outline {
    int32_t left = INT32_MAX, top = INT32_MAX, right = INT32_MIN, bottom = INT32_MIN;
    uint32_t points = 0; // projected; 0: nothing to frame
    uint32_t hidden = 0; // behind the eye or past the guard band (not in the box)
    void add(const Projected& p);
};


class Framer {
public:
    static constexpr uint32_t kPointsPerUnit = 4; // a unit: about 4 projected points (~250 instructions each on the ARM926)
    static constexpr int kRounds = 8;
    static constexpr float kFill = 0.85f; // of the free area

    // Frame the whole model (face = kNone) or one face of one instance, on a width x height screen.
    // `instances`: the count from `instance` on (a node of the assembly tree's parts), face kNone.
    void start(uint16_t width, uint16_t height, FreeArea taken, uint32_t instance = kNone, uint32_t face = kNone, float fill = kFill,
               uint32_t instances = 1);
    void stop() { busy_ = false; }
    bool busy() const { return busy_; }
    // Up to `units` of work on `camera`; true when the framing is done (or there was nothing to frame).
    bool run(const Scene& scene, Camera& camera, uint32_t units);
    uint32_t rounds() const { return round_; }

private:
    bool adjust(const Scene& scene, Camera& camera); // a round's outline seen: true if it sits
    bool inside_outline(const int32_t centre[3], int32_t radius) const; // the sphere cannot widen the outline so far
    bool project_mesh(const Scene& scene, const FaceInfo& F, uint32_t& budget);
    void see(const Projected& p); // into the outline, unless the section cuts it away
    bool busy_ = false;
    uint16_t width_ = 0, height_ = 0;
    FreeArea taken_;
    uint32_t only_instance_ = kNone, only_end_ = kNone, only_face_ = kNone; // instances [only_instance_, only_end_)
    float fill_ = kFill;
    int round_ = 0;
    // Where the round's scan stands: instance, face, then the face's vertices (phase 0) and its
    // loops' coedges' samples (phase 1).
    uint32_t instance_ = 0, face_ = 0, loop_ = 0, coedge_ = 0, k_ = 0;
    uint8_t phase_ = 0;
    // Where a part's edges are known to be together, an instance's outline is its part's edges,
    // each once (a face's loops would give each edge twice), then the meshes of its curved faces
    // that are in (a cylinder's silhouette is no edge; a plane's mesh is its loops' samples).
    bool by_edges_ = false, curved_only_ = false;
    uint32_t edge_ = 0, edge_end_ = 0;
    bool have_transform_ = false;
    Transform t_{};
    Part part_{}; // the instance's part
    Outline o_;
};

} // namespace facet::module
