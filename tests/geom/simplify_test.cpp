// Edge-collapse simplification and the distance between meshes (geom/host/simplify.h): the
// measure is exact where the answer is known; a closed surface stays closed, manifold and
// facing out down to its cap; a solid with holes keeps them down to the cap its topology
// allows, and goes under it by closing them, the measure seeing what that cost.
#include "simplify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using namespace facet::geom;

namespace {

// A sphere of radius r: `rings` x `segments` quads between the poles, wound outward.
TriangleMesh sphere(float r, uint32_t rings, uint32_t segments) {
    TriangleMesh m;
    m.points.push_back({0, 0, r});
    for (uint32_t i = 1; i < rings; ++i) {
        const float phi = float(M_PI) * float(i) / float(rings);
        for (uint32_t j = 0; j < segments; ++j) {
            const float theta = 2 * float(M_PI) * float(j) / float(segments);
            m.points.push_back({r * std::sin(phi) * std::cos(theta), r * std::sin(phi) * std::sin(theta), r * std::cos(phi)});
        }
    }
    m.points.push_back({0, 0, -r});
    const uint32_t south = uint32_t(m.points.size() - 1);
    auto at = [&](uint32_t ring, uint32_t j) { return 1 + (ring - 1) * segments + j % segments; };
    for (uint32_t j = 0; j < segments; ++j) {
        m.triangles.insert(m.triangles.end(), {0, at(1, j), at(1, j + 1)});
        m.triangles.insert(m.triangles.end(), {south, at(rings - 1, j + 1), at(rings - 1, j)});
        for (uint32_t i = 1; i + 1 < rings; ++i) {
            m.triangles.insert(m.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.insert(m.triangles.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return m;
}

// A flat sheet of n x n unit cells at z = 0 (facing +z), with every cell where `hole` says
// left out.
template <typename Hole>
TriangleMesh sheet(uint32_t n, Hole hole) {
    TriangleMesh m;
    for (uint32_t y = 0; y <= n; ++y)
        for (uint32_t x = 0; x <= n; ++x) m.points.push_back({float(x), float(y), 0});
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            if (hole(x, y)) continue;
            const uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
        }
    }
    return welded(m);
}

// A slab n x n x 1 of unit cells with the cells `hole` says cut through, closed and wound out.
template <typename Hole>
TriangleMesh slab(uint32_t n, Hole hole) {
    TriangleMesh m;
    auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { // a b c d counter-clockwise seen from outside
        const uint32_t k = uint32_t(m.points.size());
        m.points.insert(m.points.end(), {a, b, c, d});
        m.triangles.insert(m.triangles.end(), {k, k + 1, k + 2, k, k + 2, k + 3});
    };
    auto solid = [&](int x, int y) { return x >= 0 && y >= 0 && x < int(n) && y < int(n) && !hole(uint32_t(x), uint32_t(y)); };
    for (int y = 0; y < int(n); ++y) {
        for (int x = 0; x < int(n); ++x) {
            if (!solid(x, y)) continue;
            const float X = float(x), Y = float(y);
            quad({X, Y, 1}, {X + 1, Y, 1}, {X + 1, Y + 1, 1}, {X, Y + 1, 1}); // top
            quad({X, Y, 0}, {X, Y + 1, 0}, {X + 1, Y + 1, 0}, {X + 1, Y, 0}); // bottom
            if (!solid(x, y - 1)) quad({X, Y, 0}, {X + 1, Y, 0}, {X + 1, Y, 1}, {X, Y, 1});
            if (!solid(x, y + 1)) quad({X + 1, Y + 1, 0}, {X, Y + 1, 0}, {X, Y + 1, 1}, {X + 1, Y + 1, 1});
            if (!solid(x - 1, y)) quad({X, Y + 1, 0}, {X, Y, 0}, {X, Y, 1}, {X, Y + 1, 1});
            if (!solid(x + 1, y)) quad({X + 1, Y, 0}, {X + 1, Y + 1, 0}, {X + 1, Y + 1, 1}, {X + 1, Y, 1});
        }
    }
    return welded(m);
}

// V - E + F.
int euler(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> sides;
    for (size_t t = 0; t < m.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) sides[std::minmax(m.triangles[t + k], m.triangles[t + (k + 1) % 3])] = 1;
    return int(m.points.size()) - int(sides.size()) + int(m.triangle_count());
}

// Every side of a closed, oriented, manifold surface is used once each way.
bool closed_and_oriented(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> sides;
    for (size_t t = 0; t < m.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) ++sides[{m.triangles[t + k], m.triangles[t + (k + 1) % 3]}];
    for (const auto& [side, n] : sides)
        if (n != 1 || sides.count({side.second, side.first}) == 0 || sides.at({side.second, side.first}) != 1) return false;
    return true;
}

} // namespace

TEST(Simplify, TheDistanceBetweenMeshesIsExactWhereItIsKnown) {
    const TriangleMesh plane = sheet(4, [](uint32_t, uint32_t) { return false; });
    TriangleMesh lifted = plane;
    for (Vec3& p : lifted.points) p.z = 0.5f;
    EXPECT_FLOAT_EQ(farthest(plane, lifted), 0.5f);
    EXPECT_NEAR(farthest(plane, plane), 0.0f, 1e-6f);
    // A sheet twice as wide reaches 4 beyond the small one's side: its far corner (8, 8) is
    // 4 sqrt 2 from the small one's (4, 4); the small one lies wholly on the large one.
    const TriangleMesh large = sheet(8, [](uint32_t, uint32_t) { return false; });
    EXPECT_NEAR(farthest(large, plane), 4 * std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(farthest(plane, large), 0.0f, 1e-6f);
}

TEST(Simplify, AClosedSurfaceStaysClosedAndFacingOutDownToItsCap) {
    const TriangleMesh round = welded(sphere(10, 24, 48));
    ASSERT_TRUE(closed_and_oriented(round));
    for (const uint32_t cap : {1000u, 200u, 40u}) {
        const TriangleMesh coarse = simplified(round, cap);
        EXPECT_LE(coarse.triangle_count(), cap);
        EXPECT_GE(coarse.triangle_count(), cap * 9 / 10) << "stops at the cap, not far below it";
        EXPECT_TRUE(closed_and_oriented(coarse)) << cap;
        for (size_t t = 0; t < coarse.triangles.size(); t += 3) {
            const Vec3 a = coarse.points[coarse.triangles[t]], b = coarse.points[coarse.triangles[t + 1]], c = coarse.points[coarse.triangles[t + 2]];
            EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0) << "triangle " << t / 3 << " faces out, at cap " << cap;
        }
        // The error both ways, within three times what as many equal triangles would stray:
        // each of area 4 pi r^2 / n, its corners sqrt(s^2 / 3) from its middle (s its side),
        // its middle r - sqrt(r^2 - that^2) inside the sphere.
        const float strays = std::max(farthest(round, coarse), farthest(coarse, round));
        const float side2 = 16 * float(M_PI) * 100 / (std::sqrt(3.0f) * float(coarse.triangle_count()));
        const float even = 10 - std::sqrt(100 - side2 / 3);
        EXPECT_LT(strays, 3 * even) << cap;
        EXPECT_GT(strays, 0) << cap;
    }
}

TEST(Simplify, ASolidKeepsItsHolesUntilTheCapAsksForFewerTrianglesThanTheyTake) {
    // A 17 x 17 x 1 slab with 16 square holes through it: genus 16, so V - E + F = -30, and
    // at least 2V + 60 triangles.
    const TriangleMesh holed = slab(17, [](uint32_t x, uint32_t y) { return x % 4 == 2 && y % 4 == 2; });
    ASSERT_TRUE(closed_and_oriented(holed));
    ASSERT_EQ(euler(holed), -30);
    const TriangleMesh kept = simplified(holed, 400);
    EXPECT_LE(kept.triangle_count(), 400u);
    EXPECT_TRUE(closed_and_oriented(kept));
    EXPECT_EQ(euler(kept), -30) << "every hole still there";
    EXPECT_LT(std::max(farthest(holed, kept), farthest(kept, holed)), 1e-4f) << "flat faces stay flat: nothing strays";
    // Under what 16 holes take: some close, and what that costs is measured.
    const TriangleMesh closed = simplified(holed, 40);
    EXPECT_LE(closed.triangle_count(), 40u);
    EXPECT_GT(euler(closed), -30);
    EXPECT_GT(std::max(farthest(holed, closed), farthest(closed, holed)), 0.1f);
    for (const Vec3& p : closed.points) { // (within the slab's box: the corners' planes hold them)
        EXPECT_TRUE(p.x >= -1e-4f && p.x <= 17 + 1e-4f && p.y >= -1e-4f && p.y <= 17 + 1e-4f && p.z >= -1e-4f && p.z <= 1 + 1e-4f)
            << p.x << " " << p.y << " " << p.z;
    }
}
