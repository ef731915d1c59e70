// Triangles into spans: the exact edge walks of larger triangles (rows a chunk at a time, two
// pixels a turn), the 32-bit pixel box of small ones, the attributes' gradients, and the span
// loops that depth-test and shade (raster.cpp dispatches; render/subpixel.h states the format).
#include "render/raster.h"

#include "raster_internal.h"
#include "render/fixed.h"

#include <algorithm>
#include <cstdint>

namespace facet::render {
namespace {

using namespace detail;

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

    // `transposed`: p and e are a triangle's vertices with x and y swapped and its edge reversed
    // (Rasterizer::scan's columns), whose function is the screen edge's: the tie goes the
    // screen edge's way, bias 0 where that edge goes up or is horizontal going right.
    void start(const ScreenVertex& p, const ScreenVertex& e, int64_t sy, bool transposed) {
        const int64_t dx = e.x - p.x, dy = e.y - p.y;
        const int64_t bias = transposed ? ((dx > 0 || (dx == 0 && dy < 0)) ? 0 : 1) : ((dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1);
        const int64_t k = dx * (sy - p.y) + dy * p.x - bias; // inside: -dy*sx + k >= 0
        int64_t t, step, s;
        if (dy == 0) {
            side = Side::Flat;
            q = T(k);
            dq = T(kPerPixel * dx);
            return;
        }
        if (dy < 0) { // sx >= ceil(-k / -dy)
            side = Side::Left;
            s = -dy;
            t = -k;
            step = -kPerPixel * dx;
        } else { // sx <= floor(k / dy)
            side = Side::Right;
            s = dy;
            t = k;
            step = kPerPixel * dx;
        }
        int64_t q64, dq64;
        floor_div_pair(t, step, s, q64, dq64);
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

namespace {

// The common case of a span: n pixels in place, `step` entries apart (1 along a row, the
// width down a column), values within range (no clamps). z and s are the depth and shade at
// the first pixel, d the first pixel's depth and d + to_out (bytes) its colour: one pointer to
// step, two pixels a turn. Returns the pixels depth-tested (what a span costs; counting those
// that pass would cost an instruction a pixel).
[[gnu::always_inline]] inline uint32_t shade_span(uint16_t* d, uint32_t n, ptrdiff_t step, uintptr_t to_out, uint32_t z,
                                                  uint32_t zs, uint32_t s, uint32_t ss, const uint32_t* colour) {
    static_assert(sizeof(Rgb565) == sizeof(uint16_t));
    uint16_t* const end = d + ptrdiff_t(n) * step;
    auto pixel = [&](uint16_t* at, uint32_t zz, uint32_t sh) {
        const uint32_t zv = zz >> kFrac; // within [0, 65535] on this path (no clamps needed)
        if (zv < *at) {
            *at = uint16_t(zv);
            *reinterpret_cast<Rgb565*>(reinterpret_cast<uintptr_t>(at) + to_out) = Rgb565(colour[sh >> kFrac]);
        }
    };
    if (n & 1) {
        pixel(d, z, s);
        d += step, z += zs, s += ss;
    }
    for (; d != end; d += 2 * step) {
        pixel(d, z, s);
        z += zs, s += ss;
        pixel(d + step, z, s);
        z += zs, s += ss;
    }
    return n;
}

// The same span with one colour (a triangle whose shade does not change across it: a plane's,
// Gouraud from equal normals): the same pixels, without stepping the shade.
[[gnu::always_inline]] inline uint32_t flat_span(uint16_t* d, uint32_t n, ptrdiff_t step, uintptr_t to_out, uint32_t z,
                                                 uint32_t zs, Rgb565 c) {
    uint16_t* const end = d + ptrdiff_t(n) * step;
    auto pixel = [&](uint16_t* at, uint32_t zz) {
        const uint32_t zv = zz >> kFrac;
        if (zv < *at) {
            *at = uint16_t(zv);
            *reinterpret_cast<Rgb565*>(reinterpret_cast<uintptr_t>(at) + to_out) = c;
        }
    };
    if (n & 1) {
        pixel(d, z);
        d += step, z += zs;
    }
    for (; d != end; d += 2 * step) {
        pixel(d, z);
        pixel(d + step, z + zs);
        z += 2 * zs;
    }
    return n;
}

inline uintptr_t byte_distance(const uint16_t* from, const Rgb565* to) {
    return reinterpret_cast<uintptr_t>(to) - reinterpret_cast<uintptr_t>(from);
}

// A row's n pixels from d (depth) and out (colour).
[[gnu::always_inline]] inline uint32_t shade_in_place(uint16_t* d, uint32_t n, Rgb565* out, uint32_t z, uint32_t zs,
                                                      uint32_t s, uint32_t ss, const uint32_t* colour) {
    return shade_span(d, n, 1, byte_distance(d, out), z, zs, s, ss, colour);
}

// One part of a larger triangle (lines between two vertices: rows, or columns where it is
// scanned transposed), pixels in place: the exact edge walks of its left and right edges, and
// depth and shade at each line's position 0.
struct InPlaceRows {
    int32_t lq, lr, ls, ldq, ldr; // left edge: first column first_centre_from(q + (r != 0))
    int32_t rq, rr, rs, rdq, rdr; // right edge: last column last_centre_to(q)
    uint32_t zrow, zx, zy, srow, sx, sy;
};

// The hot loop of larger triangles, apart from the rest so it has the registers to itself:
// lines a chunk at a time, first their spans (the two edge walks alone in registers), then
// their pixels (a line's span is often a few pixels: slivers, zoomed views, so what a line
// costs besides its pixels matters as much). Rows (kColumns false): `depth` is the first row's
// column 0, a span's pixels adjacent. Columns (a tall triangle scanned transposed): `depth` is
// the first column's entry in the band's first row, screen row `origin`; a span's pixels are
// `width` apart. Returns the pixels depth-tested.
template <bool kColumns>
[[gnu::noinline]] uint32_t rows_in_place(InPlaceRows& w, int32_t rows, int32_t col0, int32_t col1, int32_t origin,
                                          uint16_t* depth, Rgb565* fb, uint32_t width, const uint32_t* colour) {
    constexpr int32_t kChunk = 32;
    int32_t span[2 * kChunk];
    uint32_t tested = 0;
    const uintptr_t to_out = byte_distance(depth, fb);
    const ptrdiff_t step = kColumns ? ptrdiff_t(width) : 1, line_step = kColumns ? 1 : ptrdiff_t(width);
    if constexpr (!kColumns) origin = 0;
    while (rows > 0) {
        const int32_t n = rows < kChunk ? rows : kChunk;
        rows -= n;
        {
            // Biased by the columns' rounding: lo = first_centre_from(q + (r != 0)), hi = last_centre_to(q).
            int32_t lq = w.lq + (kHalfPixel - 1), lr = w.lr, rq = w.rq - kHalfPixel, rr = w.rr;
            const int32_t ls = w.ls, ldq = w.ldq, ldr = w.ldr, rs = w.rs, rdq = w.rdq, rdr = w.rdr;
            for (int32_t* at = span; at < span + 2 * n; at += 2) {
                const int32_t lo = pixel_of(lq + (lr != 0)), hi = pixel_of(rq);
                lq += ldq, lr += ldr;
                if (lr >= ls) lr -= ls, ++lq;
                rq += rdq, rr += rdr;
                if (rr >= rs) rr -= rs, ++rq;
                at[0] = lo < col0 ? col0 : lo;
                at[1] = hi > col1 ? col1 : hi;
            }
            w.lq = lq - (kHalfPixel - 1), w.lr = lr, w.rq = rq + kHalfPixel, w.rr = rr;
        }
        uint32_t zrow = w.zrow, srow = w.srow;
        const uint32_t zx = w.zx, zy = w.zy, sx = w.sx, sy = w.sy;
        if (sx == 0 && sy == 0) { // one shade: one colour
            const Rgb565 c = Rgb565(colour[srow >> kFrac]);
            for (const int32_t* at = span; at < span + 2 * n; at += 2, depth += line_step, zrow += zy) {
                const int32_t lo = at[0], hi = at[1];
                if (lo <= hi) tested += flat_span(depth + (lo - origin) * step, uint32_t(hi - lo + 1), step, to_out, zrow + zx * uint32_t(lo), zx, c);
            }
        } else {
            for (const int32_t* at = span; at < span + 2 * n; at += 2, depth += line_step, zrow += zy, srow += sy) {
                const int32_t lo = at[0], hi = at[1];
                if (lo <= hi) {
                    tested += shade_span(depth + (lo - origin) * step, uint32_t(hi - lo + 1), step, to_out, zrow + zx * uint32_t(lo), zx,
                                         srow + sx * uint32_t(lo), sx, colour);
                }
            }
        }
        w.zrow = zrow, w.srow = srow;
    }
    return tested;
}

} // namespace

// One attribute over a triangle, stepped per pixel and per row in 32-bit modular arithmetic
// (exact wherever the true value fits in 32 bits: everywhere inside the triangle), in kFrac
// fixed point, read back clamped to the range of its three vertex values.
struct Rasterizer::Interp {
    uint32_t row, sx, sy; // value at the current row's column 0; steps per pixel (and row)
    // (gx, gy: gradients per sub-pixel; at_origin: the value at column 0's centre)
    int32_t lo, hi;       // the vertices' range, for clamping

    Interp() = default; // filled by gradients()
    Interp(const int32_t v[3], int64_t gx, int64_t gy, int64_t at_origin)
        : row(uint32_t(at_origin)), sx(uint32_t(gx * kPerPixel)), sy(uint32_t(gy * kPerPixel)) {
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
            div_pair(numx * (int64_t(1) << kFrac), numy * (int64_t(1) << kFrac), area2, gx, gy);
        } else {
            gx = shift >= 0 ? (numx * recip) >> shift : (numx * recip) << -shift;
            gy = shift >= 0 ? (numy * recip) >> shift : (numy * recip) << -shift;
        }
        at[k] = Interp(vals[k], gx, gy, (int64_t(A0) << kFrac) + gx * (centre(0) - v0.x) + gy * (oy - v0.y));
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
    const uint32_t ox = uint32_t(centre(0) - v0.x), oyy = uint32_t(oy - v0.y);
    for (int k = 0; k < kAttributes; ++k) {
        const int32_t A0 = vals[k][0], d1 = vals[k][1] - A0, d2 = vals[k][2] - A0;
        const int32_t numx = d1 * y2 - d2 * y1, numy = d2 * x1 - d1 * x2;
        int64_t gx, gy;
        if ((d1 | d2) == 0) { // one value (a plane's shade): no gradient, whichever way it is worked out
            gx = gy = 0;
        } else if (exact) {
            div_pair(int64_t(numx) * (int64_t(1) << kFrac), int64_t(numy) * (int64_t(1) << kFrac), area2, gx, gy);
        } else {
            gx = (int64_t(numx) * m) >> shift;
            gy = (int64_t(numy) * m) >> shift;
        }
        Interp& t = at[k];
        t.row = (uint32_t(A0) << kFrac) + uint32_t(gx) * ox + uint32_t(gy) * oyy;
        t.sx = uint32_t(gx) * kPerPixel, t.sy = uint32_t(gy) * kPerPixel;
        if (clamp) t.set_range(vals[k]);
    }
}

// The rows of a larger triangle: each row's span from the three edge walks.
template <typename T, bool kColumns>
void Rasterizer::scan_rows(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2,
                             int32_t row0, int32_t row1, int32_t col0, int32_t col1, bool clamp) {
    static_assert(!kColumns || sizeof(T) == 4, "columns take the 32-bit walks alone");
    const int64_t sy0 = int64_t(row0) * kPerPixel + kHalfPixel; // the first row's centre
    EdgeWalk<T> edges[3];
    edges[0].start(v1, v2, sy0, kColumns);
    edges[1].start(v2, v0, sy0, kColumns);
    edges[2].start(v0, v1, sy0, kColumns);
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
        const int32_t end = part == 0 ? std::min(last, int32_t(last_centre_to(int64_t(ymid) - 1))) : last;
        const bool long_left = lng.side == EdgeWalk<T>::Side::Left;
        EdgeWalk<T>& L = long_left ? lng : oth;
        EdgeWalk<T>& R = long_left ? oth : lng;
        if constexpr (sizeof(T) == 4) {
            if (kColumns || !clamp) {
                const int32_t rows = end - y + 1;
                if (rows > 0) {
                    InPlaceRows w{L.q, L.r, L.s, L.dq, L.dr, R.q, R.r, R.s, R.dq, R.dr, zrow, zx, zy, srow, sx, sy};
                    // (Columns: line y is screen column y, from the band's first row.)
                    const size_t at = kColumns ? size_t(y) : size_t(y - t_.y0) * t_.width;
                    stats.pixels += rows_in_place<kColumns>(w, rows, col0, col1, int32_t(t_.y0), t_.depth + at, t_.pixels + at,
                                                            t_.width, palette_->colour);
                    L.q = w.lq, L.r = w.lr, R.q = w.rq, R.r = w.rr, zrow = w.zrow, srow = w.srow;
                    y = end + 1;
                }
                if (part == 0 && lower >= 0) {
                    for (int32_t k = row0; k < y; ++k) edges[lower].step();
                }
                continue;
            }
        }
        // The walks in locals (registers, as far as the core has them): 64-bit walks, and
        // attributes clamped (a row at a time, never transposed).
        T lq = L.q, lr = L.r, rq = R.q, rr = R.r;
        const T ls = L.s, ldq = L.dq, ldr = L.dr, rs = R.s, rdq = R.dq, rdr = R.dr;
        uint16_t* const depth = t_.depth;
        Rgb565* const fb = t_.pixels;
        const uint32_t* const colour = palette_->colour;
        const size_t width = t_.width;
        uint32_t pixels = 0, spans = 0;
        for (; y <= end; ++y, zrow += zy, srow += sy) {
            T lo = first_centre_from(lq + (lr != 0)); // the first column whose centre is >= ceil(t/s)
            T hi = last_centre_to(rq);                // the last column whose centre is <= floor(t/s)
            lq += ldq, lr += ldr;
            if (lr >= ls) lr -= ls, ++lq;
            rq += rdq, rr += rdr;
            if (rr >= rs) rr -= rs, ++rq;
            if (lo < col0) lo = col0;
            if (hi > col1) hi = col1;
            if (lo > hi) continue;
            if (!clamp) {
                const size_t row = size_t(y - t_.y0) * width;
                pixels += shade_in_place(depth + row + lo, uint32_t(hi - lo + 1), fb + row + lo, zrow + zx * uint32_t(lo), zx,
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
    const int32_t ox = centre(col0), oy = centre(row0); // the first pixel's centre
    SmallEdge ed[3];
    small_edges(v0, v1, v2, ox, oy, ed);
    // Rows up to the first with a run: a small triangle often covers no pixel centre at all (a
    // sliver between them), and then needs no gradients.
    int32_t e0 = ed[0].e, e1 = ed[1].e, e2 = ed[2].e, lo, end, y = row0;
    for (;;) {
        small_run<kHardwareDivide>(ed, e0, e1, e2, col0, col1, lo, end);
        if (end > lo) break;
        if (++y > row1) return;
        e0 += ed[0].sy, e1 += ed[1].sy, e2 += ed[2].sy;
    }
    const bool clamp = stipple_ || needs_clamp(v0, v1, v2, kSmall);
    Interp at[kAttributes];
    small_gradients(v0, v1, v2, area2, oy, clamp, at);
    for (Interp& t : at) t.row += t.sy * uint32_t(y - row0); // (modulo 2^32, as they step)
    // The target's fields in locals: the depth writes are 16-bit, as its width and band are,
    // so the compiler would read them again after every pixel.
    const uint32_t width = t_.width;
    uint16_t* drow = t_.depth + size_t(y - t_.y0) * width;
    Rgb565* prow = t_.pixels + size_t(y - t_.y0) * width;
    const uint32_t* const colour = palette_->colour;
    const uint32_t zsx = at[0].sx, zsy = at[0].sy, ssx = at[1].sx, ssy = at[1].sy;
    const bool flat = !clamp && ssx == 0 && ssy == 0; // one shade: one colour (flat_span)
    const Rgb565 flat_colour = flat ? Rgb565(colour[at[1].row >> kFrac]) : Rgb565(0);
    uint32_t pixels = 0;
    for (;;) {
        if (end > lo) {
            if (flat) {
                pixels += flat_span(drow + lo, uint32_t(end - lo), 1, byte_distance(drow + lo, prow + lo),
                                    at[0].row + zsx * uint32_t(lo), zsx, flat_colour);
            } else if (!clamp) {
                pixels += shade_in_place(drow + lo, uint32_t(end - lo), prow + lo, at[0].row + zsx * uint32_t(lo), zsx,
                                         at[1].row + ssx * uint32_t(lo), ssx, colour);
            } else {
                shade(y, lo, end - 1, at, clamp);
            }
        }
        if (++y > row1) break;
        e0 += ed[0].sy, e1 += ed[1].sy, e2 += ed[2].sy;
        at[0].row += zsy, at[1].row += ssy;
        drow += width, prow += width;
        small_run<kHardwareDivide>(ed, e0, e1, e2, col0, col1, lo, end);
    }
    stats.pixels += pixels;
}

// Shades the pixels lo..hi of row y that pass the depth test, with the attributes clamped to
// their vertices' range where `clamp` says they could leave it.
void Rasterizer::shade(int32_t y, int32_t lo, int32_t hi, const Interp* at, bool clamp) {
    uint32_t z = at[0].row + at[0].sx * uint32_t(lo), s = at[1].row + at[1].sx * uint32_t(lo);
    const uint32_t zs = at[0].sx, ss = at[1].sx;
    const size_t row = size_t(y - t_.y0) * t_.width;
    uint16_t* const drow = t_.depth + row;
    Rgb565* const line = t_.pixels + row;
    const uint32_t* colour = palette_->colour;
    if (!clamp) {
        stats.pixels += shade_in_place(drow + lo, uint32_t(hi - lo + 1), line + lo, z, zs, s, ss, colour);
        ++stats.spans;
        return;
    }
    for (int32_t x = lo; x <= hi; ++x, z += zs, s += ss) {
        if (stipple_ && ((x ^ y) & 1)) continue;
        const uint16_t zv = uint16_t(at[0].value(z));
        if (zv < drow[x]) {
            drow[x] = zv;
            line[x] = Rgb565(colour[at[1].value(s)]);
        }
    }
    stats.pixels += uint32_t(hi - lo + 1);
    ++stats.spans;
}

template void Rasterizer::scan_rows<int32_t, false>(const ScreenVertex&, const ScreenVertex&, const ScreenVertex&, int64_t,
                                                    int32_t, int32_t, int32_t, int32_t, bool);
template void Rasterizer::scan_rows<int32_t, true>(const ScreenVertex&, const ScreenVertex&, const ScreenVertex&, int64_t,
                                                   int32_t, int32_t, int32_t, int32_t, bool);
template void Rasterizer::scan_rows<int64_t, false>(const ScreenVertex&, const ScreenVertex&, const ScreenVertex&, int64_t,
                                                    int32_t, int32_t, int32_t, int32_t, bool);

} // namespace facet::render
