#include "geom/deviation.h"

#include "geom/elementary.h"
#include "geom/fmath.h"
#include "geom/params.h"

#include <algorithm>
#include <cmath>

namespace facet::geom {
namespace {

using namespace facet::pack;

// The parameter box a free-form search stays in: the face's bounds, widened a little (a
// triangle near the boundary may have its closest point just past it).
struct Box {
    float lo[2], hi[2];
};

// Gauss-Newton on |S(u,v) - p|^2 from the guess, kept in the box. Double accumulation of the
// 2x2 system; the surface itself is evaluated in float like everywhere else.
float newton_distance(const Pack& pack, const Surface& S, Vec3 p, Vec2 uv, const Box& box) {
    float best = 3.4e38f;
    for (int it = 0; it < 12; ++it) {
        const SurfacePoint sp = eval_surface(pack, S, uv.x, uv.y);
        const Vec3 d = p - sp.p;
        best = std::min(best, length(d));
        const double a = dot(sp.du, sp.du), b = dot(sp.du, sp.dv), c = dot(sp.dv, sp.dv);
        const double ru = dot(sp.du, d), rv = dot(sp.dv, d);
        const double det = a * c - b * b;
        if (!(std::fabs(det) > 1e-30)) break;
        double du = (c * ru - b * rv) / det, dv = (a * rv - b * ru) / det;
        // Damp steps that would leave the box or jump more than a quarter of it.
        const double su = 0.25 * (box.hi[0] - box.lo[0]) + 1e-12, sv = 0.25 * (box.hi[1] - box.lo[1]) + 1e-12;
        const double scale = std::min({1.0, su / (std::fabs(du) + 1e-300), sv / (std::fabs(dv) + 1e-300)});
        du *= scale, dv *= scale;
        const float nu = std::clamp(float(uv.x + du), box.lo[0], box.hi[0]);
        const float nv = std::clamp(float(uv.y + dv), box.lo[1], box.hi[1]);
        if (nu == uv.x && nv == uv.y) break;
        uv = {nu, nv};
    }
    return best;
}

} // namespace

float distance_to_surface(const Pack& pack, uint32_t face, Vec3 p, Vec2 uv_guess) {
    const pack::Face& F = pack.faces()[face];
    const Surface& S = pack.surfaces()[F.surface];
    if (is_elementary(S)) return std::fabs(Elementary(pack, S).signed_distance(p));
    const float wu = 0.05f * (F.uv_max[0] - F.uv_min[0]), wv = 0.05f * (F.uv_max[1] - F.uv_min[1]);
    Box box{{F.uv_min[0] - wu, F.uv_min[1] - wv}, {F.uv_max[0] + wu, F.uv_max[1] + wv}};
    if (S.type == uint8_t(SurfaceType::BSpline)) {
        // A B-spline is not defined past its knots (but for a periodic direction): stay inside.
        const BSplineSurfaceView B = bspline(pack, S);
        if (!B.u_periodic) box.lo[0] = std::max(box.lo[0], B.uk[B.pu]), box.hi[0] = std::min(box.hi[0], B.uk[B.nu]);
        if (!B.v_periodic) box.lo[1] = std::max(box.lo[1], B.vk[B.pv]), box.hi[1] = std::min(box.hi[1], B.vk[B.nv]);
    }
    uv_guess.x = std::clamp(uv_guess.x, box.lo[0], box.hi[0]);
    uv_guess.y = std::clamp(uv_guess.y, box.lo[1], box.hi[1]);
    return newton_distance(pack, S, p, uv_guess, box);
}

float triangle_deviation(const Pack& pack, uint32_t face, const Vec3 p[3], const Vec2 uv[3], int n) {
    float worst = 0;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; i + j <= n; ++j) {
            const int k = n - i - j;
            if (i == n || j == n || k == n) continue; // a corner
            const float a = float(i) / float(n), b = float(j) / float(n), c = float(k) / float(n);
            const Vec3 x = p[0] * a + p[1] * b + p[2] * c;
            const Vec2 g = uv[0] * a + uv[1] * b + uv[2] * c;
            worst = std::max(worst, distance_to_surface(pack, face, x, g));
        }
    }
    return worst;
}

} // namespace facet::geom
