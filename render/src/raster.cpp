#include "render/raster.h"

#include "render/fixed.h"

#include <algorithm>
#include <cstdint>

namespace facet::render {
namespace {

constexpr int kFrac = 12; // fractional bits of interpolated attributes
constexpr int64_t kSmall = 32; // triangles whose pixel box is under this (both ways) take scan_small

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

    // Narrows [lo, hi] (pixel columns) for the current row.
    void clip(T& lo, T& hi) const {
        switch (side) {
        case Side::Flat:
            if (q < 0) hi = lo - 1;
            break;
        case Side::Left: { // first column whose centre 16x+8 >= ceil(t/s)
            const T x = (q + (r != 0) + 7) >> 4;
            if (x > lo) lo = x;
            break;
        }
        case Side::Right: { // last column whose centre 16x+8 <= floor(t/s)
            const T x = (q - 8) >> 4;
            if (x < hi) hi = x;
            break;
        }
        }
    }

    void next_row() {
        q += dq;
        if (side == Side::Flat) return;
        r += dr;
        if (r >= s) {
            r -= s;
            ++q;
        }
    }
};

// A linearly interpolated attribute: value(sx, sy) = a0 + gx*(sx - x0) + gy*(sy - y0),
// gradients per sub-pixel in kFrac fixed point.
struct Plane {
    int64_t a0, gx, gy;

    Plane(int32_t A0, int32_t A1, int32_t A2, const ScreenVertex& v0, const ScreenVertex& v1,
          const ScreenVertex& v2, int64_t area2) {
        const int64_t d1 = A1 - A0, d2 = A2 - A0;
        const int64_t numx = d1 * (v2.y - v0.y) - d2 * (v1.y - v0.y);
        const int64_t numy = d2 * (v1.x - v0.x) - d1 * (v2.x - v0.x);
        a0 = int64_t(A0) << kFrac;
        gx = div_fast(numx * (int64_t(1) << kFrac), area2);
        gy = div_fast(numy * (int64_t(1) << kFrac), area2);
    }
    int64_t at(int64_t dx, int64_t dy) const { return a0 + gx * dx + gy * dy; }
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

struct Rasterizer::Interp {
    uint32_t row = 0, sx = 0, sy = 0; // value at the current row's column 0; steps per pixel
    int32_t lo = 0, hi = 0;

