#pragma once
// Screen positions, the rasterizer's one fixed-point format (as tgx's Rasterizer.h states its
// own): 28.4, four fraction bits, 16 sub-pixels to a pixel, y down. Pixel (x, y) covers the
// sub-pixels [16 x, 16 x + 16) x [16 y, 16 y + 16) and is sampled at its centre (16 x + 8,
// 16 y + 8): a triangle covers a pixel when it covers that centre (ties by the top-left rule).
//
// Range: every vertex the rasterizer takes lies within kGuardBand of the screen's origin
// (8,192 pixels, 2^17 sub-pixels; the camera clips the rest first), so a difference of two
// coordinates is under 2^18, an edge function (a difference times a difference) under 2^37,
// and a triangle's doubled area under 2^38: 64-bit products. A triangle whose box is under
// kSmall pixels both ways (raster.cpp) keeps its differences under 2^9 and its edge functions
// and area in 32 bits.
#include <cstdint>

namespace facet::render::subpixel {

constexpr int kFractionBits = 4;
constexpr int32_t kPerPixel = 1 << kFractionBits; // sub-pixels to a pixel
constexpr int32_t kHalfPixel = kPerPixel / 2;     // a pixel's centre from its corner
constexpr int32_t kGuardPixels = 8192;            // the range above, in pixels

// Where pixel column (or row) p starts, and its centre.
constexpr int32_t start(int32_t p) { return p * kPerPixel; }
constexpr int32_t centre(int32_t p) { return p * kPerPixel + kHalfPixel; }
// The pixel whose square holds sub-pixel s.
template <typename T>
constexpr T pixel_of(T s) { return s >> kFractionBits; }
// The first pixel whose centre is at or after s, and the last whose centre is at or before s.
template <typename T>
constexpr T first_centre_from(T s) { return (s + (kHalfPixel - 1)) >> kFractionBits; }
template <typename T>
constexpr T last_centre_to(T s) { return (s - kHalfPixel) >> kFractionBits; }

static_assert(first_centre_from(centre(3)) == 3 && first_centre_from(centre(3) + 1) == 4 &&
              last_centre_to(centre(3)) == 3 && last_centre_to(centre(3) - 1) == 2);

} // namespace facet::render::subpixel
