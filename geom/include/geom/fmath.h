#pragma once
// The geometry code's transcendental functions, in single precision from + - * / only.
//
// Why not <cmath>: newlib's and glibc's sinf/cosf/atan2f differ in the last bit, so the device
// and the host would tessellate a hair differently and the host could not render reference
// images pixel-exact; and on a soft-float core newlib's versions (double-checked argument
// reduction, bit-by-bit helpers) cost several times these. Every operation here is a correctly
// rounded IEEE float operation (the build has -ffp-contract=off), so the results are
// bit-identical on every target. Accuracy: about 1e-7 absolute for |x| < 1e4 (Cephes-style
// minimax polynomials after a three-part Cody-Waite reduction), plenty for geometry at 0.1%.
#include <bit>
#include <cmath>
#include <cstdint>

// Where float arithmetic is the library's: an ARM core without an FPU (the ARM926), where each
// operation, a compare included, is a call of 25 to 80 instructions. Elsewhere (the Cortex-M7,
// the host) it is the core's, single and double precision, each operation an instruction or a
// few. Code that works around the library's cost takes the FPU's way where there is one, with
// the same results.
#if defined(__ARM_ARCH) && !defined(__ARM_FP)
#define FACET_SOFT_FLOAT 1
#else
#define FACET_SOFT_FLOAT 0
#endif
#if FACET_SOFT_FLOAT || (defined(__ARM_ARCH) && !(__ARM_FP & 8))
#define FACET_DOUBLE_FPU 0
#else
#define FACET_DOUBLE_FPU 1
#endif

