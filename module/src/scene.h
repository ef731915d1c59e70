#pragma once
// The model as the viewer holds it: the pack's records (one whole pack, or the blocks of a
// blocked pack, each a pack of a few parts, read in place), the edges' samples (shared by both
// faces of an edge, and quantized for drawing), and the mesh, face after face, as the scheduler
// tessellates them. Faces, edges and parts are numbered model-wide: a block's follow the blocks
// before it (Block::first_face...), and a block's pack numbers its own from 0. Positions are
// quantized once per face (shell coordinates, diag/2^20 units); normals are Q14.
#include "facet/sizes.h"
#include "facet/types.h"
#include "geom/pack.h"
#include "geom/pmi.h"
#include "geom/tree.h"
#include "geom/pack_index.h"
#include "geom/tessellate.h"

namespace facet::geom {
struct FaceGeometry;
} // namespace facet::geom

#include <algorithm>
#include <cstdint>
#include <span>

namespace facet::module {

constexpr uint32_t kDefaultRgb = 0x00CDBEB4; // a face (or proxy) with no colour: light warm grey (B,G,R bytes)

struct DrawVertex {
    int32_t p[3];   // shell coordinates in units of the pack's diagonal / 2^20
    int16_t n[3];   // unit normal, Q14
};
static_assert(sizeof(DrawVertex) == FACET_BYTES_PER_MESH_VERTEX);

// Deferred: too small on the screen (or off it) to be worth its triangles for now; drawn by its
// edges, its sphere bounded from them, tessellated when the view makes it large enough.
// Absent: its block is left out of a model larger than the memory (not decoded; its parts
// drawn as their proxies, or boxes), outside the totals until the view brings the block in.
enum class FaceState : uint8_t { Pending, Done, Failed, Deferred, Absent };

// +1 for a right-handed frame (x cross y along z), -1 for a left-handed one: a surface's du x dv
// (its own normal) goes with it (geom/src/elementary.h).
inline float handedness(const pack::Frame& f) {
    const float c[3] = {f.x[1] * f.y[2] - f.x[2] * f.y[1], f.x[2] * f.y[0] - f.x[0] * f.y[2], f.x[0] * f.y[1] - f.x[1] * f.y[0]};
    return c[0] * f.z[0] + c[1] * f.z[1] + c[2] * f.z[2] < 0 ? -1.0f : 1.0f;
}

struct FaceInfo {
    uint32_t first_vertex, vertex_count, first_index, triangle_count;
    uint32_t rgb;      // r | g << 8 | b << 16
    int32_t centre[3]; // a sphere holding the face's vertices (DrawVertex units), so a face
    int32_t radius;    // off the screen is skipped whole; radius 0: none known
    FaceState state;
    bool planar;       // one normal: a closed shell's plane facing away is skipped whole
};
static_assert(sizeof(FaceInfo) + sizeof(uint32_t) == FACET_BYTES_PER_FACE); // with its done_order entry
// A face with no mesh and no sphere in that state.
constexpr FaceInfo no_mesh(FaceState state, uint32_t rgb = 0) { return {0, 0, 0, 0, rgb, {0, 0, 0}, 0, state, false}; }

// A pack of whole parts (a whole pack's shells, or one block of a blocked pack), and where its
// faces, edges and parts start in the model's numbering.
struct Block {
    geom::Pack pack;
    uint32_t first_face = 0, first_edge = 0, first_part = 0;
    const uint8_t* data = nullptr; // where its pack lies (decoded, or a plain block in the file)
    // Its level of detail (mm): the pass's, set as the pass reaches its first edge (0: not yet),
    // and the previous pass's. Its parts' edges and faces all take it: watertight per part.
    float tolerance = 0, previous_tolerance = 0;
    // A refinement it could not make (no room for its samples or its mesh): not tried again
    // until the view changes or a new pass begins.
    bool refused = false;
    // Left out of a model larger than the memory (loader.h): not decoded (its pack empty), its
    // faces absent and its edges unsampled; its parts are drawn as their proxies. Numbered all
    // the same (`faces`, `edges`: its parts' counts in the index), so that it can come in and
    // go out again as the view asks (Scene::take_block, drop_block) without renumbering.
    bool left_out = false;
    bool leaving = false; // chosen to make room for a block the view brings in (swap.cpp)
    bool broken = false;  // found corrupt as it was brought in: left out for good
    float pixels = 0;     // its box's size on the screen when last judged (swap.cpp)
    uint32_t next = kNone;  // the next block a pass takes (Scheduler's BlockOrder)
    uint32_t faces = 0, edges = 0;
};

// A part (a shell): its faces in the model's numbering, and its block.
struct Part {
    uint32_t first_face, face_count, block;
    bool closed;
};

// Totals of the current pass, and high-water marks over every pass.
struct Totals {
    uint32_t faces = 0, done = 0, failed = 0, deferred = 0, triangles = 0, vertices = 0;
    uint32_t undeferred = 0; // faces deferred and then done or failed
    // The pass's progress, never going back within it: faces done, failed or deferred, and
    // again each deferred face as it is done (so faces a sweep adds show as they come).
    uint32_t finished() const { return done + failed + deferred + undeferred; }
    uint32_t arena_peak_bytes = 0; // largest CDT use of one face (vertices + triangles)
    uint32_t mesh_bytes() const { return vertices * uint32_t(sizeof(DrawVertex)) + triangles * 3 * uint32_t(sizeof(uint16_t)); } // in use
    uint32_t samples_peak = 0, face_points_peak = 0, slivers_peak = 0, vertices_peak = 0, triangles_peak = 0;
};

class Scene {
public:
    struct Memory {
        geom::EdgeSamples samples;
        std::span<int32_t> sample_q;       // 3 per pool sample: quantized like DrawVertex::p
        std::span<DrawVertex> vertices;    // the mesh, face after face
        std::span<uint16_t> indices;       // 3 per triangle, relative to the face's first vertex
        std::span<FaceInfo> faces;         // per pack face
        std::span<uint32_t> done_order;    // faces in the order they were finished
    };

