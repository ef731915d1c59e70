#pragma once
// An independent checker of a finished triangulation, kept apart from the algorithm
// (cf. CDT's VerifyTopology.h, delaunator's validate()). It re-derives every property from the
// raw CET arrays with its own code:
//   - neighbours symmetric, each back-edge index naming the shared edge; vertices' incident
//     triangles really incident
//   - every triangle counter-clockwise and non-degenerate
//   - Euler: 2V - 6 triangles, exactly 4 hull edges (the box)
//   - every input constraint present as a chain of collinear edges with Along on its left and
//     Against (or Both) on its right, and no flagged edge that no input constraint explains
//   - every unconstrained edge locally Delaunay
//   - (after mark_inner) the inner set equal to a point-in-polygon classification of each
//     triangle's centroid by winding number against the input constraints
// Allocation-free: the caller passes scratch (check_scratch_words()). A broken property is
// Corrupt, naming it and the triangle, edge or vertex where it was found.
#include "cdt/cdt.h"

#include <span>

namespace facet::cdt {

struct Segment {
    Point a, b; // a directed constraint: a -> b along its loop
};

// Scratch (32-bit words) check() needs: sorted vertices, the Along edges and their marks, and
// a slab index of the segments (its size depends on how tall they are, so it is counted).
size_t check_scratch_words(size_t vertices, size_t triangles, std::span<const Segment> segments);

template <typename Index>
Result check(const Cdt<Index>& cdt, std::span<const Segment> constraints, bool check_inner,
                  std::span<uint32_t> scratch);

extern template Result check(const Cdt<uint16_t>&, std::span<const Segment>, bool,
                                  std::span<uint32_t>);
extern template Result check(const Cdt<uint32_t>&, std::span<const Segment>, bool,
                                  std::span<uint32_t>);

} // namespace facet::cdt