    Interp() = default;
    Interp(const int32_t v[3], int64_t gx, int64_t gy, int64_t at_origin)
        : row(uint32_t(at_origin)), sx(uint32_t(gx * 16)), sy(uint32_t(gy * 16)) {
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

Rasterizer::Rasterizer(hal::Display& display, std::span<uint16_t> depth,
                       std::span<hal::Rgb565> line)
    : display_(display), depth_(depth), line_(line), width_(display.info().width)
    , height_(display.info().height) {}

Status Rasterizer::check() const {
    if (depth_.size() < size_t(width_) * height_ || line_.size() < width_) {
        return Status::OutOfRange;
    }
    return Status::Ok;
}

void Rasterizer::clear_depth() {
    // Two entries per 32-bit store; the buffer is 2-byte aligned at least, so peel one.
    using Word = uint32_t __attribute__((may_alias, aligned(2)));
    size_t n = size_t(width_) * height_, i = 0;
    if (reinterpret_cast<uintptr_t>(depth_.data()) & 2) depth_[i++] = 0xFFFF;
    Word* w = reinterpret_cast<Word*>(depth_.data() + i);
    const size_t words = (n - i) / 2;
    for (size_t k = 0; k < words; ++k) w[k] = 0xFFFFFFFFu;
    for (i += words * 2; i < n; ++i) depth_[i] = 0xFFFF;
}

Status Rasterizer::draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const Palette& palette,
                        Cull cull) {
    palette_ = &palette;
    fb_ = display_.draw_buffer();
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

Status Rasterizer::scan(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                        int64_t area2) {
    ++stats.triangles;
    int32_t ymin = v0.y, ymax = v0.y, xmin = v0.x, xmax = v0.x;
    for (const ScreenVertex* v : {&v1, &v2}) {
        ymin = v->y < ymin ? v->y : ymin;
        ymax = v->y > ymax ? v->y : ymax;
        xmin = v->x < xmin ? v->x : xmin;
        xmax = v->x > xmax ? v->x : xmax;
    }
    // Rows and columns whose centres (16i+8) can be inside, clipped to the screen.
    int64_t row0 = (int64_t(ymin) + 7) >> 4, row1 = (int64_t(ymax) - 8) >> 4;
    int64_t col0 = (int64_t(xmin) + 7) >> 4, col1 = (int64_t(xmax) - 8) >> 4;
    row0 = row0 < 0 ? 0 : row0;
    row1 = row1 > height_ - 1 ? height_ - 1 : row1;
    col0 = col0 < 0 ? 0 : col0;
    col1 = col1 > width_ - 1 ? width_ - 1 : col1;
    if (row0 > row1 || col0 > col1) return Status::Ok;

    if (col1 - col0 < kSmall && row1 - row0 < kSmall) {
        return scan_small(v0, v1, v2, area2, int32_t(row0), int32_t(row1), int32_t(col0), int32_t(col1));
    }
    const bool clamp = needs_clamp(v0, v1, v2, int32_t(std::max(xmax - xmin, ymax - ymin) >> 4));
    constexpr int32_t kNear = 16 * 1024; // sub-pixels: 32-bit edge walks within this of the origin
    const bool near = xmin >= -kNear && xmax <= kNear && ymin >= -kNear && ymax <= kNear;
    return near ? scan_rows<int32_t>(v0, v1, v2, area2, int32_t(row0), int32_t(row1), int32_t(col0), int32_t(col1), clamp)
                : scan_rows<int64_t>(v0, v1, v2, area2, int32_t(row0), int32_t(row1), int32_t(col0), int32_t(col1), clamp);
}

// The rows of a larger triangle: each row's span from the three edge walks.
template <typename T>
Status Rasterizer::scan_rows(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2,
                             int32_t row0, int32_t row1, int32_t col0, int32_t col1, bool clamp) {
    const int64_t sy0 = int64_t(row0) * 16 + 8;
    EdgeWalk<T> edges[3];
    edges[0].start(v1, v2, sy0);
    edges[1].start(v2, v0, sy0);
    edges[2].start(v0, v1, sy0);
    // Attributes: exact gradients, then stepped in 32-bit modular arithmetic (exact wherever
    // the true value fits, i.e. inside the triangle) and clamped to the vertices' range.
    const int32_t vals[kAttributes][3] = {{v0.z, v1.z, v2.z}, {v0.shade, v1.shade, v2.shade}};
    Interp at[kAttributes];
    for (int k = 0; k < kAttributes; ++k) {
        const Plane pl(vals[k][0], vals[k][1], vals[k][2], v0, v1, v2, area2);
        at[k] = Interp(vals[k], pl.gx, pl.gy, pl.at(8 - v0.x, sy0 - v0.y));
    }

    for (int32_t y = row0; y <= row1; ++y) {
        T lo = col0, hi = col1;
        edges[0].clip(lo, hi);
        edges[1].clip(lo, hi);
        edges[2].clip(lo, hi);
        edges[0].next_row();
        edges[1].next_row();
        edges[2].next_row();
        if (lo > hi) {
            for (Interp& t : at) t.row += t.sy;
            continue;
        }
        if (Status s = shade(int32_t(y), int32_t(lo), int32_t(hi), at, clamp); !ok(s)) return s;
        for (Interp& t : at) t.row += t.sy;
    }
    return Status::Ok;
}

// Small triangles (most of a tessellated model on a handheld's screen): the triangle's pixel
// box in 32-bit arithmetic, edge functions and attributes stepped per pixel. Coverage is the
// same predicate as EdgeWalk's (the same pixels, top-left rule included). Attribute gradients
// come from one reciprocal of the area (2^-15 relative error: a fraction of a unit inside a
// triangle no thinner than a quarter of its box), or from exact divisions for slivers; values
// are clamped to the vertices' range either way.
Status Rasterizer::scan_small(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                              int64_t area2, int32_t row0, int32_t row1, int32_t col0, int32_t col1) {
    const int32_t ox = col0 * 16 + 8, oy = row0 * 16 + 8; // the first pixel's centre
    const bool clamp = needs_clamp(v0, v1, v2, kSmall);
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
    // One reciprocal of the doubled area (normalized to 16 bits), then every gradient by it.
    const uint32_t a = uint32_t(area2);
    const int bits = 32 - __builtin_clz(a);
    const int e = bits - 16;
    const uint32_t an = e >= 0 ? a >> e : a << -e;
    const int64_t recip = int64_t(recip31(an));
    const int shift = 31 + e - kFrac; // gradient in kFrac fixed point per sub-pixel unit
    // Thinner than a quarter of its box: exact gradients (eight divisions) instead.
    const int32_t bw = std::max({v0.x, v1.x, v2.x}) - std::min({v0.x, v1.x, v2.x});
    const int32_t bh = std::max({v0.y, v1.y, v2.y}) - std::min({v0.y, v1.y, v2.y});
    const bool sliver = int64_t(bw) * bh > 4 * area2;
    Interp at[kAttributes];
    const int32_t vals[kAttributes][3] = {{v0.z, v1.z, v2.z}, {v0.shade, v1.shade, v2.shade}};
    const int32_t y1 = v1.y - v0.y, y2 = v2.y - v0.y, x1 = v1.x - v0.x, x2 = v2.x - v0.x;
    for (int k = 0; k < kAttributes; ++k) {
        const int32_t A0 = vals[k][0], d1 = vals[k][1] - A0, d2 = vals[k][2] - A0;
        const int64_t numx = int64_t(d1) * y2 - int64_t(d2) * y1;
        const int64_t numy = int64_t(d2) * x1 - int64_t(d1) * x2;
        int64_t gx, gy;
        if (sliver) { // exact: the reciprocal's error would grow with the gradients
            gx = div_fast(numx * (int64_t(1) << kFrac), area2);
            gy = div_fast(numy * (int64_t(1) << kFrac), area2);
        } else {
            gx = shift >= 0 ? (numx * recip) >> shift : (numx * recip) << -shift;
            gy = shift >= 0 ? (numy * recip) >> shift : (numy * recip) << -shift;
        }
        at[k] = Interp(vals[k], gx, gy, (int64_t(A0) << kFrac) + gx * (8 - v0.x) + gy * (oy - v0.y));
    }
    for (int32_t y = row0; y <= row1; ++y) {
        // The row's span: the first pixel inside, then on while inside (a triangle is convex).
        int32_t e0 = ed[0].e, e1 = ed[1].e, e2 = ed[2].e, x = col0;
        for (; x <= col1 && (e0 | e1 | e2) < 0; ++x) e0 += ed[0].sx, e1 += ed[1].sx, e2 += ed[2].sx;
        const int32_t lo = x;
        for (; x <= col1 && (e0 | e1 | e2) >= 0; ++x) e0 += ed[0].sx, e1 += ed[1].sx, e2 += ed[2].sx;
        if (x > lo) {
            if (Status s = shade(y, lo, x - 1, at, clamp); !ok(s)) return s;
        }
        ed[0].e += ed[0].sy, ed[1].e += ed[1].sy, ed[2].e += ed[2].sy;
        for (Interp& t : at) t.row += t.sy;
    }
    return Status::Ok;
}

// Shades the pixels lo..hi of row y that pass the depth test and pushes them in runs.
Status Rasterizer::shade(int32_t y, int32_t lo, int32_t hi, const Interp* at, bool clamp) {
    uint32_t z = at[0].row + at[0].sx * uint32_t(lo), s = at[1].row + at[1].sx * uint32_t(lo);
    const uint32_t zs = at[0].sx, ss = at[1].sx;
    uint16_t* drow = &depth_[size_t(y) * width_];
    // Pixels go straight into a memory-mapped draw buffer, else into the line and out in runs.
    hal::Rgb565* line = fb_ ? fb_ + size_t(y) * width_ : line_.data();
    const hal::Rgb565* colour = palette_->colour;
    int32_t run = -1; // first column of the pending run of visible pixels
    if (!clamp) {
        // Alternate runs of hidden and of visible pixels; each visible run is pushed whole.
        uint16_t* d = drow + lo;
        uint16_t* const end = drow + hi + 1;
        hal::Rgb565* out = line + lo;
        while (d < end) {
            while (d < end && (int32_t(z) >> kFrac) >= int32_t(*d)) ++d, ++out, z += zs, s += ss;
            hal::Rgb565* const first = out;
            for (; d < end; ++d, ++out, z += zs, s += ss) {
                const int32_t zv = int32_t(z) >> kFrac;
                if (zv >= int32_t(*d)) break;
                *d = uint16_t(zv);
                *out = colour[int32_t(s) >> kFrac];
            }
            if (out > first) {
                if (Status st = flush(int32_t(first - line), int32_t(out - line), y); !ok(st)) return st;
            }
        }
        return Status::Ok;
    } else {
        for (int32_t x = lo; x <= hi; ++x, z += zs, s += ss) {
            const uint16_t zv = uint16_t(at[0].value(z));
            if (zv < drow[x]) {
                drow[x] = zv;
                line[x] = colour[at[1].value(s)];
                if (run < 0) run = x;
            } else if (run >= 0) {
                if (Status st = flush(run, x, y); !ok(st)) return st;
                run = -1;
            }
        }
    }
    if (run >= 0) return flush(run, hi + 1, y);
    return Status::Ok;
}

Status Rasterizer::line(const ScreenVertex& a, const ScreenVertex& b, hal::Rgb565 colour, uint16_t bias) {
    if (!in_guard(a) || !in_guard(b)) return Status::OutOfRange;
    fb_ = display_.draw_buffer();
    const int32_t x0 = a.x >> 4, y0 = a.y >> 4, x1 = b.x >> 4, y1 = b.y >> 4;
    const int32_t dx = x1 - x0, dy = y1 - y0;
    const int32_t n = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
    // 16.16 positions and depth, stepped once per pixel along the longer axis (within the guard
    // band |dx|, |dy| < 2^14 pixels, so the slopes divide in 32 bits).
    int32_t x = (x0 << 16) + 0x8000, y = (y0 << 16) + 0x8000;
    int32_t z = int32_t(a.z) << 8;
    const int32_t sx = n ? (dx << 16) / n : 0, sy = n ? (dy << 16) / n : 0;
    const int32_t sz = n ? (int32_t(b.z) - int32_t(a.z)) * 256 / n : 0;
    // Without a memory-mapped buffer, pixels that follow each other along a row go out as one span.
    int32_t run_x = 0, run_y = -1, run_n = 0;
    auto flush_run = [&]() {
        if (run_n == 0) return Status::Ok;
        const Status st = display_.fill_span(uint16_t(run_x), uint16_t(run_y), uint16_t(run_n), colour);
        run_n = 0;
        return st;
    };
    for (int32_t i = 0; i <= n; ++i, x += sx, y += sy, z += sz) {
        const int32_t px = x >> 16, py = y >> 16;
        if (px < 0 || py < 0 || px >= width_ || py >= height_) continue;
        int32_t zv = (z >> 8) - bias;
        zv = zv < 0 ? 0 : zv;
        uint16_t& d = depth_[size_t(py) * width_ + px];
        if (zv >= d) continue;
        d = uint16_t(zv);
        ++stats.pixels;
        if (fb_) {
            fb_[size_t(py) * width_ + px] = colour;
        } else if (py == run_y && px == run_x + run_n) {
            ++run_n;
        } else {
            if (Status st = flush_run(); !ok(st)) return st;
            run_x = px, run_y = py, run_n = 1;
        }
    }
    return flush_run();
}

Status Rasterizer::flush(int32_t from, int32_t to, int64_t y) {
    const uint16_t n = static_cast<uint16_t>(to - from);
    ++stats.spans;
    stats.pixels += n;
    if (fb_) return Status::Ok; // already in place
    return display_.push_span(uint16_t(from), uint16_t(y), &line_[from], n);
}

} // namespace facet::render
