#pragma once
// One face, start to finish (the paper's Steps 1-3): loops traced as constraints with the
// sequential Locate, interior points added in a spatially coherent (Hilbert) order, inner
// triangles kept by the flood fill.
#include "cdt/cdt.h"

#include <span>

namespace facet::cdt {

struct FaceInput {
    std::span<const Point> loop_points;   // every loop's points, loop after loop
    std::span<const uint32_t> loop_sizes; // points per loop; each loop closes on its first point
    std::span<const Point> interior;      // isolated points, in any order (outside ones are fine)
};

// How each point finds where to start its walk (the paper's Fig. 17 comparison).
enum class LocateMode : uint8_t {
    Sequential,    // from the previous vertex; the kd-tree only for a loop's first point
    KdTreeNearest, // from the nearest inserted vertex, for every point
    RandomOrder,   // all points in a shuffled order, each from the previous; constraints last
};

struct FaceReport {
    Status status = Status::Ok;
    uint32_t loop = 0;     // on failure: the loop (or loop count for interior points)
    uint32_t point = 0;    // and the point index within the input
    uint32_t inner = 0;    // inner triangles
};

// Triangulates a face into `cdt` (which it resets). On failure the report names the loop and
// point; the arena still holds a valid triangulation of what was inserted before.
template <typename Index>
Status triangulate_face(Cdt<Index>& cdt, const FaceInput& in, LocateMode mode, FaceReport& report);

extern template Status triangulate_face(Cdt<uint16_t>&, const FaceInput&, LocateMode, FaceReport&);
extern template Status triangulate_face(Cdt<uint32_t>&, const FaceInput&, LocateMode, FaceReport&);

// Hilbert curve index of (x, y) on a 2^16 x 2^16 grid (exposed for tests).
uint32_t hilbert_index(uint32_t x, uint32_t y);

} // namespace facet::cdt
