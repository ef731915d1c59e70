#pragma once
// Integer trigonometry and small vector maths shared by host and target.
// Everything here is integer so the host reference renderer and the ARM firmware produce
// bit-identical pixels (no dependence on the libm or FPU of either side).
#include <array>
#include <cstdint>

namespace facet::render {

// Angles are uint16_t turns: 65536 = one full turn.
constexpr uint16_t degrees(int32_t d) { return static_cast<uint16_t>((d * 65536) / 360); }

// sin and cos in Q15 (32767 ~ 1.0).
int32_t sin_q15(uint16_t angle);
inline int32_t cos_q15(uint16_t angle) { return sin_q15(static_cast<uint16_t>(angle + 16384)); }

struct Vec3 {
    int32_t x, y, z;
};

// Rotation matrix in Q14 (16384 = 1.0), row-major.
struct Mat3 {
    int32_t m[3][3];

    static Mat3 identity();
    // Rotation about X by `pitch`, then about Y by `yaw` (applied to the object in that order).
    static Mat3 rotation(uint16_t yaw, uint16_t pitch);

    Vec3 apply(Vec3 v) const; // result in the units of v
    Mat3 operator*(const Mat3& o) const;
};

// Largest magnitude accepted by Mat3::apply without overflow (|component| < 2^30 / 3 / 2^1).
constexpr int32_t kMaxCoordinate = 1 << 27;

// Integer square root (floor).
uint32_t isqrt(uint64_t v);

// Whether the core divides integers itself: the Cortex-M7 and the host do, in an instruction;
// the ARM926 does not (a division is a library call of 80 to over a hundred instructions).
// Where the integer path works around a division, it divides on a core that can, with the
// same results: the same pixels on every core.
#if defined(__ARM_FEATURE_IDIV) || !defined(__arm__)
inline constexpr bool kHardwareDivide = true;
#else
inline constexpr bool kHardwareDivide = false;
#endif

// floor(2^31 / d) for d in [2^15, 2^16), exactly: the division itself where the core divides,
// else a table of every answer (recip31_lookup: 64 KB, a load where a division is a library
// call; linked only where it is used).
namespace detail {
constexpr uint32_t kRecip31Entries = 1u << 15;
extern const std::array<uint16_t, kRecip31Entries> recip31_table; // floor(2^31 / (2^15 + i)) - 2^15
} // namespace detail
inline uint32_t recip31_lookup(uint32_t d) { return uint32_t(detail::recip31_table[d - 32768]) + 32768u; }
inline uint32_t recip31(uint32_t d) {
    if constexpr (kHardwareDivide) return (uint32_t(1) << 31) / d;
    else return recip31_lookup(d);
}

// x / d for d >= 1, to about 2^-15 relative (d's 16 leading bits): one reciprocal, which can be
// shared by several numerators over one denominator (a vertex's x and y over its depth).
struct Reciprocal {
    uint32_t m;   // floor(2^31 / (d normalized to [2^15, 2^16)))
    int shift;    // x / d ~= (x * m) >> shift
};
// The shift e that brings d (>= 1) into [2^15, 2^16): d >> e, or d << -e when e < 0.
constexpr int reciprocal_shift(uint32_t d) { return (32 - __builtin_clz(d)) - 16; }
inline Reciprocal reciprocal(uint32_t d) {
    const int e = reciprocal_shift(d);
    const uint32_t dn = e >= 0 ? d >> e : d << -e;
    return {recip31(dn), 31 + e};
}
inline int32_t divide(int64_t x, Reciprocal r) { return int32_t((x * int64_t(r.m)) >> r.shift); }

} // namespace facet::render
