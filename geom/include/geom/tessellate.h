#pragma once
// Pack -> triangles, face by face (the paper's Steps 1-3).
//
// Edges are sampled once, by chordal deviation and turning angle, into a shared pool, so the
// two faces of an edge use identical samples and identical 3D points: watertight by
// construction. A face maps its loops' samples into (u,v) (its pcurves, or the inverse of an
// elementary surface), scales (u,v) by the surface's metric so Delaunay in the plane gives
// well-shaped 3D triangles, quantizes to the CDT grid and triangulates the loops with cdt/.
// Interior points then go in greedily where the mesh strays furthest from the surface, until
// every inner triangle is within the tolerance (planes need none; a cylinder or cone needs
// none while its triangles span small enough angles). The inner triangles are appended with
// 3D positions and normals to the mesh. All storage is the caller's.
#include "cdt/face.h"
#include "cdt/cdt.h"
#include "geom/eval.h"
#include "geom/pack.h"
#include "geom/patches.h"

#include <span>

namespace facet::geom {

struct TessOptions {
    float tolerance = 0.1f;  // mm, chordal deviation allowed (default: 0.1% of the diagonal)
    // rad (< pi), the most an edge's tangent may turn between two samples: a full circle gets
    // at least 7 sides however small it is. The tolerance alone decides everything else; a
    // view zoomed in on a small feature asks for a finer tolerance.
    float max_angle = 1.0f;
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
    uint32_t work = 0;          // curve evaluations so far (what a piece of sampling costs)
};

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

// Per-face working memory (one face at a time). uv and xyz hold every point of the face:
// the loops' samples, then the points refinement adds.
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
    std::span<Sliver> slivers;  // loop points dropped from the grid, as triangles
    // A free-form face's spans as fixed-point patches (geom/patches.h): kPatchCacheWords
    // recommended; empty, its points are evaluated in float (slower on a core without an FPU,
    // and a hair different: give host tools the same as the device).
    std::span<uint32_t> patches = {};
};

constexpr uint32_t kPatchCacheWords = 16384; // 64 KB: 230 spans of a bicubic rational surface, 142 of a quintic one

// What one face took.
struct FaceStats {
    uint32_t triangles = 0;
    uint32_t points = 0;      // CDT points (loop samples and refinement points)
    uint32_t slivers = 0;     // loop points kept as slivers (FaceScratch::slivers in use)
};

// Samples every edge of the pack. Full if the pool is too small.
Result sample_edges(const Pack& pack, const TessOptions& opt, EdgeSamples& out);
// The same a few edges at a time: edges [begin, end) appended to the pool (begin 0 empties it
// first), so a caller can do other work between pieces.
Result sample_edges(const Pack& pack, const TessOptions& opt, EdgeSamples& out, uint32_t begin, uint32_t end);

// One edge sampled a bounded amount at a time (a long free-form edge takes thousands of
// evaluations): start() begins it at the end of the pool, run(units) goes on for about
// `units` of work (a curve evaluation, weighted by its cost) and returns Busy while the edge
// is unfinished, Ok once its samples are in (EdgeSamples::count set), Full when the pool is.
// The caller checked the options and the index's size (sample_edges does).
class EdgeSampler {
public:
    void start(const Pack& pack, const TessOptions& opt, EdgeSamples& out, uint32_t edge);
    Result run(uint32_t units);
    uint32_t first() const { return start_; } // the edge's first sample in the pool

private:
    void finish();
    // The curve's point (and derivative) at t: in fixed point where spans_ takes the curve.
    Curve3Point eval(float t);
    Vec3 eval_point(float t);
    struct Piece {
        float t;
        Curve3Point p;
    };
    static constexpr int kStack = 96;
    const Pack* pack_ = nullptr;
    EdgeSamples* out_ = nullptr;
    const pack::Curve* curve_ = nullptr;
    TessOptions opt_;
    uint32_t edge_ = 0, start_ = 0, eval_ = 1;
    bool adaptive_ = false;
    Piece stack_[kStack]; // right ends of the pieces still to check, the next one on top
    int top_ = 0;
    Curve3Point left_{};
    float tl_ = 0, min_piece_ = 0, tol2_ = 0, cos_max_ = 1;
    CurveSpans spans_; // a B-spline's spans in fixed point
    Result result_ = Result::fail(Status::Busy, "not started");
};

namespace detail {
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
};
} // namespace detail

// One face tessellated a bounded amount at a time (Steps 1 to 6 in pieces), so that a viewer
// can draw frames and take input between them:
//
//   FaceJob job;
//   job.start(pack, f, samples, opt, scratch, mesh);
//   Result r;
//   while ((r = job.run(256)).status == Status::Busy) { /* a frame, input */ }
//
// A unit of work is about one CDT insertion (a few thousand instructions on the ARM926); a
// piece ends at the first point where `units` are spent. Busy while unfinished; Ok when the
// face's triangles are in the mesh; a failure names the face (and its loop and point where
// known), and leaves the mesh as it was before the face. The pack, samples, scratch and mesh
// must stay put until the job ends.
class FaceJob {
public:
    FaceJob() = default;
    FaceJob(const FaceJob&) = delete; // its builder refers to its own triangulation
    FaceJob& operator=(const FaceJob&) = delete;
    void start(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt, FaceScratch& scratch,
               Mesh& mesh);
    Result run(uint32_t units);
    uint32_t face() const { return face_; }
    const FaceStats& stats() const { return stats_; }

private:
    enum class Stage : uint8_t { Map, Triangulate, Refine, Emit, Done, Failed };
    Result fail(Result r);
    Result prepare();

    const Pack* pack_ = nullptr;
    const EdgeSamples* edges_ = nullptr;
    TessOptions opt_;
    FaceScratch* sc_ = nullptr;
    Mesh* mesh_ = nullptr;
    uint32_t face_ = 0;
    Stage stage_ = Stage::Failed;
    uint32_t np_ = 0, nl_ = 0;
    uint32_t next_loop_ = 0, next_triangle_ = 0; // where mapping and emission go on
    uint32_t base_vertex_ = 0, base_triangle_ = 0;
    detail::Grid grid_;
    detail::RefineState refine_;
    cdt::Cdt<uint16_t> cdt_{{}};
    cdt::FaceBuilder<uint16_t> builder_{cdt_};
    FaceStats stats_;
    Result result_ = Result::fail(Status::Busy, "not started");
};

// Tessellates face `face` of the pack (placed by nothing: shell coordinates), all at once.
Result tessellate_face(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt,
                       FaceScratch& scratch, Mesh& mesh, FaceStats& stats);

// 0.1% of the pack's bounding-box diagonal (the default tolerance).
float default_tolerance(const Pack& pack);

} // namespace facet::geom
