#pragma once
// The B-spline pieces that eval.cpp and patches.cpp share: finding a knot span and the basis
// functions (the layouts they read: geom/params.h).
#include "geom/eval.h"
#include "geom/fmath.h"
#include "geom/params.h"

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
    // (The compares by order_key: the knots are finite, the pack's check. A NaN t is clamped to
    // the end its sign says, as its order_bits are.)
#if !FACET_SOFT_FLOAT
    if (t != t) t = std::signbit(t) ? lo : hi;
#endif
    const OrderKey klo = order_key(lo), khi = order_key(hi);
    OrderKey kt = order_key(t);
    if (kt < klo) t = lo, kt = klo;
    if (kt > khi) t = hi, kt = khi;
    int s = p;
    if (kt >= khi) {
        s = n - 1;
        while (s > p && order_key(knots[s]) >= order_key(knots[s + 1])) --s;
    } else {
        int a = p, b = n;
        while (b - a > 1) {
            const int m = (a + b) / 2;
            if (kt < order_key(knots[m])) b = m;
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

// The basis functions of a surface's u (v) direction at u (v): basis() on its knots.
inline int u_basis(const BSplineSurfaceView& B, float u, float* N, float* dN) {
    return basis(B.uk, B.nu, B.pu, u, B.u_periodic, N, dN);
}
inline int v_basis(const BSplineSurfaceView& B, float v, float* N, float* dN) {
    return basis(B.vk, B.nv, B.pv, v, B.v_periodic, N, dN);
}

} // namespace facet::geom::detail
