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
//   * otherwise sampled at the midpoints of its edges and at its centroid, and modelled as a
//     quadratic over the triangle whose peak inside is computed: on elementary surfaces from
//     the exact signed distance of the samples to the surface, on the others from the distance
//     along the surface normal between a sample and the surface point at the sample's (u,v).
//     The point goes where the deviation peaks (never on a constrained edge: that is a chord
//     of a B-rep edge, within the tolerance by edge sampling).
#include "face_internal.h"
#include "geom/fmath.h"

#include <algorithm>
#include <cmath>
#ifdef FACET_DEBUG_REFINE
#include <cstdio>
#endif

namespace facet::geom::detail {

using namespace facet::pack;
using Tri = cdt::Triangle<uint16_t>;

namespace {

constexpr int kMaxRounds = 40;

// The points (i, j, k) / 6 of a triangle, corners left out, in barycentric coordinates; edges:
// bit e set when the point lies on edge e (coordinate e zero).
struct GridPoint {
    float l[3];
    uint8_t edges;
};
constexpr int kGridSteps = 6;
constexpr int kGridPoints = (kGridSteps + 1) * (kGridSteps + 2) / 2 - 3;
constexpr auto make_sixths() {
    struct Table {
        GridPoint p[kGridPoints];
        const GridPoint* begin() const { return p; }
        const GridPoint* end() const { return p + kGridPoints; }
        const GridPoint& operator[](int i) const { return p[i]; }
    } t{};
    int n = 0;
    for (int i = 0; i <= kGridSteps; ++i) {
        for (int j = 0; i + j <= kGridSteps; ++j) {
            const int k = kGridSteps - i - j;
            if (i == kGridSteps || j == kGridSteps || k == kGridSteps) continue;
            t.p[n++] = {{float(i) / kGridSteps, float(j) / kGridSteps, float(k) / kGridSteps},
                        uint8_t((i == 0 ? 1 : 0) | (j == 0 ? 2 : 0) | (k == 0 ? 4 : 0))};
        }
    }
    return t;
}
constexpr auto kSixths = make_sixths();

uint64_t key_of(const Tri& T) {
    return uint64_t(T.v[0]) | uint64_t(T.v[1]) << 16 | uint64_t(T.v[2]) << 32 | uint64_t(1) << 48;
}

struct Context {
    const Pack& pack;
    const Surface& S;
    SurfaceType type;
    const float* q;
    float tol2;
    float target2; // what refinement aims for: the tolerance, with a margin where it estimates
    float du_max = 0;   // cylinder, cone: widest u span that is surely within the tolerance
    float rho2_max = 0; // sphere: largest squared circumradius within the tolerance
    float sin_a = 0, cos_a = 1; // cone
    const FaceScratch& sc;
    const cdt::Cdt<uint16_t>& cdt;

    Context(const Pack& p, const pack::Face& F, const Surface& s, float tol, const FaceScratch& scratch,
            const cdt::Cdt<uint16_t>& c)
        : pack(p), S(s), type(SurfaceType(s.type)), q(p.floats().data() + s.params), tol2(tol * tol), sc(scratch), cdt(c) {
        // On a doubly curved surface the deviation is modelled from samples (exact only for
        // quadratic deviations); free-form deviations are estimated along the normal. Aim 5%
        // under the tolerance there.
        const bool exact = type == SurfaceType::Plane || type == SurfaceType::Cylinder || type == SurfaceType::Cone;
        target2 = exact ? tol2 : 0.9025f * tol2;
        switch (type) {
        case SurfaceType::Cylinder: du_max = max_arc_angle(q[12], tol); break;
        case SurfaceType::Cone: {
            sincos_f(q[13], sin_a, cos_a);
            const float r0 = std::fabs(q[12] + F.uv_min[1] * sin_a), r1 = std::fabs(q[12] + F.uv_max[1] * sin_a);
            du_max = max_arc_angle(std::max(r0, r1), tol);
            break;
        }
        case SurfaceType::Sphere: rho2_max = std::max(0.0f, 2 * q[12] * tol - tol * tol); break;
        default: break;
        }
    }

