// Whole faces through triangulate_face, in every Locate mode, each result checked by the
// independent checker (topology, Delaunay, constraints, inner set by winding number).
#include "harness.h"

#include <cmath>
#include <random>

using namespace facet;
using namespace facet::cdt;
using namespace facet::cdt::test;

namespace {

constexpr LocateMode kModes[] = {LocateMode::Sequential, LocateMode::KdTreeNearest, LocateMode::RandomOrder,
                                  LocateMode::HilbertFirst};
const char* name(LocateMode m) {
    switch (m) {
    case LocateMode::Sequential: return "sequential";
    case LocateMode::KdTreeNearest: return "kd-tree";
    case LocateMode::RandomOrder: return "random";
    case LocateMode::HilbertFirst: return "hilbert-first";
    }
    return "?";
}

// Triangulates in every mode, checks each, and returns the inner triangle count (equal in all).
template <typename Index = uint32_t>
uint32_t triangulate_all_modes(const Face& face) {
    uint32_t inner = 0;
    for (LocateMode m : kModes) {
        FaceRun<Index> r = triangulate<Index>(face, m);
        EXPECT_EQ(r.status, Status::Ok) << name(m) << ": " << status_name(r.status) << " at loop " << r.result.where.index << " point " << r.result.at.index;
        if (!ok(r.status)) return 0;
        EXPECT_TRUE(check_cdt(*r.cdt, face.segments(), true)) << name(m);
        if (m == LocateMode::Sequential) inner = r.inner;
        else EXPECT_EQ(r.inner, inner) << name(m) << ": the inner count is topological";
    }
    return inner;
}

// The paper's face (§4, Table 3): a rectangle with a circular hole, 110 constraint segments,
// and a grid of 66 interior points of which some fall in the hole.
Face paper_face() {
    Face f;
    std::vector<Point> outer;
    for (int i = 0; i < 16; ++i) outer.push_back({i * 1000, 0});
    for (int i = 0; i < 7; ++i) outer.push_back({16000, i * 1000});
    for (int i = 0; i < 16; ++i) outer.push_back({16000 - i * 1000, 7000});
    for (int i = 0; i < 7; ++i) outer.push_back({0, 7000 - i * 1000});
    f.add_loop(outer);                           // 46 segments
    f.add_loop(circle(8000, 3500, 2200, 64, false)); // 64 segments, clockwise: a hole
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 11; ++x) f.interior.push_back({700 + x * 1460, 600 + y * 1160});
    return f;
}

} // namespace

TEST(Face, PaperFace) {
    const Face f = paper_face();
    ASSERT_EQ(f.segments().size(), 110u);
    ASSERT_EQ(f.interior.size(), 66u);
    const uint32_t inner = triangulate_all_modes<uint16_t>(f);
    EXPECT_GT(inner, 110u);
    // Topology: inner triangles = boundary vertices + 2 * interior vertices - 2 + 2 * holes.
    uint32_t in_hole = 0;
    for (Point p : f.interior) in_hole += std::hypot(p.x - 8000.0, p.y - 3500.0) < 2200 * std::cos(M_PI / 64);
    EXPECT_EQ(inner, 110 + 2 * (66 - in_hole) - 2 + 2);
}

TEST(Face, RandomPolygonsWithHoles) {
    for (uint32_t seed = 0; seed < 30; ++seed) {
        triangulate_all_modes(random_face(seed));
        if (HasFailure()) FAIL() << "seed " << seed;
    }
}

TEST(Face, CollinearRunsOnEveryBoundary) {
    Face f;
    f.add_loop(rectangle(0, 0, 100000, 50000, 200)); // 800 points, 200 collinear per side
    f.add_loop(rectangle(20000, 20000, 30000, 30000, 50, false));
    for (int i = 1; i < 100; ++i) f.interior.push_back({i * 1000, 25000}); // a line through the hole
    for (int i = 1; i < 50; ++i) f.interior.push_back({i * 2000, 0});      // on the boundary itself
    triangulate_all_modes(f);
}

TEST(Face, CocircularAndExactLattice) {
    Face f;
    f.add_loop(rectangle(-2000, -2000, 2000, 2000, 8));
    // Every lattice point on x^2 + y^2 = 1625^2 (1625 = 5^3 * 13): many exactly cocircular.
    const int64_t R = 1625;
    for (int64_t x = -R; x <= R; ++x) {
        const int64_t y2 = R * R - x * x;
        const int64_t y = std::llround(std::sqrt(double(y2)));
        if (y * y == y2) {
            f.interior.push_back({int32_t(x), int32_t(y)});
            f.interior.push_back({int32_t(x), int32_t(-y)});
        }
    }
    for (int y = -19; y <= 19; ++y)
        for (int x = -19; x <= 19; ++x) f.interior.push_back({x * 100, y * 100}); // exact lattice
    triangulate_all_modes(f);
}

