#include "render/fixed.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace facet::render;

TEST(Fixed, SineWithinTwoUnitsOfQ15EverywhereAndSymmetric) {
    for (uint32_t a = 0; a < 65536; ++a) {
        const double exact = std::sin(a * 2.0 * M_PI / 65536.0) * 32767.0;
        ASSERT_NEAR(sin_q15(uint16_t(a)), exact, 2.0) << "angle " << a;
        ASSERT_EQ(sin_q15(uint16_t(a)), -sin_q15(uint16_t(65536 - a))) << "odd symmetry at " << a;
    }
    EXPECT_EQ(sin_q15(16384), 32767);
    EXPECT_EQ(cos_q15(0), 32767);
    EXPECT_EQ(sin_q15(0), 0);
}

TEST(Fixed, RotationIsOrthonormalWithinRounding) {
    for (int yaw = 0; yaw < 360; yaw += 17) {
        for (int pitch = -90; pitch <= 90; pitch += 23) {
            const Mat3 m = Mat3::rotation(degrees(yaw), degrees(pitch));
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) {
                    int64_t dot = 0;
                    for (int k = 0; k < 3; ++k) dot += int64_t(m.m[i][k]) * m.m[j][k];
                    ASSERT_NEAR(double(dot) / (16384.0 * 16384.0), i == j ? 1.0 : 0.0, 1e-3);
                }
            }
        }
    }
}

TEST(Fixed, IsqrtIsFloorOfSquareRoot) {
    for (uint64_t v = 0; v < 100000; ++v) {
        const uint64_t r = isqrt(v);
        ASSERT_LE(r * r, v);
        ASSERT_GT((r + 1) * (r + 1), v);
    }
    EXPECT_EQ(isqrt(UINT64_MAX), 4294967295u);
}

TEST(Fixed, ReciprocalIsTheExactFloorEverywhere) {
    for (uint32_t d = 1u << 15; d < 1u << 16; ++d) {
        ASSERT_EQ(recip31(d), uint32_t((uint64_t(1) << 31) / d)) << d;
        ASSERT_EQ(recip31_lookup(d), uint32_t((uint64_t(1) << 31) / d)) << d; // (the path of a core without a divider)
    }
}

// A line whose length is a power of two steps by shifts (render/src/lines.cpp): the same steps
// as the reciprocal's, over the range lines take (a difference of 2^14 pixels, shifted by 16).
TEST(Fixed, ThePowersOfTwoDivideAsShifts) {
    for (int k = 0; k <= 13; ++k) {
        const Reciprocal r = reciprocal(uint32_t(1) << k);
        for (int64_t x = -(int64_t(1) << 30); x <= (int64_t(1) << 30); x += 9973 + (x & 63))
            ASSERT_EQ(divide(x, r), int32_t(x >> k)) << x << " / 2^" << k;
    }
}
