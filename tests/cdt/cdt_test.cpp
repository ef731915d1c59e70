// Cdt primitives: point and constraint insertion, degenerate and bad input, the flood fill.
// Every result goes through the independent checker.
#include "harness.h"

#include <cmath>
#include <cstring>
#include <random>

using namespace facet;
using namespace facet::cdt;
using namespace facet::cdt::test;

namespace {

template <typename Index>
struct Fixture {
    HostArena<Index> arena;
    Cdt<Index> cdt;
    std::vector<Segment> segs;
    explicit Fixture(size_t v = 256) : arena(v), cdt(arena.view()) { EXPECT_EQ(cdt.reset(), Status::Ok); }
    Index add(int32_t x, int32_t y) {
        Index v = kNone<Index>;
        EXPECT_EQ(cdt.insert_point({x, y}, v, kNone<Index>), Status::Ok);
        return v;
    }
    Status constrain(Index a, Index b) {
        const Status s = cdt.insert_constraint(a, b);
        if (ok(s)) segs.push_back({cdt.vertex(a).p, cdt.vertex(b).p});
        return s;
    }
    // Adds a closed loop as points + constraints.
    std::vector<Index> loop(const std::vector<Point>& pts) {
        std::vector<Index> ids;
        for (Point p : pts) ids.push_back(add(p.x, p.y));
        for (size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(constrain(ids[i], ids[(i + 1) % ids.size()]), Status::Ok);
        return ids;
    }
    uint32_t inner() const {
        uint32_t n = 0;
        for (Index t = 0; t < cdt.triangle_count(); ++t) n += cdt.triangle(t).inner();
        return n;
    }
};

} // namespace

TEST(Cdt, ResetGivesTheBox) {
    Fixture<uint16_t> f;
    EXPECT_EQ(f.cdt.vertex_count(), 4);
    EXPECT_EQ(f.cdt.triangle_count(), 2);
    EXPECT_TRUE(check_cdt(f.cdt, {}, false));
}

TEST(Cdt, RefusesArenasSmallerThanStated) {
    HostArena<uint16_t> small(16);
    small.work.resize(10);
    Cdt<uint16_t> cdt(small.view());
    EXPECT_EQ(cdt.reset(), Status::OutOfRange);
}

// The paper's Table 1 class: a CCW pentagon with 4 interior points gives 9 vertices and
// 11 inner triangles (5 + 2*4 - 2).
TEST(Cdt, PaperTable1Pentagon) {
    Fixture<uint16_t> f;
    f.loop({{0, 0}, {100, -20}, {160, 60}, {80, 130}, {-10, 90}});
    for (Point p : std::vector<Point>{{40, 30}, {90, 40}, {70, 90}, {20, 70}}) f.add(p.x, p.y);
    ASSERT_EQ(f.cdt.mark_inner(), Status::Ok);
    EXPECT_EQ(f.cdt.vertex_count() - kBoxVertices, 9);
    EXPECT_EQ(f.inner(), 11u);
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, true));
}

TEST(Cdt, DuplicatePointReturnsTheExistingVertex) {
    Fixture<uint16_t> f;
    const auto a = f.add(5, 5), b = f.add(5, 5);
    EXPECT_EQ(a, b);
    EXPECT_EQ(f.cdt.vertex_count(), 5);
    EXPECT_TRUE(check_cdt(f.cdt, {}, false));
}

TEST(Cdt, PointsOnEdgesAndCollinearRuns) {
    Fixture<uint16_t> f;
    for (int i = 0; i < 50; ++i) f.add(i * 10, 0);          // a collinear run
    for (int i = 0; i < 50; ++i) f.add(i * 10 + 5, 0);      // each exactly on an edge
    for (int i = 0; i < 30; ++i) f.add(i * 7 - 50, i * 7 - 50); // the diagonal
    EXPECT_EQ(f.cdt.vertex_count(), 4 + 50 + 50 + 30); // the diagonal misses every run point
    EXPECT_TRUE(check_cdt(f.cdt, {}, false));
}

