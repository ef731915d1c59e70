// Rasterizer properties: exact coverage (top-left rule: shared edges drawn once, no gaps),
// depth order independent of draw order, culling, guard band, Gouraud end points, palettes.
#include "render/fixed.h"
#include "render/raster.h"
#include "raster_internal.h" // (render/src: the small triangles' two ways, compared)

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

using namespace facet;
using render::Rasterizer;
using render::ScreenVertex;

namespace {

// A screen with its depth buffer, and for every pixel how many triangles covered it (each
// triangle is also drawn alone into a scratch target, whose changed depth is its coverage).
struct Fixture {
    uint16_t w, h;
    std::vector<Rgb565> colour;
    std::vector<uint16_t> depth;
    std::vector<int> count;
    std::vector<Rgb565> scratch_pixels;
    std::vector<uint16_t> scratch_depth;
    Rasterizer raster, alone;
    Fixture(uint16_t w_, uint16_t h_)
        : w(w_), h(h_), colour(size_t(w_) * h_), depth(size_t(w_) * h_), count(size_t(w_) * h_),
          scratch_pixels(size_t(w_) * h_), scratch_depth(size_t(w_) * h_),
          raster(render::Target{colour.data(), depth.data(), w_, h_, 0, h_}),
          alone(render::Target{scratch_pixels.data(), scratch_depth.data(), w_, h_, 0, h_}) {
        raster.clear_depth();
    }
    Status draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const render::Palette& p,
                render::Cull cull = render::Cull::Back) {
        alone.clear_depth();
        const Status s = alone.draw(a, b, c, p, cull);
        for (size_t i = 0; i < count.size(); ++i) count[i] += scratch_depth[i] != 0xFFFF;
        const Status t = raster.draw(a, b, c, p, cull);
        EXPECT_EQ(s, t);
        return t;
    }
};

ScreenVertex v(int32_t x, int32_t y, uint16_t z = 100, uint8_t shade = 255) { return {x, y, z, shade}; }

// A palette whose colour is its own index: a pixel then shows the shade it was given.
const render::Palette& ramp() {
    static render::Palette p = [] {
        render::Palette r;
        for (int i = 0; i < 256 + render::Palette::kPad; ++i) r.colour[i] = uint32_t(i < 256 ? i : 255);
        return r;
    }();
    return p;
}

} // namespace

TEST(Raster, TwoTrianglesTileTheScreenExactlyOnce) {
    Fixture f(64, 48);
    const int32_t W = 64 * 16, H = 48 * 16;
    // Counter-clockwise on screen (y down): (0,0) -> (0,H) -> (W,H).
    ASSERT_EQ(f.draw(v(0, 0), v(0, H), v(W, H), ramp()), Status::Ok);
    ASSERT_EQ(f.draw(v(0, 0), v(W, H, 50), v(W, 0, 50), ramp()), Status::Ok);
    for (size_t i = 0; i < f.count.size(); ++i) ASSERT_EQ(f.count[i], 1) << i;
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
            ASSERT_EQ(f.draw(a, d, c, ramp()), Status::Ok);
            ASSERT_EQ(f.draw(a, c, b, ramp()), Status::Ok);
        }
    }
    // Pixels whose centre lies strictly inside the outer boundary (axis-aligned here).
    const int x0 = 10, x1 = 10 + N * 15, y0 = 5, y1 = 5 + N * 11;
    for (int y = 0; y < 150; ++y) {
        for (int x = 0; x < 200; ++x) {
            const int c = f.count[size_t(y) * 200 + x];
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
            ASSERT_EQ(f.draw(nearA, nearB, nearC, ramp()), Status::Ok);
            ASSERT_EQ(f.draw(farA, farB, farC, ramp()), Status::Ok);
        } else {
            ASSERT_EQ(f.draw(farA, farB, farC, ramp()), Status::Ok);
            ASSERT_EQ(f.draw(nearA, nearB, nearC, ramp()), Status::Ok);
        }
        EXPECT_EQ(f.colour[20 * 32 + 5], 200) << "order " << order;
    }
}

