// Lines: a DDA along the longer axis, depth-tested per pixel (B-rep edges over faces, and
// surfaces' outlines tested against the pixel beyond them).
#include "render/raster.h"

#include "raster_internal.h"
#include "render/fixed.h"

#include <cstdint>

namespace facet::render {
namespace {

using namespace detail;

// reciprocal(n) for the lengths of most lines, the same values (recip31 is floor(2^31 / d)
// exactly), worked out when compiling.
constexpr int32_t kShortLine = 256;
constexpr auto kShortReciprocal = [] {
    struct Table {
        Reciprocal r[kShortLine];
        constexpr const Reciprocal& operator[](int32_t n) const { return r[n]; }
    } table{};
    for (uint32_t n = 1; n < kShortLine; ++n) { // (shift = 31 + e >= 16)
        const int e = reciprocal_shift(n); // < 0 here: n << -e in [2^15, 2^16)
        const uint32_t dn = n << -e;
        table.r[n] = {uint32_t((uint64_t(1) << 31) / dn), 31 + e};
    }
    return table;
}();
static_assert([] {
    for (int32_t n = 1; n < kShortLine; ++n)
        if (kShortReciprocal[n].shift < 16 || kShortReciprocal[n].m > (1u << 16)) return false;
    return true;
}(), "a short line's steps fit 32 bits: |d| < 256 times m <= 2^16, shifted right by shift - 16 >= 0");

// The steps of a one-pixel line from a to b (pixel centres nearest the ends, a DDA along the
// longer axis): 16.16 positions and depth pulled `bias` toward the eye, the three slopes over
// one reciprocal of the length. Each pixel on the screen and in the band is depth-tested: a
// line against itself, an outline (kBeyond) against its neighbour (ox, oy) when that one is
// in the band. A pixel that passes is drawn, and its depth written where nearer. Returns the
// pixels stepped.
template <bool kBeyond>
uint32_t stroke(const Target& t, const ScreenVertex& a, const ScreenVertex& b, Rgb565 colour, uint16_t bias,
                int32_t ox = 0, int32_t oy = 0) {
    const int32_t x0 = pixel_of(a.x), y0 = pixel_of(a.y), dx = pixel_of(b.x) - x0, dy = pixel_of(b.y) - y0;
    const int32_t n = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
    int32_t x = (x0 << 16) + 0x8000, y = (y0 << 16) + 0x8000, z = int32_t(a.z) << 8;
    int32_t sx = 0, sy = 0, sz = 0;
    if (n && (n & (n - 1)) == 0) { // a power of two (most short lines): the same steps by shifts
        // In 32 bits: |dx|, |dy| are at most twice the guard band (2^14 pixels), so d << 16 fits,
        // and a depth's difference << 8 is under 2^24 (an arithmetic shift floors either way).
        static_assert(2 * subpixel::kGuardPixels <= (1 << 14));
        const int k = __builtin_ctz(uint32_t(n));
        sx = int32_t(uint32_t(dx) << 16) >> k;
        sy = int32_t(uint32_t(dy) << 16) >> k;
        sz = int32_t(uint32_t(int32_t(b.z) - int32_t(a.z)) << 8) >> k;
    } else if (n) {
        if (n < kShortLine) {
            // The same values as divide() below: (d << 16) m >> shift is d m >> (shift - 16) (the
            // low bits are zeros; shift >= 16 for these lengths), and |d m| < 2^24 here.
            const Reciprocal r = kShortReciprocal[n];
            sx = (dx * int32_t(r.m)) >> (r.shift - 16);
            sy = (dy * int32_t(r.m)) >> (r.shift - 16);
            sz = int32_t(((int64_t(b.z) - a.z) * r.m) >> (r.shift - 8));
        } else {
            const Reciprocal r = reciprocal(uint32_t(n));
            sx = divide(int64_t(dx) << 16, r);
            sy = divide(int64_t(dy) << 16, r);
            sz = divide((int64_t(b.z) - a.z) << 8, r);
        }
    }
    z -= int32_t(bias) << 8; // pulled toward the eye
    uint16_t* const depth = t.depth;
    Rgb565* const fb = t.pixels;
    const uint32_t width = t.width, band0 = t.y0, rows = t.rows;
    for (int32_t i = 0; i <= n; ++i, x += sx, y += sy, z += sz) {
        const int32_t px = x >> 16, py = y >> 16;
        // Off the screen or the band (negatives too).
        if (uint32_t(px) >= width || uint32_t(py) - band0 >= rows) continue;
        const int32_t zv = z < 0 ? 0 : z >> 8;
        const size_t at = size_t(uint32_t(py) - band0) * width + uint32_t(px);
        if constexpr (kBeyond) {
            const bool in = uint32_t(px + ox) < width && uint32_t(py + oy) - band0 < rows;
            if (zv >= depth[in ? size_t(uint32_t(py + oy) - band0) * width + uint32_t(px + ox) : at]) continue;
            if (zv < depth[at]) depth[at] = uint16_t(zv);
        } else {
            if (zv >= depth[at]) continue;
            depth[at] = uint16_t(zv);
        }
        fb[at] = colour;
    }
    return uint32_t(n + 1);
}

} // namespace

Status Rasterizer::line(const ScreenVertex& a, const ScreenVertex& b, Rgb565 colour, uint16_t bias) {
    if (!in_guard(a) || !in_guard(b)) return Status::OutOfRange;
    stats.pixels += stroke<false>(t_, a, b, colour, bias);
    return Status::Ok;
}

Status Rasterizer::point(const ScreenVertex& c, Rgb565 colour, uint16_t bias) {
    if (!in_guard(c)) return Status::OutOfRange;
    ++stats.pixels;
    const int32_t px = pixel_of(c.x), py = pixel_of(c.y);
    if (uint32_t(px) >= t_.width || uint32_t(py) - t_.y0 >= t_.rows) return Status::Ok; // off the screen or the band
    const int32_t z = int32_t(c.z) - int32_t(bias); // pulled toward the eye, as a line's
    const uint16_t zv = uint16_t(z < 0 ? 0 : z);
    const size_t at = size_t(uint32_t(py) - t_.y0) * t_.width + uint32_t(px);
    if (zv >= t_.depth[at]) return Status::Ok;
    t_.depth[at] = zv;
    t_.pixels[at] = colour;
    return Status::Ok;
}

Status Rasterizer::splat(const ScreenVertex& c, int32_t size, Rgb565 colour) {
    if (!in_guard(c) || size < 1 || size > kMaxSplat) return Status::OutOfRange;
    const int32_t x0 = pixel_of(c.x) - (size - 1) / 2, y0 = pixel_of(c.y) - (size - 1) / 2;
    for (int32_t y = y0; y < y0 + size; ++y) {
        if (uint32_t(y) - t_.y0 >= t_.rows) continue; // off the band (negatives too)
        for (int32_t x = x0; x < x0 + size; ++x) {
            if (uint32_t(x) >= t_.width) continue;
            const size_t at = size_t(uint32_t(y) - t_.y0) * t_.width + uint32_t(x);
            if (c.z >= t_.depth[at]) continue;
            t_.depth[at] = c.z;
            t_.pixels[at] = colour;
        }
    }
    stats.pixels += uint32_t(size * size);
    return Status::Ok;
}

Status Rasterizer::outline(const ScreenVertex& a, const ScreenVertex& b, Rgb565 colour, uint16_t bias, uint8_t beyond) {
    if (!in_guard(a) || !in_guard(b)) return Status::OutOfRange;
    stats.pixels += stroke<true>(t_, a, b, colour, bias, beyond == 0 ? 1 : beyond == 2 ? -1 : 0, beyond == 1 ? 1 : beyond == 3 ? -1 : 0);
    return Status::Ok;
}

} // namespace facet::render
