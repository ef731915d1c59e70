#pragma once
// Pieces of tessellate_face shared between its source files (not part of geom's interface).
#include "geom/tessellate.h"

#include <cstdint>

namespace facet::geom::detail {

constexpr float kTwoPi = 6.28318530717958647692f;
constexpr int32_t kGridHalf = 16384; // the face's (scaled) extent spans 2 * kGridHalf grid units

// Edge sampling and refinement aim this far under the tolerance, where their bounds are exact
// (a circle's sag, a cylinder's arc): the pack's float32 geometry leaves points a little off
// their surfaces (up to about 1e-6 of the coordinates' size, 1e-4 mm on a 150 mm part), and
// a mesh measured against the exact surfaces must stay within the tolerance all the same.
constexpr float kAim = 0.98f;

// Whether directions a and b turn by more than the angle whose cosine is cos_max, without
// square roots or acos (long library calls on a soft-float core). A zero vector turns by nothing.
inline bool turns_more(Vec3 a, Vec3 b, float cos_max) {
    const float l2 = dot(a, a) * dot(b, b);
    if (l2 == 0) return false;
    const float d = dot(a, b);
    if (cos_max < 0) return d < 0 && d * d > cos_max * cos_max * l2;
    return d < 0 || d * d < cos_max * cos_max * l2;
}

// The largest angle an arc of radius r may span while its chord stays within tol of it:
// r (1 - cos(a/2)) = 2 r sin^2(a/4) <= tol. 2 pi and more when any chord will do.
float max_arc_angle(float r, float tol);

// Step 1: every sample of every coedge of every loop of the face into (u,v) (sc.uv, sc.xyz,
// sc.pinned), loop after loop (sc.loop_sizes). np, nl: points and loops so far. From loop
// `next_loop` (of the face) on, whole loops until `max_points` have been mapped: Busy, and
// next_loop says where to go on (np, nl 0 and next_loop 0 start a face).
Result map_loops(const Pack& pack, uint32_t face, const EdgeSamples& edges, FaceScratch& sc, uint32_t& np,
                 uint32_t& nl, uint32_t& next_loop, uint32_t max_points);

// Whether every loop of the face (as mapped) runs between at most two distinct 3D points:
// a lens of two edges whose samples are their chords alone, a loop shrunk to a point. The
// face then has no area at this tolerance, and its neighbours meet along those chords
// directly: it needs no triangle for the mesh to stay closed.
bool retraces(const FaceScratch& sc, uint32_t np, uint32_t nl);

// Step 3b: after quantization (sc.loop_points), drop the points that fall on their
// predecessor's grid point and the tips of collinear U-turns (two pcurves ending a hair apart
// at a corner), and the loops left without area; uv/xyz/pinned move along. Each dropped point
// B of A -> B -> C becomes a sliver triangle A, B, C (sc.slivers), so that the face still uses
// every edge sample its neighbour uses: the mesh stays watertight around features smaller
// than the grid.
Result clean_loops(FaceScratch& sc, uint32_t& np, uint32_t& nl, uint32_t& slivers);

// Step 5: adds surface points until every inner triangle is within the tolerance (see
// refine.cpp), about `units` of work at a time (`spent` says how much): Busy while unfinished.
// sc.mesh_of maps CDT vertices to points (sc.uv/sc.xyz); state.total (the face's points so
// far) grows with every point added. A fresh RefineState{} with total set starts a face.
Result refine(const Pack& pack, uint32_t face, const TessOptions& opt, const Grid& grid, cdt::Cdt<uint16_t>& cdt,
              FaceScratch& sc, RefineState& state, uint32_t units, uint32_t& spent);

} // namespace facet::geom::detail