TEST(Raster, BackFacesAreCulledAndDegenerateOnesSkipped) {
    Fixture f(16, 16);
    ASSERT_EQ(f.draw(v(0, 0), v(200, 200), v(0, 200), ramp()), Status::Ok); // clockwise on screen
    ASSERT_EQ(f.draw(v(0, 0), v(100, 100), v(200, 200), ramp()), Status::Ok); // collinear
    EXPECT_EQ(f.raster.stats.culled, 2u);
    for (int c : f.count) EXPECT_EQ(c, 0);
    ASSERT_EQ(f.draw(v(0, 0), v(200, 200), v(0, 200), ramp(), render::Cull::None), Status::Ok);
    EXPECT_GT(f.raster.stats.pixels, 0u);
}

TEST(Raster, RefusesVerticesOutsideTheGuardBand) {
    Fixture f(16, 16);
    EXPECT_EQ(f.draw(v(0, 0), v(0, 100), v(render::kGuardBand + 1, 100), ramp()), Status::OutOfRange);
    EXPECT_EQ(f.raster.stats.triangles, 0u);
}

TEST(Raster, GouraudReproducesVertexShadesAtVertexPixels) {
    Fixture f(64, 64);
    // Vertex a sits on a pixel centre where a left edge (a-b) meets a top edge (c-a), so the
    // top-left rule gives that pixel to this triangle and its shade is a's exactly.
    const ScreenVertex a = {8, 8, 100, 240}, b = {8, 62 * 16 + 8, 100, 40}, c = {62 * 16 + 8, 8, 100, 0};
    ASSERT_EQ(f.draw(a, b, c, ramp()), Status::Ok);
    EXPECT_EQ(f.count[0], 1);
    EXPECT_EQ(f.colour[0], 240);
    // Pixels on b-c (a right edge) belong to the neighbour: b's and c's pixels are not drawn.
    EXPECT_EQ(f.count[size_t(62) * 64], 0);
    EXPECT_EQ(f.count[62], 0);
    // Midway down the left edge and along the top edge: the mean of the ends' shades; and every
    // shade along the top falls from a's to c's.
    EXPECT_NEAR(f.colour[size_t(31) * 64], 140, 2);
    EXPECT_NEAR(f.colour[31], 120, 2);
    for (int x = 1; x < 62; ++x) EXPECT_LE(f.colour[x], f.colour[x - 1]) << x;
}

