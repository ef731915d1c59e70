// Rasterizer properties: exact coverage (top-left rule: shared edges drawn once, no gaps),
// depth order independent of draw order, culling, guard band, Gouraud end points, palettes.
#include "render/raster.h"

#include "hal/fake.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace facet;
using render::Rasterizer;
using render::ScreenVertex;

namespace {

// Counts how often each pixel is written, and keeps the last colour.
class CountingDisplay final : public hal::Display {
public:
    CountingDisplay(uint16_t w, uint16_t h) : w_(w), h_(h), count(size_t(w) * h), colour(size_t(w) * h) {}
    hal::DisplayInfo info() const override { return {w_, h_, hal::PixelFormat::Rgb565, 1}; }
    Status push_span(uint16_t x, uint16_t y, const hal::Rgb565* px, uint16_t n) override {
        if (n == 0 || y >= h_ || x + n > w_) {
            ++bad;
            return Status::OutOfRange;
        }
        for (uint16_t i = 0; i < n; ++i) {
            ++count[size_t(y) * w_ + x + i];
            colour[size_t(y) * w_ + x + i] = px[i];
        }
        return Status::Ok;
    }
    Status fill_span(uint16_t x, uint16_t y, uint16_t n, hal::Rgb565 c) override {
        std::vector<hal::Rgb565> px(n, c);
        return push_span(x, y, px.data(), n);
    }
    Status flip() override { return Status::Ok; }

    uint16_t w_, h_;
    std::vector<int> count;
    std::vector<hal::Rgb565> colour;
    int bad = 0;
};

struct Fixture {
    CountingDisplay display;
    std::vector<uint16_t> depth;
    std::vector<hal::Rgb565> line;
    Rasterizer raster;
    Fixture(uint16_t w, uint16_t h)
        : display(w, h), depth(size_t(w) * h), line(w), raster(display, depth, line) {
        raster.clear_depth();
    }
};

ScreenVertex v(int32_t x, int32_t y, uint16_t z = 100, uint8_t shade = 255) { return {x, y, z, shade}; }

// A palette whose colour is its own index: a pixel then shows the shade it was given.
const render::Palette& ramp() {
    static render::Palette p = [] {
        render::Palette r;
        for (int i = 0; i < 256; ++i) r.colour[i] = uint32_t(i);
        return r;
    }();
    return p;
}


} // namespace

TEST(Raster, RefusesBuffersSmallerThanTheDisplay) {
    CountingDisplay d(64, 32);
    std::vector<uint16_t> depth(64 * 31);
    std::vector<hal::Rgb565> line(64);
    Rasterizer r(d, depth, line);
    EXPECT_EQ(r.check(), Status::OutOfRange);
}

TEST(Raster, TwoTrianglesTileTheScreenExactlyOnce) {
    Fixture f(64, 48);
    const int32_t W = 64 * 16, H = 48 * 16;
    // Counter-clockwise on screen (y down): (0,0) -> (0,H) -> (W,H).
    ASSERT_EQ(f.raster.draw(v(0, 0), v(0, H), v(W, H), ramp()), Status::Ok);
    ASSERT_EQ(f.raster.draw(v(0, 0), v(W, H, 50), v(W, 0, 50), ramp()), Status::Ok);
    for (size_t i = 0; i < f.display.count.size(); ++i) ASSERT_EQ(f.display.count[i], 1) << i;
    EXPECT_EQ(f.display.bad, 0);
}

TEST(Raster, RandomMeshCoversEveryInteriorPixelExactlyOnce) {
    // A jittered lattice, each cell split in two: shared edges at every angle, and vertices
    // placed anywhere on the 1/16-pixel grid, including exactly on pixel centres.
    Fixture f(200, 150);
    std::mt19937 rng(7);
    constexpr int N = 12;
    int32_t px[N + 1][N + 1], py[N + 1][N + 1];
    for (int i = 0; i <= N; ++i) {
        for (int j = 0; j <= N; ++j) {
            const int jitter = (i > 0 && i < N && j > 0 && j < N) ? 60 : 0;
            std::uniform_int_distribution<int> d(-jitter, jitter);
            px[i][j] = 16 * 10 + i * 16 * 15 + d(rng);
            py[i][j] = 16 * 5 + j * 16 * 11 + d(rng);
            if ((i + j) % 5 == 0) { // snap some to pixel centres
                px[i][j] = (px[i][j] / 16) * 16 + 8;
                py[i][j] = (py[i][j] / 16) * 16 + 8;
            }
        }
    }
    for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) {
            const ScreenVertex a = v(px[i][j], py[i][j]), b = v(px[i + 1][j], py[i + 1][j]);
            const ScreenVertex c = v(px[i + 1][j + 1], py[i + 1][j + 1]), d = v(px[i][j + 1], py[i][j + 1]);
            // Screen-CCW: a (top-left) -> d (below) -> c -> b.
            ASSERT_EQ(f.raster.draw(a, d, c, ramp()), Status::Ok);
            ASSERT_EQ(f.raster.draw(a, c, b, ramp()), Status::Ok);
        }
    }
    // Pixels whose centre lies strictly inside the outer boundary (axis-aligned here).
    const int x0 = 10, x1 = 10 + N * 15, y0 = 5, y1 = 5 + N * 11;
    for (int y = 0; y < 150; ++y) {
        for (int x = 0; x < 200; ++x) {
            const int c = f.display.count[size_t(y) * 200 + x];
            ASSERT_LE(c, 1) << "overdraw at " << x << "," << y;
            const bool inside = x >= x0 && x < x1 && y >= y0 && y < y1;
            ASSERT_EQ(c, inside ? 1 : 0) << "pixel " << x << "," << y;
        }
    }
    EXPECT_EQ(f.raster.stats.culled, 0u);
}

