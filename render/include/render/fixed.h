#pragma once
// Integer trigonometry and small vector maths shared by host and target.
// Everything here is integer so the host reference renderer and the ARM firmware produce
// bit-identical pixels (no dependence on the libm or FPU of either side).
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

} // namespace facet::render
