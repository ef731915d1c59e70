// Step 5 of tessellate_face: interior points where the mesh strays from the surface.
//
// Greedy insertion (as Garland & Heckbert's for terrains): each inner triangle's deviation is
// estimated once (and again only when the triangle changes), and a point goes in where the
// estimate is worst. Worst first, in rounds: a round inserts into every triangle above half
// the largest deviation left (and above the tolerance), then the changed triangles are
// measured again. No point is ever added where none is needed, so a cylinder or cone whose
// loops are sampled finely enough gets none at all, and a plane is never measured.
//
// The estimate of one triangle, cheapest test first:
//   * no longer than the tolerance: it cannot stray further (its corners are on the surface);
//   * plane: 0;  cylinder, cone: the sag of the arc its corners span in u, an exact bound
//     (its points project along the axis into the arc's circular segment); sphere: the
//     triangle's plane cuts the sphere in its circumcircle, so R - sqrt(R^2 - rho^2) bounds it;
//   * otherwise sampled at seven points (each edge's thirds, the centroid) that fix a cubic
//     model of the deviation over the triangle, whose peak on a grid of sixths is the
//     estimate: on elementary surfaces from the exact signed distance of the samples to the
//     surface, on the others from the distance along the triangle's normal between a sample
//     and the surface point at the sample's (u,v); on spheres and tori past the bound the
//     grid's 25 exact distances are measured instead of modelled. The point goes where it peaks
//     (never on a constrained edge: that is a chord of a B-rep edge, within the tolerance by
//     edge sampling).
#include "geom/elementary.h"
#include "face_internal.h"
#include "geom/patches.h"
#include "geom/fmath.h"

#include <algorithm>
#include <bit>
#include <cmath>
#ifdef FACET_DEBUG_REFINE
#include <cstdio>
#endif

