// The curve spans (geom/patches.h): a B-spline curve's knot spans in Bézier form, fixed point.
#include "geom/patches.h"

#include "bspline.h"
#include "fixed_spans.h"
#include "geom/fmath.h"

#include <algorithm>

namespace facet::geom {

using namespace detail;

void CurveSpans::bind(const Pack& pack, const pack::Curve& c, int min_degree) {
    usable_ = false, last_ = -1;
    for (Slot& slot : slots_) slot.span = -1;
    if (c.type != uint8_t(pack::CurveType::BSpline) || (c.dim != 2 && c.dim != 3)) return;
    const BSplineCurveView C = bspline(pack, c);
    if (C.p < std::max(min_degree, 1) || C.p > kMaxBezierDegree) return;
    p_ = C.p, n_ = C.n, dim_ = c.dim, rational_ = C.rational, periodic_ = C.periodic;
    dims_ = dim_ + (rational_ ? 1 : 0);
    knots_ = C.knots, poles_ = C.poles, weights_ = C.weights;
    usable_ = true;
}

void CurveSpans::extract(int span, Slot& slot) const {
    const int dims = dims_, i0 = span - p_;
    const float* O = poles_ + dim_ * i0;
    float f[(kMaxBezierDegree + 1) * 4];
    for (int i = 0; i <= p_; ++i) {
        const float* P = poles_ + dim_ * (i0 + i);
        const float w = rational_ ? weights_[i0 + i] : 1.0f;
        for (int d = 0; d < dim_; ++d) f[i * dims + d] = (P[d] - O[d]) * w;
        if (rational_) f[i * dims + dim_] = w;
    }
    extract_span(knots_, p_, span, f, dims, dims);
    uint32_t exps = 0; // (under 2^28, as the patches': convex sums)
    for (int d = 0; d < dims; ++d) exps |= exponent_bits(to_fixed_under(f + d, p_ + 1, dims, 28, slot.c + d), d);
    slot.span = span;
    slot.exps = exps;
    for (int d = 0; d < 3; ++d) slot.origin[d] = d < dim_ ? O[d] : 0.0f;
    slot.per_span = per_span(knots_[span + 1] - knots_[span]);
}

const CurveSpans::Slot& CurveSpans::slot_of(float& t, int32_t& q) {
    int at = last_;
    if (at < 0 || !in_span(t, knots_, slots_[at].span)) {
        const int span = detail::find_span(knots_, n_, p_, t, periodic_);
        at = span % kSlots;
        if (slots_[at].span != span) extract(span, slots_[at]);
        last_ = at;
    }
    const Slot& slot = slots_[at];
    q = int32_t((t - knots_[slot.span]) * slot.per_span);
    q = q < 0 ? 0 : (q > kOneQ ? kOneQ : q);
    return slot;
}

void CurveSpans::bezier_at(const Slot& slot, int32_t q, int32_t* out, int32_t* diff) const {
    int32_t B[kBN], Bd[kBN];
    bernstein(p_, q, B, diff ? Bd : nullptr);
    for (int d = 0; d < dims_; ++d) {
        out[d] = combine(B, slot.c + d, dims_, p_);
        if (diff) diff[d] = combine_differences(Bd, slot.c + d, dims_, p_);
    }
}

const CurveSpans::Slot& CurveSpans::coordinates(float t, float* f) {
    int32_t q, out[4];
    const Slot& slot = slot_of(t, q);
    bezier_at(slot, q, out, nullptr);
    for (int d = 0; d < dims_; ++d) f[d] = times_pow2(float(out[d]), -exponent_at(slot.exps, d));
    if (rational_) { // from homogeneous coordinates
        const float inv = 1 / (f[dim_] != 0 ? f[dim_] : 1.0f);
        for (int d = 0; d < dim_; ++d) f[d] *= inv;
    }
    return slot;
}

Vec3 CurveSpans::point(float t) {
    float f[4];
    const Slot& slot = coordinates(t, f);
    return {slot.origin[0] + f[0], slot.origin[1] + f[1], slot.origin[2] + f[2]};
}

Vec2 CurveSpans::point2(float t) {
    float f[4];
    const Slot& slot = coordinates(t, f);
    return {slot.origin[0] + f[0], slot.origin[1] + f[1]};
}

Curve3Point CurveSpans::point_and_derivative(float t) {
    int32_t q, out[4], diff[4];
    const Slot& slot = slot_of(t, q);
    bezier_at(slot, q, out, diff);
    // d/dt = p times the last difference, over the span's length (per_span / 2^30).
    const float to_t = float(p_) * slot.per_span * (1 / kOne);
    float f[4], df[4];
    for (int d = 0; d < dims_; ++d) {
        const int e = -exponent_at(slot.exps, d);
        f[d] = times_pow2(float(out[d]), e), df[d] = float(diff[d]) * times_pow2(to_t, e);
    }
    const Vec3 O{slot.origin[0], slot.origin[1], slot.origin[2]};
    if (!rational_) return {O + Vec3{f[0], f[1], f[2]}, Vec3{df[0], df[1], df[2]}};
    const float inv = 1 / (f[3] != 0 ? f[3] : 1.0f);
    const Vec3 p = Vec3{f[0], f[1], f[2]} * inv; // from O
    return {O + p, (Vec3{df[0], df[1], df[2]} - p * df[3]) * inv};
}

} // namespace facet::geom
