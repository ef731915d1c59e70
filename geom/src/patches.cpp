#include "geom/patches.h"

#include "bspline.h"
#include "fixed_spans.h"
#include "geom/fmath.h"

#include <algorithm>
#include <bit>

namespace facet::geom {
using namespace detail;
namespace {

constexpr int kN = kMaxPatchDegree + 1;
constexpr uint32_t kEmpty = 0xFFFFFFFFu;

// The p + 1 basis functions that are non-zero on a span, N[s-p+a] for a = 0..p, as polynomials
// in the span's local parameter t in [0, 1]: M[a][k] is the coefficient of t^k. K: the knots
// s - p + 1 to s + p over the span (K[p - 1] = 0, K[p] = 1; PatchCache::SpanKnots). The
// Cox-de Boor recursion (The NURBS Book A2.2) on polynomials: each step multiplies by the linear
// factors (t - K_i) / (K_{i+j} - K_i) and (K_{i+j+1} - t) / (K_{i+j+1} - K_{i+1}).
void span_polynomials(const float* K, int p, float M[kN][kN]) {
    float P[kN][kN] = {}, Q[kN][kN];
    P[0][0] = 1;
    for (int j = 1; j <= p; ++j) {
        for (int r = 0; r <= j; ++r)
            for (int k = 0; k <= j; ++k) Q[r][k] = 0;
        for (int r = 0; r <= j; ++r) {
            const int i = p - 1 - j + r; // (the knot s - j + r)
            if (r >= 1) { // N[i, j-1] = P[r-1]
                const float d = K[i + j] - K[i];
                if (d != 0) {
                    const float a1 = 1 / d, a0 = -K[i] * a1;
                    for (int k = 0; k < j; ++k) Q[r][k] += P[r - 1][k] * a0, Q[r][k + 1] += P[r - 1][k] * a1;
                }
            }
            if (r <= j - 1) { // N[i+1, j-1] = P[r]
                const float d = K[i + j + 1] - K[i + 1];
                if (d != 0) {
                    const float b1 = -1 / d, b0 = -K[i + j + 1] * b1;
                    for (int k = 0; k < j; ++k) Q[r][k] += P[r][k] * b0, Q[r][k + 1] += P[r][k] * b1;
                }
            }
        }
        for (int r = 0; r <= j; ++r)
            for (int k = 0; k <= j; ++k) P[r][k] = Q[r][k];
    }
    for (int a = 0; a <= p; ++a)
        for (int k = 0; k <= p; ++k) M[a][k] = P[a][k];
}

inline uint64_t magnitude(int64_t x) { return x < 0 ? uint64_t(0) - uint64_t(x) : uint64_t(x); }

// Bits of x: the e with x < 2^e (0 for 0).
inline int bit_length(uint64_t x) { return x ? 64 - __builtin_clzll(x) : 0; }

// The smallest s with (top >> s) + 1 < 2^bits: a magnitude under 2^bits after a rounded shift.
inline int shift_under(uint64_t top, int bits) {
    int s = std::max(bit_length(top) - bits, 0); // one short at most
    while ((top >> s) + 1 >= (uint64_t(1) << bits)) ++s;
    return s;
}

// x / 2^s rounded (half up); s in [0, 62].
inline int64_t shift_round(int64_t x, int s) { return s ? (x + (int64_t(1) << (s - 1))) >> s : x; }

// The smallest s for which n coefficients whose magnitudes over 64 sum to sum64 (so sum to at
// most 64 (sum64 + n)) still sum under 2^29 after each is shifted right by s and rounded (each
// then at most its share plus 1).
inline int sum_shift(uint64_t sum64, uint32_t n) {
    const uint64_t bound = sum64 + n, limit = (uint64_t(1) << 29) - n; // want 64 bound / 2^s < limit
    for (int s = std::max(bit_length(bound) - 25, 0); s < 62; ++s) // (none below it fits)
        if (s <= 6 ? bound < (limit >> (6 - s)) : (bound >> (s - 6)) < limit) return s;
    return 62;
}

// A span's basis polynomials (span_polynomials) in fixed point under 2^30, I[a * (p + 1) + k],
// from its knots over the span (`knots`: the 2p - 2 besides the span's own); returns the exponent.
int fixed_span_polynomials(const float* knots, int p, int32_t* I) {
    float K[2 * kMaxPatchDegree], M[kN][kN], flat[kN * kN];
    for (int i = 0, at = 0; i < 2 * p; ++i) K[i] = i == p - 1 ? 0.0f : i == p ? 1.0f : knots[at++];
    span_polynomials(K, p, M);
    for (int a = 0; a <= p; ++a)
        for (int k = 0; k <= p; ++k) flat[a * (p + 1) + k] = M[a][k];
    return to_fixed_under(flat, (p + 1) * (p + 1), 1, 30, I);
}

// Knot span s's knots s - p + 1 to s + p over the span, but its own two: (k - k_s) / h, kept
// within +-1e15 (a span far shorter than its neighbours: a corrupt or absurd knot vector).
void span_knots(const float* knots, int p, int s, float* out) {
    const float ks = knots[s], h = knots[s + 1] - ks;
    for (int i = s - p + 1, at = 0; i <= s + p; ++i) {
        if (i == s || i == s + 1) continue;
        const float x = (knots[i] - ks) / h;
        out[at++] = x < 1e15f ? (x > -1e15f ? x : -1e15f) : 1e15f; // (NaN: 1e15)
    }
}

inline uint32_t mix(uint32_t h, uint32_t w) { return (h ^ w) * 0x9E3779B1u; }

} // namespace

PatchCache::PatchCache(const Pack& pack, const pack::Surface& S, std::span<uint32_t> memory) {
    if (S.type != uint8_t(pack::SurfaceType::BSpline)) return;
    const BSplineSurfaceView B = bspline(pack, S);
    if (B.pu > kMaxBezierDegree || B.pv > kMaxBezierDegree || B.pu < 1 || B.pv < 1) return;
    bezier_ = B.pu > kMaxPatchDegree || B.pv > kMaxPatchDegree;
    pu_ = B.pu, pv_ = B.pv, nu_ = B.nu, nv_ = B.nv;
    rational_ = B.rational, u_periodic_ = B.u_periodic, v_periodic_ = B.v_periodic;
    uk_ = B.uk, vk_ = B.vk, poles_ = B.poles, weights_ = B.weights;
    slot_words_ = slot_words(pu_, pv_, rational_);
    if (memory.size() < 1 + slot_words_) return;
    // The spans' basis matrices first (power form only), if there is room for them and a few
    // patches; then the patches.
    uint32_t* m = memory.data() + 1;
    const uint32_t matrices = bezier_ ? 0 : kMatrixSlots * (matrix_words(pu_) + matrix_words(pv_));
    if (matrices && memory.size() >= 1 + matrices + 8 * slot_words_) {
        mu_ = m, mv_ = m + kMatrixSlots * matrix_words(pu_);
        m += matrices;
    }
    memory_ = m;
    slots_ = uint32_t((memory.data() + memory.size() - m) / slot_words_);
    const uint32_t tag = S.params + 1; // the surface the patches belong to
    if (memory[0] != tag) {
        memory[0] = tag;
        for (uint32_t i = 0; i < slots_; ++i) reinterpret_cast<PatchHead*>(memory_ + i * slot_words_)->key = kEmpty;
    }
}

void PatchCache::forget(std::span<uint32_t> memory) {
    if (!memory.empty()) memory[0] = 0;
}

const PatchCache::PatchHead* PatchCache::patch(int su, int sv) {
    const uint32_t key = uint32_t(su) << 16 | uint32_t(sv);
    PatchHead* slot = reinterpret_cast<PatchHead*>(memory_ + (uint32_t(su) * 40503u + uint32_t(sv)) % slots_ * slot_words_);
    if (slot->key != key) {
        convert(su, sv, slot);
        slot->key = key;
        ++conversions_;
    }
    return slot;
}

void PatchCache::homogeneous(int at, const float* O, float* h) const {
    const float* P = poles_ + 3 * at;
    const float w = rational_ ? weights_[at] : 1.0f;
    for (int d = 0; d < 3; ++d) h[d] = (P[d] - O[d]) * w;
    if (rational_) h[3] = w;
}

void PatchCache::write_head(PatchHead* slot, int su, int sv, const float* O, uint32_t exps) const {
    slot->exponents = exps;
    slot->origin[0] = O[0], slot->origin[1] = O[1], slot->origin[2] = O[2];
    slot->per_span[0] = per_span(uk_[su + 1] - uk_[su]);
    slot->per_span[1] = per_span(vk_[sv + 1] - vk_[sv]);
}

uint32_t PatchCache::matrix_check(int p, const MatrixHead* head) {
    uint32_t h = mix(0x6A09E667u, uint32_t(p));
    for (int i = 0; i < 2 * p - 2; ++i) h = mix(h, std::bit_cast<uint32_t>(head->knots.at[i]));
    h = mix(h, uint32_t(head->exponent));
    const uint32_t* c = reinterpret_cast<const uint32_t*>(head + 1);
    for (int i = 0; i < (p + 1) * (p + 1); ++i) h = mix(h, c[i]);
    return h ^ (h >> 16);
}

const int32_t* PatchCache::span_matrix(bool v, int span, int& e, int32_t* local) {
    const int p = v ? pv_ : pu_;
    SpanKnots key;
    span_knots(v ? vk_ : uk_, p, span, key.at);
    uint32_t* cache = v ? mv_ : mu_;
    if (!cache) {
        e = fixed_span_polynomials(key.at, p, local);
        return local;
    }
    uint32_t h = uint32_t(p);
    for (int i = 0; i < 2 * p - 2; ++i) h = mix(h, std::bit_cast<uint32_t>(key.at[i]));
    MatrixHead* slot = reinterpret_cast<MatrixHead*>(cache + (h >> 16) % kMatrixSlots * matrix_words(p));
    int32_t* matrix = reinterpret_cast<int32_t*>(slot + 1);
    bool same = true;
    for (int i = 0; i < 2 * p - 2; ++i) same = same && std::bit_cast<uint32_t>(slot->knots.at[i]) == std::bit_cast<uint32_t>(key.at[i]);
    if (!same || slot->check != matrix_check(p, slot)) {
        slot->knots = key;
        slot->exponent = fixed_span_polynomials(key.at, p, matrix);
        slot->check = matrix_check(p, slot);
    }
    e = slot->exponent;
    return matrix;
}

void PatchCache::convert(int su, int sv, PatchHead* slot) {
    if (bezier_) return convert_bezier(su, sv, slot);
    // The span matrices (kept for the next patch of the same row or column of spans).
    int32_t u_local[kN * kN], v_local[kN * kN];
    int mu_e, mv_e;
    const int32_t* Mu = span_matrix(false, su, mu_e, u_local);
    const int32_t* Mv = span_matrix(true, sv, mv_e, v_local);
    const int mrow = pu_ + 1, nrow = pv_ + 1; // the matrices' rows: [a][k] and [b][l]
    const int dims = rational_ ? 4 : 3, i0 = su - pu_, j0 = sv - pv_, row = pv_ + 1;
    const int per = (pu_ + 1) * row;
    const float* O = poles_ + 3 * (i0 * nv_ + j0); // the patch's first pole: coordinates stay small
    // The homogeneous poles w (P - O), w in float, then each coordinate in fixed point under 2^29.
    float H[kN * kN][4];
    int32_t Hq[kN * kN][4];
    for (int a = 0; a <= pu_; ++a)
        for (int b = 0; b <= pv_; ++b) homogeneous((i0 + a) * nv_ + j0 + b, O, H[a * row + b]);
    int32_t* c = coefficients(slot);
    uint32_t exps = 0;
    for (int d = 0; d < dims; ++d) {
        // Fixed point all through: the poles (exponent eh), the two matrices (mu_e, mv_e).
        // C = Mu^T H Mv as T = Mu^T H (int64, back to int32 under 2^29) then T Mv (int64).
        const int eh = to_fixed_under(&H[0][d], per, 4, 29, &Hq[0][d]);
        int32_t T[kN][kN];
        int64_t W[kN][kN];
        uint64_t top = 0;
        for (int k = 0; k <= pu_; ++k) {
            for (int b = 0; b <= pv_; ++b) {
                int64_t x = 0;
                for (int a = 0; a <= pu_; ++a) x += int64_t(Mu[a * mrow + k]) * Hq[a * row + b][d];
                W[k][b] = x;
                top = std::max(top, magnitude(x));
            }
        }
        const int st = shift_under(top, 29);
        for (int k = 0; k <= pu_; ++k)
            for (int b = 0; b <= pv_; ++b) T[k][b] = int32_t(shift_round(W[k][b], st));
        uint64_t sum = 0; // of the magnitudes over 64 (up to 64 terms under 2^62: no overflow)
        for (int k = 0; k <= pu_; ++k) {
            for (int l = 0; l <= pv_; ++l) {
                int64_t x = 0;
                for (int b = 0; b <= pv_; ++b) x += int64_t(T[k][b]) * Mv[b * nrow + l];
                W[k][l] = x;
                sum += magnitude(x) >> 6;
            }
        }
        // The stored coefficients' magnitudes, each rounded, sum under 2^29: neither Horner
        // scheme can overflow. Their exponent: the poles', the matrices', less the shifts.
        int sc = sum_shift(sum, uint32_t(per));
        int e = eh + mu_e + mv_e - st - sc;
        if (e > 100) sc = std::min(sc + e - 100, 62), e = 100; // (noise: its coefficients are ~0)
        for (int k = 0; k <= pu_; ++k)
            for (int l = 0; l <= pv_; ++l) c[d * per + k * row + l] = int32_t(shift_round(W[k][l], sc));
        exps |= exponent_bits(e, d);
    }
    write_head(slot, su, sv, O, exps);
}

void PatchCache::convert_bezier(int su, int sv, PatchHead* slot) {
    // The span's (pu + 1) x (pv + 1) poles in homogeneous coordinates w (P - O), w, as floats
    // in the slot's coefficient words; extracted along u (each column of the slot), then
    // along v (each row); then each coordinate to fixed point in place.
    const int dims = rational_ ? 4 : 3, i0 = su - pu_, j0 = sv - pv_, row = pv_ + 1;
    const float* O = poles_ + 3 * (i0 * nv_ + j0);
    float* f = reinterpret_cast<float*>(coefficients(slot)); // [k][l][d], floats until made fixed point
    for (int a = 0; a <= pu_; ++a)
        for (int b = 0; b <= pv_; ++b) homogeneous((i0 + a) * nv_ + j0 + b, O, f + (a * row + b) * dims);
    for (int b = 0; b <= pv_; ++b) extract_span(uk_, pu_, su, f + b * dims, row * dims, dims);
    for (int a = 0; a <= pu_; ++a) extract_span(vk_, pv_, sv, f + a * row * dims, dims, dims);
    // Each coordinate with the largest exponent that keeps its largest magnitude under 2^28
    // (the Bernstein sums are convex combinations: they stay in the net's hull, and the
    // differences for derivatives under 2^29), in place.
    const int per = (pu_ + 1) * row;
    uint32_t exps = 0;
    for (int d = 0; d < dims; ++d) exps |= exponent_bits(to_fixed_under(f + d, per, dims, 28, reinterpret_cast<int32_t*>(f) + d), d);
    write_head(slot, su, sv, O, exps);
}

const PatchCache::PatchHead* PatchCache::locate(float& u, float& v, int32_t& qs, int32_t& qt) {
    // The spans: the last point's if u and v are still in them, else found (and wrapped or
    // clamped as the B-spline's own evaluation does).
    int su = last_su_, sv = last_sv_;
    if (su < 0 || !in_span(u, uk_, su)) su = detail::find_span(uk_, nu_, pu_, u, u_periodic_);
    if (sv < 0 || !in_span(v, vk_, sv)) sv = detail::find_span(vk_, nv_, pv_, v, v_periodic_);
    if (su != last_su_ || sv != last_sv_ || !last_) {
        last_ = patch(su, sv);
        last_su_ = su, last_sv_ = sv;
    }
    const PatchHead* slot = last_;
    // The local parameters in [0, 2^30].
    qs = int32_t((u - uk_[su]) * slot->per_span[0]), qt = int32_t((v - vk_[sv]) * slot->per_span[1]);
    qs = qs < 0 ? 0 : (qs > kOneQ ? kOneQ : qs);
    qt = qt < 0 ? 0 : (qt > kOneQ ? kOneQ : qt);
    return slot;
}

void PatchCache::bezier(const PatchHead* slot, int32_t qs, int32_t qt, int32_t* out, int32_t* ds, int32_t* dt) const {
    const int32_t* c = coefficients(slot);
    const int dims = rational_ ? 4 : 3, row = pv_ + 1;
    // Each line of the higher degree's direction (inner) to a point, then those points (outer).
    const bool s_first = pu_ >= pv_;
    const int lines = s_first ? pv_ + 1 : pu_ + 1, inner = s_first ? pu_ : pv_, outer = s_first ? pv_ : pu_;
    const int step_line = s_first ? dims : row * dims, step_in = s_first ? row * dims : dims;
    int32_t Bi[kBN], Bdi[kBN], Bo[kBN], Bdo[kBN], V[kBN], Dn[kBN];
    bernstein(inner, s_first ? qs : qt, Bi, ds ? Bdi : nullptr);
    bernstein(outer, s_first ? qt : qs, Bo, ds ? Bdo : nullptr);
    for (int d = 0; d < dims; ++d) {
        for (int k = 0; k < lines; ++k) {
            const int32_t* line = c + k * step_line + d;
            V[k] = combine(Bi, line, step_in, inner);
            if (ds) Dn[k] = combine_differences(Bdi, line, step_in, inner);
        }
        out[d] = combine(Bo, V, 1, outer);
        if (!ds) continue;
        const int32_t d_out = combine_differences(Bdo, V, 1, outer), d_in = combine(Bo, Dn, 1, outer);
        ds[d] = s_first ? d_in : d_out, dt[d] = s_first ? d_out : d_in;
    }
}

Vec3 PatchCache::point(float u, float v) {
    int32_t qs, qt;
    const PatchHead* slot = locate(u, v, qs, qt);
    const int32_t* c = coefficients(slot);
    const int dims = rational_ ? 4 : 3, row = pv_ + 1;
    int32_t out[4];
    if (bezier_) {
        bezier(slot, qs, qt, out, nullptr, nullptr);
    } else {
        for (int d = 0; d < dims; ++d, c += (pu_ + 1) * row) {
            // Horner in t along each row (a power of s), then in s.
            int32_t acc = 0;
            for (int k = pu_; k >= 0; --k) {
                const int32_t* r = c + k * row;
                int32_t x = r[pv_];
                for (int l = pv_ - 1; l >= 0; --l) x = mulq(x, qt) + r[l];
                acc = k == pu_ ? x : mulq(acc, qs) + x;
            }
            out[d] = acc;
        }
    }
    // (The scalings by the exponents are powers of two: times_pow2, exact.)
    const uint32_t exps = slot->exponents;
    auto unscale = [&](float x, int d) { return times_pow2(x, -exponent_at(exps, d)); };
    const Vec3 O{slot->origin[0], slot->origin[1], slot->origin[2]};
    if (!rational_) return {O.x + unscale(float(out[0]), 0), O.y + unscale(float(out[1]), 1), O.z + unscale(float(out[2]), 2)};
    float W = unscale(float(out[3]), 3);
    if (W == 0) W = 1;
    const float inv = 1 / W;
    return {O.x + float(out[0]) * unscale(inv, 0), O.y + float(out[1]) * unscale(inv, 1), O.z + float(out[2]) * unscale(inv, 2)};
}

SurfacePoint PatchCache::point_and_derivatives(float u, float v) {
    int32_t qs, qt;
    const PatchHead* slot = locate(u, v, qs, qt);
    const int32_t* c = coefficients(slot);
    const int dims = rational_ ? 4 : 3, row = pv_ + 1;
    // Per coordinate: the value, and its derivatives in s and t over 8 (a derivative of the
    // polynomial can reach its degree times the coefficients' sum: 8 keeps it in 32 bits).
    float f[4], fs[4], ft[4];
    const uint32_t exps = slot->exponents;
    if (bezier_) {
        // The Bézier derivatives are the degree times the last differences.
        int32_t out[4], ds[4], dt[4];
        bezier(slot, qs, qt, out, ds, dt);
        for (int d = 0; d < dims; ++d) {
            const int e = -exponent_at(exps, d);
            f[d] = times_pow2(float(out[d]), e), fs[d] = float(ds[d]) * times_pow2(float(pu_), e), ft[d] = float(dt[d]) * times_pow2(float(pv_), e);
        }
    } else {
        for (int d = 0; d < dims; ++d, c += (pu_ + 1) * row) {
            int32_t acc = 0, acc_s = 0, acc_t = 0;
            for (int k = pu_; k >= 0; --k) {
                const int32_t* r = c + k * row;
                int32_t x = r[pv_], dx = 0;
                for (int l = pv_ - 1; l >= 0; --l) dx = mulq(dx, qt) + (x >> 3), x = mulq(x, qt) + r[l];
                if (k == pu_) {
                    acc = x, acc_t = dx;
                } else {
                    acc_s = mulq(acc_s, qs) + (acc >> 3);
                    acc = mulq(acc, qs) + x;
                    acc_t = mulq(acc_t, qs) + dx;
                }
            }
            const int e = -exponent_at(exps, d); // (times 8: the derivatives were kept over 8)
            f[d] = times_pow2(float(acc), e), fs[d] = times_pow2(float(acc_s), e + 3), ft[d] = times_pow2(float(acc_t), e + 3);
        }
    }
    // d/du = d/ds over the span's length (per_span / 2^30).
    const float hu = slot->per_span[0] * (1 / kOne), hv = slot->per_span[1] * (1 / kOne);
    const Vec3 O{slot->origin[0], slot->origin[1], slot->origin[2]};
    if (!rational_) {
        return {{O.x + f[0], O.y + f[1], O.z + f[2]}, Vec3{fs[0], fs[1], fs[2]} * hu, Vec3{ft[0], ft[1], ft[2]} * hv};
    }
    float W = f[3];
    if (W == 0) W = 1;
    const float inv = 1 / W;
    const Vec3 p{f[0] * inv, f[1] * inv, f[2] * inv}; // from O
    const Vec3 du = (Vec3{fs[0], fs[1], fs[2]} - p * fs[3]) * (inv * hu), dv = (Vec3{ft[0], ft[1], ft[2]} - p * ft[3]) * (inv * hv);
    return {O + p, du, dv};
}

} // namespace facet::geom