namespace facet::geom::detail {

using namespace facet::pack;
using Tri = cdt::Triangle<uint16_t>;

namespace {

// A safety net: a round that adds no point ends refinement, and rounds that stall insert
// everywhere over the target (below), so real faces need tens of rounds (anc101's longest
// at 0.01 mm: 75 before that rule).
constexpr int kMaxRounds = 256;

// Work units (about five thousand ARM926 instructions) of making one fixed-point patch of a
// B-spline span (geom/patches.h). The sample part's quintic spans take about 130 k
// instructions each on the ARM926 (26 units); counted at 40 for rational spans of higher
// degree, whose contraction grows with the coefficients times the degree.
constexpr uint32_t kConvertUnits = 40;

// The deviation over a triangle, zero at its corners, is modelled as a cubic in the
// barycentric coordinates l0, l1, l2 (exact for cubic deviations, which bend one way more than
// the other along an edge: the peak is then off the middle):
//   sum over edges k (between corners i, j):  li lj (A_k + B_k (li - lj))  +  C l0 l1 l2.
// Seven samples fix it: each edge k at li = 2/3 (a_k) and li = 1/3 (b_k), and the centroid
// (c), which give A_k = 9/4 (a_k + b_k), B_k = 27/4 (a_k - b_k), C = 27 c - 3 sum A_k. Its
// value at a point is therefore a fixed combination of the seven samples, tabulated below for
// the points (i, j, k) / 6 of the triangle (corners left out). edges: bit e set when the point
// lies on edge e (coordinate e zero).
constexpr int kSamples = 7; // a0 b0 a1 b1 a2 b2 c
struct GridPoint {
    float l[3];
    float w[kSamples];   // the model's value here = sum of w[s] * sample s
    int16_t w32[kSamples]; // 32 w[s], whole numbers at the points (i, j, k) / 6
    uint8_t edges;
};
constexpr int kGridSteps = 6;
constexpr int kGridPoints = (kGridSteps + 1) * (kGridSteps + 2) / 2 - 3;
constexpr auto make_sixths() {
    struct Table {
        GridPoint p[kGridPoints];
        float lebesgue; // the largest sum of |w| over the points: |model| <= it * max |sample|
        const GridPoint* begin() const { return p; }
        const GridPoint* end() const { return p + kGridPoints; }
    } t{};
    int n = 0;
    for (int i = 0; i <= kGridSteps; ++i) {
        for (int j = 0; i + j <= kGridSteps; ++j) {
            const int k = kGridSteps - i - j;
            if (i == kGridSteps || j == kGridSteps || k == kGridSteps) continue;
            const double l[3] = {double(i) / kGridSteps, double(j) / kGridSteps, double(k) / kGridSteps};
            const double cube = l[0] * l[1] * l[2];
            GridPoint& g = t.p[n++];
            double sum = 0;
            for (int e = 0; e < 3; ++e) {
                const double li = l[(e + 1) % 3], lj = l[(e + 2) % 3];
                const double wa = li * lj * (2.25 + 6.75 * (li - lj)) - 6.75 * cube;
                const double wb = li * lj * (2.25 - 6.75 * (li - lj)) - 6.75 * cube;
                g.w[2 * e] = float(wa), g.w[2 * e + 1] = float(wb);
                sum += (wa < 0 ? -wa : wa) + (wb < 0 ? -wb : wb);
            }
            g.w[6] = float(27 * cube);
            // 32 w: 2 i j + i j (i - j) - i j k per edge sample (li = i/6 ...), 4 i j k for the centroid.
            const int ijk[3] = {i, j, k};
            for (int e = 0; e < 3; ++e) {
                const int a = ijk[(e + 1) % 3], b = ijk[(e + 2) % 3];
                g.w32[2 * e] = int16_t(2 * a * b + a * b * (a - b) - i * j * k);
                g.w32[2 * e + 1] = int16_t(2 * a * b - a * b * (a - b) - i * j * k);
            }
            g.w32[6] = int16_t(4 * i * j * k);
            sum += 27 * cube;
            for (int e = 0; e < 3; ++e) g.l[e] = float(l[e]);
            g.edges = uint8_t((i == 0 ? 1 : 0) | (j == 0 ? 2 : 0) | (k == 0 ? 4 : 0));
            if (float(sum) > t.lebesgue) t.lebesgue = float(sum);
        }
    }
    t.lebesgue *= 1.0001f; // the table's float rounding
    return t;
}
constexpr auto kSixths = make_sixths();
constexpr bool whole_weights_agree() {
    for (int p = 0; p < kGridPoints; ++p)
        for (int s = 0; s < kSamples; ++s) {
            const GridPoint& g = kSixths.p[p];
            const double d = double(g.w32[s]) - 32.0 * double(g.w[s]);
            if (d > 1e-4 || d < -1e-4) return false;
        }
    return true;
}
static_assert(whole_weights_agree(), "the grid's integer weights are 32 times its weights");

uint64_t key_of(const Tri& T) {
    return uint64_t(T.v[0]) | uint64_t(T.v[1]) << 16 | uint64_t(T.v[2]) << 32 | uint64_t(1) << 48;
}

// Whether one of the face's coedges lies on a seam of its surface.
bool has_seam(const Pack& pack, const pack::Face& F) {
    for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
        const Loop& L = pack.loops()[l];
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c)
            if (pack.coedges()[c].seam() != Seam::None) return true;
    }
    return false;
}

struct Context {
    const Pack& pack;
    const Surface& S;
    bool elementary;
    Elementary shape; // its closed forms (none unless elementary)
    Elementary::FlatBound flat; // what needs no samples (elementary surfaces)
    bool seams;    // the face's loops run along a seam (each side of it: points twice in 3D)
    uint32_t loop_points; // the points from the loops' samples (refinement's come after them)
    float tol2;
    float target2; // what refinement aims for: the tolerance, with a margin where it estimates
    const FaceScratch& sc;
    const cdt::Cdt<uint16_t>& cdt;
    mutable PatchCache patches; // a B-spline's points in fixed point (its cache is the scratch's)