TEST(Face, Lattice317WithItsBoundaryAsLoop) {
    Face f;
    std::vector<Point> loop;
    const int n = 317;
    for (int i = 0; i < n - 1; ++i) loop.push_back({i, 0});
    for (int i = 0; i < n - 1; ++i) loop.push_back({n - 1, i});
    for (int i = 0; i < n - 1; ++i) loop.push_back({n - 1 - i, n - 1});
    for (int i = 0; i < n - 1; ++i) loop.push_back({0, n - 1 - i});
    f.add_loop(loop);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) f.interior.push_back({x, y}); // boundary ones are duplicates
    FaceRun<uint32_t> r = triangulate<uint32_t>(f);
    ASSERT_EQ(r.status, Status::Ok);
    EXPECT_EQ(r.cdt->vertex_count(), 4u + n * n);
    EXPECT_EQ(r.inner, 2u * (n - 1) * (n - 1));
    EXPECT_TRUE(check_cdt(*r.cdt, f.segments(), true));
}

TEST(Face, JitteredLattice) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int32_t> j(-3, 3);
    Face f;
    f.add_loop(rectangle(-10, -10, 1010, 1010, 20));
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 60; ++x) f.interior.push_back({x * 17 + j(rng), y * 17 + j(rng)});
    triangulate_all_modes(f);
}

TEST(Face, DuplicatePointsEverywhere) {
    Face f;
    f.add_loop({{0, 0}, {1000, 0}, {1000, 0}, {1000, 1000}, {0, 1000}, {0, 1000}, {0, 1000}}); // zero-length segments
    for (int i = 0; i < 3; ++i) {
        f.interior.push_back({500, 500});
        f.interior.push_back({1000, 0}); // a loop vertex again
        f.interior.push_back({0, 500});  // on the boundary
    }
    const uint32_t inner = triangulate_all_modes<uint16_t>(f);
    EXPECT_EQ(inner, 4u + 1); // 5 boundary vertices, 1 interior: 5 + 2 - 2
}

TEST(Face, LoopsTouchingAtAVertex) {
    Face f;
    f.add_loop(rectangle(0, 0, 300, 200, 3));
    f.add_loop({{100, 100}, {100, 150}, {150, 150}, {150, 100}}); // hole (clockwise)
    f.add_loop({{150, 50}, {150, 100}, {200, 100}, {200, 50}});   // hole touching the first at (150,100)
    f.add_loop({{0, 100}, {40, 130}, {40, 70}});                  // hole touching the outer loop mid-side
    f.add_loop({{300, 200}, {280, 140}, {250, 150}});             // hole touching the outer corner
    for (int y = 1; y < 20; ++y)
        for (int x = 1; x < 30; ++x) f.interior.push_back({x * 10 + 3, y * 10 + 3});
    triangulate_all_modes(f);
}

TEST(Face, IslandsInsideHolesAndPointsOutside) {
    Face f;
    f.add_loop(circle(0, 0, 100000, 90, true));
    f.add_loop(circle(0, 0, 60000, 70, false));  // hole
    f.add_loop(circle(0, 0, 30000, 50, true));   // island in the hole
    f.add_loop(circle(0, 0, 10000, 20, false));  // hole in the island
    std::mt19937 rng(9);
    std::uniform_int_distribution<int32_t> d(-150000, 150000);
    for (int i = 0; i < 2000; ++i) f.interior.push_back({d(rng), d(rng)});
    triangulate_all_modes(f);
}

TEST(Face, TouchingSquareHoles5000) {
    // A 100 x 100 checkerboard: the 5,000 dark squares are holes, each touching four others
    // at its corners; the board sits inside an outer square with a one-cell margin.
    Face f;
    const int n = 100, s = 100;
    f.add_loop(rectangle(-s, -s, (n + 1) * s, (n + 1) * s, 4));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            if ((x + y) % 2 == 0)
                f.add_loop({{x * s, y * s}, {x * s, (y + 1) * s}, {(x + 1) * s, (y + 1) * s}, {(x + 1) * s, y * s}});
    ASSERT_EQ(f.loop_sizes.size(), 5001u);
    FaceRun<uint32_t> r = triangulate<uint32_t>(f);
    ASSERT_EQ(r.status, Status::Ok) << status_name(r.status);
    EXPECT_TRUE(check_cdt(*r.cdt, f.segments(), true));
}