TEST(Raster, NearerTriangleWinsWhateverTheOrder) {
    for (int order = 0; order < 2; ++order) {
        Fixture f(32, 32);
        const ScreenVertex nearA = v(0, 0, 10, 200), nearB = v(0, 512, 10, 200), nearC = v(512, 512, 10, 200);
        const ScreenVertex farA = v(0, 0, 900, 50), farB = v(0, 512, 900, 50), farC = v(512, 512, 900, 50);
        if (order == 0) {
            ASSERT_EQ(f.raster.draw(nearA, nearB, nearC, ramp()), Status::Ok);
            ASSERT_EQ(f.raster.draw(farA, farB, farC, ramp()), Status::Ok);
        } else {
            ASSERT_EQ(f.raster.draw(farA, farB, farC, ramp()), Status::Ok);
            ASSERT_EQ(f.raster.draw(nearA, nearB, nearC, ramp()), Status::Ok);
        }
        EXPECT_EQ(f.display.colour[20 * 32 + 5], 200) << "order " << order;
    }
}

TEST(Raster, BackFacesAreCulledAndDegenerateOnesSkipped) {
    Fixture f(16, 16);
    ASSERT_EQ(f.raster.draw(v(0, 0), v(200, 200), v(0, 200), ramp()), Status::Ok); // clockwise on screen
    ASSERT_EQ(f.raster.draw(v(0, 0), v(100, 100), v(200, 200), ramp()), Status::Ok); // collinear
    EXPECT_EQ(f.raster.stats.culled, 2u);
    for (int c : f.display.count) EXPECT_EQ(c, 0);
    ASSERT_EQ(f.raster.draw(v(0, 0), v(200, 200), v(0, 200), ramp(), render::Cull::None), Status::Ok);
    EXPECT_GT(f.raster.stats.pixels, 0u);
}

TEST(Raster, RefusesVerticesOutsideTheGuardBand) {
    Fixture f(16, 16);
    EXPECT_EQ(f.raster.draw(v(0, 0), v(0, 100), v(render::kGuardBand + 1, 100), ramp()), Status::OutOfRange);
    EXPECT_EQ(f.raster.stats.triangles, 0u);
}

TEST(Raster, GouraudReproducesVertexShadesAtVertexPixels) {
    Fixture f(64, 64);
    // Vertex a sits on a pixel centre where a left edge (a-b) meets a top edge (c-a), so the
    // top-left rule gives that pixel to this triangle and its shade is a's exactly.
    const ScreenVertex a = {8, 8, 100, 240}, b = {8, 62 * 16 + 8, 100, 40}, c = {62 * 16 + 8, 8, 100, 0};
    ASSERT_EQ(f.raster.draw(a, b, c, ramp()), Status::Ok);
    EXPECT_EQ(f.display.count[0], 1);
    EXPECT_EQ(f.display.colour[0], 240);
    // Pixels on b-c (a right edge) belong to the neighbour: b's and c's pixels are not drawn.
    EXPECT_EQ(f.display.count[size_t(62) * 64], 0);
    EXPECT_EQ(f.display.count[62], 0);
    // Midway down the left edge and along the top edge: the mean of the ends' shades; and every
    // shade along the top falls from a's to c's.
    EXPECT_NEAR(f.display.colour[size_t(31) * 64], 140, 2);
    EXPECT_NEAR(f.display.colour[31], 120, 2);
    for (int x = 1; x < 62; ++x) EXPECT_LE(f.display.colour[x], f.display.colour[x - 1]) << x;
}