namespace facet::geom {

constexpr float kPi = 3.14159265358979323846f;

// 2^e for e in [-126, 127], from its bits (exact, no library call).
inline float pow2_f(int e) { return std::bit_cast<float>(uint32_t(e + 127) << 23); }

// x 2^e for e in [-126, 127], the same value as x * pow2_f(e). Without an FPU by the float's
// exponent bits when x and the result are normal (exact: a multiply by a power of two rounds
// nothing), else by the multiply.
inline float times_pow2(float x, int e) {
#if FACET_SOFT_FLOAT
    const uint32_t b = std::bit_cast<uint32_t>(x);
    const int be = int(b >> 23 & 0xFF), to = be + e;
    if (be != 0 && be != 0xFF && to > 0 && to < 0xFF) return std::bit_cast<float>(b + (uint32_t(e) << 23));
#endif
    return x * pow2_f(e);
}

// The e with 2^(e-1) <= x < 2^e for a positive normal float x (frexp's exponent), from its bits.
inline int exponent_f(float x) { return int((std::bit_cast<uint32_t>(x) >> 23) & 0xFF) - 126; }

namespace detail {
// 1/sqrt(A) at the middle of each sixteenth of [1, 4) (index 16 A), in Q31: sqrt_f's start.
struct RsqrtTable {
    uint32_t v[64] = {};
    constexpr RsqrtTable() {
        for (int i = 16; i < 64; ++i) {
            const double A = (i + 0.5) / 16;
            double r = A; // sqrt A by Newton (in double, at compile time)
            for (int k = 0; k < 60; ++k) r = 0.5 * (r + A / r);
            v[i] = uint32_t(2147483648.0 / r + 0.5);
        }
    }
};
inline constexpr RsqrtTable kRsqrt{};
} // namespace detail

// sqrt x, correctly rounded (the same bits as IEEE sqrt, checked on every positive normal
// float) from integer multiplies: newlib's soft-float sqrtf takes about 290 instructions on the
// ARM926 (a bit at a time), this about 50. 1/sqrt of the mantissa from a table and two Newton
// steps in Q30/Q31, times the mantissa, then the root made exact by integer squares and
// rounded (no ties: the radicand is whole). Zeros, subnormals, negatives, infinities and NaN
// (rare here) go to std::sqrt.
inline float sqrt_by_integers(float x) {
    const uint32_t b = std::bit_cast<uint32_t>(x);
    const int e = int(b >> 23); // sign and biased exponent
    if (e == 0 || e >= 0xFF) return std::sqrt(x);
    const int ex = e - 127, odd = ex & 1;
    // x = M 2^(ex - odd - 23) with M in [2^23, 2^25): sqrt x = sqrt(M 2^23) 2^((ex - odd) / 2 - 23).
    const uint32_t M = ((b & 0x7FFFFFu) | 0x800000u) << odd;
    const uint32_t a = M << 7; // A = a / 2^30 in [1, 4)
    uint32_t y = detail::kRsqrt.v[a >> 26]; // 1/sqrt A in Q31, to 6 bits
    for (int k = 0; k < 2; ++k) { // y (3 - A y^2) / 2: 6, 12, 24 bits
        const uint32_t y2 = uint32_t((uint64_t(y) * y) >> 32);   // Q30
        const uint32_t ay2 = uint32_t((uint64_t(a) * y2) >> 30); // Q30, about 1
        y = uint32_t((uint64_t(y) * ((3u << 30) - ay2)) >> 31);  // Q31
    }
    const uint64_t N = uint64_t(M) << 23; // the root's radicand: r = sqrt N in [2^23, 2^24)
    uint32_t r = uint32_t((uint64_t(a) * y) >> 38);
    while (uint64_t(r) * r > N) --r; // (at most a step or two either way)
    while (uint64_t(r + 1) * (r + 1) <= N) ++r;
    if (N - uint64_t(r) * r > r) ++r; // N > r^2 + r: nearer r + 1
    // r carries the leading one (r = 2^24 after rounding carries into the exponent).
    return std::bit_cast<float>((uint32_t((ex - odd) / 2 + 126) << 23) + r);
}

// A small float routine called from a hot loop: inlined where the core has an FPU (its float
// operations are single instructions, and the call would cost more than they do); kept out of
// line on an ARM core without one, where every operation is a library call anyway and each
// inlined copy is kilobytes of code.
#if FACET_SOFT_FLOAT
#define FACET_INLINE_WITH_FPU [[gnu::noinline]]
#else
#define FACET_INLINE_WITH_FPU
#endif

// sqrt x, correctly rounded: by integers on an ARM core without an FPU, else the FPU's own
// instruction (the Cortex-M7's vsqrt, the host's): the same bits either way.
inline float sqrt_f(float x) {
#if FACET_SOFT_FLOAT
    return sqrt_by_integers(x);
#else
    return std::sqrt(x);
#endif
}

// sin x and cos x, one reduction for both.
inline void sincos_f(float x, float& s, float& c) {
    if (!(std::fabs(x) < 8192.0f)) {
        if (x != x) { // NaN in, NaN out
            s = c = x;
            return;
        }
        x = std::fmod(x, 2 * kPi); // exact; keeps the reduction below accurate
    }
    // x = k pi/2 + r, |r| <= pi/4; pi/2 = P1 + P2 + P3 with P1, P2 short enough that k*P1 and
    // k*P2 are exact.
    const float kf = x * 0.636619772367581343f;
    const int32_t k = int32_t(kf + (kf >= 0 ? 0.5f : -0.5f));
    const float fk = float(k);
    const float r = ((x - fk * 1.5703125f) - fk * 4.838705062866211e-4f) - fk * -4.371138828673793e-8f;
    const float z = r * r;
    const float sr = r + r * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
    const float cr = 1.0f - 0.5f * z + z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
    switch (k & 3) {
    case 0: s = sr, c = cr; break;
    case 1: s = cr, c = -sr; break;
    case 2: s = -sr, c = -cr; break;
    default: s = -cr, c = sr; break;
    }
}

inline float sin_f(float x) {
    float s, c;
    sincos_f(x, s, c);
    return s;
}
inline float cos_f(float x) {
    float s, c;
    sincos_f(x, s, c);
    return c;
}

// atan2(y, x) in (-pi, pi]; atan2(0, 0) = 0.
inline float atan2_f(float y, float x) {
    if (y != y || x != x) return y + x;
    const float ax = std::fabs(x), ay = std::fabs(y);
    if (ax == 0 && ay == 0) return std::signbit(x) ? (std::signbit(y) ? -kPi : kPi) : y;
    const bool swap = ay > ax; // t = min/max in [0, 1]
    float t = swap ? ax / ay : ay / ax, base = 0;
    if (t > 0.4142135623730950f) { // tan(pi/8): atan t = pi/4 + atan((t-1)/(t+1))
        t = (t - 1.0f) / (t + 1.0f);
        base = 0.25f * kPi;
    }
    const float z = t * t;
    float a = base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * t + t);
    if (swap) a = 0.5f * kPi - a;
    if (std::signbit(x)) a = kPi - a;
    return std::signbit(y) ? -a : a;
}

