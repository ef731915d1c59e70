#pragma once
// The rasterizer's pieces shared by its files (raster.cpp: the entry points; scan.cpp: triangles
// into spans; lines.cpp: lines): not part of render's interface.
#include "render/raster.h"

#include <cstdint>
#include <initializer_list>

namespace facet::render::detail {

using subpixel::centre;
using subpixel::first_centre_from;
using subpixel::kFractionBits;
using subpixel::kHalfPixel;
using subpixel::kPerPixel;
using subpixel::last_centre_to;
using subpixel::pixel_of;

constexpr int kFrac = 12; // fractional bits of interpolated attributes
constexpr int64_t kSmall = 20; // triangles whose pixel box is under this (both ways) take scan_small

// Truncating division, in 32 bits when both operands fit (a 64-bit divide is a long library
// call on 32-bit cores; most triangles are small enough for the 32-bit one). Same result.
inline int64_t div_fast(int64_t a, int64_t b) {
    if (a == int32_t(a) && b == int32_t(b) && !(a == INT32_MIN && b == -1)) return int32_t(a) / int32_t(b);
    return a / b;
}

inline int64_t floor_div(int64_t a, int64_t b) { // b > 0
    const int64_t q = div_fast(a, b);
    return (q * b != a && a < 0) ? q - 1 : q;
}

inline bool in_guard(const ScreenVertex& v) {
    return v.x >= -kGuardBand && v.x <= kGuardBand && v.y >= -kGuardBand && v.y <= kGuardBand;
}

// A triangle's box (sub-pixels) and the rows and columns whose pixel centres can be inside
// it, clipped to the screen: the way a triangle is scanned depends on the screen alone, so
// every band gets the same values. Then band() clips the rows to the target's band. (The
// vertices inside the guard band: everything fits 32 bits.)
struct PixelBox {
    int32_t xmin, ymin, xmax, ymax;
    int32_t row0, row1, col0, col1;
    PixelBox(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, const Target& t)
        : PixelBox(bounds(v0, v1, v2), t) {}
    // The sub-pixel box alone (xmin, ymin, xmax, ymax), and the pixels from it.
    struct Bounds {
        int32_t xmin, ymin, xmax, ymax;
    };
    static Bounds bounds(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2) {
        Bounds b{v0.x, v0.y, v0.x, v0.y};
        for (const ScreenVertex* v : {&v1, &v2}) {
            b.ymin = v->y < b.ymin ? v->y : b.ymin;
            b.ymax = v->y > b.ymax ? v->y : b.ymax;
            b.xmin = v->x < b.xmin ? v->x : b.xmin;
            b.xmax = v->x > b.xmax ? v->x : b.xmax;
        }
        return b;
    }
    PixelBox(const Bounds& b, const Target& t) : xmin(b.xmin), ymin(b.ymin), xmax(b.xmax), ymax(b.ymax) {
        row0 = first_centre_from(ymin), row1 = last_centre_to(ymax);
        col0 = first_centre_from(xmin), col1 = last_centre_to(xmax);
        row0 = row0 < 0 ? 0 : row0;
        row1 = row1 > int32_t(t.height) - 1 ? int32_t(t.height) - 1 : row1;
        col0 = col0 < 0 ? 0 : col0;
        col1 = col1 > int32_t(t.width) - 1 ? int32_t(t.width) - 1 : col1;
    }
    bool empty() const { return row0 > row1 || col0 > col1; }
    void band(const Target& t) {
        row0 = row0 < int32_t(t.y0) ? int32_t(t.y0) : row0;
        row1 = row1 > int32_t(t.y0 + t.rows) - 1 ? int32_t(t.y0 + t.rows) - 1 : row1;
    }
};

// Whether a triangle's attributes need clamping per pixel (scan.cpp).
bool needs_clamp(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t extent);

} // namespace facet::render::detail
