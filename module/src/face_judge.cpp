// Which faces the view wants now (face_judge.h).
#include "face_judge.h"

#include "geom/fmath.h"
#include "geom/params.h"

namespace facet::module {
namespace {

// A cylinder's or a cone's face as SphereView::faces_away takes it; false for other surfaces, a
// cone face reaching its apex, or a range of u it cannot read.
bool round_face(const Scene& scene, uint32_t f, RoundFace& r) {
    const Block& block = scene.block_of_face(f);
    const pack::Face& F = block.pack.faces()[f - block.first_face];
    const pack::Surface& S = block.pack.surfaces()[F.surface];
    const auto type = pack::SurfaceType(S.type);
    if (type != pack::SurfaceType::Cylinder && type != pack::SurfaceType::Cone) return false;
    geom::ElementaryRecord e;
    (void)geom::elementary(block.pack, S, e);
    const pack::Frame& frame = *e.frame;
    r.radius = e.radius, r.sin_a = 0, r.cos_a = 1;
    if (type == pack::SurfaceType::Cone) {
        geom::sincos_f(e.semi_angle, r.sin_a, r.cos_a);
        // Its normal as below holds on the apex's near side: both ends of v there.
        if (!(r.radius + F.uv_min[1] * r.sin_a > 0 && r.radius + F.uv_max[1] * r.sin_a > 0) || !(r.cos_a > 0)) return false;
    }
    r.span = F.uv_max[0] - F.uv_min[0];
    if (!(r.span >= 0) || !(r.radius > 0)) return false;
    for (int k = 0; k < 3; ++k) r.o[k] = frame.origin[k], r.x[k] = frame.x[k], r.y[k] = frame.y[k], r.z[k] = frame.z[k];
    r.sign = e.inward(F.reversed != 0) ? -1.0f : 1.0f; // (du x dv, outward or in: geom::ElementaryRecord)
    geom::sincos_f(F.uv_min[0], r.s0, r.c0);
    geom::sincos_f(F.uv_max[0], r.s1, r.c1);
    return true;
}

} // namespace

bool FaceJudge::update() {
    const bool section = camera_.section().on;
    if (radius_ == scene_.radius() && section == section_ && same_view(camera_.view(), camera_view_)) return false;
    view_ = camera_.sphere_view(scene_, config_.display.width, config_.display.height);
    camera_view_ = camera_.view(), radius_ = scene_.radius(), section_ = section;
    ++views_;
    return true;
}

void FaceJudge::take_part(uint32_t f) {
    const Scene& scene = scene_;
    const uint32_t part = scene.shell_of(f);
    const Part P = scene.part(part);
    part_ = part, part_first_ = P.first_face, part_end_ = P.first_face + P.face_count, part_closed_ = P.closed, part_view_ = views_;
    // Its instances that show it at all (by its box's sphere, wide enough to hold every face's:
    // its centre's offset and its radius sum to at most the box's half extents summed, with
    // room for the rounding of both spheres), the first kInstances of them kept for its faces;
    // more, and each face looks at every instance of the part. No box known (or judge_parts
    // off): every instance shows it.
    int32_t lo[3], hi[3];
    const bool known = by_parts_ && scene.part_box(part, lo, hi);
    float c[3] = {0, 0, 0}, r = 0;
    if (known) {
        int64_t half = 0;
        const float u = scene.unit();
        for (int k = 0; k < 3; ++k) half += (int64_t(hi[k]) - lo[k]) / 2 + 1, c[k] = 0.5f * (float(lo[k]) + float(hi[k])) * u;
        r = (float(half) * (1.0f + 1.0f / 32) + 16.0f) * u;
    }
    const auto instances = scene.instances();
    count_ = 0;
    for (uint32_t i = 0; i < instances.size(); ++i) {
        if (instances[i].shell != part) continue;
        if (known) {
            float w[3];
            pack::Instance scratch;
            place(scene.placed(i, scratch).m, c, w);
            if (view_.pixels(w, r) < kMinPixels) continue;
        }
        if (count_ < kInstances) instances_[count_] = i;
        ++count_;
    }
    part_shown_ = count_ > 0;
}

bool FaceJudge::shows(uint32_t f) {
    const Scene& scene = scene_;
    const FaceInfo& F = scene.face(f);
    if (F.radius <= 0 || !(config_.screen_error_px > 0)) return true; // nothing to bound it by; or the view chooses no detail
    update();
    if (part_view_ != views_ || !(f >= part_first_ && f < part_end_)) take_part(f);
    if (!part_shown_) return false;
    const uint32_t part = part_;
    const auto instances = scene.instances();
    const float u = scene.unit();
    const float p[3] = {float(F.centre[0]) * u, float(F.centre[1]) * u, float(F.centre[2]) * u}, r = float(F.radius) * u;
    // A closed part's face turned away from the eye shows nothing unless a section opens the
    // solid (Transform::hides_plane): a plane, a cylinder's or a cone's face is left for when
    // the view turns it round.
    // Its size first: most faces of a large model left out are left out for it, and it costs a
    // fraction of the tests of which way a face looks (those, and their set-up, only for a face
    // that is large enough somewhere).
    float on_plane[3], normal[3];
    const bool closed = !section_ && part_closed_;
    enum class Facing : uint8_t { Unknown, Plane, Round, Neither } facing = closed ? Facing::Unknown : Facing::Neither;
    RoundFace round;
    const float sag = DetailScale::kBlockCoarsest * scheduler_.tolerance(); // (its mesh's chords: at most its block's tolerance inside it)
    auto shown = [&](const pack::Instance& inst) {
        float w[3];
        place(inst.m, p, w);
        if (view_.pixels(w, r) < kMinPixels) return false;
        if (facing == Facing::Unknown) {
            facing = scene.face_plane(f, on_plane, normal) ? Facing::Plane : round_face(scene, f, round) ? Facing::Round : Facing::Neither;
        }
        if (facing == Facing::Plane) {
            float wn[3];
            place(inst.m, on_plane, w), place(inst.m, normal, wn, false);
            return !view_.faces_away(w, wn);
        }
        return !(facing == Facing::Round && view_.faces_away(round, inst.m, sag));
    };
    pack::Instance scratch; // (exploded, where the view is)
    if (count_ <= kInstances) {
        for (uint32_t k = 0; k < count_; ++k)
            if (shown(scene.placed(instances_[k], scratch))) return true;
        return false;
    }
    for (uint32_t i = 0; i < instances.size(); ++i)
        if (instances[i].shell == part && shown(scene.placed(i, scratch))) return true;
    return false;
}

bool FaceJudge::wants(void* self, uint32_t f) { return static_cast<FaceJudge*>(self)->shows(f); }

} // namespace facet::module
