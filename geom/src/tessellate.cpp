#include "geom/tessellate.h"

#include "geom/fmath.h"

#include <algorithm>
#include <cmath>

namespace facet::geom {
namespace {

using namespace facet::pack;

// Whether directions a and b turn by more than the angle whose cosine is cos_max (in [0, 1]),
// without square roots or acos (both are long library calls on a soft-float core). A zero
// vector turns by nothing.
bool turns_more(Vec3 a, Vec3 b, float cos_max) {
    const float l2 = dot(a, a) * dot(b, b);
    if (l2 == 0) return false;
    const float d = dot(a, b);
    if (cos_max < 0) return d < 0 && d * d > cos_max * cos_max * l2;
    return d < 0 || d * d < cos_max * cos_max * l2;
}

constexpr float kTwoPi = 6.28318530717958647692f;

bool any_periodic(const Surface& s) { return u_periodic(s) || v_periodic(s); }

// Makes the periodic coordinates of a loop continuous (see tessellate_face).
void unwrap_loop(FaceScratch& sc, uint32_t start, uint32_t n, const Surface& S, const pack::Face& F) {
    for (int axis = 0; axis < 2; ++axis) {
        if (!(axis == 0 ? u_periodic(S) : v_periodic(S))) continue;
        const uint8_t bit = uint8_t(1 << axis);
        auto get = [&](uint32_t i) -> float& { return axis == 0 ? sc.uv[start + i].x : sc.uv[start + i].y; };
        uint32_t anchor = n;
        for (uint32_t i = 0; i < n && anchor == n; ++i)
            if (sc.pinned[start + i] & bit) anchor = i;
        if (anchor == n) { // no seam: put the first sample within pi of the face's middle
            anchor = 0;
            const float mid = axis == 0 ? 0.5f * (F.uv_min[0] + F.uv_max[0]) : 0.5f * (F.uv_min[1] + F.uv_max[1]);
            float& a = get(0);
            while (a < mid - kTwoPi / 2) a += kTwoPi;
            while (a >= mid + kTwoPi / 2) a -= kTwoPi;
        }
        float prev = get(anchor);
        for (uint32_t k = 1; k < n; ++k) {
            const uint32_t i = (anchor + k) % n;
            float& a = get(i);
            if (!(sc.pinned[start + i] & bit)) {
                while (a - prev > kTwoPi / 2) a -= kTwoPi;
                while (a - prev < -kTwoPi / 2) a += kTwoPi;
            }
            prev = a;
        }
    }
}

} // namespace

namespace {
// The surface point that measures c's deviation (see surface_deviation).
Vec3 nearest_on_surface(const Pack& pack, uint32_t face, Vec3 c, Vec2 uv_guess, Vec2& uv) {
    const pack::Face& F = pack.faces()[face];
    const Surface& S = pack.surfaces()[F.surface];
    uv = uv_guess;
    if (is_elementary(S)) {
        Vec2 inv;
        if (invert_elementary(pack, S, c, F.uv_min, F.uv_max, inv)) uv = inv;
    }
    return eval_surface(pack, S, uv.x, uv.y).p;
}
} // namespace

float surface_deviation(const Pack& pack, uint32_t face, Vec3 c, Vec2 uv_guess, Vec2& uv) {
    return length(c - nearest_on_surface(pack, face, c, uv_guess, uv));
}

float default_tolerance(const Pack& pack) {
    const pack::Header& h = pack.header();
    const Vec3 d{h.bbox_max[0] - h.bbox_min[0], h.bbox_max[1] - h.bbox_min[1], h.bbox_max[2] - h.bbox_min[2]};
    const float diag = length(d);
    return diag > 0 ? diag * 0.001f : 0.01f;
}

Status sample_edges(const Pack& pack, const TessOptions& opt, EdgeSamples& out) {
    out.used = 0;
    const float tol2 = opt.tolerance * opt.tolerance, cos_max = cos_f(opt.max_angle);
    const auto edges = pack.edges();
    if (out.first.size() < edges.size() || out.count.size() < edges.size()) return Status::Full;
    for (uint32_t e = 0; e < edges.size(); ++e) {
        const Edge& E = edges[e];
        out.first[e] = out.used;
        auto emit = [&](float t, Vec3 p) {
            if (out.used >= out.t.size() || out.used >= out.p.size()) return false;
            out.t[out.used] = t;
            out.p[out.used] = p;
            ++out.used;
            return true;
        };
        const Vec3 a = {pack.vertices()[E.v0].p[0], pack.vertices()[E.v0].p[1], pack.vertices()[E.v0].p[2]};
        const Vec3 b = {pack.vertices()[E.v1].p[0], pack.vertices()[E.v1].p[1], pack.vertices()[E.v1].p[2]};
        if (E.curve == kNoIndex) { // degenerate: a single point
            if (!emit(E.t0, a) || !emit(E.t1, a)) return Status::Full;
            out.count[e] = 2;
            continue;
        }
        const Curve& C = pack.curves3()[E.curve];
        // The vertices are the exact ends (both faces and neighbouring edges share them).
        if (C.type == uint8_t(CurveType::Line)) {
            if (!emit(E.t0, a) || !emit(E.t1, b)) return Status::Full;
            out.count[e] = 2;
            continue;
        }
        // Adaptive: start from 4 pieces, split a piece while its midpoint leaves the chord by
        // more than the tolerance or its ends turn by more than max_angle.
        constexpr int kStack = 64;
        float stack[kStack];
        int top = 0;
        const float t0 = E.t0, t1 = E.t1;
        const uint32_t start = out.used;
        if (!emit(t0, a)) return Status::Full;
        for (int k = 4; k >= 1; --k) stack[top++] = t0 + (t1 - t0) * k / 4; // right ends, reversed
        float tl = t0;
        Curve3Point pl = eval_curve3(pack, C, t0);
        while (top) {
            const float tr = stack[top - 1];
            const Curve3Point pr = eval_curve3(pack, C, tr);
            const Curve3Point pm = eval_curve3(pack, C, 0.5f * (tl + tr));
            const Vec3 chord = pr.p - pl.p;
            const float len2 = dot(chord, chord);
            const Vec3 off = pm.p - pl.p;
            const float along = len2 > 0 ? dot(off, chord) / len2 : 0;
            const bool split = (length2(off - chord * along) > tol2 || turns_more(pl.d, pr.d, cos_max)) &&
                               top < kStack && (tr - tl) > 1e-6f * (std::fabs(t1 - t0) + 1e-6f) && out.used - start < 4000;
            if (split) {
                stack[top++] = 0.5f * (tl + tr);
                continue;
            }
            --top;
            if (!emit(tr, top == 0 ? b : pr.p)) return Status::Full;
            tl = tr;
            pl = pr;
        }
        if (out.used - start > 0xFFFF) return Status::Full;
        out.count[e] = uint16_t(out.used - start);
    }
    return Status::Ok;
}

FaceResult tessellate_face(const Pack& pack, uint32_t fi, const EdgeSamples& edges, const TessOptions& opt,
                           FaceScratch& sc, Mesh& mesh) {
    FaceResult res;
    auto fail = [&](Status s, const char* why) {
        res.status = s;
        res.reason = why;
        return res;
    };
    const pack::Face& F = pack.faces()[fi];
    const Surface& S = pack.surfaces()[F.surface];
    const bool elementary = is_elementary(S);

    // 1. Loops into (u,v): every sample of every coedge, then duplicates dropped.
    uint32_t np = 0, nl = 0;
    const uint32_t cap = uint32_t(std::min({sc.uv.size(), sc.xyz.size(), sc.loop_points.size()}));
    for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
        const Loop& L = pack.loops()[l];
        const uint32_t loop_start = np;
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const Coedge& CE = pack.coedges()[c];
            const Edge& E = pack.edges()[CE.edge];
            if (E.curve == kNoIndex && CE.pcurve == kNoIndex) continue; // a pole: bridged below
            const uint32_t first = edges.first[CE.edge], n = edges.count[CE.edge];
            for (uint32_t k = 0; k < n; ++k) {
                const uint32_t s = first + (CE.reversed ? n - 1 - k : k);
                if (np >= cap) return fail(Status::Full, "more edge samples than the face scratch holds");
                Vec2 uv;
                if (CE.pcurve != kNoIndex) {
                    uv = eval_curve2(pack, pack.curves2()[CE.pcurve], edges.t[s]).p;
                } else {
                    Vec2 cand[2];
                    const int n = invert_candidates(pack, S, edges.p[s], F.uv_min, F.uv_max, cand);
                    if (n == 0) return fail(Status::Corrupt, "no pcurve on a free-form surface");
                    uv = cand[0];
                    if (n == 2 && np > loop_start) {
                        // Two preimages: follow the loop (the one nearer the previous sample,
                        // periodic coordinates compared modulo 2 pi).
                        auto dist = [&](Vec2 a) {
                            auto per = [](float d) {
                                d = std::fabs(std::fmod(d, 6.28318530717958647692f));
                                return std::min(d, 6.28318530717958647692f - d);
                            };
                            return per(a.x - sc.uv[np - 1].x) + per(a.y - sc.uv[np - 1].y);
                        };
                        if (dist(cand[1]) < dist(cand[0])) uv = cand[1];
                    } else if (n == 2) {
                        invert_elementary(pack, S, edges.p[s], F.uv_min, F.uv_max, uv); // inside the bounds
                    }
                }
                switch (Seam(CE.seam)) {
                case Seam::ULow: uv.x = F.uv_min[0]; break;
                case Seam::UHigh: uv.x = F.uv_max[0]; break;
                case Seam::VLow: uv.y = F.uv_min[1]; break;
                case Seam::VHigh: uv.y = F.uv_max[1]; break;
                case Seam::None: break;
                }
                sc.uv[np] = uv;
                // Which parameters are pinned (by a seam) or exact (from a pcurve) for unwrapping.
                sc.pinned[np] = uint8_t((CE.pcurve != kNoIndex ? 3 : 0) |
                                        (CE.seam == uint8_t(Seam::ULow) || CE.seam == uint8_t(Seam::UHigh) ? 1 : 0) |
                                        (CE.seam == uint8_t(Seam::VLow) || CE.seam == uint8_t(Seam::VHigh) ? 2 : 0));
                sc.xyz[np] = edges.p[s];
                ++np;
            }
        }
        const uint32_t n = np - loop_start;
        // Singular samples (a sphere's or cone's apex: u undefined there) take u from a
        // neighbour along the loop, so the pole becomes a segment along v = pole.
        if (elementary && S.type != uint8_t(SurfaceType::Plane) && n > 2) {
            const float* q = pack.floats().data() + S.params;
            const Vec3 O{q[0], q[1], q[2]}, Z{q[9], q[10], q[11]};
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
        // Periodic parameters: inverted samples are only known modulo 2 pi. Unwrap them along
        // the loop so it is continuous, starting from a seam sample (its side is known), or
        // else from the first sample taken within pi of the face's middle.
        if (n > 1 && any_periodic(S)) {
            unwrap_loop(sc, loop_start, n, S, F);
        }
        if (np > loop_start) {
            if (nl >= sc.loop_sizes.size()) return fail(Status::Full, "more loops than the face scratch holds");
            sc.loop_sizes[nl++] = np - loop_start;
        }
    }
    if (nl == 0) return fail(Status::Degenerate, "no loop with any sample");