TEST(Cdt, OutOfRangeIsRefusedAndChangesNothing) {
    Fixture<uint16_t> f;
    f.add(0, 0);
    uint16_t v;
    EXPECT_EQ(f.cdt.insert_point({kMaxCoord + 1, 0}, v, kNone<uint16_t>), Status::OutOfRange);
    EXPECT_EQ(f.cdt.insert_point({0, -kMaxCoord - 1}, v, kNone<uint16_t>), Status::OutOfRange);
    EXPECT_EQ(f.cdt.insert_point({kMaxCoord, -kMaxCoord}, v, kNone<uint16_t>), Status::Ok); // the limit itself
    EXPECT_EQ(f.cdt.insert_constraint(0, 4), Status::OutOfRange); // a box corner
    EXPECT_EQ(f.cdt.insert_constraint(4, 99), Status::OutOfRange);
    EXPECT_TRUE(check_cdt(f.cdt, {}, false));
}

TEST(Cdt, FullArenaSaysFullAndStaysValid) {
    Fixture<uint16_t> f(12); // 8 points after the box
    uint16_t v;
    int inserted = 0;
    Status last = Status::Ok;
    for (int i = 0; i < 20 && ok(last); ++i) {
        last = f.cdt.insert_point({i * 13 % 97, i * 31 % 89}, v, kNone<uint16_t>);
        inserted += ok(last);
    }
    EXPECT_EQ(last, Status::Full);
    EXPECT_EQ(inserted, 8);
    EXPECT_EQ(f.cdt.insert_point({0, 0}, v, kNone<uint16_t>), Status::Ok) << "a duplicate needs no room";
    EXPECT_TRUE(check_cdt(f.cdt, {}, false));
}

TEST(Cdt, ConstraintThroughVerticesIsSplitThere) {
    Fixture<uint16_t> f;
    std::vector<uint16_t> row;
    for (int i = 0; i <= 10; ++i) row.push_back(f.add(i * 100, 0));
    for (int i = 0; i < 10; ++i) { f.add(i * 100 + 50, 37); f.add(i * 100 + 50, -41); }
    ASSERT_EQ(f.constrain(row.front(), row.back()), Status::Ok);
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, false));
    // Each piece between consecutive row vertices is now a constrained edge.
    std::vector<Segment> pieces;
    for (int i = 0; i < 10; ++i) pieces.push_back({{i * 100, 0}, {i * 100 + 100, 0}});
    EXPECT_TRUE(check_cdt(f.cdt, pieces, false));
}

TEST(Cdt, LongConstraintAcrossALattice) {
    Fixture<uint32_t> f(2000);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) f.add(x * 10, y * 10);
    const auto a = f.add(-3, 1), b = f.add(397, 388); // crosses ~80 triangles, no lattice point on it
    ASSERT_EQ(f.constrain(a, b), Status::Ok);
    EXPECT_GT(f.cdt.stats().cavity_triangles, 40u);
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, false));
    ASSERT_EQ(f.constrain(b, a), Status::Ok); // the reverse direction merges to Both
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, false));
}

TEST(Cdt, OverlappingConstraintsMerge) {
    Fixture<uint16_t> f;
    const auto a = f.add(0, 0), b = f.add(100, 0), c = f.add(200, 0), d = f.add(300, 0);
    f.add(150, 50);
    f.add(150, -50);
    ASSERT_EQ(f.constrain(b, c), Status::Ok);
    ASSERT_EQ(f.constrain(a, d), Status::Ok); // covers b-c again, same direction
    ASSERT_EQ(f.constrain(a, d), Status::Ok); // twice
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, false));
}

TEST(Cdt, CrossingConstraintIsRefusedAndNothingChanges) {
    Fixture<uint16_t> f;
    const auto a = f.add(0, 0), b = f.add(100, 100), c = f.add(0, 100), d = f.add(100, 0);
    for (int i = 1; i < 5; ++i) f.add(i * 20, 50 + (i % 2) * 7);
    ASSERT_EQ(f.constrain(a, b), Status::Ok);
    const uint64_t flips = f.cdt.stats().flips;
    std::vector<Triangle<uint16_t>> before(f.arena.triangles.begin(), f.arena.triangles.begin() + f.cdt.triangle_count());
    EXPECT_EQ(f.cdt.insert_constraint(c, d), Status::Crossing);
    for (size_t t = 0; t < before.size(); ++t) {
        ASSERT_EQ(0, std::memcmp(&before[t], &f.arena.triangles[t], sizeof before[t])) << "triangle " << t << " changed";
    }
    EXPECT_EQ(f.cdt.stats().flips, flips);
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, false));
}

