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
#include "core/last_call.h"
#include "geom/eval.h"
#include "geom/face_storage.h"
#include "geom/pack.h"
#include "geom/patches.h"

#include <cstddef>
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

// What one face took.
struct FaceStats {
    uint32_t triangles = 0;
    uint32_t points = 0;      // CDT points (loop samples and refinement points)
    uint32_t slivers = 0;     // loop points kept as slivers (of FaceCapacity::slivers)
    uint32_t untangled = 0;   // pieces of crossing loops dropped (as slivers; at most kMaxUntangles)
};
// The most pieces of crossing loops a face drops before it fails (each drop triangulates the
// loops anew): a B-rep artefact takes one or two.
constexpr uint32_t kMaxUntangles = 8;

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
    struct AngleCosines {
        float whole = 1, half = 1; // cos(angle), cos(angle / 2) (past a right angle: 0)
    };
    LastCall<AngleCosines, 1> cosines_; // of opt_.max_angle (every edge of a block has the same)
    LastCall<float, 2> arc_;            // detail::max_arc_angle(r, tol): a hole's two circles, a pattern of equal holes
    const AngleCosines& angle_cosines(); // (sample_edges.cpp says why they are kept)
    float circle_arc(float r);
    CurveSpans spans_; // a B-spline's spans in fixed point
    Result result_ = Result::fail(Status::Busy, "not started");
};

// One face tessellated a bounded amount at a time (Steps 1 to 6 in pieces), so that a viewer
// can draw frames and take input between them:
//
//   FaceJob job;
//   job.start(pack, f, samples, opt, storage, mesh);   // storage: geom/face_storage.h
//   Result r;
//   while ((r = job.run(256)).status == Status::Busy) { /* a frame, input */ }
//
// A unit of work is about one CDT insertion (a few thousand instructions on the ARM926); a
// piece ends at the first point where `units` are spent. Busy while unfinished; Ok when the
// face's triangles are in the mesh; a failure names the face (and its loop and point where
// known), and leaves the mesh as it was before the face. The pack, samples, storage and mesh
// must stay put until the job ends.
class FaceJob {
public:
    FaceJob();
    FaceJob(const FaceJob&) = delete; // its builder refers to its own triangulation
    FaceJob& operator=(const FaceJob&) = delete;
    // A storage that is not bound fails the job (run() says so).
    void start(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt, FaceStorage& storage,
               Mesh& mesh);
    Result run(uint32_t units);
    uint32_t face() const { return face_; }
    const FaceStats& stats() const { return stats_; }

private:
    enum class Stage : uint8_t { Map, Triangulate, Refine, Emit, Done, Failed };
    struct Engine; // the face's CDT and its builder, the scratch's arrays, the grid, refinement's state
    Engine& engine();
    Result fail(Result r);
    Result prepare();

    const Pack* pack_ = nullptr;
    const EdgeSamples* edges_ = nullptr;
    TessOptions opt_;
    Mesh* mesh_ = nullptr;
    uint32_t face_ = 0;
    Stage stage_ = Stage::Failed;
    uint32_t np_ = 0, nl_ = 0;
    uint32_t next_loop_ = 0, next_triangle_ = 0; // where mapping and emission go on
    uint32_t base_vertex_ = 0, base_triangle_ = 0;
    FaceStats stats_;
    Result result_ = Result::fail(Status::Busy, "not started");
    // The Engine in place (its types are geom's and cdt's own: tessellate.cpp checks it fits).
    static constexpr size_t kEngineBytes = 112 * sizeof(void*);
    alignas(8) unsigned char engine_[kEngineBytes];
};

// Tessellates face `face` of the pack (placed by nothing: shell coordinates), all at once.
Result tessellate_face(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt,
                       FaceStorage& storage, Mesh& mesh, FaceStats& stats);

// 0.1% of the pack's bounding-box diagonal (the default tolerance).
float default_tolerance(const Pack& pack);
// The same from a box (mm): 0.1% of its diagonal (0.01 mm for an empty one).
float default_tolerance(const float box_min[3], const float box_max[3]);

} // namespace facet::geom
