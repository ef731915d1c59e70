#include "render/raster.h"

#include "render/fixed.h"

#include <algorithm>
#include <cstdint>

namespace facet::render {
namespace {

constexpr int kFrac = 12; // fractional bits of interpolated attributes
constexpr int64_t kSmall = 20; // triangles whose pixel box is under this (both ways) take scan_small

// Truncating division, in 32 bits when both operands fit (a 64-bit divide is a long library
// call on 32-bit cores; most triangles are small enough for the 32-bit one). Same result.
inline int64_t div_fast(int64_t a, int64_t b) {
    if (a == int32_t(a) && b == int32_t(b) && !(a == INT32_MIN && b == -1)) return int32_t(a) / int32_t(b);
    return a / b;
}

int64_t floor_div(int64_t a, int64_t b) { // b > 0
    const int64_t q = div_fast(a, b);
    return (q * b != a && a < 0) ? q - 1 : q;
}

bool in_guard(const ScreenVertex& v) {
    return v.x >= -kGuardBand && v.x <= kGuardBand && v.y >= -kGuardBand && v.y <= kGuardBand;
}

// A triangle's box (28.4) and the rows and columns whose pixel centres (16i+8) can be inside
// it, clipped to the screen: the way a triangle is scanned depends on the screen alone, so
// every band gets the same values. Then band() clips the rows to the target's band. (The
// vertices inside the guard band: everything fits 32 bits.)
struct PixelBox {
    int32_t xmin, ymin, xmax, ymax;
    int32_t row0, row1, col0, col1;
    PixelBox(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, const Target& t) {
        ymin = ymax = v0.y, xmin = xmax = v0.x;
        for (const ScreenVertex* v : {&v1, &v2}) {
            ymin = v->y < ymin ? v->y : ymin;
            ymax = v->y > ymax ? v->y : ymax;
            xmin = v->x < xmin ? v->x : xmin;
            xmax = v->x > xmax ? v->x : xmax;
        }
        row0 = (ymin + 7) >> 4, row1 = (ymax - 8) >> 4;
        col0 = (xmin + 7) >> 4, col1 = (xmax - 8) >> 4;
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

// The steps of a one-pixel line from a to b (pixel centres nearest the ends, a DDA along the
// longer axis): 16.16 positions and depth pulled `bias` toward the eye, the three slopes over
// one reciprocal of the length. Each pixel on the screen and in the band is depth-tested: a
// line against itself, an outline (kBeyond) against its neighbour (ox, oy) when that one is
// in the band. A pixel that passes is drawn, and its depth written where nearer. Returns the
// pixels stepped.
template <bool kBeyond>
uint32_t stroke(const Target& t, const ScreenVertex& a, const ScreenVertex& b, hal::Rgb565 colour, uint16_t bias,
                int32_t ox = 0, int32_t oy = 0) {
    const int32_t x0 = a.x >> 4, y0 = a.y >> 4, dx = (b.x >> 4) - x0, dy = (b.y >> 4) - y0;
    const int32_t n = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
    int32_t x = (x0 << 16) + 0x8000, y = (y0 << 16) + 0x8000, z = int32_t(a.z) << 8;
    int32_t sx = 0, sy = 0, sz = 0;
    if (n) {
        const Reciprocal r = reciprocal(uint32_t(n));
        sx = divide(int64_t(dx) << 16, r);
        sy = divide(int64_t(dy) << 16, r);
        sz = divide((int64_t(b.z) - a.z) << 8, r);
    }
    z -= int32_t(bias) << 8; // pulled toward the eye
    uint16_t* const depth = t.depth;
    hal::Rgb565* const fb = t.pixels;
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

// One edge p->q of a triangle with positive doubled area, walked row by row.
//
// A pixel centre (sx, sy) is inside the edge when dx*(sy - py) - dy*(sx - px) - bias >= 0.
// Top-left rule: pixels exactly on a left edge (going up) or a top edge (horizontal, going
// right) belong to this triangle (bias 0); on other edges they belong to the neighbour (bias 1).
// For dy != 0 the condition bounds sx on one side by t(sy)/s for an integer t that changes by a
// constant from row to row, so the bound is kept exactly as a quotient and remainder
// (t = q*s + r, 0 <= r < s) and advanced without dividing.
template <typename T>
struct EdgeWalk {
    enum class Side : uint8_t { Left, Right, Flat } side;
    T q = 0, r = 0, s = 1, dq = 0, dr = 0; // Left/Right: bound = t/s; Flat: q = k

    void start(const ScreenVertex& p, const ScreenVertex& e, int64_t sy) {
        const int64_t dx = e.x - p.x, dy = e.y - p.y;
        const int64_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
        const int64_t k = dx * (sy - p.y) + dy * p.x - bias; // inside: -dy*sx + k >= 0
        int64_t t, step, s;
        if (dy == 0) {
            side = Side::Flat;
            q = T(k);
            dq = T(16 * dx);
            return;
        }
        if (dy < 0) { // sx >= ceil(-k / -dy)
            side = Side::Left;
            s = -dy;
            t = -k;
            step = -16 * dx;
        } else { // sx <= floor(k / dy)
            side = Side::Right;
            s = dy;
            t = k;
            step = 16 * dx;
        }
        const int64_t q64 = floor_div(t, s), dq64 = floor_div(step, s);
        this->s = T(s);
        q = T(q64);
        r = T(t - q64 * s);
        dq = T(dq64);
        dr = T(step - dq64 * s);
    }

    // The next row of a Left or Right edge.
    void step() {
        q += dq;
        r += dr;
        if (r >= s) {
            r -= s;
            ++q;
        }
    }
};

} // namespace

// One attribute over a triangle, stepped per pixel and per row in 32-bit modular arithmetic
// (exact wherever the true value fits in 32 bits: everywhere inside the triangle), in kFrac
// fixed point, read back clamped to the range of its three vertex values.
// Whether the attributes of a triangle whose pixel box is `extent` pixels across need clamping
// per pixel: a value inside the triangle is a mix of its vertices' values, off by the rounding
// of its gradients: under extent/128 units (gradients carry kFrac bits per sub-pixel), plus two
// where the small path multiplies by a reciprocal of the area (2^-15 of the range). Only where
// that could leave the representable range (depth 0..65535, a palette index) is it clamped.
bool needs_clamp(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t extent) {
    const int32_t margin = 4 + extent / 64;
    const int32_t zmin = std::min({a.z, b.z, c.z}), zmax = std::max({a.z, b.z, c.z});
    const int32_t smin = std::min({a.shade, b.shade, c.shade}), smax = std::max({a.shade, b.shade, c.shade});
    return zmin < margin || zmax > 65535 - margin || smin < margin || smax > 255 + Palette::kPad - 1 - margin;
}

// The common case of a span: pixels in place, values within range (no clamps). z and s are
// the depth and shade at the first pixel, d the first pixel's depth and d + to_out (bytes)
// its colour: one pointer to step, two pixels a turn. Returns the pixels depth-tested (what a
// span costs; counting those that pass would cost an instruction a pixel).
[[gnu::always_inline]] inline uint32_t shade_span(uint16_t* d, uint16_t* end, uintptr_t to_out, uint32_t z, uint32_t zs,
                                                  uint32_t s, uint32_t ss, const uint32_t* colour) {
    static_assert(sizeof(hal::Rgb565) == sizeof(uint16_t));
    const uint32_t n = uint32_t(end - d);
    auto pixel = [&](uint16_t* at, uint32_t zz, uint32_t sh) {
        const uint32_t zv = zz >> kFrac; // within [0, 65535] on this path (no clamps needed)
        if (zv < *at) {
            *at = uint16_t(zv);
            *reinterpret_cast<hal::Rgb565*>(reinterpret_cast<uintptr_t>(at) + to_out) = hal::Rgb565(colour[sh >> kFrac]);
        }
    };
    if (n & 1) {
        pixel(d, z, s);
        ++d, z += zs, s += ss;
    }
    for (; d < end; d += 2) {
        pixel(d, z, s);
        z += zs, s += ss;
        pixel(d + 1, z, s);
        z += zs, s += ss;
    }
    return n;
}

inline uintptr_t byte_distance(const uint16_t* from, const hal::Rgb565* to) {
    return reinterpret_cast<uintptr_t>(to) - reinterpret_cast<uintptr_t>(from);
}

[[gnu::always_inline]] inline uint32_t shade_in_place(uint16_t* d, uint16_t* end, hal::Rgb565* out, uint32_t z,
                                                      uint32_t zs, uint32_t s, uint32_t ss, const uint32_t* colour) {
    return shade_span(d, end, byte_distance(d, out), z, zs, s, ss, colour);
}

// One part of a larger triangle (rows between two vertices), pixels in place: the exact edge
// walks of its left and right edges, and depth and shade at each row's column 0.
struct InPlaceRows {
    int32_t lq, lr, ls, ldq, ldr; // left edge: first column from (q + (r != 0) + 7) >> 4
    int32_t rq, rr, rs, rdq, rdr; // right edge: last column from (q - 8) >> 4
    uint32_t zrow, zx, zy, srow, sx, sy;
};

// The hot loop of larger triangles, apart from the rest so it has the registers to itself:
// rows a chunk at a time, first their columns (the two edge walks alone in registers), then
// their pixels (a row's span is often a few pixels: slivers, zoomed views, so what a row
// costs besides its pixels matters as much). Returns the pixels depth-tested.
[[gnu::noinline]] uint32_t rows_in_place(InPlaceRows& w, int32_t rows, int32_t col0, int32_t col1, uint16_t* depth,
                                          hal::Rgb565* fb, uint32_t width, const uint32_t* colour) {
    constexpr int32_t kChunk = 32;
    int32_t span[2 * kChunk];
    uint32_t tested = 0;
    const uintptr_t to_out = byte_distance(depth, fb);
    while (rows > 0) {
        const int32_t n = rows < kChunk ? rows : kChunk;
        rows -= n;
        {
            int32_t lq = w.lq + 7, lr = w.lr, rq = w.rq - 8, rr = w.rr; // biased by the column rounding
            const int32_t ls = w.ls, ldq = w.ldq, ldr = w.ldr, rs = w.rs, rdq = w.rdq, rdr = w.rdr;
            for (int32_t* at = span; at < span + 2 * n; at += 2) {
                const int32_t lo = (lq + (lr != 0)) >> 4, hi = rq >> 4;
                lq += ldq, lr += ldr;
                if (lr >= ls) lr -= ls, ++lq;
                rq += rdq, rr += rdr;
                if (rr >= rs) rr -= rs, ++rq;
                at[0] = lo < col0 ? col0 : lo;
                at[1] = hi > col1 ? col1 : hi;
            }
            w.lq = lq - 7, w.lr = lr, w.rq = rq + 8, w.rr = rr;
        }
        uint32_t zrow = w.zrow, srow = w.srow;
        const uint32_t zx = w.zx, zy = w.zy, sx = w.sx, sy = w.sy;
        for (const int32_t* at = span; at < span + 2 * n; at += 2, depth += width, zrow += zy, srow += sy) {
            const int32_t lo = at[0], hi = at[1];
            if (lo <= hi) {
                tested += shade_span(depth + lo, depth + hi + 1, to_out, zrow + zx * uint32_t(lo), zx, srow + sx * uint32_t(lo), sx,
                                     colour);
            }
        }
        w.zrow = zrow, w.srow = srow;
    }
    return tested;
}

struct Rasterizer::Interp {
    uint32_t row, sx, sy; // value at the current row's column 0; steps per pixel (and row)
    int32_t lo, hi;       // the vertices' range, for clamping

    Interp() = default; // filled by gradients()
    Interp(const int32_t v[3], int64_t gx, int64_t gy, int64_t at_origin)
        : row(uint32_t(at_origin)), sx(uint32_t(gx * 16)), sy(uint32_t(gy * 16)) {
        set_range(v);
    }
    void set_range(const int32_t v[3]) {
        const int32_t mn = std::min({v[0], v[1], v[2]}), mx = std::max({v[0], v[1], v[2]});
        lo = mn << kFrac;
        hi = (mx << kFrac) | ((1 << kFrac) - 1);
    }
    int32_t value(uint32_t v) const {
        const int32_t s = int32_t(v);
        return (s < lo ? lo : (s > hi ? hi : s)) >> kFrac;
    }
};

void make_palette(Palette& out, uint8_t r, uint8_t g, uint8_t b) {
    // round(c * s / 255) without dividing: x / 255 = (x + 1 + (x >> 8)) >> 8 for x < 65535.
    auto scaled = [](uint32_t c, uint32_t s) {
        const uint32_t x = c * s + 127;
        return uint8_t((x + 1 + (x >> 8)) >> 8);
    };
    for (uint32_t s = 0; s < 256; ++s) out.colour[s] = hal::rgb565(scaled(r, s), scaled(g, s), scaled(b, s));
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

// The attributes (depth, shade) of a triangle: gradients per sub-pixel in kFrac fixed point and
// values at column 0 of the row whose centre is at sub-pixel y = oy, stepped from there in
// 32-bit modular arithmetic (exact wherever the true value fits, i.e. inside the triangle).
// The gradients come from one reciprocal of the area (2^-15 relative error: under two units
// across a triangle no thinner than a quarter of its box), or from exact divisions for slivers
// and for areas past 32 bits.
[[gnu::always_inline]] inline void Rasterizer::gradients(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                                                       int64_t area2, int32_t oy, Interp at[]) const {
    const int32_t bw = std::max({v0.x, v1.x, v2.x}) - std::min({v0.x, v1.x, v2.x});
    const int32_t bh = std::max({v0.y, v1.y, v2.y}) - std::min({v0.y, v1.y, v2.y});
    const bool exact = int64_t(bw) * bh > 4 * area2 || area2 > int64_t(UINT32_MAX);
    int64_t recip = 0;
    int shift = 0;
    if (!exact) {
        const Reciprocal r = reciprocal(uint32_t(area2)); // x / area2 ~= (x * r.m) >> r.shift
        recip = r.m;
        shift = r.shift - kFrac; // gradient in kFrac fixed point per sub-pixel unit
    }
    const int32_t vals[kAttributes][3] = {{v0.z, v1.z, v2.z}, {v0.shade, v1.shade, v2.shade}};
    const int32_t y1 = v1.y - v0.y, y2 = v2.y - v0.y, x1 = v1.x - v0.x, x2 = v2.x - v0.x;
    for (int k = 0; k < kAttributes; ++k) {
        const int32_t A0 = vals[k][0], d1 = vals[k][1] - A0, d2 = vals[k][2] - A0;
        const int64_t numx = int64_t(d1) * y2 - int64_t(d2) * y1;
        const int64_t numy = int64_t(d2) * x1 - int64_t(d1) * x2;
        int64_t gx, gy;
        if (exact) { // the reciprocal's error would grow with the gradients
            gx = div_fast(numx * (int64_t(1) << kFrac), area2);
            gy = div_fast(numy * (int64_t(1) << kFrac), area2);
        } else {
            gx = shift >= 0 ? (numx * recip) >> shift : (numx * recip) << -shift;
            gy = shift >= 0 ? (numy * recip) >> shift : (numy * recip) << -shift;
        }
        at[k] = Interp(vals[k], gx, gy, (int64_t(A0) << kFrac) + gx * (8 - v0.x) + gy * (oy - v0.y));
    }
}

// gradients() for a triangle whose box is under kSmall pixels both ways, the same values in
// fewer instructions: its coordinate differences (under 2^9 sub-pixels) and value differences
// (under 2^16) keep the numerators in 32 bits, its area under 2^17 makes the reciprocal's
// shift a right shift, and the rows' values are kept modulo 2^32 anyway (so are computed
// so). The clamping range only where `clamp` asks for it.
[[gnu::always_inline]] inline void Rasterizer::small_gradients(const ScreenVertex& v0, const ScreenVertex& v1,
                                                               const ScreenVertex& v2, int64_t area2, int32_t oy, bool clamp,
                                                               Interp at[]) const {
    const int32_t bw = std::max({v0.x, v1.x, v2.x}) - std::min({v0.x, v1.x, v2.x});
    const int32_t bh = std::max({v0.y, v1.y, v2.y}) - std::min({v0.y, v1.y, v2.y});
    const int32_t area = int32_t(area2);
    const bool exact = bw * bh > 4 * area;
    int32_t m = 0, shift = 0;
    if (!exact) {
        const Reciprocal r = reciprocal(uint32_t(area));
        m = int32_t(r.m), shift = r.shift - kFrac; // >= 4: the area is under 2^17
    }
    const int32_t vals[kAttributes][3] = {{v0.z, v1.z, v2.z}, {v0.shade, v1.shade, v2.shade}};
    const int32_t y1 = v1.y - v0.y, y2 = v2.y - v0.y, x1 = v1.x - v0.x, x2 = v2.x - v0.x;
    const uint32_t ox = uint32_t(8 - v0.x), oyy = uint32_t(oy - v0.y);
    for (int k = 0; k < kAttributes; ++k) {
        const int32_t A0 = vals[k][0], d1 = vals[k][1] - A0, d2 = vals[k][2] - A0;
        const int32_t numx = d1 * y2 - d2 * y1, numy = d2 * x1 - d1 * x2;
        int64_t gx, gy;
        if (exact) {
            gx = div_fast(int64_t(numx) * (int64_t(1) << kFrac), area2);
            gy = div_fast(int64_t(numy) * (int64_t(1) << kFrac), area2);
        } else {
            gx = (int64_t(numx) * m) >> shift;
            gy = (int64_t(numy) * m) >> shift;
        }
        Interp& t = at[k];
        t.row = (uint32_t(A0) << kFrac) + uint32_t(gx) * ox + uint32_t(gy) * oyy;
        t.sx = uint32_t(gx) * 16, t.sy = uint32_t(gy) * 16;
        if (clamp) t.set_range(vals[k]);
    }
}

Status Rasterizer::draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const Palette& palette,
                        Cull cull) {
    palette_ = &palette;
    if (!in_guard(a) || !in_guard(b) || !in_guard(c)) return Status::OutOfRange;
    // Doubled signed area; with y down, counter-clockwise on screen gives a negative value.
    const int64_t area2 =
        int64_t(b.x - a.x) * (c.y - a.y) - int64_t(b.y - a.y) * (c.x - a.x);
    if (area2 == 0 || (area2 > 0 && cull == Cull::Back)) {
        ++stats.culled;
        return Status::Ok;
    }
    // Scan with a positive area: swap two vertices of a front face.
    return area2 < 0 ? scan(a, c, b, -area2) : scan(a, b, c, area2);
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

Status Rasterizer::scan(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                        int64_t area2) {
    PixelBox box(v0, v1, v2, t_);
    if (box.empty()) return Status::Ok;
    const int32_t xmin = box.xmin, xmax = box.xmax, ymin = box.ymin, ymax = box.ymax;
    // Small: the triangle's own box (not the part of it on the screen) under kSmall pixels
    // both ways, which keeps scan_small's edge functions and small_gradients' products in 32 bits.
    const bool small = int64_t(xmax) - xmin < 16 * kSmall && int64_t(ymax) - ymin < 16 * kSmall;
    // Then the rows of this band.
    box.band(t_);
    const int32_t row0 = box.row0, row1 = box.row1, col0 = box.col0, col1 = box.col1;
    if (row0 > row1) return Status::Ok;
    ++stats.triangles;
    if (small) {
        scan_small(v0, v1, v2, area2, row0, row1, col0, col1);
        return Status::Ok;
    }
    // (A stippled triangle takes the per-pixel path, which leaves out every other pixel.)
    const bool clamp = stipple_ || needs_clamp(v0, v1, v2, int32_t(std::max(xmax - xmin, ymax - ymin) >> 4));
    constexpr int32_t kNear = 16 * 1024; // sub-pixels: 32-bit edge walks within this of the origin
    const bool near = xmin >= -kNear && xmax <= kNear && ymin >= -kNear && ymax <= kNear;
    if (near) scan_rows<int32_t>(v0, v1, v2, area2, row0, row1, col0, col1, clamp);
    else scan_rows<int64_t>(v0, v1, v2, area2, row0, row1, col0, col1, clamp);
    return Status::Ok;
}

// The rows of a larger triangle: each row's span from the three edge walks.
template <typename T>
void Rasterizer::scan_rows(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2,
                             int32_t row0, int32_t row1, int32_t col0, int32_t col1, bool clamp) {
    const int64_t sy0 = int64_t(row0) * 16 + 8;
    EdgeWalk<T> edges[3];
    edges[0].start(v1, v2, sy0);
    edges[1].start(v2, v0, sy0);
    edges[2].start(v0, v1, sy0);
    Interp at[kAttributes];
    gradients(v0, v1, v2, area2, int32_t(sy0), at);

    // Rows above the middle vertex are bounded by the long edge (top to bottom) and the top
    // edge, rows below by the long edge and the bottom edge: one left and one right edge per
    // row, kept in registers. (The third edge's half-plane holds the whole span of those rows.)
    // A flat edge only decides whether its own row is in.
    const ScreenVertex* from[3] = {&v1, &v2, &v0};
    const ScreenVertex* to[3] = {&v2, &v0, &v1};
    const int32_t ymid = v0.y + v1.y + v2.y - std::min({v0.y, v1.y, v2.y}) - std::max({v0.y, v1.y, v2.y});
    int upper = -1, lower = -1, longest = -1;
    for (int i = 0; i < 3; ++i) {
        const int32_t a = std::min(from[i]->y, to[i]->y), b = std::max(from[i]->y, to[i]->y);
        if (a == b) continue; // flat
        if (longest < 0 || b - a > std::max(from[longest]->y, to[longest]->y) - std::min(from[longest]->y, to[longest]->y)) longest = i;
    }
    for (int i = 0; i < 3; ++i) {
        if (i == longest) continue;
        const int32_t a = std::min(from[i]->y, to[i]->y), b = std::max(from[i]->y, to[i]->y);
        if (a == b) continue;
        if (b <= ymid) upper = i;
        else lower = i;
    }
    int32_t flat_skip_first = 0, flat_skip_last = 0; // rows a flat edge leaves out, at each end
    for (const EdgeWalk<T>& e : edges) {
        if (e.side != EdgeWalk<T>::Side::Flat || e.q >= 0) continue;
        if (e.dq > 0) flat_skip_first = 1; // a flat edge left out its first row (the top)
        else flat_skip_last = 1;
    }
    for (const EdgeWalk<T>& e : edges) {
        if (e.side != EdgeWalk<T>::Side::Flat || e.dq > 0 || e.q + T(row1 - row0) * e.dq >= 0) continue;
        flat_skip_last = 1; // a bottom edge whose row is out
    }
    uint32_t zrow = at[0].row, srow = at[1].row;
    const uint32_t zx = at[0].sx, zy = at[0].sy, sx = at[1].sx, sy = at[1].sy;
    EdgeWalk<T> lng = edges[longest];
    int32_t y = row0;
    const int32_t last = row1 - flat_skip_last;
    if (flat_skip_first) { // the long edge still moves through the skipped row
        lng.step();
        if (upper >= 0) edges[upper].step();
        else if (lower >= 0) edges[lower].step();
        zrow += zy, srow += sy, ++y;
    }
    for (int part = 0; part < 2; ++part) {
        const int other = part == 0 ? upper : lower;
        if (other < 0) continue;
        EdgeWalk<T> oth = edges[other];
        // Upper part: rows whose centre is above the middle vertex; lower part: the rest.
        const int32_t end = part == 0 ? std::min(last, int32_t((int64_t(ymid) - 9) >> 4)) : last;
        const bool long_left = lng.side == EdgeWalk<T>::Side::Left;
        EdgeWalk<T>& L = long_left ? lng : oth;
        EdgeWalk<T>& R = long_left ? oth : lng;
        if constexpr (sizeof(T) == 4) {
            if (!clamp) {
                const int32_t rows = end - y + 1;
                if (rows > 0) {
                    InPlaceRows w{L.q, L.r, L.s, L.dq, L.dr, R.q, R.r, R.s, R.dq, R.dr, zrow, zx, zy, srow, sx, sy};
                    const size_t at_row = size_t(y - t_.y0) * t_.width;
                    stats.pixels += rows_in_place(w, rows, col0, col1, t_.depth + at_row, t_.pixels + at_row, t_.width,
                                                  palette_->colour);
                    L.q = w.lq, L.r = w.lr, R.q = w.rq, R.r = w.rr, zrow = w.zrow, srow = w.srow;
                    y = end + 1;
                }
                if (part == 0 && lower >= 0) {
                    for (int32_t k = row0; k < y; ++k) edges[lower].step();
                }
                continue;
            }
        }
        // The walks in locals (registers, as far as the core has them).
        T lq = L.q, lr = L.r, rq = R.q, rr = R.r;
        const T ls = L.s, ldq = L.dq, ldr = L.dr, rs = R.s, rdq = R.dq, rdr = R.dr;
        uint16_t* const depth = t_.depth;
        hal::Rgb565* const fb = t_.pixels;
        const uint32_t* const colour = palette_->colour;
        const size_t width = t_.width;
        uint32_t pixels = 0, spans = 0;
        for (; y <= end; ++y, zrow += zy, srow += sy) {
            T lo = (lq + (lr != 0) + 7) >> 4; // first column whose centre 16x+8 >= ceil(t/s)
            T hi = (rq - 8) >> 4;             // last column whose centre 16x+8 <= floor(t/s)
            lq += ldq, lr += ldr;
            if (lr >= ls) lr -= ls, ++lq;
            rq += rdq, rr += rdr;
            if (rr >= rs) rr -= rs, ++rq;
            if (lo < col0) lo = col0;
            if (hi > col1) hi = col1;
            if (lo > hi) continue;
            if (!clamp) {
                const size_t row = size_t(y - t_.y0) * width;
                pixels += shade_in_place(depth + row + lo, depth + row + hi + 1, fb + row + lo, zrow + zx * uint32_t(lo), zx,
                                         srow + sx * uint32_t(lo), sx, colour);
                ++spans;
            } else {
                at[0].row = zrow, at[1].row = srow;
                shade(int32_t(y), int32_t(lo), int32_t(hi), at, clamp);
            }
        }
        L.q = lq, L.r = lr, R.q = rq, R.r = rr;
        stats.pixels += pixels;
        stats.spans += spans;
        if (part == 0 && lower >= 0) { // the bottom edge starts where the top edge ended
            for (int32_t k = row0; k < y; ++k) edges[lower].step();
        }
    }
}

// Small triangles (most of a tessellated model on a handheld's screen): the triangle's pixel
// box in 32-bit arithmetic, edge functions stepped per pixel. Coverage is the same predicate as
// EdgeWalk's (the same pixels, top-left rule included).
void Rasterizer::scan_small(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                            int64_t area2, int32_t row0, int32_t row1, int32_t col0, int32_t col1) {
    const int32_t ox = col0 * 16 + 8, oy = row0 * 16 + 8; // the first pixel's centre
    struct Edge {
        int32_t e, sx, sy; // value at the current pixel; steps per pixel in x and y
    } ed[3];
    const ScreenVertex* from[3] = {&v1, &v2, &v0};
    const ScreenVertex* to[3] = {&v2, &v0, &v1};
    for (int i = 0; i < 3; ++i) {
        const int32_t dx = to[i]->x - from[i]->x, dy = to[i]->y - from[i]->y;
        const int32_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
        const int32_t px = from[i]->x - ox, py = from[i]->y - oy;
        ed[i].e = dx * (0 - py) - dy * (0 - px) - bias;
        ed[i].sx = -16 * dy;
        ed[i].sy = 16 * dx;
    }
    // The rows' spans first: a small triangle often covers no pixel centre at all (a sliver
    // between them), and then needs no gradients.
    int32_t span[2 * kSmall];
    bool any = false;
    {
        int32_t r0 = ed[0].e, r1 = ed[1].e, r2 = ed[2].e;
        const int32_t sx0 = ed[0].sx, sx1 = ed[1].sx, sx2 = ed[2].sx;
        for (int32_t* at = span; at <= span + 2 * (row1 - row0); at += 2) {
            // The first pixel inside, then on while inside (a triangle is convex).
            int32_t e0 = r0, e1 = r1, e2 = r2, x = col0;
            for (; x <= col1 && (e0 | e1 | e2) < 0; ++x) e0 += sx0, e1 += sx1, e2 += sx2;
            const int32_t lo = x;
            for (; x <= col1 && (e0 | e1 | e2) >= 0; ++x) e0 += sx0, e1 += sx1, e2 += sx2;
            at[0] = lo, at[1] = x; // [lo, x)
            any |= x > lo;
            r0 += ed[0].sy, r1 += ed[1].sy, r2 += ed[2].sy;
        }
    }
    if (!any) return;
    const bool clamp = stipple_ || needs_clamp(v0, v1, v2, kSmall);
    Interp at[kAttributes];
    small_gradients(v0, v1, v2, area2, oy, clamp, at);
    const int32_t* sp = span;
    for (int32_t y = row0; y <= row1; ++y, sp += 2) {
        const int32_t lo = sp[0], end = sp[1];
        if (end > lo) {
            if (!clamp) {
                const size_t row = size_t(y - t_.y0) * t_.width;
                stats.pixels += shade_in_place(t_.depth + row + lo, t_.depth + row + end, t_.pixels + row + lo,
                                               at[0].row + at[0].sx * uint32_t(lo), at[0].sx, at[1].row + at[1].sx * uint32_t(lo),
                                               at[1].sx, palette_->colour);
            } else {
                shade(y, lo, end - 1, at, clamp);
            }
        }
        for (Interp& t : at) t.row += t.sy;
    }
}

// Shades the pixels lo..hi of row y that pass the depth test, with the attributes clamped to
// their vertices' range where `clamp` says they could leave it.
void Rasterizer::shade(int32_t y, int32_t lo, int32_t hi, const Interp* at, bool clamp) {
    uint32_t z = at[0].row + at[0].sx * uint32_t(lo), s = at[1].row + at[1].sx * uint32_t(lo);
    const uint32_t zs = at[0].sx, ss = at[1].sx;
    const size_t row = size_t(y - t_.y0) * t_.width;
    uint16_t* const drow = t_.depth + row;
    hal::Rgb565* const line = t_.pixels + row;
    const uint32_t* colour = palette_->colour;
    if (!clamp) {
        stats.pixels += shade_in_place(drow + lo, drow + hi + 1, line + lo, z, zs, s, ss, colour);
        ++stats.spans;
        return;
    }
    for (int32_t x = lo; x <= hi; ++x, z += zs, s += ss) {
        if (stipple_ && ((x ^ y) & 1)) continue;
        const uint16_t zv = uint16_t(at[0].value(z));
        if (zv < drow[x]) {
            drow[x] = zv;
            line[x] = hal::Rgb565(colour[at[1].value(s)]);
        }
    }
    stats.pixels += uint32_t(hi - lo + 1);
    ++stats.spans;
}

Status Rasterizer::line(const ScreenVertex& a, const ScreenVertex& b, hal::Rgb565 colour, uint16_t bias) {
    if (!in_guard(a) || !in_guard(b)) return Status::OutOfRange;
    stats.pixels += stroke<false>(t_, a, b, colour, bias);
    return Status::Ok;
}

Status Rasterizer::outline(const ScreenVertex& a, const ScreenVertex& b, hal::Rgb565 colour, uint16_t bias, uint8_t beyond) {
    if (!in_guard(a) || !in_guard(b)) return Status::OutOfRange;
    stats.pixels += stroke<true>(t_, a, b, colour, bias, beyond == 0 ? 1 : beyond == 2 ? -1 : 0, beyond == 1 ? 1 : beyond == 3 ? -1 : 0);
    return Status::Ok;
}

} // namespace facet::render
