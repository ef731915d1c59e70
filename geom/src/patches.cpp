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

inline int32_t round_to_int(float v) { return int32_t(v + (v >= 0 ? 0.5f : -0.5f)); }

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
    for (const float x : {T[p], T[p + 1]}) {
        for (;;) {
            int k = 0, m = 0; // T[k] <= x < T[k+1]; m: x's multiplicity
            for (int i = 0; i < nt; ++i) {
                if (T[i] <= x) k = i;
                m += T[i] == x;
            }
            if (m >= p) break;
            for (int i = nq; i > k - m; --i)
                for (int d = 0; d < dims; ++d) Q[i][d] = Q[i - 1][d];
            for (int i = k - m; i >= k - p + 1; --i) {
                const float alpha = (x - T[i]) / (T[i + p] - T[i]);
                for (int d = 0; d < dims; ++d) Q[i][d] = alpha * Q[i][d] + (1 - alpha) * Q[i - 1][d];
            }
            for (int i = nt; i > k + 1; --i) T[i] = T[i - 1];
            T[k + 1] = x;
            ++nt, ++nq;
        }
    }
    int k = 0; // the span [a, b): its last a
    for (int i = 0; i < nt; ++i)
        if (T[i] <= T[p]) k = i;
    for (int i = 0; i <= p; ++i)
        for (int d = 0; d < dims; ++d) row[i * stride + d] = Q[k - p + i][d];
}

// A Bézier curve's point by de Casteljau, in place over c[0..n] (lerps of numbers under 2^29
// in magnitude: differences under 2^30, never overflowing).
inline int32_t casteljau(int32_t* c, int n, int32_t t) {
    for (int r = n; r > 0; --r)
        for (int i = 0; i < r; ++i) c[i] += mulq(c[i + 1] - c[i], t);
    return c[0];
}

// The same, stopping one level short: the point, and the difference of the last two points
// (the derivative over the degree).
inline int32_t casteljau_d(int32_t* c, int n, int32_t t, int32_t& diff) {
    for (int r = n; r > 1; --r)
        for (int i = 0; i < r; ++i) c[i] += mulq(c[i + 1] - c[i], t);
    diff = c[1] - c[0];
    return c[0] + mulq(diff, t);
}

} // namespace

PatchCache::PatchCache(const Pack& pack, const pack::Surface& S, std::span<uint32_t> memory) {
    if (S.type != uint8_t(pack::SurfaceType::BSpline)) return;
    const detail::BSplineSurfaceView B(pack.floats().data() + S.params);
    if (B.pu > kMaxBezierDegree || B.pv > kMaxBezierDegree || B.pu < 1 || B.pv < 1) return;
    bezier_ = B.pu > kMaxPatchDegree || B.pv > kMaxPatchDegree;
    pu_ = B.pu, pv_ = B.pv, nu_ = B.nu, nv_ = B.nv;
    rational_ = B.rational, u_periodic_ = B.u_periodic, v_periodic_ = B.v_periodic;
    uk_ = B.uk, vk_ = B.vk, poles_ = B.poles, weights_ = B.weights;
    slot_words_ = slot_words(pu_, pv_, rational_);
    if (memory.size() < 1 + slot_words_) return;
    memory_ = memory.data();
    slots_ = uint32_t((memory.size() - 1) / slot_words_);
    const uint32_t tag = S.params + 1; // the surface the patches belong to
    if (memory_[0] != tag) {
        memory_[0] = tag;
        for (uint32_t i = 0; i < slots_; ++i) memory_[1 + i * slot_words_] = kEmpty;
    }
}

void PatchCache::forget(std::span<uint32_t> memory) {
    if (!memory.empty()) memory[0] = 0;
}

