#pragma once
// The rasterizer's pieces shared by its files (raster.cpp: the entry points; scan.cpp: triangles
// into spans; lines.cpp: lines): not part of render's interface.
#include "render/fixed.h"
#include "render/raster.h"

#include <algorithm>
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

// a / d truncated, for d >= 1 and |a| <= 2^31, from d's reciprocal (render::reciprocal(d)). A
// core without a divider's division (the ARM926: a division is a library call of about 80
// instructions), one reciprocal serving several numerators. The reciprocal has 16 significant
// bits, so a quotient's estimate can be short by its 2^-15 (thousands, for a large quotient);
// for one of 2^15 or more, a second estimate, of what the first left, brings it within a unit
// or two; steps of one make it exact.
inline int64_t quotient_by_reciprocal(int64_t a, uint32_t d, Reciprocal r) {
    const uint32_t n = a < 0 ? 0u - uint32_t(a) : uint32_t(a);
    uint32_t q = uint32_t((uint64_t(n) * r.m) >> r.shift);
    if (q >= (1u << 15)) { // (under it, the estimate is within two)
        const int64_t rest = int64_t(n) - int64_t(q) * d; // (under 2^17 + d)
        if (rest > 0) q += uint32_t((uint64_t(rest) * r.m) >> r.shift);
    }
    while (uint64_t(q) * d > n) --q;
    while (uint64_t(q + 1) * d <= n) ++q;
    return a < 0 ? -int64_t(q) : int64_t(q);
}

// a0 / b and a1 / b, truncating as div_fast, for b >= 1: two quotients over one divisor (an
// edge's start and step, an attribute's two gradients). With a divider, two divisions; without
// one, where all three fit 32 bits, quotient_by_reciprocal's. The same quotients.
inline void div_pair(int64_t a0, int64_t a1, int64_t b, int64_t& q0, int64_t& q1) {
    if (kHardwareDivide || a0 != int32_t(a0) || a1 != int32_t(a1) || b != int32_t(b)) {
        q0 = div_fast(a0, b), q1 = div_fast(a1, b);
        return;
    }
    const Reciprocal r = reciprocal(uint32_t(b));
    q0 = quotient_by_reciprocal(a0, uint32_t(b), r), q1 = quotient_by_reciprocal(a1, uint32_t(b), r);
}

// floor(a0 / b) and floor(a1 / b), b > 0 (div_pair's quotients rounded down).
inline void floor_div_pair(int64_t a0, int64_t a1, int64_t b, int64_t& q0, int64_t& q1) {
    div_pair(a0, a1, b, q0, q1);
    if (a0 < 0 && q0 * b != a0) --q0;
    if (a1 < 0 && q1 * b != a1) --q1;
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

// Whether the attributes of a triangle whose pixel box is `extent` pixels across need clamping
// per pixel: a value inside the triangle is a mix of its vertices' values, off by the rounding
// of its gradients: under extent/128 units (gradients carry kFrac bits per sub-pixel), plus two
// where the small path multiplies by a reciprocal of the area (2^-15 of the range). Only where
// that could leave the representable range (depth 0..65535, a palette index) is it clamped:
// where a vertex's value lies within the margin of either end (v - margin past the range's
// width less twice the margin, as unsigned: below the margin too). A margin over half the
// palette (a triangle thousands of pixels across) leaves no shade safe.
inline bool needs_clamp(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t extent) {
    const uint32_t margin = 4 + uint32_t(extent) / 64;
    if (2 * margin > 255 + Palette::kPad - 1) return true;
    const uint32_t z_span = 65535 - 2 * margin, shade_span = 255 + Palette::kPad - 1 - 2 * margin;
    const auto out = [&](const ScreenVertex& v) {
        return (uint32_t(v.z) - margin > z_span) | (uint32_t(v.shade) - margin > shade_span);
    };
    return out(a) | out(b) | out(c);
}

// A small triangle's edge: its function at the box's first pixel centre (covered where it is
// >= 0, the top-left rule in its bias) and its steps a pixel right and a pixel down.
struct SmallEdge {
    int32_t e, sx, sy;
};

// The edges of a small triangle (v0, v1, v2 clockwise on the screen, its box under kSmall
// pixels both ways: 32-bit functions) from the pixel centre (ox, oy): edge i runs from the
// vertex after v[i] to the one after that.
inline void small_edges(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int32_t ox, int32_t oy,
                        SmallEdge ed[3]) {
    const ScreenVertex* from[3] = {&v1, &v2, &v0};
    const ScreenVertex* to[3] = {&v2, &v0, &v1};
    for (int i = 0; i < 3; ++i) {
        const int32_t dx = to[i]->x - from[i]->x, dy = to[i]->y - from[i]->y;
        const int32_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
        const int32_t px = from[i]->x - ox, py = from[i]->y - oy;
        ed[i].e = dx * (0 - py) - dy * (0 - px) - bias;
        ed[i].sx = -kPerPixel * dy;
        ed[i].sy = kPerPixel * dx;
    }
}

// One row's run of covered columns in [col0, col1], from the edges' functions e[] at its first
// column: [lo, end) (empty when end is not past lo). Both ways give the same run (a triangle
// is convex): kDivide finds where each edge's function turns non-negative (sx > 0: from
// k = ceil(-e / sx) on) or stops being so (sx < 0: up to k = floor(e / -sx)); the walk steps
// along the row from its first column. The scan divides where the core divides
// (kHardwareDivide) and walks on the ARM926, where a column costs about seven instructions and
// a division a library call.
template <bool kDivide>
[[gnu::always_inline]] inline void small_run(const SmallEdge ed[3], int32_t e0, int32_t e1, int32_t e2, int32_t col0,
                                             int32_t col1, int32_t& lo, int32_t& end) {
    if constexpr (kDivide) {
        int32_t first = 0, stop = col1 - col0 + 1;
        const int32_t e[3] = {e0, e1, e2};
        for (int i = 0; i < 3; ++i) {
            const int32_t sx = ed[i].sx;
            if (sx > 0) {
                if (e[i] < 0) first = std::max(first, (sx - 1 - e[i]) / sx);
            } else if (sx < 0) {
                stop = e[i] < 0 ? 0 : std::min(stop, e[i] / -sx + 1);
            } else if (e[i] < 0) {
                stop = 0;
            }
        }
        lo = col0 + first, end = col0 + std::max(first, stop);
    } else {
        // The first pixel inside, then on while inside.
        const int32_t sx0 = ed[0].sx, sx1 = ed[1].sx, sx2 = ed[2].sx;
        int32_t x = col0;
        for (; x <= col1 && (e0 | e1 | e2) < 0; ++x) e0 += sx0, e1 += sx1, e2 += sx2;
        lo = x;
        for (; x <= col1 && (e0 | e1 | e2) >= 0; ++x) e0 += sx0, e1 += sx1, e2 += sx2;
        end = x;
    }
}

// Each of `rows` rows' run (small_run) as span[2 r] .. span[2 r + 1]; whether any row has one.
template <bool kDivide>
inline bool small_runs(const SmallEdge ed[3], int32_t rows, int32_t col0, int32_t col1, int32_t* span) {
    bool any = false;
    int32_t r0 = ed[0].e, r1 = ed[1].e, r2 = ed[2].e;
    for (int32_t* at = span; at < span + 2 * rows; at += 2) {
        small_run<kDivide>(ed, r0, r1, r2, col0, col1, at[0], at[1]);
        any |= at[1] > at[0];
        r0 += ed[0].sy, r1 += ed[1].sy, r2 += ed[2].sy;
    }
    return any;
}

} // namespace facet::render::detail