    Context(const Pack& p, const pack::Face& F, const Surface& s, float tol, bool on_seams, uint32_t loop_point_count,
            const FaceScratch& scratch,
            const cdt::Cdt<uint16_t>& c)
        : pack(p), S(s), elementary(is_elementary(s)), shape(p, s), seams(on_seams), loop_points(loop_point_count),
          tol2(tol * tol), sc(scratch), cdt(c), patches(p, s, scratch.patches) {
        // On a doubly curved surface the deviation is modelled from samples (exact only for
        // cubic deviations); free-form deviations are estimated along the normal. Aim 5%
        // under the tolerance there.
        const bool exact = elementary && shape.developable();
        target2 = exact ? tol2 : 0.9025f * tol2;
        if (elementary) flat = shape.flat_bound(tol, F.uv_min[1], F.uv_max[1]);
    }

    // A point of the surface: from its fixed-point patch where it has one.
    Vec3 point(Vec2 uv) const { return patches.usable() ? patches.point(uv.x, uv.y) : eval_surface_point(pack, S, uv.x, uv.y); }

    // One point: the same bits (the samples of one point are copies of one computation).
    static bool same_point(Vec3 p, Vec3 q) {
        return std::bit_cast<uint32_t>(p.x) == std::bit_cast<uint32_t>(q.x) &&
               std::bit_cast<uint32_t>(p.y) == std::bit_cast<uint32_t>(q.y) &&
               std::bit_cast<uint32_t>(p.z) == std::bit_cast<uint32_t>(q.z);
    }

    // The measure of T, as estimate() gives it, but for a triangle that wraps across a seam:
    // one of its inner sides joins two corners at the same 3D point (a point on each side of a
    // periodic surface's seam: a full sphere's first triangles join u = 0 to u = 2 pi). Its
    // 3D image is flat or a segment while the surface it stands for is not, so no estimate from
    // its corners means anything: where the estimate would leave it, it gets a point at its
    // middle. (A pole's side is a loop's, constrained: a triangle on it is left to the
    // estimate.) Such corners are both loop samples on the seam (pinned): others are passed
    // over without loading a 3D point.
    TriangleMeasure measure(const Tri& T, uint32_t& cost) const {
        bool narrow = false; // accepted by the u-span bound: narrower than the period, it cannot wrap
        TriangleMeasure m = estimate(T, cost, narrow);
        if (!seams || narrow || m.error2 > target2) return m;
        for (int k = 0; k < 3; ++k) {
            if (T.constrained(k)) continue;
            const uint32_t a = sc.mesh_of[T.v[cdt::next3(k)]], b = sc.mesh_of[T.v[cdt::prev3(k)]];
            if (a >= loop_points || b >= loop_points || !sc.pinned[a] || !sc.pinned[b] || !same_point(sc.xyz[a], sc.xyz[b])) continue;
            const cdt::Point g0 = cdt.vertex(T.v[0]).p, g1 = cdt.vertex(T.v[1]).p, g2 = cdt.vertex(T.v[2]).p;
            m.error2 = 4 * target2;
            m.at = {(g0.x + g1.x + g2.x) / 3, (g0.y + g1.y + g2.y) / 3};
            break;
        }
        return m;
    }

