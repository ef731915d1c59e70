#pragma once
// The progressive tessellation, a piece at a time: a pass samples every edge (a few edges per
// piece), then tessellates the faces one after the other (a piece of a face per piece), each
// appended to the scene's mesh as it is finished. A new level of detail starts a new pass.
#include "core/last_call.h"
#include "detail_scale.h"
#include "facet/viewer.h"
#include "geom/tessellate.h"
#include "scene.h"

namespace facet::module {

// How the module's parts report: the application's event callback, if any.
struct Emitter {
    void (*fn)(void* user, const Event& e) = nullptr;
    void* user = nullptr;
    void operator()(const Event& e) const {
        if (fn) fn(user, e);
    }
};

// Whether a face is worth tessellating for the view now (large enough on the screen, on it).
struct FaceFilter {
    bool (*fn)(void* user, uint32_t face) = nullptr; // none: every face is
    void* user = nullptr;
    bool operator()(uint32_t face) const { return !fn || fn(user, face); }
};

// The tolerance (mm) a block's parts take in a pass at `pass_tolerance` (the level of detail's
// bias): none given, the pass's own.
struct BlockTolerance {
    float (*fn)(void* user, uint32_t block, float pass_tolerance) = nullptr;
    void* user = nullptr;
};

// The order a pass or a sweep takes the blocks in (what shows largest first): the first block,
// the others chained by Block::next (kNone ends it). None given: the pack's order.
struct BlockOrder {
    uint32_t (*fn)(void* user) = nullptr;
    void* user = nullptr;
};

class Scheduler {
public:
    struct Memory {
        geom::FaceStorage storage;      // one face's working memory (geom/face_storage.h)
        geom::Mesh face_mesh;           // one face's float output, before the scene quantizes it
        uint32_t max_face_vertices = 0; // the most a face may have (the painter projects them)
        // The face storage's bytes, as scratch while no face is under way: a refined block's
        // edges' new (first, count) until all are sampled, and the samples' compaction.
        std::span<uint8_t> scratch;
    };

    Scheduler(Scene& scene, const Emitter& emit) : scene_(scene), emit_(emit) {}
    void init(const Memory& memory) { mem_ = memory; }
    // The faces a pass leaves to their edges (FaceState::Deferred) are those `filter` turns down.
    void set_filter(const FaceFilter& filter) { filter_ = filter; }
    void set_block_tolerance(const BlockTolerance& t) { block_tolerance_ = t; }
    void set_block_order(const BlockOrder& o) { order_ = o; }
    // The view changed: the deferred faces are looked at again once the pass is over (a sweep:
    // those the view now wants are tessellated and appended), or again from the first.
    void revisit();

    // A pass at `tolerance` (mm): nothing of the previous one is kept but the peaks.
    void begin_pass(float tolerance);
    // Block b again at `tolerance` (mm, finer than its own), while nothing else is under way:
    // its edges sampled at the pool's end (their old samples stay theirs until every new one is
    // in: a pool too full leaves the block as it was, and says so), then its faces tessellated
    // again, each replacing its mesh, or left to their edges where the view no longer wants
    // them. Each part stays at one level, as in a pass, but for the moments its faces are
    // swapped. False when it cannot start (busy; no room to try); Block::refused then says so.
    // A block brought in (Scene::take_block; no tolerance yet) is begun alike: sampled, then
    // its faces tessellated or deferred.
    bool begin_refine(uint32_t b, float tolerance);
    static constexpr uint32_t kNewBlockSamplesPerEdge = 6;
    // The first pass, short of room for the model's edges, takes coarser levels up to this many
    // times the tolerance asked (model_needs()'s least workspace is the room at this level).
    // Whether the samples' pool has room for `need` more (compacted first if short; not while busy).
    bool make_sample_room(uint32_t need);
    bool refining() const { return refine_block_ != kNone; }
    uint32_t refined() const { return refined_; } // refinements finished
    void stop() { stage_ = Stage::Idle, started_ = false; }