    // A whole pack (validated): one block.
    Result open(const geom::Pack& pack);
    // A blocked pack: its index and its blocks (each pack opened; they stay where they are, as
    // the index does), checked against the index's parts.
    Result open(const geom::PackIndex& index, std::span<Block> blocks);
    // The memory for the opened model (planned for its counts): loaded from then on. Full if
    // it has more faces or edges than the memory holds.
    Result attach(const Memory& memory);
    bool loaded() const { return loaded_; }
    void close() { loaded_ = false, blocks_ = {}, totals_ = {}, bounds_.active = false; } // no model (the memory stays)

    uint32_t face_count() const { return faces_; }
    uint32_t edge_count() const { return edges_; }
    uint32_t part_count() const { return parts_; }
    std::span<const pack::Instance> instances() const { return instances_; } // Instance::shell: a part
    uint32_t block_count() const { return uint32_t(blocks_.size()); }
    const Block& block(uint32_t b) const { return blocks_[b]; }
    const Block& block_of_face(uint32_t f) const { return blocks_[find(f, &Block::first_face)]; }
    const Block& block_of_edge(uint32_t e) const { return blocks_[find(e, &Block::first_edge)]; }
    Block& block_of_edge(uint32_t e) { return blocks_[find(e, &Block::first_edge)]; }
    Block& block(uint32_t b) { return blocks_[b]; }
    uint32_t block_index(const Block& b) const { return uint32_t(&b - blocks_.data()); }
    // Where a block's parts lie, placed by their instances (mm): the index's box for a blocked
    // pack, the placed model's for a whole one.
    void block_box(uint32_t b, float lo[3], float hi[3]) const;
    // A part's box in its own coordinates (mesh units), from a blocked pack's index; false for
    // a whole pack (its parts' boxes are known once its edges are sampled).
    bool part_box(uint32_t part, int32_t lo[3], int32_t hi[3]) const;
    // Its eight corners, corner c taking hi along the axes of c's bits (x 1, y 2, z 4).
    bool part_corners(uint32_t part, int32_t corners[8][3]) const;
    // A sphere holding its box (mesh units, as FaceInfo's): false as part_box.
    bool part_sphere(uint32_t part, int32_t centre[3], int32_t& radius) const;
    bool blocked() const { return blocked_; } // a blocked pack: its index has the parts' boxes
    const geom::PackIndex& index() const { return index_; } // (a blocked pack's: its parts' boxes and proxies)
    // What a model larger than the memory left out (its blocks not decoded, loader.h): its
    // parts are drawn as their proxies (or boxes).
    struct LeftOut {
        uint32_t blocks = 0, parts = 0, faces = 0, edges = 0;
    };
    const LeftOut& left_out() const { return left_out_; }
    // A left-out block brought in: its pack opened (Block::pack, checked against the index),
    // its faces pending, counted in the totals (its edges to be sampled: Scheduler::begin_refine).
    Result take_block(uint32_t b);
    // A block left out again (the view wants its memory for another): its meshes and samples
    // garbage, its faces absent, its pack closed (the caller moves the decoded packs after it).
    void drop_block(uint32_t b);
    bool part_left_out(uint32_t s) const { return blocked_ && blocks_[find(s, &Block::first_part)].left_out; }
    // Drawn as its box: left out, or its block just brought in and not sampled yet (no level).
    bool part_boxed(uint32_t s) const { return blocked_ && !(blocks_[find(s, &Block::first_part)].tolerance > 0); }
    // A part's edges in the model's numbering, each once, where they are known to be together:
    // a blocked pack's part (its block's edges are its parts' in order), or a whole pack's only
    // part. False otherwise.
    bool part_edges(uint32_t part, uint32_t& first, uint32_t& count) const;
    Part part(uint32_t s) const;
    const pack::Face& face_record(uint32_t f) const {
        const Block& b = block_of_face(f);
        return b.pack.faces()[f - b.first_face];
    }
    uint8_t surface_type(uint32_t f) const; // pack::SurfaceType of the face's surface
    // Face f's exact geometry as instance i places it (geom/measure.h); its block must be in.
    [[nodiscard]] Result face_geometry(uint32_t f, uint32_t instance, geom::FaceGeometry& out) const;
    // A plane face's plane in its part's coordinates (mm): a point and the unit normal out of
    // the face (its surface's, du x dv: z, or -z in a left-handed frame; turned when the face is
    // reversed). False for other surfaces.
    bool face_plane(uint32_t f, float point[3], float normal[3]) const;
    // face_plane()'s normal in Q14 (DrawVertex::n), each component rounded half away from zero
    // from its float's bits: no soft float (the painter asks for a deferred plane's every frame).
    bool plane_normal(uint32_t f, int16_t n[3]) const;
    // A point of the face's boundary (its first sampled edge's first sample, quantized as
    // DrawVertex::p), or null before its edges are sampled.
    const int32_t* boundary_point(uint32_t f) const;
    // The assembly tree (geom/tree.h; none: a flat list of parts), a whole pack's or an index's.
    const geom::ProductTree& tree() const { return tree_; }
    // The exploded view: each instance moved out by `factor` times its offset (the tree's; 0:
    // assembled, up to kMostExplode). Where an instance is drawn, framed and judged: placed()
    // (the file's placement, plus the offset); its exact geometry stays the assembled one.
    static constexpr float kMostExplode = 2.0f;
    void set_explode(float factor) { explode_ = tree_.count() ? factor : 0; }
    float explode() const { return explode_; }
    const pack::Instance& placed(uint32_t instance, pack::Instance& scratch) const {
        if (explode_ == 0) return instances_[instance];
        scratch = instances_[instance];
        const float* d = tree_.explode(instance);
        for (int k = 0; k < 3; ++k) scratch.m[4 * k + 3] += explode_ * d[k];
        return scratch;
    }
    // The model's annotations (PMI: geom/pmi.h), a whole pack's or an index's.
    const geom::Annotations& annotations() const { return annotations_; }
    const char* model_name() const { return blocked_ ? index_.model_name() : blocks_[0].pack.model_name(); }
    const char* part_name(uint32_t s) const;
    const char* instance_name(uint32_t i) const { return blocked_ ? index_.instance_name(i) : blocks_[0].pack.instance_name(i); }
    float source_unit_mm() const { return source_unit_mm_ > 0 ? source_unit_mm_ : 1.0f; }
    // The shells' own box (every part in its own coordinates), mm.
    const float* box_min() const { return box_min_; }
    const float* box_max() const { return box_max_; }
    // The placed model (every instance's shell where the instance puts it): its bounding
    // box's centre and half its diagonal (mm), what the camera frames. The mesh quantum (mm)
    // comes from the shells' own coordinates (box_min/box_max), which the mesh is stored in.
    const float* centre() const { return centre_; }
    float radius() const { return radius_; }
    float unit() const { return unit_; }
    // The placed box again from the best the scene has: each shell's edge samples and its
    // tessellated faces (`sampled` false: the edges' end vertices only, as at open(), before
    // the pass's samples exist), through every instance's placement. About ten instructions a
    // sample and a vertex (integer compares), then 8 corners an instance.
    void fit_bounds(bool sampled);
    // The same in pieces of about `points` points each (bound() true when done: the centre and
    // radius change only then), so a large model's bounds never stall a step.
    void start_bounds(bool sampled);
    bool bound(uint32_t points);
    bool bounding() const { return bounds_.active; }
    uint32_t shell_of(uint32_t face) const;
    // Parts (instances) shown or hidden; the first kMaxHideable can be hidden (Viewer::show_part
    // refuses the rest, which stay shown). All shown at open().
    static constexpr uint32_t kMaxHideable = 4096;
    bool shown(uint32_t instance) const { return instance >= kMaxHideable || !((hidden_[instance >> 5] >> (instance & 31)) & 1u); }
    void set_shown(uint32_t instance, bool on);
    void show_all();
    uint32_t colour_of(uint32_t face) const; // rgb of the face (or of its shell, or the default)

