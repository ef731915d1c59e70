// The portable sin/cos/atan2 (geom/fmath.h): accurate against double-precision libm, and
// built only from IEEE operations (their bit-exactness across targets is what the viewer's
// pixel-exact reference images on QEMU rely on).
#include "geom/fmath.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace facet::geom;

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