// An integer ordered as the float x is, and equal where it is equal (-0 as +0), for x not
// NaN (a NaN orders past the infinities of its sign): a compare of two floats is a library
// call of about 30 instructions on a core without an FPU, of two of these one instruction.
inline int32_t order_bits(float x) {
    const int32_t b = std::bit_cast<int32_t>(x);
    if ((uint32_t(b) << 1) == 0) return 0;
    return b >= 0 ? b : int32_t(uint32_t(b) ^ 0x7FFFFFFFu);
}

// What a float is compared by in hot loops: its order_bits without an FPU, itself with one (a
// compare is then an instruction, and the bits would cost a few). The same order either way
// for floats that are not NaN.
#if FACET_SOFT_FLOAT
using OrderKey = int32_t;
inline OrderKey order_key(float x) { return order_bits(x); }
#else
using OrderKey = float;
inline OrderKey order_key(float x) { return x; }
#endif

// round(x * scale) to an integer, halves away from zero: the exact product rounded once. A
// point's millimetres to the viewer's integer units, a normal to Q14. Two ways to the same
// result: from the floats' bits (the product of their 24-bit mantissas, one shift and one
// rounding; on a core without an FPU a float multiply, add and conversion are three library
// calls of 25 to 80 instructions each, this is a dozen), or in double precision where the core
// has it (the product of two floats is exact in a double). A float multiply would round the
// product first (the two differ at near-ties). `scale` positive and normal.
class Quantizer {
public:
    explicit Quantizer(float scale) : scale_(scale) {
        const uint32_t b = std::bit_cast<uint32_t>(scale);
        m_ = (b & 0x7FFFFFu) | 0x800000u, e_ = int((b >> 23) & 0xFF) - 150; // scale = m 2^e
    }
    // False when |x * scale| rounds to 2^30 or more, or x is not finite.
    bool operator()(float x, int32_t& out) const {
#if FACET_DOUBLE_FPU
        return by_double(x, out);
#else
        return by_bits(x, out);
#endif
    }

    bool by_bits(float x, int32_t& out) const {
        const uint32_t b = std::bit_cast<uint32_t>(x);
        const int ex = int((b >> 23) & 0xFF);
        if (ex == 0xFF) return false;
        if (ex == 0) { // zero, or a subnormal: far under a unit
            out = 0;
            return true;
        }
        const uint64_t p = uint64_t((b & 0x7FFFFFu) | 0x800000u) * m_; // x * scale = p 2^-shift
        const int shift = 150 - ex - e_;
        if (shift <= 0) return false; // p is 2^46 or more
        if (shift > 62) {
            out = 0;
            return true;
        }
        const uint64_t q = (p + (uint64_t(1) << (shift - 1))) >> shift;
        if (q >= (uint64_t(1) << 30)) return false;
        out = (b >> 31) ? -int32_t(q) : int32_t(q);
        return true;
    }

    bool by_double(float x, int32_t& out) const {
        if (!(std::fabs(x) >= 1.17549435e-38f)) { // zero or a subnormal (as by_bits: 0), or NaN
            if (x != x) return false;
            out = 0;
            return true;
        }
        const double t = double(x) * double(scale_);        // exact: 48 bits at most
        if (!(std::fabs(t) < 1073741823.5)) return false;   // rounds to 2^30 or more; infinity
        out = int32_t(t + (t >= 0 ? 0.5 : -0.5));           // exact sum under 2^30; truncated
        return true;
    }

private:
    float scale_;
    uint64_t m_ = 0;
    int e_ = 0;
};

} // namespace facet::geom