    bool busy() const { return stage_ != Stage::Idle; }
    bool sweeping() const { return sweep_; }
    bool sampling() const { return stage_ == Stage::Sampling; } // no edge may be drawn meanwhile
    uint32_t pass() const { return pass_; }
    float tolerance() const { return opt_.tolerance; }
    Work work() const { return stage_ == Stage::Sampling || stage_ == Stage::Refining ? Work::Sampling : Work::Face; }
    uint32_t item() const { return stage_ == Stage::Sampling || stage_ == Stage::Refining ? next_edge_ : face_; }

    // One piece: about `units` of work (geom::FaceJob's units). False when there was none.
    bool run(uint32_t units);

private:
    enum class Stage : uint8_t { Idle, Sampling, Faces, Refining };
    void sample(uint32_t units);
    Result sample_edges(uint32_t end, uint32_t units);
    void refine_sample(uint32_t units);
    bool evict_unwanted(); // the meshes of done faces the view does not want now (true: some)
    bool next_face(); // past faces not to tessellate now; false when the piece is spent on them
    // A pass's or a sweep's faces: every block's, block after block in order_'s order (asked for
    // when the first face is reached), face_ .. face_end_ the current block's.
    void all_blocks();
    bool next_block(); // face_ and face_end_ at the next block in order with faces; false past the last
    void finish_face(const Result& r);
    void end_faces();
    static constexpr uint32_t kChecksPerPiece = 48;
    static constexpr float kMaxFarAngle = 2.0f; // rad: a full circle in four sides at the coarsest // faces looked at (and deferred) in one piece

    Scene& scene_;
    Emitter emit_;
    Memory mem_{};
    FaceFilter filter_;
    BlockTolerance block_tolerance_;
    void set_level(Block& b);                         // its tolerance in this pass, when it has none yet
    geom::TessOptions options(const Block& b) const { return options_at(b.tolerance); } // the pass's at the block's level
    geom::TessOptions options_at(float tolerance) const;
    geom::TessOptions options_for(float tolerance) const; // (options_at() keeps its last)
    // A block's edges and faces all ask for the same (a square root and a division each in soft
    // float on the ARM926, 10 M instructions over the 10 k-face assembly's 25 k edges).
    mutable LastCall<geom::TessOptions, 3> options_;
    geom::TessOptions opt_;
    Stage stage_ = Stage::Idle;
    uint32_t pass_ = 0;        // 0: the first tessellation; +1 per level-of-detail change
    bool started_ = false;     // a pass has begun since load
    bool restoring_ = false;   // sampling the previous pass again after this one failed
    float previous_ = 0;       // the previous pass's tolerance
    float first_tolerance_ = 0; // the first pass's tolerance as asked (before it went coarser for room)
    uint32_t next_edge_ = 0;
    bool in_edge_ = false;     // an edge is being sampled (sampler_ holds where)
    uint32_t quantized_ = 0;   // samples quantized so far
    geom::EdgeSamples view_;   // the pool as the block of the edge or face under way numbers its edges
                               // (refining: with the block's edges' new (first, count) in the scratch)
    geom::EdgeSampler sampler_;
    uint32_t face_ = 0;        // the face being tessellated
    uint32_t face_end_ = 0;    // past the faces of this block (a pass, a sweep) or refinement
    uint32_t next_block_ = kNone; // the block after this one in order (a pass, a sweep)
    bool ordered_ = false;     // the order asked for in this pass or sweep
    BlockOrder order_;
    bool in_face_ = false;
    uint32_t refine_block_ = kNone; // the block being refined
    float refine_tolerance_ = 0;
    uint32_t refine_from_ = 0;         // its new samples' first in the pool
    uint32_t refined_ = 0;
    bool sweep_ = false;       // the faces again after the pass: only the deferred ones
    bool revisit_ = false;     // the view changed during the pass or sweep: a sweep (again) after it
    bool room_awaited_ = false; // a face the view wants was left to its edges for want of room in the mesh
    geom::FaceJob job_;
};

} // namespace facet::module
