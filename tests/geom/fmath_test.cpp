// The portable sin/cos/atan2 (geom/fmath.h): accurate against double-precision libm, and
// built only from IEEE operations (their bit-exactness across targets is what the viewer's
// pixel-exact reference images on QEMU rely on).
#include "geom/fmath.h"
#include "bspline.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

using namespace facet::geom;

// sqrt_by_integers (sqrt_f on a core without an FPU) is correctly rounded: the same bits as
// IEEE sqrt. Every mantissa of four exponents (both parities, both sides of 1), a stride
// through every positive normal float, and the special values. (Every one of the 2^31 - 2^24 positive normal floats was compared once, 2026-11-24.)
TEST(Fmath, SqrtHasTheBitsOfIeeeSqrt) {
    uint64_t checked = 0, differ = 0;
    auto check = [&](uint32_t bits) {
        const float x = std::bit_cast<float>(bits);
        differ += std::bit_cast<uint32_t>(sqrt_by_integers(x)) != std::bit_cast<uint32_t>(std::sqrt(x));
        ++checked;
    };
    for (uint32_t e : {1u, 126u, 127u, 200u})
        for (uint32_t m = 0; m < (1u << 23); ++m) check(e << 23 | m);
    for (uint32_t bits = 0x00800000u; bits < 0x7F800000u; bits += 997) check(bits);
    EXPECT_EQ(differ, 0u) << "of " << checked;
    EXPECT_EQ(sqrt_by_integers(0.0f), 0.0f);
    EXPECT_TRUE(std::signbit(sqrt_by_integers(-0.0f)));
    EXPECT_TRUE(std::isnan(sqrt_by_integers(-1.0f)));
    EXPECT_TRUE(std::isinf(sqrt_by_integers(INFINITY)));
    EXPECT_EQ(sqrt_by_integers(std::bit_cast<float>(1u)), std::sqrt(std::bit_cast<float>(1u))); // subnormal
    EXPECT_EQ(sqrt_by_integers(4.0f), 2.0f);
    EXPECT_EQ(sqrt_by_integers(2.0f), std::sqrt(2.0f));
}

TEST(Fmath, SinCosWithin2e7OfLibmOverManyTurns) {
    double worst = 0;
    for (int i = -200000; i <= 200000; ++i) {
        const float x = float(i) * 1.0e-4f * 3.0f; // [-60, 60] rad
        float s, c;
        sincos_f(x, s, c);
        worst = std::max({worst, std::fabs(s - std::sin(double(x))), std::fabs(c - std::cos(double(x)))});
    }
    EXPECT_LT(worst, 2e-7);
    float s, c;
    sincos_f(0.0f, s, c);
    EXPECT_EQ(s, 0.0f);
    EXPECT_EQ(c, 1.0f);
    // Large arguments (a float's spacing there is already 0.06 rad): still a unit vector.
    sincos_f(1.0e6f, s, c);
    EXPECT_NEAR(s * s + c * c, 1.0f, 1e-6f);
    sincos_f(NAN, s, c);
    EXPECT_TRUE(std::isnan(s) && std::isnan(c));
}

TEST(Fmath, Atan2Within3e7OfLibmInEveryOctant) {
    double worst = 0;
    for (int i = 0; i < 3600; ++i) {
        const double a = i * 2 * M_PI / 3600;
        for (float r : {1e-3f, 1.0f, 250.0f}) {
            const float y = float(r * std::sin(a)), x = float(r * std::cos(a));
            double d = std::fabs(atan2_f(y, x) - std::atan2(double(y), double(x)));
            d = std::min(d, 2 * M_PI - d); // pi and -pi are the same angle
            worst = std::max(worst, d);
        }
    }
    EXPECT_LT(worst, 3e-7); // a float's spacing near pi is 2.4e-7
    EXPECT_EQ(atan2_f(0.0f, 0.0f), 0.0f);
    EXPECT_EQ(atan2_f(0.0f, 1.0f), 0.0f);
    EXPECT_FLOAT_EQ(atan2_f(1.0f, 0.0f), 0.5f * kPi);
    EXPECT_FLOAT_EQ(atan2_f(0.0f, -1.0f), kPi);
}

