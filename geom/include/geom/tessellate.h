#pragma once
// Pack -> triangles, face by face (the paper's Steps 1-3).
//
// Edges are sampled once, by chordal deviation and turning angle, into a shared pool, so the
// two faces of an edge use identical samples and identical 3D points: watertight by
// construction. A face maps its loops' samples into (u,v) (its pcurves, or the inverse of an
// elementary surface), scales (u,v) by the surface's metric so Delaunay in the plane gives
// well-shaped 3D triangles, quantizes to the CDT grid, adds curvature points where the surface
// leaves its flat cells by more than the tolerance, triangulates with cdt/, and appends the
// inner triangles with 3D positions and normals to the mesh. All storage is the caller's.
#include "cdt/face.h"
#include "geom/eval.h"
#include "geom/pack.h"

#include <span>

namespace facet::geom {

struct TessOptions {
    float tolerance = 0.1f;  // mm, chordal deviation allowed (default: 0.1% of the diagonal)
    float max_angle = 0.5f;  // rad, turning between neighbouring samples / cell corners (< pi)
};

struct MeshVertex {
    Vec3 p, n;
};

// Fixed-capacity output. Faces append; Full leaves earlier faces intact.
struct Mesh {
    std::span<MeshVertex> vertices;
    std::span<uint32_t> indices; // three per triangle
    std::span<Vec2> uv;          // optional: each vertex's (u,v) on its face (for measuring)
    uint32_t vertex_count = 0, triangle_count = 0;
};

// Where each edge's samples live in the pool.
struct EdgeSamples {
    std::span<uint32_t> first;  // per edge
    std::span<uint16_t> count;  // per edge
    std::span<float> t;         // pool: parameters
    std::span<Vec3> p;          // pool: 3D points
    uint32_t used = 0;
};

// Per-face working memory (one face at a time).
struct FaceScratch {
    cdt::ArenaView<uint16_t> arena;
    std::span<cdt::Point> loop_points;
    std::span<uint32_t> loop_sizes;
    std::span<cdt::Point> interior;
    std::span<Vec2> uv;          // per input point (loops then interior), unquantized
    std::span<uint8_t> pinned;   // per loop point: bit 0 u, bit 1 v known exactly (seam, pcurve)
    std::span<Vec3> xyz;         // per loop point: the edge sample's 3D point
    std::span<uint32_t> mesh_of; // per CDT vertex: its mesh vertex
    // Optional, per CDT triangle slot: which triangles already met the tolerance, so that a
    // refinement round measures only the triangles that changed (empty: measure all, slower).
    std::span<uint64_t> passed = {};
};

struct FaceResult {
    Status status = Status::Ok;
    const char* reason = "";  // on failure
    uint32_t triangles = 0;
    uint32_t points = 0;      // CDT input points
};

// Samples every edge of the pack. Full if the pool is too small.
Status sample_edges(const Pack& pack, const TessOptions& opt, EdgeSamples& out);

// Tessellates face `face` of the pack (placed by nothing: shell coordinates).
FaceResult tessellate_face(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt,
                           FaceScratch& scratch, Mesh& mesh);

// How far point c (a triangle's centroid) is from face `face`'s surface, and the surface
// point's (u,v): on elementary surfaces by inverting c (well defined even at poles and apexes),
// else at `uv_guess` (the triangle's uv centroid).
float surface_deviation(const Pack& pack, uint32_t face, Vec3 c, Vec2 uv_guess, Vec2& uv_out);

// 0.1% of the pack's bounding-box diagonal (the default tolerance).
float default_tolerance(const Pack& pack);

} // namespace facet::geom
