#include "fit.h"

namespace facet::module {

void Outline::add(const Projected& p) {
    if (p.out) {
        ++hidden;
        return;
    }
    left = p.s.x < left ? p.s.x : left;
    right = p.s.x > right ? p.s.x : right;
    top = p.s.y < top ? p.s.y : top;
    bottom = p.s.y > bottom ? p.s.y : bottom;
    ++points;
}

void Framer::start(uint16_t width, uint16_t height, FreeArea taken, uint32_t instance, uint32_t face, float fill, uint32_t instances) {
    busy_ = true;
    fill_ = fill;
    width_ = width, height_ = height, taken_ = taken;
    only_instance_ = instance, only_end_ = instance == kNone ? kNone : instance + instances, only_face_ = face;
    round_ = 0;
    instance_ = face_ = loop_ = coedge_ = k_ = 0, phase_ = 0;
    have_transform_ = false;
    o_ = {};
}

bool Framer::run(const Scene& scene, Camera& camera, uint32_t units) {
    if (!busy_) return true;
    const auto instances = scene.instances();
    const geom::EdgeSamples& samples = scene.samples();
    uint32_t budget = units * kPointsPerUnit;
    Projected p;
    while (budget > 0) {
        if (instance_ >= instances.size()) { // a round is complete
            if (adjust(scene, camera) || ++round_ >= kRounds) {
                busy_ = false;
                return true;
            }
            instance_ = face_ = loop_ = coedge_ = k_ = 0, phase_ = 0;
            have_transform_ = false;
            o_ = {};
            budget = budget > 64 ? budget - 64 : 0; // the adjustment's own cost
            continue;
        }
        if (only_instance_ != kNone && (instance_ < only_instance_ || instance_ >= only_end_)) {
            ++instance_;
            continue;
        }
        if (!have_transform_) {
            t_ = camera.transform(scene, instance_, width_, height_);
            have_transform_ = true;
            part_ = scene.part(instances[instance_].shell);
            face_ = part_.first_face, phase_ = 0, k_ = 0;
            uint32_t first = 0, count = 0;
            by_edges_ = only_face_ == kNone && !samples.count.empty() && scene.part_edges(instances[instance_].shell, first, count);
            edge_ = first, edge_end_ = first + count;
            curved_only_ = false;
            budget = budget > 32 ? budget - 32 : 0;
            int32_t corners[8][3];
            if (scene.part_left_out(instances[instance_].shell)) { // a part left out (drawn as its proxy): its box's corners
                if (scene.part_corners(instances[instance_].shell, corners)) {
                    for (const int32_t* q : corners) {
                        t_.project(q, p);
                        see(p);
                    }
                }
                ++instance_;
                have_transform_ = false;
                continue;
            }
            int32_t centre[3], radius;
            if (scene.part_sphere(instances[instance_].shell, centre, radius) && inside_outline(centre, radius)) {
                ++instance_; // the whole part projects inside the outline so far: nothing of it can widen it
                have_transform_ = false;
                continue;
            }
        }
        if (by_edges_ && !curved_only_) {
            while (edge_ < edge_end_ && budget > 0) {
                const uint32_t n = samples.count[edge_], first = samples.first[edge_];
                for (; k_ < n && budget > 0; ++k_, --budget) {
                    t_.project(scene.sample_q(first + k_), p);
                    see(p);
                }
                if (k_ < n) break;
                ++edge_, k_ = 0;
            }
            if (edge_ < edge_end_) continue;
            if (scene.totals().done == 0) { // no mesh yet: the edges are all there is
                ++instance_;
                have_transform_ = false;
                continue;
            }
            curved_only_ = true, k_ = 0; // then the curved faces' meshes (their silhouettes)
        }
        const Part& sh = part_;
        if (face_ >= sh.first_face + sh.face_count) {
            ++instance_;
            have_transform_ = false;
            continue;
        }
        if (only_face_ != kNone && face_ != only_face_) {
            ++face_;
            continue;
        }
        const FaceInfo& F = scene.face(face_);
        if (curved_only_) { // the edges are in: a curved face's mesh can reach past them, a plane's cannot
            if (F.state == FaceState::Done && !F.planar && k_ == 0 && inside_outline(F.centre, F.radius)) {
                ++face_; // its sphere projects inside the outline so far: so does its mesh
                --budget;
                continue;
            }
            if (F.state == FaceState::Done && !F.planar && !project_mesh(scene, F, budget)) continue;
            ++face_, k_ = 0;
            continue;
        }
        const Block& block = scene.block_of_face(face_);
        const auto loops = block.pack.loops();
        const auto coedges = block.pack.coedges();
        const pack::Face& PF = block.pack.faces()[face_ - block.first_face];
        if (phase_ == 0) { // the face's mesh (its loops' samples among its vertices)
            if (F.state == FaceState::Done) {
                if (!project_mesh(scene, F, budget)) continue;
                ++face_, k_ = 0;
                continue;
            }
            phase_ = 1, loop_ = PF.first_loop, coedge_ = loop_ < loops.size() ? loops[loop_].first_coedge : 0, k_ = 0;
        }
        // The face's edges, as sampled (all there is of a face not yet tessellated).
        if (samples.count.empty() || loop_ >= PF.first_loop + PF.loop_count) {
            ++face_, phase_ = 0, k_ = 0;
            continue;
        }
        if (coedge_ >= loops[loop_].first_coedge + loops[loop_].coedge_count) {
            ++loop_;
            if (loop_ < PF.first_loop + PF.loop_count) coedge_ = loops[loop_].first_coedge;
            continue;
        }
        const uint32_t e = block.first_edge + coedges[coedge_].edge(), n = samples.count[e];
        for (; k_ < n && budget > 0; ++k_, --budget) {
            t_.project(scene.sample_q(samples.first[e] + k_), p);
            see(p);
        }
        if (k_ < n) continue;
        ++coedge_, k_ = 0;
    }
    return false;
}

// A point into the outline, unless a section cuts it away: with a section on, what is framed is
// what is drawn, the kept side (its points; where the plane crosses a face the outline ends at
// the nearest of them, within a sample's spacing of the cut).
void Framer::see(const Projected& p) {
    if (t_.cut.on && t_.cut.side(p.x, p.y, p.d) > 0) return;
    o_.add(p);
}

// The face's vertices from k_ on, while the budget lasts: true when all are in the outline.
bool Framer::project_mesh(const Scene& scene, const FaceInfo& F, uint32_t& budget) {
    Projected p;
    for (; k_ < F.vertex_count && budget > 0; ++k_, --budget) {
        t_.project(scene.vertices()[F.first_vertex + k_].p, p);
        see(p);
    }
    return k_ == F.vertex_count;
}

// Whether a sphere (a face's, a part's) projects wholly inside the outline found so far (which only grows
// within a round), so no point of the face can widen it. Conservative: the box around the
// sphere, each side over the depth that pushes it furthest out (parallel: the centre's depth),
// with a pixel to spare; a sphere reaching the near plane is never inside.
bool Framer::inside_outline(const int32_t centre[3], int32_t radius) const {
    if (radius <= 0 || o_.points == 0) return false;
    int32_t x, y, d;
    t_.to_view(centre, x, y, d);
    const int64_t rv = ((int64_t(radius) * t_.k16) >> 16) + 2; // view units, rounded up
    if (d - rv < t_.near) return false;
    const int64_t nearest = t_.ortho ? t_.dist : d - rv, furthest = t_.ortho ? t_.dist : d + rv;
    const int64_t f = t_.f16, pad = render::subpixel::kPerPixel;
    auto screen = [&](int64_t v) { return v * f / (v >= 0 ? nearest : furthest); }; // the outer bound of v / depth
    auto screen_in = [&](int64_t v) { return v * f / (v >= 0 ? furthest : nearest); }; // the inner bound
    const int64_t right = t_.cx16 + screen(x + rv), left = t_.cx16 + screen_in(x - rv);
    const int64_t top = t_.cy16 - screen(y + rv), bottom = t_.cy16 - screen_in(y - rv);
    return left - pad >= o_.left && right + pad <= o_.right && top - pad >= o_.top && bottom + pad <= o_.bottom;
}

bool Framer::adjust(const Scene& scene, Camera& camera) {
    const int32_t aw = int32_t(width_) - taken_.left - taken_.right, ah = int32_t(height_) - taken_.top - taken_.bottom;
    if (o_.points == 0 || aw < 8 || ah < 8) return true; // nothing to frame
    // The area's centre and the outline's offset from it, in sub-pixels.
    constexpr int32_t kSub = render::subpixel::kPerPixel;
    const int32_t ax16 = (taken_.left * 2 + aw) * (kSub / 2), ay16 = (taken_.top * 2 + ah) * (kSub / 2);
    const int32_t dx = ax16 - int32_t((int64_t(o_.left) + o_.right) / 2), dy = ay16 - int32_t((int64_t(o_.top) + o_.bottom) / 2);
    const float w = float(o_.right - o_.left) / (float(kSub) * float(aw)), h = float(o_.bottom - o_.top) / (float(kSub) * float(ah));
    const float now = w > h ? w : h;
    const bool centred = dx >= -kSub && dx <= kSub && dy >= -kSub && dy <= kSub; // within a pixel
    if (!o_.hidden && centred && now <= fill_ * 1.02f && now >= fill_ * 0.98f) return true;
    // Centre: pan by the offset (pan_pixels moves the model's centre with the pointer). Size:
    // the dolly scales the outline about inversely (exactly for a flat model at the centre's
    // depth); a point behind the eye means: back off.
    camera.pan_pixels(dx / 16, dy / 16, scene.radius(), width_, height_);
    if (o_.hidden) {
        camera.dolly(2.0f);
    } else if (now > 0) {
        camera.dolly(now / fill_);
    }
    return false;
}

} // namespace facet::module