const uint32_t* PatchCache::patch(int su, int sv) {
    const uint32_t key = uint32_t(su) << 16 | uint32_t(sv);
    uint32_t* slot = memory_ + 1 + (uint32_t(su) * 40503u + uint32_t(sv)) % slots_ * slot_words_;
    if (slot[0] != key) {
        convert(su, sv, slot);
        slot[0] = key;
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

void PatchCache::write_head(uint32_t* slot, int su, int sv, const float* O, uint32_t exps) const {
    slot[1] = exps;
    slot[2] = std::bit_cast<uint32_t>(O[0]), slot[3] = std::bit_cast<uint32_t>(O[1]), slot[4] = std::bit_cast<uint32_t>(O[2]);
    slot[5] = std::bit_cast<uint32_t>(per_span(uk_[su + 1] - uk_[su]));
    slot[6] = std::bit_cast<uint32_t>(per_span(vk_[sv + 1] - vk_[sv]));
}

void PatchCache::convert(int su, int sv, uint32_t* slot) {
    if (bezier_) return convert_bezier(su, sv, slot);
    float Mu[kN][kN], Mv[kN][kN];
    span_polynomials(uk_, pu_, su, Mu);
    span_polynomials(vk_, pv_, sv, Mv);
    const int dims = rational_ ? 4 : 3, i0 = su - pu_, j0 = sv - pv_;
    const float* O = poles_ + 3 * (i0 * nv_ + j0); // the patch's first pole: coordinates stay small
    // T[d][k][b] = sum over a of Mu[a][k] H[a][b][d], H the homogeneous poles w (P - O), w.
    float T[4][kN][kN] = {};
    for (int a = 0; a <= pu_; ++a) {
        for (int b = 0; b <= pv_; ++b) {
            float H[4];
            homogeneous((i0 + a) * nv_ + j0 + b, O, H);
            for (int k = 0; k <= pu_; ++k) {
                const float m = Mu[a][k];
                if (!detail::nonzero(m)) continue;
                for (int d = 0; d < dims; ++d) T[d][k][b] += m * H[d];
            }
        }
    }
    // C[d][k][l] = sum over b of T[d][k][b] Mv[b][l]; each coordinate in fixed point with the
    // largest exponent that keeps the sum of its coefficients' magnitudes under 2^29, so that
    // neither Horner scheme can overflow.
    int32_t* c = reinterpret_cast<int32_t*>(slot + kHead);
    uint32_t exps = 0;
    const int per = (pu_ + 1) * (pv_ + 1);
    for (int d = 0; d < dims; ++d) {
        float C[kN][kN], sum = 0;
        for (int k = 0; k <= pu_; ++k) {
            for (int l = 0; l <= pv_; ++l) {
                float x = 0;
                for (int b = 0; b <= pv_; ++b) // (a span's matrix is about a third zeros)
                    if (detail::nonzero(Mv[b][l])) x += T[d][k][b] * Mv[b][l];
                C[k][l] = x;
                sum += std::fabs(x);
            }
        }
        // sum < 2^exponent (a sum too small for a normal float: its coefficients are noise)
        const int e = sum >= 1e-30f ? std::clamp(29 - exponent_f(sum), -100, 100) : 0;
        const float scale = pow2_f(e);
        for (int k = 0; k <= pu_; ++k) {
            for (int l = 0; l <= pv_; ++l) {
                const float v = C[k][l] * scale;
                c[d * per + k * (pv_ + 1) + l] = round_to_int(v);
            }
        }
        exps |= exponent_bits(e, d);
    }
    write_head(slot, su, sv, O, exps);
}

void PatchCache::convert_bezier(int su, int sv, uint32_t* slot) {
    // The span's (pu + 1) x (pv + 1) poles in homogeneous coordinates w (P - O), w, as floats
    // in the slot's coefficient words; extracted along u (each column of the slot), then
    // along v (each row); then each coordinate to fixed point in place.
    const int dims = rational_ ? 4 : 3, i0 = su - pu_, j0 = sv - pv_, row = pv_ + 1;
    const float* O = poles_ + 3 * (i0 * nv_ + j0);
    float* f = reinterpret_cast<float*>(slot + kHead); // [k][l][d]
    for (int a = 0; a <= pu_; ++a)
        for (int b = 0; b <= pv_; ++b) homogeneous((i0 + a) * nv_ + j0 + b, O, f + (a * row + b) * dims);
    for (int b = 0; b <= pv_; ++b) extract_span(uk_, pu_, su, f + b * dims, row * dims, dims);
    for (int a = 0; a <= pu_; ++a) extract_span(vk_, pv_, sv, f + a * row * dims, dims, dims);
    // Each coordinate with the largest exponent that keeps its largest magnitude under 2^28
    // (de Casteljau's points stay in the net's hull: nothing grows past it).
    const int per = (pu_ + 1) * row;
    uint32_t exps = 0;
    for (int d = 0; d < dims; ++d) {
        float big = 0;
        for (int i = 0; i < per; ++i) big = std::max(big, std::fabs(f[i * dims + d]));
        const int e = big >= 1e-30f ? std::clamp(28 - exponent_f(big), -100, 100) : 0;
        exps |= exponent_bits(e, d);
    }
    // In place, each pole's coordinates together ([k][l][d]: the order extraction left).
    int32_t* c = reinterpret_cast<int32_t*>(f);
    for (int d = 0; d < dims; ++d) {
        const float scale = pow2_f(exponent_at(exps, d));
        for (int i = d; i < per * dims; i += dims) c[i] = round_to_int(f[i] * scale);
    }
    write_head(slot, su, sv, O, exps);
}

const uint32_t* PatchCache::locate(float& u, float& v, int32_t& qs, int32_t& qt) {
    // The spans: the last point's if u and v are still in them, else found (and wrapped or
    // clamped as the B-spline's own evaluation does).
    int su = last_su_, sv = last_sv_;
    if (su < 0 || !(u >= uk_[su] && u < uk_[su + 1])) su = detail::find_span(uk_, nu_, pu_, u, u_periodic_);
    if (sv < 0 || !(v >= vk_[sv] && v < vk_[sv + 1])) sv = detail::find_span(vk_, nv_, pv_, v, v_periodic_);
    if (su != last_su_ || sv != last_sv_ || !last_) {
        last_ = patch(su, sv);
        last_su_ = su, last_sv_ = sv;
    }
    const uint32_t* slot = last_;
    // The local parameters in [0, 2^30] (slot[5], slot[6]: 2^30 over the spans' lengths).
    qs = int32_t((u - uk_[su]) * std::bit_cast<float>(slot[5])), qt = int32_t((v - vk_[sv]) * std::bit_cast<float>(slot[6]));
    qs = qs < 0 ? 0 : (qs > kOneQ ? kOneQ : qs);
    qt = qt < 0 ? 0 : (qt > kOneQ ? kOneQ : qt);
    return slot;
}

void PatchCache::bezier(const uint32_t* slot, int32_t qs, int32_t qt, int32_t* out, int32_t* ds, int32_t* dt) const {
    const int32_t* c = reinterpret_cast<const int32_t*>(slot + kHead);
    const int dims = rational_ ? 4 : 3, row = pv_ + 1;
    // Reduce the higher degree first: each of the other direction's lines costs its own
    // degree squared over two, and the last reduction is one line of the other degree
    // (6 x 10: 11 columns in s then a row in t, 286 steps, not 406).
    const bool s_first = (pv_ + 1) * pu_ * (pu_ + 1) + pv_ * (pv_ + 1) < (pu_ + 1) * pv_ * (pv_ + 1) + pu_ * (pu_ + 1);
    const int lines = s_first ? pv_ + 1 : pu_ + 1, inner = s_first ? pu_ : pv_, outer = s_first ? pv_ : pu_;
    const int step_line = s_first ? dims : row * dims, step_in = s_first ? row * dims : dims;
    const int32_t q_in = s_first ? qs : qt, q_out = s_first ? qt : qs;
    int32_t V[kBN], Dn[kBN], r[kBN], d_in = 0, d_out = 0;
    for (int d = 0; d < dims; ++d) {
        // Each line's point in the inner parameter (and its difference), then theirs in the outer.
        for (int k = 0; k < lines; ++k) {
            const int32_t* src = c + k * step_line + d;
            for (int l = 0; l <= inner; ++l) r[l] = src[l * step_in];
            V[k] = ds ? casteljau_d(r, inner, q_in, Dn[k]) : casteljau(r, inner, q_in);
        }
        if (!ds) {
            out[d] = casteljau(V, outer, q_out);
            continue;
        }
        out[d] = casteljau_d(V, outer, q_out, d_out);
        d_in = casteljau(Dn, outer, q_out);
        ds[d] = s_first ? d_in : d_out, dt[d] = s_first ? d_out : d_in;
    }
}

Vec3 PatchCache::point(float u, float v) {
    int32_t qs, qt;
    const uint32_t* slot = locate(u, v, qs, qt);
    const int32_t* c = reinterpret_cast<const int32_t*>(slot + kHead);
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
    const uint32_t exps = slot[1];
    auto unscale = [&](int d) { return pow2_f(-exponent_at(exps, d)); };
    const Vec3 O{std::bit_cast<float>(slot[2]), std::bit_cast<float>(slot[3]), std::bit_cast<float>(slot[4])};
    if (!rational_) return {O.x + float(out[0]) * unscale(0), O.y + float(out[1]) * unscale(1), O.z + float(out[2]) * unscale(2)};
    float W = float(out[3]) * unscale(3);
    if (W == 0) W = 1;
    const float inv = 1 / W;
    return {O.x + float(out[0]) * (unscale(0) * inv), O.y + float(out[1]) * (unscale(1) * inv),
            O.z + float(out[2]) * (unscale(2) * inv)};
}

SurfacePoint PatchCache::point_and_derivatives(float u, float v) {
    int32_t qs, qt;
    const uint32_t* slot = locate(u, v, qs, qt);
    const int32_t* c = reinterpret_cast<const int32_t*>(slot + kHead);
    const int dims = rational_ ? 4 : 3, row = pv_ + 1;
    // Per coordinate: the value, and its derivatives in s and t over 8 (a derivative of the
    // polynomial can reach its degree times the coefficients' sum: 8 keeps it in 32 bits).
    float f[4], fs[4], ft[4];
    const uint32_t exps = slot[1];
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
    // d/du = d/ds over the span's length (slot[5] / 2^30).
    const float hu = std::bit_cast<float>(slot[5]) * (1 / kOne), hv = std::bit_cast<float>(slot[6]) * (1 / kOne);
    const Vec3 O{std::bit_cast<float>(slot[2]), std::bit_cast<float>(slot[3]), std::bit_cast<float>(slot[4])};
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
