#pragma once
// Test harness for cdt/: heap-backed arenas of any size, face builders, and a one-call
// "triangulate and run the independent checker" helper.
#include "cdt/check.h"
#include "core/format.h"
#include "cdt/face.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace facet::cdt::test {

template <typename Index>
struct HostArena {
    std::vector<Vertex<Index>> vertices;
    std::vector<Triangle<Index>> triangles;
    std::vector<Index> work, order, minseq, ins;
    std::vector<uint32_t> keys;

    explicit HostArena(size_t v)
        : vertices(v), triangles(triangles_for(v)), work(work_for(v)), order(v), minseq(v), ins(v), keys(v) {}
    ArenaView<Index> view() { return {vertices, triangles, work, order, minseq, ins, keys}; }
};

struct Face {
    std::vector<Point> loop_points;
    std::vector<uint32_t> loop_sizes;
    std::vector<Point> interior;

    void add_loop(const std::vector<Point>& pts) {
        loop_points.insert(loop_points.end(), pts.begin(), pts.end());
        loop_sizes.push_back(uint32_t(pts.size()));
    }
    FaceInput input() const { return {loop_points, loop_sizes, interior}; }
    std::vector<Segment> segments() const {
        std::vector<Segment> s;
        size_t first = 0;
        for (uint32_t n : loop_sizes) {
            for (uint32_t j = 0; j < n; ++j) s.push_back({loop_points[first + j], loop_points[first + (j + 1) % n]});
            first += n;
        }
        return s;
    }
    size_t points() const { return loop_points.size() + interior.size(); }
};

// Axis-aligned rectangle loop with `per_side` points per side, counter-clockwise (or not).
std::vector<Point> rectangle(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int per_side, bool ccw = true);
// A random star polygon (20..20+max_outer vertices, radius 60k..100k) with up to 11 circular
// holes in separate cells and `points` scattered points, some outside: the random face of the
// face and stress tests.
Face random_face(uint32_t seed, int max_outer = 200, int points = 300);
// Regular polygon approximating a circle, integer-rounded, ccw or cw.
std::vector<Point> circle(int32_t cx, int32_t cy, int32_t r, int n, bool ccw);

template <typename Index>
::testing::AssertionResult check_cdt(const Cdt<Index>& cdt, const std::vector<Segment>& segs, bool inner) {
    std::vector<uint32_t> scratch(check_scratch_words(cdt.vertex_count(), cdt.triangle_count(), std::span<const Segment>(segs)));
    const Result r = check(cdt, std::span<const Segment>(segs), inner, std::span<uint32_t>(scratch));
    if (r.ok()) return ::testing::AssertionSuccess();
    char message[192];
    describe(r, message, sizeof message);
    return ::testing::AssertionFailure() << message;
}

// Triangulates `face` with a fresh arena sized for it and checks the result.
template <typename Index = uint32_t>
struct FaceRun {
    std::unique_ptr<HostArena<Index>> arena;
    std::unique_ptr<Cdt<Index>> cdt;
    Result result;         // what triangulate_face returned
    Status status;         // its code
    uint32_t inner = 0;    // inner triangles
};

template <typename Index = uint32_t>
FaceRun<Index> triangulate(const Face& face, LocateMode mode = LocateMode::Sequential, size_t extra = 16) {
    FaceRun<Index> r;
    r.arena = std::make_unique<HostArena<Index>>(face.points() + kBoxVertices + extra);
    r.cdt = std::make_unique<Cdt<Index>>(r.arena->view());
    r.result = triangulate_face(*r.cdt, face.input(), mode);
    r.status = r.result.status;
    r.inner = r.cdt->inner_count();
    return r;
}

} // namespace facet::cdt::test
