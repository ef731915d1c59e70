#pragma once
// Fixed-point Bézier spans, shared by the B-spline surface patches and the curve spans
// (geom/patches.h): a span's local parameter in [0, 2^30], its Bézier points by knot insertion
// (in float, once per span), numbers to fixed point with one exponent, and the Bernstein sums.
#include "geom/fmath.h"
#include "geom/patches.h"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace facet::geom::detail {

constexpr float kOne = 1073741824.0f; // 2^30: the local parameters' 1
constexpr int32_t kOneQ = 1 << 30;
constexpr int kBN = kMaxBezierDegree + 1;

// 2^30 over a span's length, kept finite: a span under 3e-30 long (a corrupt or absurd knot
// vector) would make it infinite, and the local parameters NaN.
inline float per_span(float h) {
    const float r = kOne / h;
    return r < 1e30f ? r : 1e30f;
}

// A coordinate's exponent in a slot's exponent word (one signed byte each), in and out.
inline uint32_t exponent_bits(int e, int d) { return uint32_t(uint8_t(int8_t(e))) << (8 * d); }
inline int exponent_at(uint32_t exps, int d) { return int8_t(uint8_t(exps >> (8 * d))); }

// Whether x lies in the span [knots[s], knots[s+1]), by order_key (the knots are finite, the
// pack's check; a NaN is in no span, as by float compares).
inline bool in_span(float x, const float* knots, int s) {
    const OrderKey k = order_key(x);
    return k >= order_key(knots[s]) && k < order_key(knots[s + 1]);
}

// a x t / 2^30 for t in [0, 2^30]: |result| <= |a|.
inline int32_t mulq(int32_t a, int32_t t) { return int32_t((int64_t(a) * t) >> 30); }

// The Bernstein basis of degree n at q in [0, 2^30] (B[0..n], 2^30 = 1) and, if Bd is not null,
// of degree n - 1 (Bd[0..n-1]): the triangle B_i,k = (1 - t) B_i,k-1 + t B_i-1,k-1, convex
// combinations of numbers in [0, 2^30] that stay there. Computed once for a parameter, it
// serves every row of coefficients evaluated at it: a point is then one sum of products per
// row, not de Casteljau's n (n + 1) / 2 steps per row.
inline void bernstein(int n, int32_t q, int32_t* B, int32_t* Bd) {
    B[0] = kOneQ;
    for (int k = 1; k <= n; ++k) {
        if (k == n && Bd)
            for (int i = 0; i < n; ++i) Bd[i] = B[i];
        int32_t carried = 0; // t B_i-1,k-1
        for (int i = 0; i < k; ++i) {
            const int32_t b = B[i], tb = mulq(b, q);
            B[i] = b - tb + carried;
            carried = tb;
        }
        B[k] = carried;
    }
}

// sum of B[i] c[i * stride], i = 0..n, rounded back from 2^30 (|c| < 2^29: each product under
// 2^59, the sum under 2^63).
inline int32_t combine(const int32_t* B, const int32_t* c, int stride, int n) {
    int64_t x = int64_t(1) << 29;
    for (int i = 0; i <= n; ++i) x += int64_t(B[i]) * c[i * stride];
    return int32_t(x >> 30);
}

// sum of Bd[i] (c[i+1] - c[i]), i = 0..n-1: the derivative over the degree.
inline int32_t combine_differences(const int32_t* Bd, const int32_t* c, int stride, int n) {
    int64_t x = int64_t(1) << 29;
    for (int i = 0; i < n; ++i) x += int64_t(Bd[i]) * (c[(i + 1) * stride] - c[i * stride]);
    return int32_t(x >> 30);
}

// Bézier extraction of one span s of a B-spline of degree p (knot insertion; the row's p + 1
// points, `dims` floats each, `stride` floats apart, read and overwritten: fixed_spans.cpp).
void extract_span(const float* knots, int p, int s, float* row, int stride, int dims);

// The larger of big (>= 0) and |x|, by the floats' bits (a soft-float compare costs ~25
// instructions; for finite floats the order of the bits is the order of the magnitudes).
inline float larger_magnitude(float big, float x) {
    const uint32_t b = std::bit_cast<uint32_t>(x) & 0x7FFFFFFFu;
    return b > std::bit_cast<uint32_t>(big) ? std::bit_cast<float>(b) : big;
}

// round(x 2^e) by the float's bits (no soft-float call), for x 2^e under 2^31 in magnitude (the
// caller's exponent sees to it; larger is clamped). Zeros, subnormals, NaN and infinities give 0.
inline int32_t to_fixed(float x, int e) {
    const uint32_t b = std::bit_cast<uint32_t>(x);
    const int be = int(b >> 23 & 0xFF);
    if (be == 0 || be == 0xFF) return 0;
    const uint32_t m = (b & 0x7FFFFFu) | 0x800000u; // x = m 2^(be - 150)
    const int sh = be - 150 + e;
    uint32_t v;
    if (sh >= 0) v = sh <= 7 ? m << sh : 0x7FFFFFFFu;
    else v = sh > -25 ? (m + (1u << (-sh - 1))) >> -sh : 0;
    return b >> 31 ? -int32_t(v) : int32_t(v);
}

// Numbers f[i * stride], i < n, in fixed point with one exponent, the largest that keeps their
// magnitudes under 2^bits (within +-100: a signed byte of a slot's exponent word holds it; 0
// when all are zero or noise under 1e-30), into out[i * stride] (out may be f itself: each
// number is read before its word is written). Returns the exponent.
inline int to_fixed_under(const float* f, int n, int stride, int bits, int32_t* out) {
    float big = 0;
    for (int i = 0; i < n; ++i) big = larger_magnitude(big, f[i * stride]);
    const int e = big >= 1e-30f ? std::clamp(bits - exponent_f(big), -100, 100) : 0;
    for (int i = 0; i < n; ++i) {
        const float x = f[i * stride];
        out[i * stride] = to_fixed(x, e);
    }
    return e;
}

} // namespace facet::geom::detail