// A triangle of one shade (a plane's) takes a span loop of one colour (render/src/scan.cpp,
// flat_span), large or small: the same pixels and depths as the same triangle with its shade
// stepping, every pixel in the one colour.
TEST(Raster, ATriangleOfOneShadeDrawsTheSameDepthsInOneColour) {
    constexpr uint16_t W = 160, H = 120;
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> coord(-400, 16 * W + 400), z(0, 65535), small(-160, 160);
    int large = 0, little = 0;
    for (int trial = 0; trial < 600; ++trial) {
        ScreenVertex t[3];
        for (ScreenVertex& p : t) p = {coord(rng), coord(rng) * H / W, uint16_t(z(rng)), 100};
        if (trial % 2) { // a few pixels across (the small triangles' path)
            for (int k = 1; k < 3; ++k) t[k].x = t[0].x + small(rng), t[k].y = t[0].y + small(rng);
        }
        std::vector<Rgb565> flat_px(W * H, 0), shaded_px(W * H, 0);
        std::vector<uint16_t> flat_z(W * H), shaded_z(W * H);
        Rasterizer flat(render::Target{flat_px.data(), flat_z.data(), W, H, 0, H});
        Rasterizer shaded(render::Target{shaded_px.data(), shaded_z.data(), W, H, 0, H});
        flat.clear_depth(), shaded.clear_depth();
        ASSERT_EQ(flat.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
        t[1].shade = 180, t[2].shade = 30;
        ASSERT_EQ(shaded.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
        ASSERT_EQ(flat_z, shaded_z) << "trial " << trial;
        int drawn = 0;
        for (size_t i = 0; i < flat_z.size(); ++i) {
            if (flat_z[i] == 0xFFFF) continue;
            ++drawn;
            ASSERT_EQ(flat_px[i], Rgb565(100)) << "trial " << trial << " pixel " << i;
        }
        large += drawn > 400, little += drawn > 0 && drawn < 20;
    }
    EXPECT_GT(large, 100) << "larger triangles (their rows in place)";
    EXPECT_GT(little, 50) << "small ones";
}

TEST(Raster, ATallTriangleDrawsInColumnsWhatItDrawsInRows) {
    // A triangle taller than wide is scanned a column at a time; in bands of one row it is
    // always scanned in rows. Slivers and wider ones, shaded and of one shade, on and off the
    // screen's edges, vertices on pixel centres and edges on their rows and columns (ties):
    // the same depths and colours both ways.
    constexpr uint16_t W = 96, H = 120;
    std::mt19937 rng(29);
    std::uniform_int_distribution<int> x0(-100, 16 * W + 100), y0(-400, 16 * H / 3), width(1, 16 * 30),
        height(16 * 25, 16 * H + 400), z(200, 65000), shade(20, 230);
    int columns = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const int x = x0(rng), y = y0(rng), wd = width(rng) / (trial % 3 == 1 ? 8 : 1); // (a third slivers)
        ScreenVertex t[3] = {{x, y, uint16_t(z(rng)), uint8_t(shade(rng))},
                             {x + wd, y + height(rng) / 2, uint16_t(z(rng)), uint8_t(shade(rng))},
                             {x + width(rng) - 16 * 15, y + height(rng), uint16_t(z(rng)), uint8_t(shade(rng))}};
        if (trial % 4 == 0) {
            for (ScreenVertex& p : t) p.x = (p.x / 16) * 16 + 8, p.y = (p.y / 16) * 16 + 8; // on pixel centres
        }
        if (trial % 5 == 0) t[2].x = t[0].x;          // a vertical edge
        if (trial % 7 == 0) t[1].shade = t[2].shade = t[0].shade; // one shade
        std::vector<Rgb565> whole(W * H, 0), rows(W * H, 0), band(W);
        std::vector<uint16_t> whole_z(W * H), rows_z(W * H), band_z(W);
        Rasterizer all(render::Target{whole.data(), whole_z.data(), W, H, 0, H});
        all.clear_depth();
        ASSERT_EQ(all.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
        for (uint16_t r = 0; r < H; ++r) {
            Rasterizer one(render::Target{band.data(), band_z.data(), W, H, r, 1});
            one.clear_depth();
            std::fill(band.begin(), band.end(), 0);
            ASSERT_EQ(one.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
            std::copy(band.begin(), band.end(), rows.begin() + size_t(r) * W);
            std::copy(band_z.begin(), band_z.end(), rows_z.begin() + size_t(r) * W);
        }
        ASSERT_EQ(whole_z, rows_z) << "trial " << trial;
        ASSERT_EQ(whole, rows) << "trial " << trial;
        columns += std::count_if(whole_z.begin(), whole_z.end(), [](uint16_t d) { return d != 0xFFFF; }) > 0;
    }
    EXPECT_GT(columns, 300) << "triangles that drew";
}

TEST(Raster, PalettesScaleTheColourByTheShade) {
    render::Palette p;
    render::make_palette(p, 255, 128, 64);
    EXPECT_EQ(p.colour[0], rgb565(0, 0, 0));
    EXPECT_EQ(p.colour[255], rgb565(255, 128, 64));
    EXPECT_EQ(p.colour[128], rgb565(128, 64, 32));
    Fixture f(16, 16);
    ASSERT_EQ(f.draw(v(0, 0), v(0, 256), v(256, 256), p), Status::Ok);
    EXPECT_EQ(f.colour[15 * 16], rgb565(255, 128, 64));
}

TEST(Raster, SamePixelsInBandsAndOnTheWholeScreen) {
    // Partial rendering: the screen drawn band after band (each band its own small depth
    // buffer) must come out exactly as drawn at once, for bands of every height, with random
    // triangles large and small, on and off the screen, and lines.
    constexpr uint16_t W = 96, H = 80;
    render::Palette pal;
    render::make_palette(pal, 200, 150, 90);
    struct Item {
        ScreenVertex t[3];
        bool line;
    };
    std::vector<Item> items;
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> coord(-200, 16 * W + 200), shade(0, 255), z(0, 65535), small(-200, 200);
    for (int i = 0; i < 400; ++i) {
        Item it{};
        for (ScreenVertex& p : it.t) p = {coord(rng), coord(rng) * H / W, uint16_t(z(rng)), uint8_t(shade(rng))};
        if (i % 2) { // small ones (the pixel-box path)
            for (int k = 1; k < 3; ++k) it.t[k].x = it.t[0].x + small(rng), it.t[k].y = it.t[0].y + small(rng);
        }
        it.line = i % 3 == 0;
        items.push_back(it);
    }
    auto draw_all = [&](Rasterizer& r) {
        r.clear_depth();
        for (const Item& it : items) {
            ASSERT_EQ(r.draw(it.t[0], it.t[1], it.t[2], pal, render::Cull::None), Status::Ok);
            if (it.line) {
                ASSERT_EQ(r.line(it.t[0], it.t[1], 0x1234, 100), Status::Ok);
            }
        }
    };
    std::vector<Rgb565> whole(W * H, 0);
    std::vector<uint16_t> whole_depth(W * H);
    Rasterizer a(render::Target{whole.data(), whole_depth.data(), W, H, 0, H});
    draw_all(a);
    for (uint16_t band : {1, 7, 16, 33, 80}) {
        std::vector<Rgb565> screen(W * H, 0), pixels(size_t(W) * band);
        std::vector<uint16_t> screen_depth(W * H), depth(size_t(W) * band);
        for (uint16_t y0 = 0; y0 < H; y0 += band) {
            const uint16_t rows = uint16_t(std::min<int>(band, H - y0));
            std::fill(pixels.begin(), pixels.end(), 0);
            Rasterizer b(render::Target{pixels.data(), depth.data(), W, H, y0, rows});
            draw_all(b);
            std::copy(pixels.begin(), pixels.begin() + W * rows, screen.begin() + W * y0);
            std::copy(depth.begin(), depth.begin() + W * rows, screen_depth.begin() + W * y0);
        }
        EXPECT_EQ(screen, whole) << "bands of " << band;
        EXPECT_EQ(screen_depth, whole_depth) << "bands of " << band;
    }
}

// Checks the fixture's coverage of triangle t (drawn alone, without culling) against the rule:
// the pixels drawn are exactly those whose centre passes all three edge tests, with the
// top-left rule for centres on an edge (evaluated here pixel by pixel, in 64 bits).
void expect_top_left_coverage(const Fixture& f, ScreenVertex t[3], int trial) {
    int64_t area2 = int64_t(t[1].x - t[0].x) * (t[2].y - t[0].y) - int64_t(t[1].y - t[0].y) * (t[2].x - t[0].x);
    if (area2 == 0) return;
    if (area2 < 0) std::swap(t[1], t[2]);
    for (int y = 0; y < f.h; ++y) {
        for (int x = 0; x < f.w; ++x) {
            const int64_t sx = 16 * x + 8, sy = 16 * y + 8;
            bool inside = true;
            for (int e = 0; e < 3; ++e) {
                const ScreenVertex& p = t[(e + 1) % 3];
                const ScreenVertex& q = t[(e + 2) % 3];
                const int64_t dx = q.x - p.x, dy = q.y - p.y;
                const int64_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
                inside = inside && dx * (sy - p.y) - dy * (sx - p.x) - bias >= 0;
            }
            ASSERT_EQ(f.count[size_t(y) * f.w + x], inside ? 1 : 0) << "trial " << trial << " pixel " << x << "," << y;
        }
    }
}

TEST(Raster, CoverageIsExactlyTheTopLeftRule) {
    // Random triangles, small and large, on and off the screen.
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
        ASSERT_EQ(f.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
        expect_top_left_coverage(f, t, trial);
        if (HasFatalFailure()) return;
    }
}

TEST(Raster, ATriangleReachingTheGuardBandIsExactWhereOnlyACornerShows) {
    // Triangles as large as the guard band allows of which only a few pixels in a corner of
    // the screen show: what is on the screen is small, the triangle is not (its edge functions
    // need 64 bits, so it must not take the small triangles' 32-bit path).
    constexpr uint16_t W = 120, H = 90;
    constexpr int32_t G = render::kGuardBand;
    const int32_t cut[] = {16 * 3, 16 * 5 + 8, 16 * 12 + 3, 16 * 19};
    int trial = 0;
    for (int32_t c : cut) {
        // The half-plane x + y < c (a corner of c / 16 pixels) cut by a triangle reaching far
        // beyond the screen, then the same mirrored into the other three corners.
        const ScreenVertex tl[3] = {v(c + G / 2, -G / 2), v(-G / 2, c + G / 2), v(16 * W - G, 16 * H - G)};
        for (int mirror = 0; mirror < 4; ++mirror) {
            ScreenVertex tri[3];
            for (int k = 0; k < 3; ++k) {
                tri[k] = tl[k];
                if (mirror & 1) tri[k].x = 16 * W - tri[k].x;
                if (mirror & 2) tri[k].y = 16 * H - tri[k].y;
            }
            Fixture f(W, H);
            ScreenVertex t[3] = {tri[0], tri[1], tri[2]};
            ASSERT_EQ(f.draw(t[0], t[1], t[2], ramp(), render::Cull::None), Status::Ok);
            int drawn = 0;
            for (int k : f.count) drawn += k;
            EXPECT_GT(drawn, 0) << "trial " << trial;
            expect_top_left_coverage(f, t, trial++);
            if (HasFatalFailure()) return;
        }
    }
}

// hidden() is exact where it says so: a triangle it calls hidden changes no pixel and no depth
// when drawn, in whole screens and in bands; and it does not call every triangle hidden (the
// back faces of a cut solid are skipped with it, so a wrong "hidden" would lose pixels).
TEST(Raster, ATriangleCalledHiddenDrawsNothing) {
    constexpr uint16_t W = 96, H = 80;
    render::Palette pal;
    render::make_palette(pal, 200, 150, 90);
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> coord(-200, 16 * W + 200), z(0, 65535), small(-300, 300), near(0, 20000), shade(0, 255);
    int said_hidden = 0, said_shown = 0;
    for (uint16_t band : {H, uint16_t(17)}) {
        std::vector<Rgb565> px(size_t(W) * band);
        std::vector<uint16_t> depth(size_t(W) * band);
        for (uint16_t y0 = 0; y0 < H; y0 += band) {
            const uint16_t rows = uint16_t(std::min<int>(band, H - y0));
            Rasterizer r(render::Target{px.data(), depth.data(), W, H, y0, rows});
            r.clear_depth();
            std::mt19937 scene(5); // the same occluders in every band: near, large
            std::uniform_int_distribution<int> big(-400, 16 * W + 400);
            for (int i = 0; i < 12; ++i) {
                ScreenVertex t[3];
                for (ScreenVertex& p : t) p = {big(scene), big(scene) * H / W, uint16_t(near(scene)), 128};
                ASSERT_EQ(r.draw(t[0], t[1], t[2], pal, render::Cull::None), Status::Ok);
            }
            for (int i = 0; i < 300; ++i) {
                ScreenVertex t[3];
                t[0] = {coord(rng), coord(rng) * H / W, uint16_t(z(rng)), uint8_t(shade(rng))};
                for (int k = 1; k < 3; ++k) t[k] = {t[0].x + small(rng), t[0].y + small(rng), uint16_t(z(rng)), uint8_t(shade(rng))};
                const std::vector<Rgb565> px0 = px;
                const std::vector<uint16_t> depth0 = depth;
                const bool hidden = r.hidden(t[0], t[1], t[2]);
                ASSERT_EQ(r.draw(t[0], t[1], t[2], pal, render::Cull::None), Status::Ok);
                if (hidden) {
                    ASSERT_EQ(px, px0) << "triangle " << i << " was called hidden";
                    ASSERT_EQ(depth, depth0);
                    ++said_hidden;
                } else {
                    ++said_shown;
                }
            }
        }
    }
    EXPECT_GT(said_hidden, 50);
    EXPECT_GT(said_shown, 50);
}

// A splat: a square of size x size pixels around its centre's pixel, each depth-tested at the
// centre's depth and drawn where nearer, clipped to the screen and the band; a size out of
// range or a centre past the guard band draws nothing.
TEST(Raster, ASplatIsADepthTestedSquareClippedToTheBand) {
    constexpr uint16_t W = 20, H = 12;
    for (const uint16_t band : {H, uint16_t(5)}) {
        std::vector<Rgb565> screen(W * H, 0);
        for (uint16_t y0 = 0; y0 < H; y0 += band) {
            const uint16_t rows = uint16_t(std::min<int>(band, H - y0));
            std::vector<Rgb565> px(W * rows, 0);
            std::vector<uint16_t> depth(W * rows, 0xFFFF);
            if (3 >= y0 && 3 < y0 + rows) depth[size_t(3 - y0) * W + 10] = 100; // pixel (10, 3): nearer than the splats
            Rasterizer r(render::Target{px.data(), depth.data(), W, H, y0, rows});
            const auto at = [](int x, int y, uint16_t z) { return ScreenVertex{x * 16 + 8, y * 16 + 8, z, 0}; };
            EXPECT_EQ(r.splat(at(10, 4, 500), 3, 7), Status::Ok); // pixels 9..11 x 3..5
            EXPECT_EQ(r.splat(at(0, 11, 500), 4, 9), Status::Ok);  // pixels -1..2 x 10..13: clipped
            EXPECT_EQ(r.splat(at(5, 5, 500), 0, 3), Status::OutOfRange);
            EXPECT_EQ(r.splat(at(5, 5, 500), Rasterizer::kMaxSplat + 1, 3), Status::OutOfRange);
            EXPECT_EQ(r.splat({1 << 20, 0, 500, 0}, 2, 3), Status::OutOfRange);
            std::copy(px.begin(), px.end(), screen.begin() + W * y0);
        }
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                Rgb565 want = 0;
                if (x >= 9 && x <= 11 && y >= 3 && y <= 5 && !(x == 10 && y == 3)) want = 7;
                if (x <= 2 && y >= 10) want = 9;
                EXPECT_EQ(screen[size_t(y) * W + x], want) << x << "," << y << " band " << band;
            }
    }
}

// A point is the one-pixel line from a place to itself: the same pixel, depth (pulled toward
// the eye, at least 0) and test, on the screen, off it, in a band and outside it.
TEST(Raster, APointDrawsWhatALineFromItToItselfDraws) {
    constexpr uint16_t W = 16, H = 10;
    std::mt19937 rng(7);
    std::uniform_int_distribution<int32_t> pos(-40, 16 * 17), depth(0, 700);
    for (const uint16_t y0 : {uint16_t(0), uint16_t(4)}) {
        const uint16_t rows = y0 ? 3 : H;
        std::vector<Rgb565> px_line(W * rows, 0), px_point(W * rows, 0);
        std::vector<uint16_t> z_line(W * rows, 0xFFFF), z_point(W * rows, 0xFFFF);
        for (size_t i = 0; i < z_line.size(); i += 3) z_line[i] = z_point[i] = 300; // some nearer pixels already
        Rasterizer by_line(render::Target{px_line.data(), z_line.data(), W, H, y0, rows});
        Rasterizer by_point(render::Target{px_point.data(), z_point.data(), W, H, y0, rows});
        for (int k = 0; k < 2000; ++k) {
            const ScreenVertex c{pos(rng), pos(rng) * H / W, uint16_t(depth(rng)), 0};
            const Rgb565 colour = Rgb565(k & 0xFFFF);
            ASSERT_EQ(by_line.line(c, c, colour, 384), by_point.point(c, colour, 384));
        }
        EXPECT_EQ(px_line, px_point);
        EXPECT_EQ(z_line, z_point);
        EXPECT_EQ(by_line.stats.pixels, by_point.stats.pixels);
    }
    std::vector<Rgb565> px(W * H, 0);
    std::vector<uint16_t> z(W * H, 0xFFFF);
    Rasterizer r(render::Target{px.data(), z.data(), W, H, 0, H});
    EXPECT_EQ(r.point({1 << 20, 0, 5, 0}, 1, 0), Status::OutOfRange);
}

// Lines of every length and slope step as the 64-bit reciprocal division says (the short
// lines' 32-bit steps are the same values): each line drawn alone against a reference DDA.
TEST(Raster, LinesStepAsTheirReciprocalSays) {
    constexpr uint16_t W = 640, H = 480;
    std::vector<Rgb565> px(W * H);
    std::vector<uint16_t> z(W * H);
    Rasterizer r(render::Target{px.data(), z.data(), W, H, 0, H});
    std::mt19937 rng(11);
    std::uniform_int_distribution<int32_t> len(0, 300), pos(0, 16 * 300), depth(0, 65535);
    for (int k = 0; k < 3000; ++k) {
        const ScreenVertex a{16 * 170 + pos(rng) % 16, 16 * 90 + pos(rng) % 16, uint16_t(depth(rng)), 0};
        const int32_t n = len(rng), sign_x = rng() & 1 ? 1 : -1, sign_y = rng() & 1 ? 1 : -1;
        const int32_t other = n ? int32_t(rng() % uint32_t(n + 1)) : 0;
        const bool steep = rng() & 1;
        const ScreenVertex b{a.x + 16 * sign_x * (steep ? other : n), a.y + 16 * sign_y * (steep ? n : other) / 2,
                             uint16_t(depth(rng)), 0};
        std::fill(z.begin(), z.end(), uint16_t(0xFFFF));
        std::fill(px.begin(), px.end(), Rgb565(0));
        ASSERT_EQ(r.line(a, b, 1, 100), Status::Ok);
        // The reference: the DDA with each step divide(d << 16 (or 8), reciprocal(n)).
        const int32_t x0 = a.x >> 4, y0 = a.y >> 4, dx = (b.x >> 4) - x0, dy = (b.y >> 4) - y0;
        const int32_t m = std::max(std::abs(dx), std::abs(dy));
        int32_t x = (x0 << 16) + 0x8000, y = (y0 << 16) + 0x8000, zz = int32_t(a.z) << 8, sx = 0, sy = 0, sz = 0;
        if (m) {
            const render::Reciprocal q = render::reciprocal(uint32_t(m));
            sx = render::divide(int64_t(dx) << 16, q), sy = render::divide(int64_t(dy) << 16, q);
            sz = render::divide((int64_t(b.z) - a.z) << 8, q);
        }
        zz -= 100 << 8;
        std::vector<uint16_t> want(W * H, 0xFFFF);
        for (int32_t i = 0; i <= m; ++i, x += sx, y += sy, zz += sz) {
            const int32_t X = x >> 16, Y = y >> 16;
            if (X < 0 || X >= W || Y < 0 || Y >= H) continue;
            const uint16_t v = uint16_t(zz < 0 ? 0 : zz >> 8);
            uint16_t& w = want[size_t(Y) * W + X];
            if (v < w) w = v;
        }
        ASSERT_EQ(z, want) << "line " << k << " of length " << m;
    }
}

// A small triangle's rows' runs come out the same whether found by dividing (a core with a
// divider: the Cortex-M7, the host) or by walking the columns (the ARM926): 200,000 random
// triangles whose box is under kSmall pixels, slivers and single pixels among them, every row.
TEST(Raster, SmallTrianglesRunsAreTheSameDividedOrWalked) {
    namespace detail = render::detail;
    std::mt19937 rng(17);
    std::uniform_int_distribution<int32_t> base(0, 16 * 600), off(0, 16 * (detail::kSmall - 1)), pick(0, 3);
    uint32_t rows = 0, covered = 0;
    for (int k = 0; k < 200000; ++k) {
        ScreenVertex v[3];
        const int32_t bx = base(rng), by = base(rng);
        for (ScreenVertex& p : v) {
            const int32_t scale = pick(rng) == 0 ? 1 : 4; // some tiny ones (slivers between centres)
            p = {bx + off(rng) / scale, by + off(rng) / scale, 0, 0};
        }
        const int64_t area2 = render::doubled_area(v[0], v[1], v[2]);
        if (area2 == 0) continue;
        if (area2 < 0) std::swap(v[1], v[2]);
        int32_t lo[2] = {INT32_MAX, INT32_MAX}, hi[2] = {INT32_MIN, INT32_MIN}; // x, y
        for (const ScreenVertex& p : v) {
            lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x), lo[1] = std::min(lo[1], p.y), hi[1] = std::max(hi[1], p.y);
        }
        const int32_t col0 = render::subpixel::first_centre_from(lo[0]), col1 = render::subpixel::last_centre_to(hi[0]);
        const int32_t row0 = render::subpixel::first_centre_from(lo[1]), row1 = render::subpixel::last_centre_to(hi[1]);
        if (col1 < col0 || row1 < row0) continue; // no pixel centre in the box
        detail::SmallEdge ed[3];
        detail::small_edges(v[0], v[1], v[2], render::subpixel::centre(col0), render::subpixel::centre(row0), ed);
        int32_t walked[2 * detail::kSmall], divided[2 * detail::kSmall];
        const int32_t n = row1 - row0 + 1;
        const bool any_walked = detail::small_runs<false>(ed, n, col0, col1, walked);
        const bool any_divided = detail::small_runs<true>(ed, n, col0, col1, divided);
        ASSERT_EQ(any_walked, any_divided) << "triangle " << k;
        for (int32_t r = 0; r < n; ++r, ++rows) {
            const bool run = walked[2 * r + 1] > walked[2 * r];
            ASSERT_EQ(run, divided[2 * r + 1] > divided[2 * r]) << "triangle " << k << ", row " << r;
            if (!run) continue;
            ++covered;
            ASSERT_EQ(walked[2 * r], divided[2 * r]) << "triangle " << k << ", row " << r;
            ASSERT_EQ(walked[2 * r + 1], divided[2 * r + 1]) << "triangle " << k << ", row " << r;
        }
    }
    EXPECT_GT(covered, rows / 4);
}


// The ARM926's division (quotient_by_reciprocal: the reciprocal's estimate made exact) is the
// truncating division, on numerators and divisors of every size and sign the rasterizer
// passes it (32-bit ones), the extremes included.
TEST(Raster, QuotientsByReciprocalAreTheDivisions) {
    std::mt19937 rng(29);
    auto check = [](int32_t a, uint32_t d) {
        const int64_t want = int64_t(a) / int64_t(d);
        ASSERT_EQ(render::detail::quotient_by_reciprocal(a, d, render::reciprocal(d)), want) << a << " / " << d;
    };
    for (int k = 0; k < 2000000; ++k) {
        const uint32_t d = (rng() >> 1) >> (rng() % 31); // 1 .. 2^31 - 1, every size
        const int32_t a = int32_t(rng()) >> (rng() % 32);
        if (d != 0) check(a, d);
    }
    for (const uint32_t d : {1u, 2u, 3u, 5u, 7u, 12345u, 32767u, 32768u, 32769u, 65535u, 65536u, 65537u, 1u << 30, uint32_t(INT32_MAX)}) {
        for (const int32_t a : {0, 1, -1, int32_t(d - 1), int32_t(d), -int32_t(d), INT32_MAX, INT32_MIN, INT32_MIN + 1}) check(a, d);
    }
}