TEST(Face, CrossingLoopsAreReportedWithTheirPlace) {
    Face f;
    f.add_loop(rectangle(0, 0, 1000, 1000, 2));
    f.add_loop({{500, -100}, {600, 500}, {400, 500}}); // crosses the outer loop
    FaceRun<uint16_t> r = triangulate<uint16_t>(f);
    EXPECT_EQ(r.status, Status::Crossing);
    EXPECT_STREQ(r.result.where.kind, "loop");
    EXPECT_EQ(r.result.where.index, 1u);
    Face outer;
    outer.add_loop(rectangle(0, 0, 1000, 1000, 2));
    EXPECT_TRUE(check_cdt(*r.cdt, outer.segments(), false)) << "still valid: the outer loop, nothing of the crossing one";
}

TEST(Face, TooManyPointsForTheArenaIsFullNotACrash) {
    Face f;
    f.add_loop(rectangle(0, 0, 1000, 1000, 10));
    for (int i = 0; i < 100; ++i) f.interior.push_back({i * 7 + 1, i * 9 + 1});
    HostArena<uint16_t> arena(40);
    Cdt<uint16_t> cdt(arena.view());
    EXPECT_EQ(triangulate_face(cdt, f.input(), LocateMode::Sequential).status, Status::Full);
}

TEST(Face, InPiecesTheSameTriangulationAsAtOnce) {
    // FaceBuilder::run(units) stops after `units` insertions and goes on where it stopped: one
    // unit at a time must give the very same arrays as one call, in every mode.
    const Face f = random_face(5, 120, 200);
    for (LocateMode m : kModes) {
        FaceRun<uint32_t> whole = triangulate<uint32_t>(f, m);
        ASSERT_EQ(whole.status, Status::Ok) << name(m);
        HostArena<uint32_t> arena(f.points() + kBoxVertices + 16);
        Cdt<uint32_t> cdt(arena.view());
        FaceBuilder<uint32_t> b(cdt);
        ASSERT_TRUE(b.start(f.input(), m).ok()) << name(m);
        Result r;
        uint32_t pieces = 0;
        while ((r = b.run(1)).status == Status::Busy) ++pieces;
        ASSERT_TRUE(r.ok()) << name(m) << ": " << r.what;
        EXPECT_GE(pieces, f.points()) << name(m) << ": a piece per point at least";
        ASSERT_EQ(cdt.vertex_count(), whole.cdt->vertex_count()) << name(m);
        ASSERT_EQ(cdt.triangle_count(), whole.cdt->triangle_count()) << name(m);
        for (uint32_t t = 0; t < cdt.triangle_count(); ++t) {
            const Triangle<uint32_t>& a = cdt.triangle(t);
            const Triangle<uint32_t>& w = whole.cdt->triangle(t);
            ASSERT_TRUE(a.v[0] == w.v[0] && a.v[1] == w.v[1] && a.v[2] == w.v[2] && a.flags == w.flags) << name(m) << " triangle " << t;
        }
    }
}

TEST(Face, HilbertIndexStepsBetweenNeighbouringCells) {
    // On a 256 x 256 grid (the top 8 levels), cell k+1 of the curve is always next to cell k.
    std::vector<std::pair<int, int>> cell(1u << 16);
    for (uint32_t y = 0; y < 256; ++y)
        for (uint32_t x = 0; x < 256; ++x) cell[hilbert_index(x << 8, y << 8) >> 16] = {int(x), int(y)};
    for (size_t k = 1; k < cell.size(); ++k) {
        const int step = std::abs(cell[k].first - cell[k - 1].first) + std::abs(cell[k].second - cell[k - 1].second);
        ASSERT_EQ(step, 1) << "between curve cells " << k - 1 << " and " << k;
    }
    EXPECT_EQ(cell[0], std::make_pair(0, 0));
}

TEST(Face, HilbertIndexIsABijectionOnASmallGrid) {
    std::vector<bool> seen(1u << 16);
    for (uint32_t y = 0; y < 256; ++y)
        for (uint32_t x = 0; x < 256; ++x) {
            const uint32_t d = hilbert_index(x << 8, y << 8) >> 16;
            ASSERT_LT(d, 1u << 16);
            seen[d] = true;
        }
    uint32_t n = 0;
    for (bool b : seen) n += b;
    EXPECT_EQ(n, 1u << 16);
}