    // The estimate of T's deviation; `cost` gets the work it took in units (FaceJob's: about
    // five thousand ARM926 instructions): none for the quick answers, 3 for seven distances to
    // an elementary surface or seven points of a fixed-point patch, 30 for seven points of a
    // free-form surface in float, kConvertUnits for each patch made.
    TriangleMeasure estimate(const Tri& T, uint32_t& cost, bool& narrow) const {
        TriangleMeasure m{key_of(T), 0, {0, 0}};
        cost = 0;
        Vec3 P[3];
        Vec2 UV[3];
        cdt::Point G[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t pt = sc.mesh_of[T.v[k]];
            P[k] = sc.xyz[pt];
            UV[k] = sc.uv[pt];
            G[k] = cdt.vertex(T.v[k]).p;
        }
        const Vec3 e0 = P[2] - P[1], e1 = P[0] - P[2], e2 = P[1] - P[0];
        const float l0 = dot(e0, e0), l1 = dot(e1, e1), l2 = dot(e2, e2);
        if (std::max({l0, l1, l2}) <= tol2) return m;
        using Flat = Elementary::FlatBound::Kind;
        switch (flat.kind) {
        case Flat::Everywhere: return m;
        case Flat::USpan: {
            const float span = std::max({UV[0].x, UV[1].x, UV[2].x}) - std::min({UV[0].x, UV[1].x, UV[2].x});
            if (span <= flat.limit) {
                narrow = true;
                return m;
            }
            break;
        }
        case Flat::Circumradius: {
            // rho^2 = l0 l1 l2 / (4 |e1 x e2|^2) <= the limit
            const Vec3 c = cross(e1, e2);
            if (l0 * l1 * l2 <= 4 * dot(c, c) * flat.limit) return m;
            break;
        }
        case Flat::None: break;
        }
        auto grid_at = [&](float w0, float w1, float w2) {
            return cdt::Point{int32_t(std::lround(w0 * float(G[0].x) + w1 * float(G[1].x) + w2 * float(G[2].x))),
                              int32_t(std::lround(w0 * float(G[0].y) + w1 * float(G[1].y) + w2 * float(G[2].y)))};
        };
        // The cubic model of the deviation (above): its seven samples, then its largest value
        // over the grid of sixths as the estimate, and where the point goes. When every sample
        // is so small that the model cannot reach the target anywhere, that bound will do.
        // The samples: at the thirds of each side (e[2k] nearer corner i, e[2k+1] nearer j) and
        // at the middle, each from a corner and a third of a side (fewer soft-float operations
        // than three weighted corners each).
        float e[kSamples];
        float largest = 0;
        const uint32_t conversions = patches.conversions();
        cost = elementary || patches.usable() ? 3 : 30;
        auto sample = [&](const auto* X, auto error) { // X: the corners in 3D or in (u,v)
            for (int k = 0; k < 3; ++k) {
                const int i = (k + 1) % 3, j = (k + 2) % 3;
                const auto third = (X[i] - X[j]) * (1.0f / 3);
                e[2 * k] = error(X[j] + (third + third));
                e[2 * k + 1] = error(X[j] + third);
            }
            e[6] = error((X[0] + X[1] + X[2]) * (1.0f / 3));
        };
        auto on_elementary = [&](Vec3 x) { return shape.signed_distance(x); };
        if (elementary) {
            sample(P, on_elementary);
        } else {
            // Signed deviation from a free-form surface: from the surface point at the sample's
            // parameters, along the triangle's unit normal (near the surface's where it matters,
            // and no derivatives to evaluate), along which every point of the triangle is as
            // far as its corner.
            const Vec3 normal = normalized(cross(e1, e2));
            const float level = dot(normal, P[0]);
            sample(UV, [&](Vec2 uv) { return level - dot(normal, point(uv)); });
        }
        cost += (patches.conversions() - conversions) * kConvertUnits;
        for (float x : e) largest = std::max(largest, std::fabs(x)); // (NaN: not the largest)
        const float bound = kSixths.lebesgue * largest;
        if (bound * bound <= target2) {
            m.error2 = bound * bound;
            return m;
        }
        // A constrained edge is a chord of a B-rep edge, within the tolerance by edge sampling,
        // and no point inside changes it: its points feed the model, but do not count.
        const uint8_t constrained = uint8_t((T.constrained(0) ? 1 : 0) | (T.constrained(1) ? 2 : 0) | (T.constrained(2) ? 4 : 0));
        // The model over the grid in integers (a soft-float core's sums are its costliest part):
        // the samples scaled so the largest is under 2^20, times the weights' 32 w.
        if (!(largest <= 1e30f)) { // a surface point gone to infinity: the worst, at the middle
            m.error2 = largest * largest;
            m.at = grid_at(1.0f / 3, 1.0f / 3, 1.0f / 3);
            return m;
        }
        if (elementary && !shape.developable()) {
            // On a sphere or a torus the deviation is measured at every point of the grid, not
            // modelled: over a triangle that spans much of a small tube (a fillet meshed at a
            // coarse tolerance) it is far from cubic. Across nist_ftc_11's torus at 1 mm a
            // side's chord sags radially by a quadratic and the tube turns that into a
            // quartic, peaking at the side's middle 1.4 times what its thirds give (the model:
            // 0.905 mm, the surface: 1.095); on nist_ctc_02's corner blends at 0.53 mm it peaks
            // inside. Each distance is a closed form: 25 of them cost about what 7 points of a
            // fixed-point patch do, past the bounds above that most triangles stop at.
            float worst = 0;
            const float* w = kSixths.p[kGridPoints / 2].l;
            for (const GridPoint& g : kSixths) {
                if (g.edges & constrained) continue;
                const float d = std::fabs(on_elementary(P[0] * g.l[0] + P[1] * g.l[1] + P[2] * g.l[2]));
                if (d > worst) worst = d, w = g.l; // (NaN: not the worst)
            }
            cost += 8;
            m.error2 = worst * worst;
            m.at = grid_at(w[0], w[1], w[2]);
            return m;
        }
        // largest < 2^exponent (it is over the target here: a normal float).
        const float scale = pow2_f(20 - std::clamp(exponent_f(largest), -100, 100));
        int32_t qe[kSamples];
        for (int s = 0; s < kSamples; ++s) qe[s] = e[s] == e[s] ? int32_t(e[s] * scale) : 0; // a NaN counts for nothing
        int32_t worst = -1;
        const float* w = kSixths.p[0].l;
        for (const GridPoint& g : kSixths) {
            if (g.edges & constrained) continue;
            int32_t v = 0;
            for (int s = 0; s < kSamples; ++s) v += int32_t(g.w32[s]) * qe[s];
            v = v < 0 ? -v : v;
            if (v > worst) worst = v, w = g.l;
        }
        const float worst_f = float(worst < 0 ? 0 : worst) / (32 * scale);
        m.error2 = worst_f * worst_f;
        m.at = grid_at(w[0], w[1], w[2]);
        return m;
    }
};

} // namespace