    // Signed distance from x to an elementary surface (exact, untrimmed; outward positive).
    float elementary_error(Vec3 x) const {
        const Vec3 d = x - Vec3{q[0], q[1], q[2]};
        const float a = dot(d, {q[3], q[4], q[5]}), b = dot(d, {q[6], q[7], q[8]}), z = dot(d, {q[9], q[10], q[11]});
        const float rho2 = a * a + b * b;
        switch (type) {
        case SurfaceType::Cylinder: return std::sqrt(rho2) - q[12];
        case SurfaceType::Cone: {
            // In the half-plane through the axis and x, the cone is the line (R + v sin a,
            // v cos a); past the apex its radius is negative: x is then nearer the mirror line.
            const float rho = std::sqrt(rho2);
            const float near_side = (rho - q[12]) * cos_a - z * sin_a, far_side = (-rho - q[12]) * cos_a - z * sin_a;
            return std::fabs(near_side) <= std::fabs(far_side) ? near_side : far_side;
        }
        case SurfaceType::Sphere: return std::sqrt(rho2 + z * z) - q[12];
        case SurfaceType::Torus: {
            // The tube on x's side of the axis, or (a self-intersecting torus) the other side's.
            const float rho = std::sqrt(rho2), w = rho - q[12];
            const float e = std::sqrt(w * w + z * z) - q[13];
            if (q[13] <= q[12]) return e;
            const float w2 = rho + q[12], e2 = std::sqrt(w2 * w2 + z * z) - q[13];
            return std::fabs(e) <= std::fabs(e2) ? e : e2;
        }
        default: return z; // plane
        }
    }

    // Signed deviation of x (the triangle's point at parameters uv) from a free-form surface:
    // from the surface point at uv, along the triangle's unit normal n (near the surface's
    // where it matters, and no derivatives to evaluate).
    float freeform_error(Vec3 x, Vec2 uv, Vec3 n) const { return dot(n, x - eval_surface_point(pack, S, uv.x, uv.y)); }

