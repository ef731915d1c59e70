#pragma once
// Pieces of tessellate_face shared between its source files (not part of geom's interface).
#include "cdt/cdt.h"
#include "cdt/face.h"
#include "geom/face_storage.h"
#include "geom/tessellate.h"

#include <cstdint>
#include <span>

namespace facet::geom::detail {

// How far one triangle strays from its surface, and where a point would help most.
struct TriangleMeasure {
    uint64_t key;     // the slot's three vertices when measured (a changed triangle is re-measured)
    float error2;     // squared deviation estimate
    cdt::Point at;    // the grid point to insert if it is too large
};

// A triangle that keeps a loop point the CDT grid could not hold (see clean_loops).
struct Sliver {
    Vec3 p[3];
    Vec2 uv[3];
};

// A face's storage (geom/face_storage.h) as typed arrays. uv and xyz hold every point of the
// face: the loops' samples, then the points refinement adds.
struct FaceScratch {
    cdt::ArenaView<uint16_t> arena;
    std::span<cdt::Point> loop_points;
    std::span<uint32_t> loop_sizes;
    std::span<Vec2> uv;          // per point, unquantized
    std::span<uint8_t> pinned;   // per loop point: bit 0 u, bit 1 v known exactly (seam, pcurve)
    std::span<Vec3> xyz;         // per point: the edge sample's 3D point, or the surface point
    std::span<uint32_t> mesh_of; // per CDT vertex: its point (while refining), then its mesh vertex
    // Per CDT triangle slot: the last measure of the triangle in it, so that a refinement
    // round measures only the triangles that changed. At least triangles_for(arena vertices).
    std::span<TriangleMeasure> measured;
    std::span<Sliver> slivers;   // loop points dropped from the grid, as triangles
    std::span<uint32_t> patches; // a free-form face's spans as fixed-point patches (geom/patches.h)
};

// The storage's block cut by the plan (face_storage.cpp).
FaceScratch scratch_of(const FaceStorage& storage);

// How a face's (u,v) maps to the CDT's integer grid: u and v scaled by the surface's metric
// (|Su|, |Sv| at the middle of the face), shifted and scaled so the face's extent spans
// [-kGridHalf, kGridHalf].
struct Grid {
    float su = 1, sv = 1; // metric scale
    float x0 = 0, y0 = 0; // scaled (u,v) of the grid's corner
    float q = 1;          // grid units per scaled unit

    cdt::Point to_grid(Vec2 uv) const;
    Vec2 to_uv(cdt::Point g) const;
};
// Where refinement (Step 5) stands between two pieces.
struct RefineState {
    uint32_t round = 0;
    uint32_t cleared = 0;   // measured[] slots reset for this face
    uint32_t next = 0;      // the next triangle slot to measure or to refine
    uint32_t triangles = 0; // the triangles at the round's start
    bool inserting = false; // measuring the changed triangles, or inserting points
    float worst = 0, threshold = 0;
    float last_worst = 0;   // the previous round's worst
    uint32_t added = 0;     // points this round
    uint32_t total = 0;     // points of the face so far
    uint32_t loop_points = 0; // the points from the loops' samples (refinement's come after them)
    int8_t seams = -1;      // the face's loops run along a seam (-1: not looked yet)
};

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
// The slivers are appended to the `slivers` already made.
Result clean_loops(FaceScratch& sc, uint32_t& np, uint32_t& nl, uint32_t& slivers);

// Step 4, when the CDT refused the loop segment from point `from` to the next one, `to`, as
// crossing another (tangles.cpp): finds the segment it crosses and drops the smaller piece the
// crossing cuts off, as a fan of slivers (appended to `slivers`), or one point when two loops
// cross. Crossing, and nothing changed, when no such segment is found or the piece is no small
// artefact (a quarter of its loop's length or more). The caller cleans the loops again and
// triangulates them anew.
Result untangle(FaceScratch& sc, uint32_t& np, uint32_t& nl, uint32_t& slivers, uint32_t from, uint32_t to);

// Step 4, once the CDT holds the loops (sc.mesh_of maps its vertices to the first point on
// each): where loop points of different 3D points share a vertex or a point splits another
// loop's segment (features thinner than the grid), a fan of slivers (appended to `slivers`)
// joins each segment to the path of edges the triangulation holds for it (tangles.cpp).
Result stitch(FaceScratch& sc, uint32_t np, uint32_t nl, const cdt::Cdt<uint16_t>& cdt, uint32_t& slivers);

// Step 5: adds surface points until every inner triangle is within the tolerance (see
// refine.cpp), about `units` of work at a time (`spent` says how much): Busy while unfinished.
// sc.mesh_of maps CDT vertices to points (sc.uv/sc.xyz); state.total (the face's points so
// far) grows with every point added. A fresh RefineState{} with total and loop_points set (the
// loops' points) starts a face.
Result refine(const Pack& pack, uint32_t face, const TessOptions& opt, const Grid& grid, cdt::Cdt<uint16_t>& cdt,
              FaceScratch& sc, RefineState& state, uint32_t units, uint32_t& spent);

} // namespace facet::geom::detail
