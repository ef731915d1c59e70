// A face's loops into its (u,v) domain (tessellate_face steps 1 and 3b).
#include "geom/elementary.h"
#include "face_internal.h"
#include "geom/fmath.h"

#include <algorithm>
#include <cmath>

namespace facet::geom::detail {

using namespace facet::pack;

namespace {

bool any_periodic(const Surface& s) { return u_periodic(s) || v_periodic(s); }

// a moved by whole turns to within half a turn of ref. Neighbouring samples are a turn or two
// apart at most: a step at a time. A corrupt pack can put them 1e30 apart, where adding 2 pi
// does nothing: then one jump of whole turns, and the steps are bounded.
float wrap_near(float a, float ref) {
    if (std::fabs(a - ref) > 4 * kTwoPi) {
        const float turns = std::nearbyint((a - ref) / kTwoPi);
        if (std::fabs(turns) < 1e6f) a -= turns * kTwoPi; // else no parameter a face can have
    }
    for (int k = 0; k < 8 && a - ref > kTwoPi / 2; ++k) a -= kTwoPi;
    for (int k = 0; k < 8 && a - ref < -kTwoPi / 2; ++k) a += kTwoPi;
    return a;
}

// Makes the periodic coordinates of a loop continuous: inverted samples are only known modulo
// 2 pi. Starts from a seam sample (its side is known), or else from the first sample taken
// within pi of the face's middle.
void unwrap_loop(FaceScratch& sc, uint32_t start, uint32_t n, const Surface& S, const pack::Face& F) {
    for (int axis = 0; axis < 2; ++axis) {
        if (!(axis == 0 ? u_periodic(S) : v_periodic(S))) continue;
        const uint8_t bit = uint8_t(1 << axis);
        auto get = [&](uint32_t i) -> float& { return axis == 0 ? sc.uv[start + i].x : sc.uv[start + i].y; };
        uint32_t anchor = n;
        for (uint32_t i = 0; i < n && anchor == n; ++i)
            if (sc.pinned[start + i] & bit) anchor = i;
        if (anchor == n) {
            anchor = 0;
            const float mid = axis == 0 ? 0.5f * (F.uv_min[0] + F.uv_max[0]) : 0.5f * (F.uv_min[1] + F.uv_max[1]);
            float& a = get(0);
            a = wrap_near(a, mid);
        }
        float prev = get(anchor);
        for (uint32_t k = 1; k < n; ++k) {
            const uint32_t i = (anchor + k) % n;
            float& a = get(i);
            if (!(sc.pinned[start + i] & bit)) a = wrap_near(a, prev);
            prev = a;
        }
    }
}

// Two preimages (a self-intersecting torus): the one nearer the previous sample, periodic
// coordinates compared modulo 2 pi.
float periodic_distance(Vec2 a, Vec2 b) {
    auto per = [](float d) {
        d = std::fabs(std::fmod(d, kTwoPi));
        return std::min(d, kTwoPi - d);
    };
    return per(a.x - b.x) + per(a.y - b.y);
}

// Whether point i and (p, uv) are one vertex of the loop: one 3D point, and either both from
// pcurves (which may disagree a little) or at one (u,v) (an inverted point; the same 3D point
// at u = 0 and u = 2 pi is two points of the loop).
bool same_vertex(const FaceScratch& sc, uint32_t i, Vec3 p, Vec2 uv, uint8_t pinned) {
    const Vec3 q = sc.xyz[i];
    if (!(p.x == q.x && p.y == q.y && p.z == q.z)) return false;
    if (pinned == 3 && sc.pinned[i] == 3) return true;
    return uv.x == sc.uv[i].x && uv.y == sc.uv[i].y;
}

} // namespace

Result map_loops(const Pack& pack, uint32_t fi, const EdgeSamples& edges, FaceScratch& sc, uint32_t& np, uint32_t& nl,
                 uint32_t& next_loop, uint32_t max_points) {
    const pack::Face& F = pack.faces()[fi];
    const Surface& S = pack.surfaces()[F.surface];
    const bool elementary = is_elementary(S);
    const Elementary shape(pack, S); // (u,v) from the 3D samples where the face has no pcurves
    if (next_loop == 0) np = nl = 0;
    const uint32_t cap = uint32_t(std::min({sc.uv.size(), sc.xyz.size(), sc.loop_points.size(), sc.pinned.size()}));
    const uint32_t np0 = np;
    // A B-spline pcurve of degree 4 or more in fixed point. An edge's samples walk along it,
    // but few fall in each span: below that degree an extraction costs more than it saves
    // (tail_section_asm's cubics: 2.8 M instructions more on the ARM926; m6_screw's degree 6-13
    // pcurves: 4.7 M less).
    CurveSpans pcurve_spans;
    for (uint32_t l = F.first_loop + next_loop; l < F.first_loop + F.loop_count; ++l) {
        if (np - np0 >= max_points) { // enough for this piece: the next loop next time
            next_loop = l - F.first_loop;
            return Result::fail(Status::Busy, "mapping loops");
        }
        const Loop& L = pack.loops()[l];
        const uint32_t loop_start = np;
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const Coedge& CE = pack.coedges()[c];
            const uint32_t ei = CE.edge(), pcurve = pack.pcurve_of(F, c);
            const Seam seam = CE.seam();
            const Edge& E = pack.edges()[ei];
            const uint32_t first = edges.first[ei], n = edges.count[ei];
            if (E.curve == kNoIndex && pcurve == kNoIndex) continue; // a pole: bridged below
            if (pcurve != kNoIndex) pcurve_spans.bind(pack, pack.curves2()[pcurve], 4);
            for (uint32_t k = 0; k < n; ++k) {
                const uint32_t s = first + (CE.reversed() ? n - 1 - k : k);
                if (np >= cap) {
                    return Result::fail(Status::Full, "more edge samples than the face scratch holds", {"loop", l - F.first_loop});
                }
                Vec2 uv;
                if (pcurve != kNoIndex) {
                    uv = pcurve_spans.usable() ? pcurve_spans.point2(edges.t[s]) : eval_curve2(pack, pack.curves2()[pcurve], edges.t[s]).p;
                } else {
                    if (!elementary) {
                        return Result::fail(Status::Corrupt, "no pcurve on a free-form surface", {"loop", l - F.first_loop}, {"coedge", c - L.first_coedge});
                    }
                    Vec2 cand[2];
                    const int count = shape.preimages(edges.p[s], F.uv_min, F.uv_max, cand);
                    uv = cand[0];
                    if (count == 2 && np > loop_start) {
                        if (periodic_distance(cand[1], sc.uv[np - 1]) < periodic_distance(cand[0], sc.uv[np - 1])) uv = cand[1];
                    } else if (count == 2) {
                        uv = shape.inverse(edges.p[s], F.uv_min, F.uv_max); // inside the bounds
                    }
                }
                switch (seam) {
                case Seam::ULow: uv.x = F.uv_min[0]; break;
                case Seam::UHigh: uv.x = F.uv_max[0]; break;
                case Seam::VLow: uv.y = F.uv_min[1]; break;
                case Seam::VHigh: uv.y = F.uv_max[1]; break;
                case Seam::None: break;
                }
                // Which parameters are pinned (by a seam) or exact (from a pcurve) for unwrapping.
                const uint8_t pinned = uint8_t((pcurve != kNoIndex ? 3 : 0) | (seam == Seam::ULow || seam == Seam::UHigh ? 1 : 0) |
                                               (seam == Seam::VLow || seam == Seam::VHigh ? 2 : 0));
                // The vertex where two coedges meet is one point: two pcurves ending a hair
                // apart there would give the loop a spike, or make it cross itself.
                if (k == 0 && np > loop_start && same_vertex(sc, np - 1, edges.p[s], uv, pinned)) {
                    sc.uv[np - 1] = (sc.uv[np - 1] + uv) * 0.5f;
                    continue;
                }
                sc.uv[np] = uv;
                sc.pinned[np] = pinned;
                sc.xyz[np] = edges.p[s];
                ++np;
            }
        }
        if (np - loop_start > 1 && same_vertex(sc, loop_start, sc.xyz[np - 1], sc.uv[np - 1], sc.pinned[np - 1])) {
            sc.uv[loop_start] = (sc.uv[loop_start] + sc.uv[np - 1]) * 0.5f; // the loop closes on its first point
            --np;
        }
        const uint32_t n = np - loop_start;
        // Singular samples (a sphere's or cone's apex: u undefined there) take u from a
        // neighbour along the loop, so the pole becomes a segment along v = pole.
        if (elementary && S.type != uint8_t(SurfaceType::Plane) && n > 2) {
            const Vec3 O = shape.origin(), Z = shape.axis();
            auto singular = [&](uint32_t i) {
                const Vec3 d = sc.xyz[loop_start + i] - O;
                const Vec3 radial = d - Z * dot(d, Z);
                return length2(radial) < 1e-10f * (length2(d) + 1e-12f);
            };
            for (uint32_t i = 0; i < n; ++i) {
                if (!singular(i)) continue;
                const uint32_t prev = (i + n - 1) % n, next = (i + 1) % n;
                const Vec3 a = sc.xyz[loop_start + prev], b = sc.xyz[loop_start + i];
                const bool prev_same = a.x == b.x && a.y == b.y && a.z == b.z;
                // The copy of the pole that follows a real sample takes that sample's u; the copy
                // that precedes the next real sample takes the next one's.
                const uint32_t from = prev_same ? next : prev;
                if (!singular(from)) sc.uv[loop_start + i].x = sc.uv[loop_start + from].x;
            }
        }
        if (n > 1 && any_periodic(S)) unwrap_loop(sc, loop_start, n, S, F);
        if (np > loop_start) {
            if (nl >= sc.loop_sizes.size()) {
                return Result::fail(Status::Full, "more loops than the face scratch holds", {"loops", F.loop_count});
            }
            sc.loop_sizes[nl++] = np - loop_start;
        }
    }
    next_loop = F.loop_count;
    if (nl == 0) {
        return Result::fail(Status::Degenerate, "no loop with any sample");
    }
    return {};
}