    TriangleMeasure measure(const Tri& T) const {
        TriangleMeasure m{key_of(T), 0, {0, 0}};
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
        switch (type) {
        case SurfaceType::Plane: return m;
        case SurfaceType::Cylinder:
        case SurfaceType::Cone: {
            const float span = std::max({UV[0].x, UV[1].x, UV[2].x}) - std::min({UV[0].x, UV[1].x, UV[2].x});
            if (span <= du_max) return m;
            break;
        }
        case SurfaceType::Sphere: {
            // rho^2 = l0 l1 l2 / (4 |e1 x e2|^2) <= rho2_max
            const Vec3 c = cross(e1, e2);
            if (l0 * l1 * l2 <= 4 * dot(c, c) * rho2_max) return m;
            break;
        }
        default: break;
        }
        const bool elementary = type <= SurfaceType::Torus;
        const Vec3 normal = elementary ? Vec3{0, 0, 0} : normalized(cross(e1, e2));
        auto error = [&](float w0, float w1, float w2) {
            const Vec3 x = P[0] * w0 + P[1] * w1 + P[2] * w2;
            return elementary ? elementary_error(x) : freeform_error(x, UV[0] * w0 + UV[1] * w1 + UV[2] * w2, normal);
        };
        auto grid_at = [&](float w0, float w1, float w2) {
            return cdt::Point{int32_t(std::lround(w0 * float(G[0].x) + w1 * float(G[1].x) + w2 * float(G[2].x))),
                              int32_t(std::lround(w0 * float(G[0].y) + w1 * float(G[1].y) + w2 * float(G[2].y)))};
        };
        // The deviation over the triangle, zero at its corners, modelled as a cubic in the
        // barycentric coordinates l0, l1, l2 (exact for cubic deviations, which bend one way
        // more than the other along an edge: the peak is then off the middle):
        //   sum over edges k (between corners i, j):  li lj (A_k + B_k (li - lj))  +  C l0 l1 l2.
        // Seven samples fix it: each edge at a third and two thirds, and the centroid. Its
        // largest value over a grid of sixths is the estimate, and where the point goes.
        float A[3], B[3];
        for (int k = 0; k < 3; ++k) {
            const int i = (k + 1) % 3, j = (k + 2) % 3;
            float wa[3] = {0, 0, 0}, wb[3] = {0, 0, 0};
            wa[i] = wb[j] = 2.0f / 3, wa[j] = wb[i] = 1.0f / 3;
            const float ea = error(wa[0], wa[1], wa[2]), eb = error(wb[0], wb[1], wb[2]); // li = 2/3, then 1/3
            A[k] = 2.25f * (ea + eb);
            B[k] = 6.75f * (ea - eb);
        }
        const float C = 27 * (error(1.0f / 3, 1.0f / 3, 1.0f / 3) - (A[0] + A[1] + A[2]) / 9);
        auto model = [&](const float l[3]) {
            float e = C * l[0] * l[1] * l[2];
            for (int k = 0; k < 3; ++k) {
                const int i = (k + 1) % 3, j = (k + 2) % 3;
                e += l[i] * l[j] * (A[k] + B[k] * (l[i] - l[j]));
            }
            return e;
        };
        // A constrained edge is a chord of a B-rep edge, within the tolerance by edge sampling,
        // and no point inside changes it: its points feed the model, but do not count.
        const uint8_t constrained = uint8_t((T.constrained(0) ? 1 : 0) | (T.constrained(1) ? 2 : 0) | (T.constrained(2) ? 4 : 0));
        float worst = 0;
        const float* w = kSixths[0].l;
        for (const GridPoint& g : kSixths) {
            if (g.edges & constrained) continue;
            const float e = std::fabs(model(g.l));
            if (e > worst) worst = e, w = g.l;
        }
        m.error2 = worst * worst;
        m.at = grid_at(w[0], w[1], w[2]);
        return m;
    }
};

} // namespace

Status refine(const Pack& pack, uint32_t fi, const TessOptions& opt, const Grid& grid, cdt::Cdt<uint16_t>& cdt,
              FaceScratch& sc, uint32_t& total, const char*& why) {
    const pack::Face& F = pack.faces()[fi];
    const Surface& S = pack.surfaces()[F.surface];
    if (S.type == uint8_t(SurfaceType::Plane)) return Status::Ok; // flat: nothing to add
    const Context ctx(pack, F, S, opt.tolerance, sc, cdt);
    if (sc.measured.size() < cdt::triangles_for(cdt.vertex_capacity())) {
        why = "the refinement's triangle measures are fewer than the arena's triangles";
        return Status::Full;
    }
    uint32_t cleared = 0; // measured[] slots reset for this face
    for (int round = 0; round < kMaxRounds; ++round) {
        const uint16_t nt = cdt.triangle_count();
        for (; cleared < nt; ++cleared) sc.measured[cleared].key = 0;
        float worst = 0;
        for (uint16_t t = 0; t < nt; ++t) {
            const Tri& T = cdt.triangle(t);
            if (!T.inner()) continue;
            TriangleMeasure& m = sc.measured[t];
            if (m.key != key_of(T)) m = ctx.measure(T);
            worst = std::max(worst, m.error2);
        }
#ifdef FACET_DEBUG_REFINE
        std::fprintf(stderr, "face %u round %d worst %g target %g tris %u\n", fi, round, std::sqrt(worst), std::sqrt(ctx.target2), nt);
#endif
        if (worst <= ctx.target2) return Status::Ok;
        const float threshold = std::max(ctx.target2, 0.25f * worst); // half the worst deviation
        uint32_t added = 0;
        for (uint16_t t = 0; t < nt; ++t) {
            const Tri& T = cdt.triangle(t);
            TriangleMeasure& m = sc.measured[t];
            if (!T.inner() || m.key != key_of(T) || m.error2 <= threshold) continue; // changed since measured
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
                std::fprintf(stderr, "  not placed: tri %u err %g\n", t, std::sqrt(m.error2));
#endif
                m.error2 = 0; // nowhere to put a point: leave it as it is
                continue;
            }
            if (total >= sc.uv.size() || total >= sc.xyz.size()) {
                why = "refinement needs more points than the face scratch holds";
                return Status::Full;
            }
            uint16_t v;
            const Status ins = cdt.insert_point(at, v, from);
            if (ins == Status::Full) {
                why = "more points than the CDT arena holds";
                return Status::Full;
            }
            if (!ok(ins) || v < cdt.vertex_count() - 1) continue; // not a new vertex
            const Vec2 uv = grid.to_uv(at);
            sc.uv[total] = uv;
            sc.xyz[total] = eval_surface(pack, S, uv.x, uv.y).p;
            sc.mesh_of[v] = total++;
            ++added;
        }
        if (!added) return Status::Ok;
        if (!ok(cdt.mark_inner())) {
            why = "refinement broke the loops";
            return Status::Degenerate;
        }
    }
    return Status::Ok;
}

} // namespace facet::geom::detail
