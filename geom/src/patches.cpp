#include "geom/patches.h"

#include "bspline.h"
#include "geom/fmath.h"

#include <algorithm>
#include <bit>

namespace facet::geom {
namespace {

constexpr int kN = kMaxPatchDegree + 1;
constexpr uint32_t kEmpty = 0xFFFFFFFFu;
constexpr float kOne = 1073741824.0f; // 2^30: the local parameters' 1
constexpr int32_t kOneQ = 1 << 30;

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

// The p + 1 basis functions that are non-zero on span s, N[s-p+a] for a = 0..p, as polynomials
// in the span's local parameter t = (u - knots[s]) / (knots[s+1] - knots[s]): M[a][k] is the
// coefficient of t^k. The Cox-de Boor recursion (The NURBS Book A2.2) on polynomials: each
// step multiplies by the linear factors (u - k_i) / (k_{i+j} - k_i) and
// (k_{i+j+1} - u) / (k_{i+j+1} - k_{i+1}), written in t.
void span_polynomials(const float* knots, int p, int s, float M[kN][kN]) {
    const float h = knots[s + 1] - knots[s], ks = knots[s];
    float P[kN][kN] = {}, Q[kN][kN];
    P[0][0] = 1;
    for (int j = 1; j <= p; ++j) {
        for (int r = 0; r <= j; ++r)
            for (int k = 0; k <= j; ++k) Q[r][k] = 0;
        for (int r = 0; r <= j; ++r) {
            const int i = s - j + r;
            if (r >= 1) { // N[i, j-1] = P[r-1]
                const float d = knots[i + j] - knots[i];
                if (d != 0) {
                    const float a0 = (ks - knots[i]) / d, a1 = h / d;
                    for (int k = 0; k < j; ++k) Q[r][k] += P[r - 1][k] * a0, Q[r][k + 1] += P[r - 1][k] * a1;
                }
            }
            if (r <= j - 1) { // N[i+1, j-1] = P[r]
                const float d = knots[i + j + 1] - knots[i + 1];
                if (d != 0) {
                    const float b0 = (knots[i + j + 1] - ks) / d, b1 = -h / d;
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

// Bézier extraction of one span, on one row of control points (The NURBS Book A5.1, knot
// insertion): the span's ends a = knots[s] < b = knots[s+1] are inserted into the local knot
// vector until each has multiplicity p; the p + 1 points then left over the span are its
// Bézier control points. Only convex combinations with weights in [0, 1] (the knots are
// ordered): the points stay within the row's hull and the float rounding stays at its size.
// row: p + 1 points of `dims` floats, `stride` floats apart, read and overwritten.
constexpr int kBN = kMaxBezierDegree + 1;
void extract_span(const float* knots, int p, int s, float* row, int stride, int dims) {
    float T[4 * kBN], Q[3 * kBN][4];
    int nt = 2 * p + 2, nq = p + 1;
    for (int i = 0; i < nt; ++i) T[i] = knots[s - p + i];
    for (int i = 0; i < nq; ++i)
        for (int d = 0; d < dims; ++d) Q[i][d] = row[i * stride + d];
    int span_at = 0; // where the span [a, b) starts once a has multiplicity p: its last a
    const float ends[2] = {T[p], T[p + 1]};
    for (int end = 0; end < 2; ++end) {
        const float x = ends[end];
        const OrderKey kx = order_key(x); // (knots are finite: the pack's check)
        int k = 0, m = 0; // T[k] <= x < T[k+1]; m: x's multiplicity (an insertion adds one to each)
        for (int i = 0; i < nt; ++i) {
            const OrderKey ki = order_key(T[i]);
            if (ki <= kx) k = i;
            m += ki == kx;
        }
        for (; m < p; ++m, ++k, ++nt, ++nq) {
            for (int i = nq; i > k - m; --i)
                for (int d = 0; d < dims; ++d) Q[i][d] = Q[i - 1][d];
            for (int i = k - m; i >= k - p + 1; --i) {
                const float alpha = (x - T[i]) / (T[i + p] - T[i]);
                for (int d = 0; d < dims; ++d) Q[i][d] = alpha * Q[i][d] + (1 - alpha) * Q[i - 1][d];
            }
            for (int i = nt; i > k + 1; --i) T[i] = T[i - 1];
            T[k + 1] = x;
        }
        if (end == 0) span_at = k; // (b's insertions all come after it)
    }
    for (int i = 0; i <= p; ++i)
        for (int d = 0; d < dims; ++d) row[i * stride + d] = Q[span_at - p + i][d];
}

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
// when all are zero or noise under 1e-30), into
// out[i * stride] (out may be f itself: each number is read before its word is written).
// Returns the exponent.
int to_fixed_under(const float* f, int n, int stride, int bits, int32_t* out) {
    float big = 0;
    for (int i = 0; i < n; ++i) big = larger_magnitude(big, f[i * stride]);
    const int e = big >= 1e-30f ? std::clamp(bits - exponent_f(big), -100, 100) : 0;
    for (int i = 0; i < n; ++i) {
        const float x = f[i * stride];
        out[i * stride] = to_fixed(x, e);
    }
    return e;
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

// A span's basis polynomials (span_polynomials) in fixed point under 2^30, I[a * (p + 1) + k];
// returns the exponent.
int fixed_span_polynomials(const float* knots, int p, int s, int32_t* I) {
    float M[kN][kN], flat[kN * kN];
    span_polynomials(knots, p, s, M);
    for (int a = 0; a <= p; ++a)
        for (int k = 0; k <= p; ++k) flat[a * (p + 1) + k] = M[a][k];
    return to_fixed_under(flat, (p + 1) * (p + 1), 1, 30, I);
}

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
        for (uint32_t i = 0; mu_ && i < kMatrixSlots; ++i) {
            reinterpret_cast<MatrixHead*>(mu_ + i * matrix_words(pu_))->span = kEmpty;
            reinterpret_cast<MatrixHead*>(mv_ + i * matrix_words(pv_))->span = kEmpty;
        }
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

const int32_t* PatchCache::span_matrix(bool v, int span, int& e, int32_t* local) {
    const int p = v ? pv_ : pu_;
    const float* knots = v ? vk_ : uk_;
    uint32_t* cache = v ? mv_ : mu_;
    if (!cache) {
        e = fixed_span_polynomials(knots, p, span, local);
        return local;
    }
    MatrixHead* slot = reinterpret_cast<MatrixHead*>(cache + uint32_t(span) % kMatrixSlots * matrix_words(p));
    int32_t* matrix = reinterpret_cast<int32_t*>(slot + 1);
    if (slot->span != uint32_t(span)) {
        slot->exponent = fixed_span_polynomials(knots, p, span, matrix);
        slot->span = uint32_t(span);
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
    const uint32_t exps = slot->exponents;
    auto unscale = [&](int d) { return pow2_f(-exponent_at(exps, d)); };
    const Vec3 O{slot->origin[0], slot->origin[1], slot->origin[2]};
    if (!rational_) return {O.x + float(out[0]) * unscale(0), O.y + float(out[1]) * unscale(1), O.z + float(out[2]) * unscale(2)};
    float W = float(out[3]) * unscale(3);
    if (W == 0) W = 1;
    const float inv = 1 / W;
    return {O.x + float(out[0]) * (unscale(0) * inv), O.y + float(out[1]) * (unscale(1) * inv),
            O.z + float(out[2]) * (unscale(2) * inv)};
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
            const float unscale = pow2_f(-exponent_at(exps, d));
            f[d] = float(out[d]) * unscale, fs[d] = float(ds[d]) * (float(pu_) * unscale), ft[d] = float(dt[d]) * (float(pv_) * unscale);
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
            const float unscale = pow2_f(-exponent_at(exps, d));
            f[d] = float(acc) * unscale, fs[d] = float(acc_s) * (8 * unscale), ft[d] = float(acc_t) * (8 * unscale);
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
    for (int d = 0; d < dims_; ++d) f[d] = float(out[d]) * pow2_f(-exponent_at(slot.exps, d));
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
        const float unscale = pow2_f(-exponent_at(slot.exps, d));
        f[d] = float(out[d]) * unscale, df[d] = float(diff[d]) * (unscale * to_t);
    }
    const Vec3 O{slot.origin[0], slot.origin[1], slot.origin[2]};
    if (!rational_) return {O + Vec3{f[0], f[1], f[2]}, Vec3{df[0], df[1], df[2]}};
    const float inv = 1 / (f[3] != 0 ? f[3] : 1.0f);
    const Vec3 p = Vec3{f[0], f[1], f[2]} * inv; // from O
    return {O + p, (Vec3{df[0], df[1], df[2]} - p * df[3]) * inv};
}

} // namespace facet::geom