    // 2. Metric scale from the surface's derivatives at the middle of the face.
    const float um = 0.5f * (F.uv_min[0] + F.uv_max[0]), vm = 0.5f * (F.uv_min[1] + F.uv_max[1]);
    const SurfacePoint mid = eval_surface(pack, S, um, vm);
    float su = length(mid.du), sv = length(mid.dv);
    if (!(su > 1e-9f)) su = 1;
    if (!(sv > 1e-9f)) sv = 1;
    // Interior curvature points (not on planes): an anisotropic quadtree over the face's
    // bounds. A cell splits along u (v) while the surface's midpoint along u (v) leaves the
    // chord by more than half the tolerance or its normals turn by more than max_angle, and
    // also across its length when it is curved across and over 4x longer than wide (a ruled
    // cylinder needs no points along its rulings, but a triangle must not span its curved
    // width end to end). Each leaf below the root adds its centre. Points outside the loops are kept (the flood fill drops
    // their triangles; testing them would cost more).
    uint32_t ni = 0;
    if (S.type != uint8_t(SurfaceType::Plane)) {
        struct Cell {
            float u0, v0, u1, v1;
            int depth;
        };
        constexpr int kStack = 128;
        Cell stack[kStack];
        int top = 0;
        stack[top++] = {F.uv_min[0], F.uv_min[1], F.uv_max[0], F.uv_max[1], 0};
        // The surface on a 3x3 grid of the cell (corners, edge midpoints, centre): each of the
        // three lines along u (v) gives its midpoint's sag from the chord and the turn of the
        // normals at its ends. Normals at (near-)singular points are ignored: at a pole or apex
        // the normal is undefined, and a hair past an apex it even points the other way.
        const float tol2 = 0.25f * opt.tolerance * opt.tolerance; // (tolerance / 2)^2
        const float cos_max = cos_f(opt.max_angle);
        auto usable = [](const SurfacePoint& P, Vec3 n) {
            const float a = length2(P.du), b = length2(P.dv);
            return length2(n) > 1e-8f * a * b + 1e-24f && a >= 1e-8f * b && b >= 1e-8f * a;
        };
        auto line = [&](const SurfacePoint& A, const SurfacePoint& M, const SurfacePoint& B, Vec3 na, Vec3 nb,
                        bool ua, bool ub, bool& over, bool& turned) {
            over = over || length2(M.p - (A.p + B.p) * 0.5f) > tol2;
            turned = turned || (ua && ub && turns_more(na, nb, cos_max));
        };
        while (top) {
            const Cell c = stack[--top];
            const float uc = 0.5f * (c.u0 + c.u1), vc = 0.5f * (c.v0 + c.v1);
            const float us[3] = {c.u0, uc, c.u1}, vs[3] = {c.v0, vc, c.v1};
            SurfacePoint P[3][3]; // [u][v]
            Vec3 N[3][3];
            bool U[3][3];
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) {
                    P[i][j] = eval_surface(pack, S, us[i], vs[j]);
                    N[i][j] = cross(P[i][j].du, P[i][j].dv);
                    U[i][j] = usable(P[i][j], N[i][j]);
                }
            }
            bool over_u = false, turn_u = false, over_v = false, turn_v = false;
            for (int k = 0; k < 3; ++k) {
                line(P[0][k], P[1][k], P[2][k], N[0][k], N[2][k], U[0][k], U[2][k], over_u, turn_u);
                line(P[k][0], P[k][1], P[k][2], N[k][0], N[k][2], U[k][0], U[k][2], over_v, turn_v);
            }
            // Half the tolerance: a triangle spans about a cell's diagonal, not one side.
            bool split_u = (over_u || turn_u) && c.depth < 12;
            bool split_v = (over_v || turn_v) && c.depth < 12;
            // A cell curved across but much longer than wide (in metric units) would let a
            // triangle span its whole curved width from end to end: cut it shorter too.
            const float w = (c.u1 - c.u0) * su, h = (c.v1 - c.v0) * sv;
            if (split_u && !split_v && h > 4 * w && c.depth < 12) split_v = true;
            if (split_v && !split_u && w > 4 * h && c.depth < 12) split_u = true;
            if ((split_u || split_v) && top + 4 <= kStack) {
                if (split_u && split_v) {
                    stack[top++] = {c.u0, c.v0, uc, vc, c.depth + 1};
                    stack[top++] = {uc, c.v0, c.u1, vc, c.depth + 1};
                    stack[top++] = {c.u0, vc, uc, c.v1, c.depth + 1};
                    stack[top++] = {uc, vc, c.u1, c.v1, c.depth + 1};
                } else if (split_u) {
                    stack[top++] = {c.u0, c.v0, uc, c.v1, c.depth + 1};
                    stack[top++] = {uc, c.v0, c.u1, c.v1, c.depth + 1};
                } else {
                    stack[top++] = {c.u0, c.v0, c.u1, vc, c.depth + 1};
                    stack[top++] = {c.u0, vc, c.u1, c.v1, c.depth + 1};
                }
            } else if (c.depth > 0) {
                if (np + ni >= sc.uv.size() || ni >= sc.interior.size()) return fail(Status::Full, "more curvature points than the face scratch holds");
                sc.uv[np + ni++] = {uc, vc};
            }
        }
    }

    // 3. Quantize the scaled (u,v) to the CDT grid: the face's extent maps to 2^15 units.
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (uint32_t i = 0; i < np + ni; ++i) {
        x0 = std::min(x0, sc.uv[i].x * su), x1 = std::max(x1, sc.uv[i].x * su);
        y0 = std::min(y0, sc.uv[i].y * sv), y1 = std::max(y1, sc.uv[i].y * sv);
    }
    const float extent = std::max(x1 - x0, y1 - y0);
    if (!(extent > 0) || !std::isfinite(extent)) return fail(Status::Degenerate, "the face has no extent in (u,v)");
    const float q = 32768.0f / extent;
    for (uint32_t i = 0; i < np + ni; ++i) {
        const cdt::Point g{int32_t(std::lround((sc.uv[i].x * su - x0) * q)) - 16384,
                           int32_t(std::lround((sc.uv[i].y * sv - y0) * q)) - 16384};
        if (i < np) sc.loop_points[i] = g;
        else sc.interior[i - np] = g;
    }

    // 3b. Clean the quantized loops: drop repeated points and collinear U-turns (a spike where
    //     two pcurves end a hair apart at a corner would be a constraint run both ways, which
    //     seeds the flood fill on both sides). The per-point arrays move with their points.
    {
        uint32_t read = 0, write = 0, kept_loops = 0;
        for (uint32_t l = 0; l < nl; ++l) {
            const uint32_t start = write;
            for (uint32_t k = 0; k < sc.loop_sizes[l]; ++k, ++read) {
                sc.loop_points[write] = sc.loop_points[read];
                sc.uv[write] = sc.uv[read];
                sc.xyz[write] = sc.xyz[read];
                sc.pinned[write] = sc.pinned[read];
                ++write;
                // Pop while the last point repeats its predecessor or turns straight back.
                while (write - start >= 2) {
                    const cdt::Point A = write - start >= 3 ? sc.loop_points[write - 3] : cdt::Point{INT32_MIN, 0};
                    const cdt::Point B = sc.loop_points[write - 2], C = sc.loop_points[write - 1];
                    if (B == C) {
                        --write;
                        continue;
                    }
                    if (A.x == INT32_MIN) break;
                    const int64_t cr = int64_t(B.x - A.x) * (C.y - B.y) - int64_t(B.y - A.y) * (C.x - B.x);
                    const int64_t dt = int64_t(B.x - A.x) * (C.x - B.x) + int64_t(B.y - A.y) * (C.y - B.y);
                    if (cr != 0 || dt >= 0) break;
                    // A -> B -> C folds back on itself: B goes.
                    sc.loop_points[write - 2] = C;
                    sc.uv[write - 2] = sc.uv[write - 1];
                    sc.xyz[write - 2] = sc.xyz[write - 1];
                    sc.pinned[write - 2] = sc.pinned[write - 1];
                    --write;
                }
            }
            // The loop closes on its first point: drop a last point equal to it.
            while (write - start >= 2 && sc.loop_points[write - 1] == sc.loop_points[start]) --write;
            if (write - start >= 3) sc.loop_sizes[kept_loops++] = write - start;
            else write = start; // a loop with no area left
        }
        if (kept_loops == 0) return fail(Status::Degenerate, "no loop with any area in (u,v)");
        // The curvature points follow the loop points in uv[].
        for (uint32_t k = 0; k < ni; ++k) sc.uv[write + k] = sc.uv[np + k];
        np = write;
        nl = kept_loops;
    }

    // 4. Triangulate.
    cdt::Cdt<uint16_t> cdt(sc.arena);
    cdt::FaceReport rep;
    const cdt::FaceInput in{{sc.loop_points.data(), np}, {sc.loop_sizes.data(), nl}, {sc.interior.data(), ni}};
    res.points = np + ni;
    const Status st = cdt::triangulate_face(cdt, in, cdt::kDefaultLocateMode, rep);
    if (!ok(st)) {
        return fail(st, st == Status::Full ? "more points than the CDT arena holds"
                        : st == Status::Crossing ? "its loops cross in (u,v)"
                        : st == Status::Degenerate ? "a loop is open or runs the wrong way in (u,v)"
                                                    : "triangulation failed");
    }

    // 5. Refine by measured deviation: every inner triangle whose centroid lies farther from
    //    the surface than the tolerance gets the surface point at its centroid's (u,v);
    //    repeated until none does (or 12 rounds). Points that would land on a loop's edge are
    //    skipped (they would split it in this face only).
    auto point_of = [&](uint32_t v) { return sc.mesh_of[v]; }; // CDT vertex -> input point
    auto position = [&](uint32_t i) { return i < np ? sc.xyz[i] : eval_surface(pack, S, sc.uv[i].x, sc.uv[i].y).p; };
    uint32_t total = np + ni;
    const float tol2 = opt.tolerance * opt.tolerance;
    // A triangle that passed keeps passing while its slot holds the same three vertices.
    uint32_t cleared = 0; // passed[] entries valid for this face
    // A plane's triangles lie on it: nothing to refine.
    const int rounds = S.type == uint8_t(SurfaceType::Plane) ? 0 : 12;
    for (int round = 0; round < rounds; ++round) {
        const uint32_t nv_now = cdt.vertex_count();
        if (sc.mesh_of.size() < nv_now) return fail(Status::Full, "more vertices than the face scratch holds");
        for (uint32_t v = 0; v < nv_now; ++v) sc.mesh_of[v] = UINT32_MAX;
        for (uint32_t i = 0; i < total; ++i) {
            const uint32_t v = sc.arena.keys[i];
            if (v < nv_now && sc.mesh_of[v] == UINT32_MAX) sc.mesh_of[v] = i;
        }
        uint32_t added = 0;
        const uint16_t nt = cdt.triangle_count();
        for (; cleared < nt && cleared < sc.passed.size(); ++cleared) sc.passed[cleared] = 0;
        for (uint16_t t = 0; t < nt; ++t) {
            const cdt::Triangle<uint16_t>& T = cdt.triangle(t);
            if (!T.inner()) continue;
            const uint32_t i0 = point_of(T.v[0]), i1 = point_of(T.v[1]), i2 = point_of(T.v[2]);
            if (i0 == UINT32_MAX || i1 == UINT32_MAX || i2 == UINT32_MAX) continue;
            const Vec3 p0 = position(i0), p1 = position(i1), p2 = position(i2);
            // A triangle no longer than the tolerance cannot leave the surface by more (its
            // corners are on it). This also stops refinement where (u,v) is singular (poles,
            // apexes), where the uv centroid is no measure of a tiny 3D triangle.
            const uint64_t signature = uint64_t(T.v[0]) | uint64_t(T.v[1]) << 16 | uint64_t(T.v[2]) << 32 | uint64_t(1) << 48;
            if (t < sc.passed.size() && sc.passed[t] == signature) continue; // checked in an earlier round
            if (std::max({length2(p1 - p0), length2(p2 - p1), length2(p0 - p2)}) <= tol2) continue;
            Vec2 uv;
            const Vec3 c = (p0 + p1 + p2) * (1.0f / 3);
            if (length2(c - nearest_on_surface(pack, fi, c, (sc.uv[i0] + sc.uv[i1] + sc.uv[i2]) * (1.0f / 3), uv)) <= tol2) {
                if (t < sc.passed.size()) sc.passed[t] = signature;
                continue;
            }
            // The new point goes where the surface is nearest the centroid, in this face's branch
            // of (u,v): keep it inside the triangle's (u,v) span.
            if (!(uv.x >= std::min({sc.uv[i0].x, sc.uv[i1].x, sc.uv[i2].x}) && uv.x <= std::max({sc.uv[i0].x, sc.uv[i1].x, sc.uv[i2].x}) &&
                  uv.y >= std::min({sc.uv[i0].y, sc.uv[i1].y, sc.uv[i2].y}) && uv.y <= std::max({sc.uv[i0].y, sc.uv[i1].y, sc.uv[i2].y}))) {
                uv = (sc.uv[i0] + sc.uv[i1] + sc.uv[i2]) * (1.0f / 3);
            }
            if (total >= sc.uv.size() || total >= sc.arena.keys.size()) return fail(Status::Full, "refinement needs more points than the face scratch holds");
            const cdt::Point g{int32_t(std::lround((uv.x * su - x0) * q)) - 16384, int32_t(std::lround((uv.y * sv - y0) * q)) - 16384};
            // Never on a loop's edge (after quantizing): that would split it in this face only.
            cdt::Location<uint16_t> at;
            if (!ok(cdt.locate(g, T.v[0] >= cdt::kBoxVertices ? T.v[0] : T.v[1], at))) continue;
            if (at.kind == cdt::Location<uint16_t>::Kind::OnVertex) continue;
            if (at.kind == cdt::Location<uint16_t>::Kind::OnEdge && cdt.triangle(at.tri).constrained(at.edge)) continue;
            uint16_t v;
            const Status ins = cdt.insert_point(g, v, T.v[0] >= cdt::kBoxVertices ? T.v[0] : T.v[1]);
            if (ins == Status::Full) return fail(Status::Full, "more points than the CDT arena holds");
            if (!ok(ins)) continue;
            sc.uv[total] = uv;
            sc.arena.keys[total] = v;
            ++total;
            ++added;
        }
        if (!added) break;
        if (!ok(cdt.mark_inner())) return fail(Status::Degenerate, "refinement broke the loops");
    }
    res.points = total;

    const uint32_t nv = cdt.vertex_count();
    if (sc.mesh_of.size() < nv) return fail(Status::Full, "more vertices than the face scratch holds");
    for (uint32_t v = 0; v < nv; ++v) sc.mesh_of[v] = UINT32_MAX;
    const uint32_t* vertex_of_point = sc.arena.keys.data(); // point -> CDT vertex
    const float flip = F.reversed ? -1.0f : 1.0f;
    const uint32_t base = mesh.vertex_count;
    for (uint32_t i = 0; i < total; ++i) {
        const uint32_t v = vertex_of_point[i];
        if (v >= nv || sc.mesh_of[v] != UINT32_MAX) continue;
        if (mesh.vertex_count >= mesh.vertices.size()) return fail(Status::Full, "the mesh is full");
        const SurfacePoint sp = eval_surface(pack, S, sc.uv[i].x, sc.uv[i].y);
        Vec3 n = cross(sp.du, sp.dv);
        if (length2(n) < 1e-24f) { // a pole: look a little toward the middle of the face
            const SurfacePoint s2 = eval_surface(pack, S, sc.uv[i].x + 1e-3f * (um - sc.uv[i].x), sc.uv[i].y + 1e-3f * (vm - sc.uv[i].y));
            n = cross(s2.du, s2.dv);
        }
        mesh.vertices[mesh.vertex_count] = {i < np ? sc.xyz[i] : sp.p, normalized(n) * flip};
        if (mesh.vertex_count < mesh.uv.size()) mesh.uv[mesh.vertex_count] = sc.uv[i];
        sc.mesh_of[v] = mesh.vertex_count++;
    }
    for (uint16_t t = 0; t < cdt.triangle_count(); ++t) {
        const cdt::Triangle<uint16_t>& T = cdt.triangle(t);
        if (!T.inner()) continue;
        if ((mesh.triangle_count + 1) * 3 > mesh.indices.size()) {
            mesh.vertex_count = base;
            return fail(Status::Full, "the mesh is full");
        }
        uint32_t* out = &mesh.indices[mesh.triangle_count * 3];
        out[0] = sc.mesh_of[T.v[0]];
        out[1] = F.reversed ? sc.mesh_of[T.v[2]] : sc.mesh_of[T.v[1]];
        out[2] = F.reversed ? sc.mesh_of[T.v[1]] : sc.mesh_of[T.v[2]];
        ++mesh.triangle_count;
        ++res.triangles;
    }
    return res;
}

} // namespace facet::geom
