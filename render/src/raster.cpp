#include "render/raster.h"

#include "raster_internal.h"

#include <algorithm>
#include <cstdint>

// The rasterizer's entry points: palettes, the depth buffer, a triangle's culling and its
// dispatch to the scan (scan.cpp), the hidden-triangle test. Lines: lines.cpp.
namespace facet::render {

using namespace detail;

void make_palette(Palette& out, uint8_t r, uint8_t g, uint8_t b) {
    // round(c * s / 255) without dividing: x / 255 = (x + 1 + (x >> 8)) >> 8 for x < 65535.
    auto scaled = [](uint32_t c, uint32_t s) {
        const uint32_t x = c * s + 127;
        return uint8_t((x + 1 + (x >> 8)) >> 8);
    };
    for (uint32_t s = 0; s < 256; ++s) out.colour[s] = rgb565(scaled(r, s), scaled(g, s), scaled(b, s));
    for (int k = 0; k < Palette::kPad; ++k) out.colour[256 + k] = out.colour[255];
}

void Rasterizer::clear_depth() {
    // Two entries per 32-bit store; the buffer is 2-byte aligned at least, so peel one.
    using Word = uint32_t __attribute__((may_alias, aligned(2)));
    uint16_t* const depth = t_.depth;
    size_t n = size_t(t_.width) * t_.rows, i = 0;
    if (n && (reinterpret_cast<uintptr_t>(depth) & 2)) depth[i++] = 0xFFFF;
    Word* w = reinterpret_cast<Word*>(depth + i);
    const size_t words = (n - i) / 2;
    for (size_t k = 0; k < words; ++k) w[k] = 0xFFFFFFFFu;
    for (i += words * 2; i < n; ++i) depth[i] = 0xFFFF;
}

Status Rasterizer::draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const Palette& palette,
                        Cull cull) {
    palette_ = &palette;
    // One pass for the common case: the box says whether the triangle is in the guard band and
    // small; a small one's doubled area is a 32-bit product (differences under 2^9 sub-pixels).
    const PixelBox::Bounds bounds = PixelBox::bounds(a, b, c);
    if (bounds.xmin < -kGuardBand || bounds.xmax > kGuardBand || bounds.ymin < -kGuardBand || bounds.ymax > kGuardBand) {
        return Status::OutOfRange;
    }
    // Small: the triangle's own box (not the part of it on the screen) under kSmall pixels
    // both ways, which keeps scan_small's edge functions and small_gradients' products in 32 bits.
    const bool small = bounds.xmax - bounds.xmin < kPerPixel * kSmall && bounds.ymax - bounds.ymin < kPerPixel * kSmall;
    // Doubled signed area; with y down, counter-clockwise on screen gives a negative value.
    const int64_t area2 = small ? int64_t((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x))
                                : doubled_area(a, b, c);
    if (area2 == 0 || (area2 > 0 && cull == Cull::Back)) {
        ++stats.culled;
        return Status::Ok;
    }
    PixelBox box(bounds, t_);
    if (box.empty()) return Status::Ok;
    box.band(t_); // the rows of this band
    if (box.row0 > box.row1) return Status::Ok;
    ++stats.triangles;
    // Scan with a positive area: swap two vertices of a front face.
    if (small) {
        if (area2 < 0) scan_small(a, c, b, -area2, box.row0, box.row1, box.col0, box.col1);
        else scan_small(a, b, c, area2, box.row0, box.row1, box.col0, box.col1);
        return Status::Ok;
    }
    if (area2 < 0) scan(a, c, b, -area2, box);
    else scan(a, b, c, area2, box);
    return Status::Ok;
}

bool Rasterizer::hidden(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) const {
    constexpr int32_t kMargin = 4; // depth units an interpolated value may fall below its corners'
    const int32_t z = int32_t(a.z < b.z ? (a.z < c.z ? a.z : c.z) : (b.z < c.z ? b.z : c.z)) - kMargin;
    if (z <= 0 || !in_guard(a) || !in_guard(b) || !in_guard(c)) return false;
    PixelBox box(a, b, c, t_); // what scan() could draw, in the band
    box.band(t_);
    if (box.empty()) return true;
    // Two entries a load (the depth rows are 4-byte aligned when the width is even; else one
    // at a time): an entry farther than z shows the triangle would draw.
    const uint32_t zz = uint32_t(z);
    const int32_t col0 = box.col0, col1 = box.col1;
    for (int32_t y = box.row0; y <= box.row1; ++y) {
        const uint16_t* d = t_.depth + size_t(y - t_.y0) * t_.width;
        int32_t x = col0;
        if ((reinterpret_cast<uintptr_t>(d + x) & 2) && d[x++] > zz) return false;
        using Word = uint32_t __attribute__((may_alias, aligned(4)));
        for (; x < col1; x += 2) {
            const uint32_t w = *reinterpret_cast<const Word*>(d + x);
            if ((w & 0xFFFFu) > zz || (w >> 16) > zz) return false;
        }
        if (x == col1 && d[x] > zz) return false;
    }
    return true;
}

void Rasterizer::scan(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2,
                      const detail::PixelBox& box) {
    const int32_t xmin = box.xmin, xmax = box.xmax, ymin = box.ymin, ymax = box.ymax;
    const int32_t row0 = box.row0, row1 = box.row1, col0 = box.col0, col1 = box.col1;
    // (A stippled triangle takes the per-pixel path, which leaves out every other pixel.)
    const bool clamp = stipple_ || needs_clamp(v0, v1, v2, pixel_of(std::max(xmax - xmin, ymax - ymin)));
    constexpr int32_t kNear = 1024 * kPerPixel; // 32-bit edge walks within this of the origin
    const bool near = xmin >= -kNear && xmax <= kNear && ymin >= -kNear && ymax <= kNear;
    if (!near) {
        scan_rows<int64_t, false>(v0, v1, v2, area2, row0, row1, col0, col1, clamp);
    } else if (clamp || col1 - col0 >= row1 - row0) {
        scan_rows<int32_t, false>(v0, v1, v2, area2, row0, row1, col0, col1, clamp);
    } else {
        // Taller than wide (in the band): scanned a column at a time, what a line costs besides
        // its pixels paid for fewer lines. The same pixels, depths and shades: the edge
        // functions are the screen's (ties included), the attributes a function of the pixel.
        const auto swapped = [](const ScreenVertex& v) { return ScreenVertex{v.y, v.x, v.z, v.shade}; };
        scan_rows<int32_t, true>(swapped(v0), swapped(v2), swapped(v1), area2, col0, col1, row0, row1, false);
    }
}

} // namespace facet::render
