#include "render/raster.h"

#include <cstdint>

namespace facet::render {
namespace {

constexpr int kFrac = 12; // fractional bits of interpolated attributes

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
struct EdgeWalk {
    enum class Side : uint8_t { Left, Right, Flat } side;
    int64_t q = 0, r = 0, s = 1, dq = 0, dr = 0; // Left/Right: bound = t/s; Flat: q = k

    void start(const ScreenVertex& p, const ScreenVertex& e, int64_t sy) {
        const int64_t dx = e.x - p.x, dy = e.y - p.y;
        const int64_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
        const int64_t k = dx * (sy - p.y) + dy * p.x - bias; // inside: -dy*sx + k >= 0
        int64_t t, step;
        if (dy == 0) {
            side = Side::Flat;
            q = k;
            dq = 16 * dx;
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
        q = floor_div(t, s);
        r = t - q * s;
        dq = floor_div(step, s);
        dr = step - dq * s;
    }

    // Narrows [lo, hi] (pixel columns) for the current row.
    void clip(int64_t& lo, int64_t& hi) const {
        switch (side) {
        case Side::Flat:
            if (q < 0) hi = lo - 1;
            break;
        case Side::Left: { // first column whose centre 16x+8 >= ceil(t/s)
            const int64_t x = (q + (r != 0) + 7) >> 4;
            if (x > lo) lo = x;
            break;
        }
        case Side::Right: { // last column whose centre 16x+8 <= floor(t/s)
            const int64_t x = (q - 8) >> 4;
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

// One attribute's walk along a span, in 32 bits.
struct SpanValue {
    int32_t v, step;
    bool in_range; // start and end both within [0, max]: no clamping needed along the span

    SpanValue(int64_t start, int64_t gx, int64_t n, int32_t max) {
        constexpr int64_t kLimit = int64_t(1) << 29; // v + step never overflows 32 bits
        int64_t st = gx * 16;
        st = st > kLimit ? kLimit : (st < -kLimit ? -kLimit : st);
        const int64_t end = start + st * (n - 1);
        const int64_t top = (int64_t(max) << kFrac) | ((1 << kFrac) - 1);
        in_range = start >= 0 && start <= top && end >= 0 && end <= top;
        v = static_cast<int32_t>(start < -kLimit ? -kLimit : (start > kLimit ? kLimit : start));
        step = static_cast<int32_t>(st);
    }
};

inline int32_t clamp_channel(int32_t v, int32_t max) {
    const int32_t c = v >> kFrac;
    return c < 0 ? 0 : (c > max ? max : static_cast<int32_t>(c));
}

} // namespace

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

Status Rasterizer::draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                        Cull cull) {
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

    const int64_t sy0 = row0 * 16 + 8;
    EdgeWalk edges[3];
    edges[0].start(v1, v2, sy0);
    edges[1].start(v2, v0, sy0);
    edges[2].start(v0, v1, sy0);
    const Plane pz(v0.z, v1.z, v2.z, v0, v1, v2, area2);
    const Plane pr(v0.r, v1.r, v2.r, v0, v1, v2, area2);
    const Plane pg(v0.g, v1.g, v2.g, v0, v1, v2, area2);
    const Plane pb(v0.b, v1.b, v2.b, v0, v1, v2, area2);

    for (int64_t y = row0; y <= row1; ++y) {
        int64_t lo = col0, hi = col1;
        edges[0].clip(lo, hi);
        edges[1].clip(lo, hi);
        edges[2].clip(lo, hi);
        edges[0].next_row();
        edges[1].next_row();
        edges[2].next_row();
        if (lo > hi) continue;

        const int64_t dx = lo * 16 + 8 - v0.x, dy = y * 16 + 8 - v0.y, n = hi - lo + 1;
        SpanValue z(pz.at(dx, dy), pz.gx, n, 0xFFFF), r(pr.at(dx, dy), pr.gx, n, 255);
        SpanValue g(pg.at(dx, dy), pg.gx, n, 255), b(pb.at(dx, dy), pb.gx, n, 255);
        const bool fast = z.in_range && r.in_range && g.in_range && b.in_range;

        uint16_t* drow = &depth_[size_t(y) * width_];
        hal::Rgb565* line = line_.data();
        const int32_t x0 = static_cast<int32_t>(lo), x1 = static_cast<int32_t>(hi);
        int32_t run = -1; // first column of the pending run of visible pixels
        for (int32_t x = x0; x <= x1; ++x) {
            const uint16_t zv = fast ? static_cast<uint16_t>(z.v >> kFrac)
                                     : static_cast<uint16_t>(clamp_channel(z.v, 0xFFFF));
            if (zv < drow[x]) {
                drow[x] = zv;
                line[x] = fast ? static_cast<hal::Rgb565>(((r.v >> (kFrac + 3)) << 11) |
                                                          ((g.v >> (kFrac + 2)) << 5) |
                                                          (b.v >> (kFrac + 3)))
                               : static_cast<hal::Rgb565>((clamp_channel(r.v, 255) >> 3) << 11 |
                                                          (clamp_channel(g.v, 255) >> 2) << 5 |
                                                          (clamp_channel(b.v, 255) >> 3));
                if (run < 0) run = x;
            } else if (run >= 0) {
                if (Status s = flush(run, x, y); !ok(s)) return s;
                run = -1;
            }
            z.v += z.step;
            r.v += r.step;
            g.v += g.step;
            b.v += b.step;
        }
        if (run >= 0) {
            if (Status s = flush(run, x1 + 1, y); !ok(s)) return s;
        }
    }
    return Status::Ok;
}

Status Rasterizer::line(const ScreenVertex& a, const ScreenVertex& b, hal::Rgb565 colour, uint16_t bias) {
    if (!in_guard(a) || !in_guard(b)) return Status::OutOfRange;
    const int32_t x0 = a.x >> 4, y0 = a.y >> 4, x1 = b.x >> 4, y1 = b.y >> 4;
    const int32_t dx = x1 - x0, dy = y1 - y0;
    const int32_t n = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
    // 16.16 positions and depth, stepped once per pixel along the longer axis.
    int32_t x = (x0 << 16) + 0x8000, y = (y0 << 16) + 0x8000;
    int32_t z = int32_t(a.z) << 8;
    const int32_t sx = n ? int32_t((int64_t(dx) << 16) / n) : 0, sy = n ? int32_t((int64_t(dy) << 16) / n) : 0;
    const int32_t sz = n ? (int32_t(b.z) - int32_t(a.z)) * 256 / n : 0;
    for (int32_t i = 0; i <= n; ++i, x += sx, y += sy, z += sz) {
        const int32_t px = x >> 16, py = y >> 16;
        if (px < 0 || py < 0 || px >= width_ || py >= height_) continue;
        int32_t zv = (z >> 8) - bias;
        zv = zv < 0 ? 0 : zv;
        uint16_t& d = depth_[size_t(py) * width_ + px];
        if (zv >= d) continue;
        d = uint16_t(zv);
        ++stats.pixels;
        if (Status s = display_.fill_span(uint16_t(px), uint16_t(py), 1, colour); !ok(s)) return s;
    }
    return Status::Ok;
}

Status Rasterizer::flush(int32_t from, int32_t to, int64_t y) {
    const uint16_t n = static_cast<uint16_t>(to - from);
    ++stats.spans;
    stats.pixels += n;
    return display_.push_span(uint16_t(from), uint16_t(y), &line_[from], n);
}

} // namespace facet::render