bool retraces(const FaceScratch& sc, uint32_t np, uint32_t nl) {
    auto same = [](Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
    uint32_t start = 0;
    for (uint32_t l = 0; l < nl; ++l) {
        const uint32_t n = sc.loop_sizes[l];
        if (start + n > np) return false;
        const Vec3 a = sc.xyz[start];
        Vec3 b = a;
        bool two = false;
        for (uint32_t i = start + 1; i < start + n; ++i) {
            const Vec3 p = sc.xyz[i];
            if (same(p, a) || (two && same(p, b))) continue;
            if (two) return false; // a third point
            b = p, two = true;
        }
        start += n;
    }
    return true;
}

namespace {

bool uturn(cdt::Point A, cdt::Point B, cdt::Point C) { // A -> B -> C folds straight back
    const int64_t cr = int64_t(B.x - A.x) * (C.y - B.y) - int64_t(B.y - A.y) * (C.x - B.x);
    const int64_t dt = int64_t(B.x - A.x) * (C.x - B.x) + int64_t(B.y - A.y) * (C.y - B.y);
    return cr == 0 && dt < 0;
}

} // namespace

Result clean_loops(FaceScratch& sc, uint32_t& np, uint32_t& nl, uint32_t& slivers) {
    // Point B of A -> B -> C goes when it sits on A's grid point or when the loop folds back
    // at it; the triangle A, B, C (in loop order) keeps B's edges in the mesh.
    auto move = [&](uint32_t to, uint32_t from) {
        sc.loop_points[to] = sc.loop_points[from];
        sc.uv[to] = sc.uv[from];
        sc.xyz[to] = sc.xyz[from];
        sc.pinned[to] = sc.pinned[from];
    };
    auto removable = [&](uint32_t a, uint32_t b, uint32_t c) {
        return sc.loop_points[a] == sc.loop_points[b] || uturn(sc.loop_points[a], sc.loop_points[b], sc.loop_points[c]);
    };
    auto sliver = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (slivers >= sc.slivers.size()) return false;
        sc.slivers[slivers++] = {{sc.xyz[a], sc.xyz[b], sc.xyz[c]}, {sc.uv[a], sc.uv[b], sc.uv[c]}};
        return true;
    };
    auto full = [&]() {
        return Result::fail(Status::Full, "more collapsed loop points than the face scratch holds");
    };
    uint32_t read = 0, write = 0, kept_loops = 0;
    for (uint32_t l = 0; l < nl; ++l) {
        const uint32_t start = write;
        // One pass along the loop, the kept points on a stack...
        for (uint32_t k = 0; k < sc.loop_sizes[l]; ++k, ++read) {
            move(write++, read);
            while (write - start >= 3 && removable(write - 3, write - 2, write - 1)) {
                if (!sliver(write - 3, write - 2, write - 1)) return full();
                move(write - 2, write - 1);
                --write;
            }
        }
        // ...then where it closes: its last point, then its first, while either can go.
        for (bool changed = true; changed && write - start >= 3;) {
            changed = false;
            if (removable(write - 2, write - 1, start)) {
                if (!sliver(write - 2, write - 1, start)) return full();
                --write;
                changed = true;
            } else if (removable(write - 1, start, start + 1)) {
                if (!sliver(write - 1, start, start + 1)) return full();
                for (uint32_t i = start; i + 1 < write; ++i) move(i, i + 1);
                --write;
                changed = true;
            }
        }
        if (write - start >= 3) sc.loop_sizes[kept_loops++] = write - start;
        else write = start; // nothing left with area: its slivers alone carry its edges
    }
    np = write;
    nl = kept_loops;
    if (kept_loops == 0 && slivers == 0) {
        return Result::fail(Status::Degenerate, "no loop with any area in (u,v)");
    }
    return {};
}

} // namespace facet::geom::detail