    geom::EdgeSamples& samples() { return mem_.samples; }
    const geom::EdgeSamples& samples() const { return mem_.samples; }
    // The pool seen through a block's own edge numbering (its first/count from the block's
    // first edge): what geom's sampler and face jobs take with the block's pack. The pool's
    // `used` and `work` are a copy (the caller carries them back).
    geom::EdgeSamples samples_of(const Block& b) const {
        geom::EdgeSamples v = mem_.samples;
        v.first = v.first.subspan(b.first_edge, b.pack.edges().size());
        v.count = v.count.subspan(b.first_edge, b.pack.edges().size());
        return v;
    }
    const int32_t* sample_q(uint32_t sample) const { return &mem_.sample_q[3 * sample]; }
    // Quantizes samples [from, to) of the pool for drawing.
    void quantize_samples(uint32_t from, uint32_t to);

    // A new pass: no face done (a left-out block's absent), the samples' peak carried over.
    void reset_mesh(bool keep_peaks);
    // Appends a tessellated face (its float mesh) to the drawing mesh; a face already done (its
    // block refined) gets the new mesh, and its old one is garbage until compact(). Full when the
    // mesh is full.
    Result append(uint32_t face, const geom::Mesh& mesh, const geom::FaceStats& stats);

    // The mesh and the samples as caches of fixed bytes (scene_cache.cpp). A done face left to
    // its edges again (its mesh garbage): deferred, as a face the view does not want.
    void evict(uint32_t face);
    // The live meshes moved down over the garbage, in the order they lie (done_order becomes
    // that order). False when there was none.
    bool compact();
    // The room compact() would leave.
    uint32_t mesh_free_vertices() const { return uint32_t(mem_.vertices.size()) - totals_.vertices; }
    uint32_t mesh_free_triangles() const { return uint32_t(mem_.indices.size() / 3) - totals_.triangles; }
    // The samples' pool: each block's samples lie together (a pass samples a block's edges one
    // after the other, and so does a refinement, at the pool's end, leaving the old ones as
    // garbage); moved down over the garbage, block after block. `scratch`: 3 words a block
    // (false when it is short, or nothing moved).
    bool compact_samples(std::span<uint32_t> scratch);
    uint32_t samples_room() const { return uint32_t(std::min(mem_.samples.t.size(), mem_.samples.p.size())) - mem_.samples.used; }
    // Counts every move of meshes and every block dropped: frames drawn before one must be drawn
    // whole again (samples moved, or a block taken in, change nothing drawn).
    uint32_t moves() const { return moves_; }
    void mark_failed(uint32_t face);
    // A face not tessellated: its sphere from its edges' samples (radius 0 when it has none),
    // kept in its FaceInfo; then, if deferred, counted so until it is appended.
    // bound() gives a waiting face (Pending) its sphere the same way as it passes its samples.
    void bound_by_edges(uint32_t face);
    void defer(uint32_t face);

