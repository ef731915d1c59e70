#pragma once
// The B-spline pieces that eval.cpp and patches.cpp share: the basis functions and a surface's
// parameters by name.
#include "geom/eval.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace facet::geom::detail {

// The span of knots [knots[s], knots[s+1]) holding t (The NURBS Book A2.1), p <= s < n, after a
// periodic B-spline (stored over one period) has taken t modulo its period and another has
// clamped t to its knots; t itself is updated. At the end of the knots the last span of
// non-zero length.
inline int find_span(const float* knots, int n, int p, float& t, bool periodic) {
    const float lo = knots[p], hi = knots[n];
    if (periodic && hi > lo && (t < lo || t > hi)) {
        t = lo + std::fmod(t - lo, hi - lo);
        if (t < lo) t += hi - lo;
    }
    if (t < lo) t = lo;
    if (t > hi) t = hi;
    int s = p;
    if (t >= hi) {
        s = n - 1;
        while (s > p && knots[s] >= knots[s + 1]) --s;
    } else {
        int a = p, b = n;
        while (b - a > 1) {
            const int m = (a + b) / 2;
            if (t < knots[m]) b = m;
            else a = m;
        }
        s = a;
    }
    return s;
}

// x != 0 (NaN too); a float by its bits: a soft-float compare is about 30 instructions.
template <typename Real>
inline bool nonzero(Real x) {
    if constexpr (std::is_same_v<Real, float>) return (std::bit_cast<uint32_t>(x) << 1) != 0;
    else return x != 0;
}

// Non-zero B-spline basis functions and their first derivatives at t (The NURBS Book A2.2/A2.3).
// knots: expanded; n: poles; p: degree. Returns the span index s: functions N[s-p .. s].
// A periodic B-spline (stored over one period) takes t modulo the period; others clamp t.
// dN null: the values only. Real: float on the device; double for the host's reference checks.
template <typename Real = float>
inline int basis(const float* knots, int n, int p, float t_in, bool periodic, Real* N, std::type_identity_t<Real>* dN) {
    const int s = find_span(knots, n, p, t_in, periodic);
    const Real t = t_in;
    Real left[kMaxDegree + 2], right[kMaxDegree + 2];
    Real ndu[kMaxDegree + 1][kMaxDegree + 1];
    ndu[0][0] = 1;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - Real(knots[s + 1 - j]);
        right[j] = Real(knots[s + j]) - t;
        Real saved = 0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];
            const Real tmp = nonzero(ndu[j][r]) ? ndu[r][j - 1] / ndu[j][r] : 0;
            ndu[r][j] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; ++j) N[j] = ndu[j][p];
    if (!dN) return s; // values only
    // First derivatives: p * (N_{j,p-1}/(u_{j+p}-u_j) - N_{j+1,p-1}/(u_{j+p+1}-u_{j+1})).
    for (int r = 0; r <= p; ++r) {
        Real d = 0;
        if (r >= 1 && nonzero(ndu[p][r - 1])) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
        if (r <= p - 1 && nonzero(ndu[p][r])) d -= ndu[r][p - 1] / ndu[p][r];
        dN[r] = p > 0 ? d * Real(p) : 0;
    }
    return s;
}

// A B-spline curve's parameters (degree, poles, knots, rational, periodic, then knots, poles
// of `dim` floats, weights) by name.
struct BSplineCurveView {
    int p, n, k;
    bool rational, periodic;
    const float *knots, *poles, *weights;

    BSplineCurveView(const float* q, int dim)
        : p(int(q[0])), n(int(q[1])), k(int(q[2])), rational(q[3] != 0), periodic(q[4] != 0), knots(q + 5),
          poles(knots + k), weights(poles + n * dim) {}
};

// A B-spline surface's parameters (BSplineSurfaceHead, then knots, poles, weights) by name.
struct BSplineSurfaceView {
    int pu, pv, nu, nv, ku, kv;
    bool rational, u_periodic, v_periodic;
    const float *uk, *vk, *poles, *weights;

    explicit BSplineSurfaceView(const float* q)
        : pu(int(q[0])), pv(int(q[1])), nu(int(q[2])), nv(int(q[3])), ku(int(q[4])), kv(int(q[5])), rational(q[6] != 0),
          u_periodic(q[7] != 0), v_periodic(q[8] != 0), uk(q + 9), vk(uk + ku), poles(vk + kv), weights(poles + 3 * nu * nv) {}
    int u_basis(float u, float* N, float* dN) const { return basis(uk, nu, pu, u, u_periodic, N, dN); }
    int v_basis(float v, float* N, float* dN) const { return basis(vk, nv, pv, v, v_periodic, N, dN); }
};

} // namespace facet::geom::detail
