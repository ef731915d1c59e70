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

// The insertion order and where each walk starts (the paper's Fig. 17 comparison, plus the
// default). Every mode walks straight from a start vertex; they differ in order and start.
enum class LocateMode : uint8_t {
    Sequential,    // the paper: each loop point, then its segment; walks start at the previous
                   // vertex, the kd-tree gives a far loop's first point; interior points last
    KdTreeNearest, // the paper's order, every walk from the nearest inserted vertex (kd-tree)
    RandomOrder,   // all points shuffled, each walk from the previous; then the loops
    HilbertFirst,  // the default: all points along a Hilbert curve, each walk from the previous
                   // vertex; then the loops, whose segments are then mostly edges already.
                   // Avoids the paper order's flip cascades on long straight loops (docs/cdt.md)
};
constexpr LocateMode kDefaultLocateMode = LocateMode::HilbertFirst;

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