Result refine(const Pack& pack, uint32_t fi, const TessOptions& opt, const Grid& grid, cdt::Cdt<uint16_t>& cdt,
              FaceScratch& sc, RefineState& st, uint32_t units, uint32_t& spent) {
    const pack::Face& F = pack.faces()[fi];
    const Surface& S = pack.surfaces()[F.surface];
    spent = 0;
    if (S.type == uint8_t(SurfaceType::Plane)) return {}; // flat: nothing to add
    if (st.seams < 0) st.seams = has_seam(pack, F) ? 1 : 0; // once a face
    const Context ctx(pack, F, S, opt.tolerance * kAim, st.seams > 0, st.loop_points, sc, cdt);
    if (sc.measured.size() < cdt::triangles_for(cdt.vertex_capacity())) {
        return Result::fail(Status::Full, "the refinement's triangle measures are fewer than the arena's triangles");
    }
    const Result busy = Result::fail(Status::Busy, "refining");
    // A locate, an insertion, a surface point (and a patch made: in the measure that led here).
    const uint32_t insert_cost = ctx.elementary || ctx.patches.usable() ? 1 : 8;
    while (spent < units) {
        if (!st.inserting) {
            // A round: measure the triangles that changed, and find the worst.
            if (st.next == 0) {
                if (st.round >= kMaxRounds) return {};
                st.triangles = cdt.triangle_count();
                for (; st.cleared < st.triangles; ++st.cleared) sc.measured[st.cleared].key = 0;
                st.worst = 0;
            }
            uint32_t visited = 0; // a unit per 16 triangles looked at
            for (; st.next < st.triangles && spent + visited / 16 < units; ++st.next, ++visited) {
                const Tri& T = cdt.triangle(uint16_t(st.next));
                if (!T.inner()) continue;
                TriangleMeasure& m = sc.measured[st.next];
                if (m.key != key_of(T)) {
                    uint32_t cost;
                    m = ctx.measure(T, cost);
                    spent += cost;
                }
                st.worst = std::max(st.worst, m.error2);
            }
            spent += visited / 16;
            if (st.next < st.triangles) return busy;
#ifdef FACET_DEBUG_REFINE
            std::fprintf(stderr, "face %u round %u worst %g target %g tris %u\n", fi, st.round, sqrt_f(st.worst),
                         sqrt_f(ctx.target2), st.triangles);
#endif
            if (st.worst <= ctx.target2) return {};
            // Worst first: a point into every triangle above half the worst deviation; but
            // when the worst has not fallen by a tenth since the last round (thin triangles whose points
            // make thin triangles again), into every triangle over the target.
            const bool stalled = st.round > 0 && st.worst > 0.81f * st.last_worst;
            st.threshold = stalled ? ctx.target2 : std::max(ctx.target2, 0.25f * st.worst);
            st.last_worst = st.worst;
            st.added = 0;
            st.next = 0;
            st.inserting = true;
            continue;
        }
        // Then a point into every triangle (of those at the round's start) above the threshold;
        // the ones looked at and passed over count too (a unit per 16, as in the round above).
        uint32_t passed = 0;
        for (; st.next < st.triangles && spent + passed / 16 < units; ++st.next) {
            const Tri& T = cdt.triangle(uint16_t(st.next));
            TriangleMeasure& m = sc.measured[st.next];
            if (!T.inner() || m.key != key_of(T) || m.error2 <= st.threshold) { // changed since measured
                ++passed;
                continue;
            }
            spent += insert_cost;
            const uint16_t from = T.v[0];
            // Never onto a vertex or a constrained edge (that would split a loop's edge in this
            // face only): then the centroid, else give up on this triangle.
            cdt::Point at = m.at;
            cdt::Location<uint16_t> loc;
            bool placed = false;
            for (int attempt = 0; attempt < 2 && !placed; ++attempt) {
                if (attempt == 1) {
                    const cdt::Point c{(cdt.vertex(T.v[0]).p.x + cdt.vertex(T.v[1]).p.x + cdt.vertex(T.v[2]).p.x) / 3,
                                       (cdt.vertex(T.v[0]).p.y + cdt.vertex(T.v[1]).p.y + cdt.vertex(T.v[2]).p.y) / 3};
                    if (c == at) break;
                    at = c;
                }
                if (!ok(cdt.locate(at, from, loc))) continue;
                const Tri& L = cdt.triangle(loc.tri);
                placed = L.inner() && (loc.kind == cdt::Location<uint16_t>::Kind::Inside ||
                                       (loc.kind == cdt::Location<uint16_t>::Kind::OnEdge && !L.constrained(loc.edge)));
            }
            if (!placed) {
#ifdef FACET_DEBUG_REFINE
                std::fprintf(stderr, "  not placed: tri %u err %g\n", st.next, sqrt_f(m.error2));
#endif
                m.error2 = 0; // nowhere to put a point: leave it as it is
                continue;
            }
            if (st.total >= sc.uv.size() || st.total >= sc.xyz.size()) {
                return Result::fail(Status::Full, "refinement needs more points than the face scratch holds", {"points", st.total});
            }
            uint16_t v;
            const Status ins = cdt.insert_point(at, v, from);
            if (ins == Status::Full) return Result::fail(Status::Full, "more points than the CDT arena holds", {"points", st.total});
            if (!ok(ins) || v < cdt.vertex_count() - 1) continue; // not a new vertex
            const Vec2 uv = grid.to_uv(at);
            sc.uv[st.total] = uv;
            sc.xyz[st.total] = ctx.patches.usable() ? ctx.patches.point(uv.x, uv.y) : eval_surface(pack, S, uv.x, uv.y).p;
            sc.mesh_of[v] = st.total++;
            ++st.added;
        }
        spent += passed / 16;
        if (st.next < st.triangles) return busy;
        if (!st.added) return {};
        if (!ok(cdt.mark_inner())) return Result::fail(Status::Degenerate, "refinement broke the loops");
        spent += 1 + st.triangles / 64;
        ++st.round;
        st.next = 0;
        st.inserting = false;
    }
    return busy;
}

} // namespace facet::geom::detail
