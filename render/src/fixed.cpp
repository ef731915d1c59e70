#include "render/fixed.h"

#include <array>

namespace facet::render {
namespace {

// Quarter-wave table, 257 entries over [0, 90] degrees, computed at compile time with a
// Taylor series in double: compile-time IEEE arithmetic is the same for every compiler.
constexpr double taylor_sin(double x) {
    double term = x, sum = x;
    for (int n = 1; n < 12; ++n) {
        term *= -x * x / ((2 * n) * (2 * n + 1));
        sum += term;
    }
    return sum;
}

constexpr std::array<int16_t, 257> make_table() {
    std::array<int16_t, 257> t{};
    constexpr double half_pi = 1.57079632679489661923;
    for (int i = 0; i <= 256; ++i) {
        const double v = taylor_sin(half_pi * i / 256.0) * 32767.0;
        t[i] = static_cast<int16_t>(v + 0.5);
    }
    return t;
}

constexpr auto kQuarter = make_table();
static_assert(kQuarter[0] == 0 && kQuarter[256] == 32767, "sine table endpoints");

// floor(2^31 / d) - 2^15 for every d in [2^15, 2^16) (0 to 2^15: 16 bits), made when compiling.
constexpr std::array<uint16_t, detail::kRecip31Entries> make_recip31_table() {
    std::array<uint16_t, detail::kRecip31Entries> t{};
    for (uint32_t i = 0; i < detail::kRecip31Entries; ++i) t[i] = uint16_t((uint64_t(1) << 31) / (32768 + i) - 32768);
    return t;
}

} // namespace

static_assert(make_recip31_table()[0] == 32768 && make_recip31_table()[detail::kRecip31Entries - 1] == 0,
              "2^31 / 2^15 and 2^31 / (2^16 - 1)");
constinit const std::array<uint16_t, detail::kRecip31Entries> detail::recip31_table = make_recip31_table();

int32_t sin_q15(uint16_t angle) {
    // Quadrant (2 bits), index into the quarter table (8 bits), interpolation fraction (6 bits).
    const uint32_t quadrant = angle >> 14;
    uint32_t pos = angle & 0x3FFF; // 14 bits within the quadrant
    if (quadrant & 1) pos = 0x4000 - pos;
    const uint32_t i = pos >> 6, frac = pos & 63;
    int32_t v = kQuarter[i];
    if (i < 256) v += ((kQuarter[i + 1] - kQuarter[i]) * static_cast<int32_t>(frac) + 32) >> 6;
    return (quadrant & 2) ? -v : v;
}

Mat3 Mat3::identity() { return {{{16384, 0, 0}, {0, 16384, 0}, {0, 0, 16384}}}; }

Mat3 Mat3::rotation(uint16_t yaw, uint16_t pitch) {
    // Q15 -> Q14 with rounding.
    const int32_t sy = (sin_q15(yaw) + 1) >> 1, cy = (cos_q15(yaw) + 1) >> 1;
    const int32_t sp = (sin_q15(pitch) + 1) >> 1, cp = (cos_q15(pitch) + 1) >> 1;
    const Mat3 ry{{{cy, 0, sy}, {0, 16384, 0}, {-sy, 0, cy}}};
    const Mat3 rx{{{16384, 0, 0}, {0, cp, -sp}, {0, sp, cp}}};
    return ry * rx;
}

Vec3 Mat3::apply(Vec3 v) const {
    Vec3 r;
    int32_t* out[3] = {&r.x, &r.y, &r.z};
    for (int i = 0; i < 3; ++i) {
        const int64_t s = int64_t(m[i][0]) * v.x + int64_t(m[i][1]) * v.y + int64_t(m[i][2]) * v.z;
        *out[i] = static_cast<int32_t>((s + 8192) >> 14);
    }
    return r;
}

Mat3 Mat3::operator*(const Mat3& o) const {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int64_t s = 0;
            for (int k = 0; k < 3; ++k) s += int64_t(m[i][k]) * o.m[k][j];
            r.m[i][j] = static_cast<int32_t>((s + 8192) >> 14);
        }
    return r;
}

uint32_t isqrt(uint64_t v) {
    uint64_t res = 0, bit = uint64_t(1) << 62;
    while (bit > v) bit >>= 2;
    while (bit) {
        if (v >= res + bit) {
            v -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    return static_cast<uint32_t>(res);
}

} // namespace facet::render