TEST(Cdt, ZeroLengthSegmentIsANoOp) {
    Fixture<uint16_t> f;
    const auto a = f.add(7, 7);
    EXPECT_EQ(f.cdt.insert_constraint(a, a), Status::Ok);
    EXPECT_TRUE(check_cdt(f.cdt, {}, false));
}

TEST(Cdt, PointOnAConstraintSplitsItKeepingFlags) {
    Fixture<uint16_t> f;
    f.loop({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
    f.add(50, 0);   // on a constrained edge
    f.add(100, 37); // on another
    f.add(50, 50);
    ASSERT_EQ(f.cdt.mark_inner(), Status::Ok);
    EXPECT_TRUE(check_cdt(f.cdt, f.segs, true));
}

TEST(Cdt, OpenOrReversedLoopIsReportedByTheFloodFill) {
    Fixture<uint16_t> f;
    const auto a = f.add(0, 0), b = f.add(100, 0), c = f.add(50, 80);
    ASSERT_EQ(f.constrain(a, b), Status::Ok);
    ASSERT_EQ(f.constrain(b, c), Status::Ok); // c -> a missing: the loop is open
    EXPECT_EQ(f.cdt.mark_inner(), Status::Degenerate);
    EXPECT_EQ(f.inner(), 0u);
}

TEST(Cdt, RandomPointsAreDelaunay) {
    for (int seed = 0; seed < 5; ++seed) {
        Fixture<uint32_t> f(3000);
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int32_t> d(-kMaxCoord, kMaxCoord);
        for (int i = 0; i < 2500; ++i) f.add(d(rng), d(rng));
        ASSERT_TRUE(check_cdt(f.cdt, {}, false)) << "seed " << seed;
    }
}

TEST(Cdt, DeviceIndexWidthHoldsItsCapacity) {
    // 16-bit indices: kNone = 65535, so at most 32,768 vertices (2V - 6 triangles < 65535).
    static_assert(triangles_for(32768) < 65535);
    EXPECT_EQ(sizeof(Triangle<uint16_t>), 14u);
    EXPECT_EQ(sizeof(Triangle<uint32_t>), 28u);
}

namespace {
// Points first, then every loop segment as a constraint, checking after each one.
void constraints_after_points(const Face& f) {
    HostArena<uint32_t> arena(f.points() + 20);
    Cdt<uint32_t> cdt(arena.view());
    ASSERT_EQ(cdt.reset(), Status::Ok);
    std::vector<uint32_t> ids;
    for (Point p : f.loop_points) {
        uint32_t v;
        ASSERT_EQ(cdt.insert_point(p, v, kNone<uint32_t>), Status::Ok);
        ids.push_back(v);
    }
    for (Point p : f.interior) {
        uint32_t v;
        ASSERT_EQ(cdt.insert_point(p, v, kNone<uint32_t>), Status::Ok);
    }
    std::vector<Segment> done;
    size_t first = 0;
    for (uint32_t size : f.loop_sizes) {
        for (uint32_t j = 0; j < size; ++j) {
            const uint32_t a = ids[first + j], b = ids[first + (j + 1) % size];
            ASSERT_EQ(cdt.insert_constraint(a, b), Status::Ok);
            done.push_back({cdt.vertex(a).p, cdt.vertex(b).p});
            ASSERT_TRUE(check_cdt(cdt, done, false)) << "after segment " << done.size();
        }
        first += size;
    }
    ASSERT_EQ(cdt.mark_inner(), Status::Ok);
    ASSERT_TRUE(check_cdt(cdt, done, true));
}
} // namespace

// Regression: segment 45->46 of this face crosses all four triangles around a vertex without
// passing through it, so the cavity's right chain is x, v, x with a slit edge v-x inside.
TEST(Cdt, CavityWithASlitEdgeAroundAVertex) { constraints_after_points(random_face(10)); }

TEST(Cdt, StressConstraintsAfterPoints) {
    for (uint32_t seed = 0; seed < 60; ++seed) {
        constraints_after_points(random_face(seed));
        if (HasFatalFailure()) FAIL() << "seed " << seed;
    }
}
