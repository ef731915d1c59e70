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

// A face triangulated a bounded amount at a time, so a caller can do other work between
// pieces (a viewer's frames and input):
//
//   FaceBuilder<uint16_t> b(cdt);
//   Result r = b.start(input, kDefaultLocateMode);   // checks, orders the points, resets cdt
//   while (r.ok() && (r = b.run(256)).status == Status::Busy) { /* something else */ }
//
// run(units) inserts up to `units` points or constraints (the flood fill at the end counts as
// one) and returns Busy while work remains, Ok when done. On failure the result names the loop
// and the point (its index in the input), and a refused segment (Crossing) is kept in
// refused(); the arena still holds a valid triangulation of what was inserted before. The
// input's spans must stay valid until the end.
template <typename Index>
class FaceBuilder {
public:
    explicit FaceBuilder(Cdt<Index>& cdt) : cdt_(cdt) {}
    Result start(const FaceInput& in, LocateMode mode);
    Result run(uint32_t units);
    uint32_t used() const { return used_; } // the units the last run() spent
    Point point(uint32_t i) const; // input point i (loop points, then interior ones)
    // The loop segment the last failure refused: its first point and the next one along its
    // loop (input indices); {kNoPoint, kNoPoint} when the failure was no segment's.
    struct Segment {
        uint32_t from, to;
    };
    static constexpr uint32_t kNoPoint = UINT32_MAX;
    Segment refused() const { return refused_; }

private:
    enum class Stage : uint8_t { Points, Constraints, Inner, Done, Failed };
    Cdt<Index>& cdt_;
    FaceInput in_;
    LocateMode mode_ = kDefaultLocateMode;
    Stage stage_ = Stage::Failed;
    uint32_t n_loop_ = 0, n_ = 0;
    uint32_t k_ = 0, loop_ = 0, loop_first_ = 0; // the next point by rank; its loop (paper's modes)
    uint32_t cl_ = 0, cj_ = 0, cfirst_ = 0;        // the next constraint: loop, point, loop's first
    bool tree_built_ = false;
    uint32_t used_ = 0;
    Segment refused_{kNoPoint, kNoPoint};
    Result result_ = Result::fail(Status::Busy, "not started");
};

extern template class FaceBuilder<uint16_t>;
extern template class FaceBuilder<uint32_t>;

// The whole face at once: start() and run() to the end.
template <typename Index>
Result triangulate_face(Cdt<Index>& cdt, const FaceInput& in, LocateMode mode);

extern template Result triangulate_face(Cdt<uint16_t>&, const FaceInput&, LocateMode);
extern template Result triangulate_face(Cdt<uint32_t>&, const FaceInput&, LocateMode);

// Hilbert curve index of (x, y) on a 2^levels x 2^levels grid (x, y < 2^levels; exposed for
// tests).
uint32_t hilbert_index(uint32_t x, uint32_t y, int levels = 16);

} // namespace facet::cdt
