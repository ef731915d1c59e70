#include "render/raster.h"

namespace facet::render {
namespace {

constexpr int kFrac = 12; // fractional bits of interpolated attributes

int64_t floor_div(int64_t a, int64_t b) { // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); } // b > 0

bool in_guard(const ScreenVertex& v) {
    return v.x >= -kGuardBand && v.x <= kGuardBand && v.y >= -kGuardBand && v.y <= kGuardBand;
}

// One edge p->q of a triangle with positive doubled area, ready for per-row bounds.
struct Edge {
    int64_t dx, dy, px, py, bias;

    Edge(const ScreenVertex& p, const ScreenVertex& q)
        : dx(q.x - p.x), dy(q.y - p.y), px(p.x), py(p.y)
        // Top-left rule: pixels exactly on a left edge (going up) or a top edge (horizontal,
        // going right) belong to this triangle; on other edges they belong to the neighbour.
        , bias((dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1) {}

    // Narrows [lo, hi] (pixel columns) to those whose centre is inside this edge on the row
    // whose centre is at sub-pixel `sy`.
    void clip_row(int64_t sy, int64_t& lo, int64_t& hi) const {
        // Inside: dx*(sy - py) - dy*(sx - px) - bias >= 0, i.e. -dy*sx + k >= 0.
        const int64_t k = dx * (sy - py) + dy * px - bias;
        if (dy == 0) {
            if (k < 0) hi = lo - 1;
        } else if (dy < 0) {
            const int64_t sx_min = ceil_div(-k, -dy);
            const int64_t x = ceil_div(sx_min - 8, 16);
            if (x > lo) lo = x;
        } else {
            const int64_t sx_max = floor_div(k, dy);
            const int64_t x = floor_div(sx_max - 8, 16);
            if (x < hi) hi = x;
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
        gx = (numx * (int64_t(1) << kFrac)) / area2;
        gy = (numy * (int64_t(1) << kFrac)) / area2;
    }
    int64_t at(int64_t dx, int64_t dy) const { return a0 + gx * dx + gy * dy; }
};

inline int32_t clamp_channel(int64_t v, int32_t max) {
    const int64_t c = v >> kFrac;
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
    const size_t n = size_t(width_) * height_;
    for (size_t i = 0; i < n; ++i) depth_[i] = 0xFFFF;
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
    const Edge edges[3] = {Edge(v1, v2), Edge(v2, v0), Edge(v0, v1)};
    const Plane z(v0.z, v1.z, v2.z, v0, v1, v2, area2);
    const Plane r(v0.r, v1.r, v2.r, v0, v1, v2, area2);
    const Plane g(v0.g, v1.g, v2.g, v0, v1, v2, area2);
    const Plane bl(v0.b, v1.b, v2.b, v0, v1, v2, area2);

    int32_t ymin = v0.y, ymax = v0.y, xmin = v0.x, xmax = v0.x;
    for (const ScreenVertex* v : {&v1, &v2}) {
        ymin = v->y < ymin ? v->y : ymin;
        ymax = v->y > ymax ? v->y : ymax;
        xmin = v->x < xmin ? v->x : xmin;
        xmax = v->x > xmax ? v->x : xmax;
    }
    int64_t row0 = ceil_div(ymin - 8, 16), row1 = floor_div(ymax - 8, 16);
    if (row0 < 0) row0 = 0;
    if (row1 > height_ - 1) row1 = height_ - 1;
    const int64_t col0 = ceil_div(xmin - 8, 16) < 0 ? 0 : ceil_div(xmin - 8, 16);
    const int64_t col1 = floor_div(xmax - 8, 16) > width_ - 1 ? width_ - 1 : floor_div(xmax - 8, 16);

    for (int64_t y = row0; y <= row1; ++y) {
        const int64_t sy = y * 16 + 8;
        int64_t lo = col0, hi = col1;
        for (const Edge& e : edges) e.clip_row(sy, lo, hi);
        if (lo > hi) continue;

        const int64_t sx = lo * 16 + 8;
        int64_t zf = z.at(sx - v0.x, sy - v0.y), rf = r.at(sx - v0.x, sy - v0.y);
        int64_t gf = g.at(sx - v0.x, sy - v0.y), bf = bl.at(sx - v0.x, sy - v0.y);
        const int64_t zs = z.gx * 16, rs = r.gx * 16, gs = g.gx * 16, bs = bl.gx * 16;

        uint16_t* drow = &depth_[size_t(y) * width_];
        int64_t run = -1; // first column of the pending run of visible pixels
        for (int64_t x = lo; x <= hi; ++x) {
            const uint16_t zv = static_cast<uint16_t>(clamp_channel(zf, 0xFFFF));
            if (zv < drow[x]) {
                drow[x] = zv;
                line_[x] = static_cast<hal::Rgb565>((clamp_channel(rf, 255) >> 3) << 11 |
                                                    (clamp_channel(gf, 255) >> 2) << 5 |
                                                    (clamp_channel(bf, 255) >> 3));
                if (run < 0) run = x;
            } else if (run >= 0) {
                const uint16_t n = static_cast<uint16_t>(x - run);
                if (Status s = display_.push_span(uint16_t(run), uint16_t(y), &line_[run], n);
                    !ok(s))
                    return s;
                ++stats.spans;
                stats.pixels += n;
                run = -1;
            }
            zf += zs;
            rf += rs;
            gf += gs;
            bf += bs;
        }
        if (run >= 0) {
            const uint16_t n = static_cast<uint16_t>(hi + 1 - run);
            if (Status s = display_.push_span(uint16_t(run), uint16_t(y), &line_[run], n); !ok(s))
                return s;
            ++stats.spans;
            stats.pixels += n;
        }
    }
    return Status::Ok;
}

} // namespace facet::render