TEST(Raster, PalettesScaleTheColourByTheShade) {
    render::Palette p;
    render::make_palette(p, 255, 128, 64);
    EXPECT_EQ(p.colour[0], hal::rgb565(0, 0, 0));
    EXPECT_EQ(p.colour[255], hal::rgb565(255, 128, 64));
    EXPECT_EQ(p.colour[128], hal::rgb565(128, 64, 32));
    Fixture f(16, 16);
    ASSERT_EQ(f.raster.draw(v(0, 0), v(0, 256), v(256, 256), p), Status::Ok);
    EXPECT_EQ(f.display.colour[15 * 16], hal::rgb565(255, 128, 64));
}

TEST(Raster, SamePixelsInPlaceAndThroughSpans) {
    // A display whose buffer is memory gets its pixels written in place; one behind a bus gets
    // them as spans. Random triangles and lines must come out identical either way.
    constexpr uint16_t W = 96, H = 80;
    hal::fake::Display direct(W, H, 1), spans(W, H, 1);
    spans.direct = false;
    std::vector<uint16_t> depth_a(W * H), depth_b(W * H);
    std::vector<hal::Rgb565> line_a(W), line_b(W);
    Rasterizer a(direct, depth_a, line_a), b(spans, depth_b, line_b);
    a.clear_depth();
    b.clear_depth();
    render::Palette pal;
    render::make_palette(pal, 200, 150, 90);
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> coord(-200, 16 * W + 200), shade(0, 255), z(0, 65535);
    for (int i = 0; i < 300; ++i) {
        ScreenVertex t[3];
        for (ScreenVertex& p : t) p = {coord(rng), coord(rng) * H / W, uint16_t(z(rng)), uint8_t(shade(rng))};
        ASSERT_EQ(a.draw(t[0], t[1], t[2], pal, render::Cull::None), Status::Ok);
        ASSERT_EQ(b.draw(t[0], t[1], t[2], pal, render::Cull::None), Status::Ok);
        if (i % 3 == 0) {
            ASSERT_EQ(a.line(t[0], t[1], 0x1234, 100), Status::Ok);
            ASSERT_EQ(b.line(t[0], t[1], 0x1234, 100), Status::Ok);
        }
    }
    EXPECT_EQ(direct.drawn(), spans.drawn());
    EXPECT_EQ(depth_a, depth_b);
    EXPECT_EQ(a.stats.pixels, b.stats.pixels);
    EXPECT_GT(spans.spans, 0u);
}

TEST(Raster, CoverageIsExactlyTheTopLeftRule) {
    // Random triangles, small and large, on and off the screen: the pixels drawn are exactly
    // those whose centre passes all three edge tests, with the top-left rule for centres on an
    // edge (evaluated here pixel by pixel, in 64 bits).
    constexpr uint16_t W = 120, H = 90;
    std::mt19937 rng(11);
    for (int trial = 0; trial < 400; ++trial) {
        Fixture f(W, H);
        const int span = trial % 2 ? 16 * 40 : 16 * 400; // small boxes, then large ones
        std::uniform_int_distribution<int> cx(-16 * 20, 16 * (W + 20)), cy(-16 * 20, 16 * (H + 20)), d(-span, span);
        const int ox = cx(rng), oy = cy(rng);
        ScreenVertex t[3];
        for (ScreenVertex& p : t) {
            p = v(ox + d(rng), oy + d(rng));
            if (trial % 5 == 0) p.x = (p.x / 16) * 16 + 8, p.y = (p.y / 16) * 16 + 8; // on pixel centres
            if (trial % 7 == 0) p.y = t[0].y;                                        // flat edges
        }
        ASSERT_EQ(f.raster.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
        int64_t area2 = int64_t(t[1].x - t[0].x) * (t[2].y - t[0].y) - int64_t(t[1].y - t[0].y) * (t[2].x - t[0].x);
        if (area2 == 0) continue;
        if (area2 < 0) std::swap(t[1], t[2]);
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x) {
                const int64_t sx = 16 * x + 8, sy = 16 * y + 8;
                bool inside = true;
                for (int e = 0; e < 3; ++e) {
                    const ScreenVertex& p = t[(e + 1) % 3];
                    const ScreenVertex& q = t[(e + 2) % 3];
                    const int64_t dx = q.x - p.x, dy = q.y - p.y;
                    const int64_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
                    inside = inside && dx * (sy - p.y) - dy * (sx - p.x) - bias >= 0;
                }
                ASSERT_EQ(f.display.count[size_t(y) * W + x], inside ? 1 : 0)
                    << "trial " << trial << " pixel " << x << "," << y;
            }
        }
    }
}