    const FaceInfo& face(uint32_t f) const { return mem_.faces[f]; }
    uint32_t done_face(uint32_t k) const { return mem_.done_order[k]; } // k-th face finished
    const DrawVertex* vertices() const { return mem_.vertices.data(); }
    const uint16_t* indices() const { return mem_.indices.data(); }
    const Totals& totals() const { return totals_; }
    Totals& totals() { return totals_; }

private:
    Result start(); // after the blocks are set: the model's counts, box and quantum
    Result check_block(const geom::PackIndex& index, uint32_t b) const; // its pack is its parts'
    void tally_left_out(uint32_t b, bool out); // block b counted in (out) or out of left_out_
    // A plane face's surface frame and whether the face is reversed (null: another surface).
    const pack::Frame* plane_frame(uint32_t f, bool& reversed) const;
    // The block holding item k of a numbering (binary search on the blocks' firsts).
    uint32_t find(uint32_t k, uint32_t Block::*first) const {
        uint32_t lo = 0, hi = uint32_t(blocks_.size());
        while (hi - lo > 1) {
            const uint32_t mid = (lo + hi) / 2;
            if (blocks_[mid].*first <= k) lo = mid;
            else hi = mid;
        }
        return lo;
    }

    Memory mem_{};
    LeftOut left_out_;
    Block whole_;                 // a whole pack's one block
    geom::Annotations annotations_; // the model's annotations (a whole pack's or the index's)
    geom::ProductTree tree_;        // the assembly tree (a whole pack's or the index's)
    float explode_ = 0;
    std::span<Block> blocks_;     // whole_, or a blocked pack's
    geom::PackIndex index_;       // a blocked pack's
    bool blocked_ = false;
    std::span<const pack::Instance> instances_;
    uint32_t faces_ = 0, edges_ = 0, parts_ = 0;
    float source_unit_mm_ = 1, box_min_[3] = {0, 0, 0}, box_max_[3] = {0, 0, 0};
    bool loaded_ = false;
    float unit_ = 1, centre_[3] = {0, 0, 0}, radius_ = 1, own_radius_ = 1;
    Totals totals_;
    uint32_t vertex_top_ = 0, triangle_top_ = 0; // the mesh's storage in use, garbage included
    uint32_t moves_ = 0;
    struct Box { // a part's or a face's box in its own coordinates (mesh units)
        int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
        bool empty() const { return lo[0] > hi[0]; }
        void add(const int32_t p[3]);
        void add(const Box& b); // (an empty one adds nothing)
    };
    // The face's sphere from the box of its edges' samples (radius 0 when empty), its colour and
    // whether it is planar, in its FaceInfo (bound_by_edges, bound).
    void set_edge_sphere(uint32_t face, const Box& box);
    struct Bounds { // where start_bounds()/bound() stand
        bool active = false, sampled = false, in_part = false;
        uint32_t part = 0, face = 0;
        Box box;
        float lo[3], hi[3]; // the placed box so far (mm)
    } bounds_;
    uint32_t hidden_[kMaxHideable / 32] = {};
};

} // namespace facet::module