// The quantizer is the exact product rounded once, halves away from zero: against long double
// over points of every size and sign, scales of every kind, and the edges of its range; both
// ways (from the bits, the cores without an FPU; in double, the others) the same.
TEST(Fmath, QuantizerRoundsTheExactProduct) {
    uint32_t seed = 12345;
    auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
    for (const float scale : {1.0f, 16384.0f, 1.0f / 0.0137f, 3.7e4f, 1.0f / 3.0f, 7.5e-3f}) {
        const Quantizer q(scale);
        for (int i = 0; i < 200000; ++i) {
            const float x = std::bit_cast<float>((next() & 0x807FFFFFu) | ((uint32_t(100 + next() % 60) & 0xFF) << 23));
            const long double exact = (long double)x * (long double)scale;
            int32_t by_bits = 0, by_double = 0;
            const bool bits_ok = q.by_bits(x, by_bits), double_ok = q.by_double(x, by_double);
            ASSERT_EQ(bits_ok, double_ok) << x << " " << scale;
            if (std::fabs(exact) >= (long double)(1 << 30) - 0.5L) {
                if (std::fabs(exact) >= (long double)(1 << 30)) {
                    EXPECT_FALSE(bits_ok) << x << " " << scale;
                }
                continue;
            }
            ASSERT_TRUE(bits_ok) << x << " " << scale;
            const long double want = exact >= 0 ? std::floor(exact + 0.5L) : -std::floor(-exact + 0.5L);
            ASSERT_EQ((long double)by_bits, want) << x << " * " << scale;
            ASSERT_EQ(by_double, by_bits) << x << " * " << scale;
        }
    }
    const Quantizer unit(1.0f);
    for (const bool in_double : {false, true}) {
        auto q = [&](float x, int32_t& v) { return in_double ? unit.by_double(x, v) : unit.by_bits(x, v); };
        int32_t v = 7;
        EXPECT_TRUE(q(0.0f, v) && v == 0);
        EXPECT_TRUE(q(-0.0f, v) && v == 0);
        EXPECT_TRUE(q(0.5f, v) && v == 1);
        EXPECT_TRUE(q(-0.5f, v) && v == -1);
        EXPECT_TRUE(q(2.5f, v) && v == 3);
        EXPECT_TRUE(q(1.0e-40f, v) && v == 0);
        EXPECT_TRUE(q(1073741823.0f, v) == false); // (2^30 - 1 is no float: it is 2^30)
        EXPECT_TRUE(q(1073741760.0f, v) && v == 1073741760);
        EXPECT_FALSE(q(std::numeric_limits<float>::infinity(), v));
        EXPECT_FALSE(q(-std::numeric_limits<float>::infinity(), v));
        EXPECT_FALSE(q(std::numeric_limits<float>::quiet_NaN(), v));
        EXPECT_FALSE(q(1.1e9f, v));
    }
}

// order_bits (a float's order_key on a core without an FPU) orders and equates as the floats
// do (finite ones, -0 as +0); order_key on this core too.
TEST(Fmath, OrderKeyComparesAsTheFloats) {
    uint32_t seed = 777;
    auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
    auto any = [&] { // finite floats of every size and sign, zeros and near-equals among them
        const uint32_t r = next();
        if (r % 16 == 0) return (r & 32) ? -0.0f : 0.0f;
        return std::bit_cast<float>(((next() & 0x807FFFFFu) | (uint32_t(next() % 254 + 1) << 23)) & ~(r % 8 == 1 ? 0xFFu : 0u));
    };
    for (int i = 0; i < 500000; ++i) {
        const float a = any(), b = (i % 4 == 0) ? a : any();
        ASSERT_EQ(order_bits(a) < order_bits(b), a < b) << a << " " << b;
        ASSERT_EQ(order_bits(a) == order_bits(b), a == b) << a << " " << b;
        ASSERT_EQ(order_key(a) < order_key(b), a < b) << a << " " << b;
    }
}

// A span's search clamps t to the knots' range; a NaN to the end its sign says, on every core
// (by its order_bits without an FPU, by a test of its own with one), so the boards and the host
// evaluate the same point.
TEST(Fmath, FindSpanClampsANaNToTheEndItsSignSays) {
    const float knots[] = {0, 0, 0, 1, 2, 3, 3, 3}; // degree 2, five poles
    float t = 1.5f;
    EXPECT_EQ(detail::find_span(knots, 5, 2, t, false), 3);
    t = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(detail::find_span(knots, 5, 2, t, false), 4);
    EXPECT_EQ(t, 3.0f);
    t = -std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(detail::find_span(knots, 5, 2, t, false), 2);
    EXPECT_EQ(t, 0.0f);
    t = 7.0f;
    EXPECT_EQ(detail::find_span(knots, 5, 2, t, false), 4);
    EXPECT_EQ(t, 3.0f);
}
