#pragma once
// Frames: which buffer to draw into, whole or band by band, a piece at a time, and the
// handshake with the application's display (flush, flush_done).
//
// A frame is drawn when the picture on the screen is behind the model: the view changed, a
// level of detail began, a face was finished (the progress bar moved). With full frames and a
// depth buffer per draw buffer, a buffer that only lacks the latest faces gets just those
// (filling in costs those faces, not a frame), at most kProgressFrames times in a pass;
// otherwise the whole frame is drawn again, band after band with partial rendering (then
// progress is shown every sixteenth of the faces).
//
// A whole frame draws every face's triangles first, then every edge, speck and part box over
// them: an edge shows where it is nearer than every face, whatever the order the parts come
// in. With a faces layer (Display::faces: full frames) the first pass draws into the layer,
// which is copied into the draw buffer before the second; while the faces stay the same (only
// edges, the overlay, or what a drag left out change: redraw()), a whole frame is that copy
// and the second pass alone.
#include "annotations.h"
#include "camera.h"
#include "detail_scale.h"
#include "facet/viewer.h"
#include "overlay.h"
#include "painter.h"
#include "scene.h"
#include "scheduler.h"

#include <atomic>
#include <cstring>

namespace facet::module {
// flush_done()'s flag: released and acquired where another core may call it; on ARMv5 (one
// core, and no barrier instruction to call: __sync_synchronize is no routine there) the
// compiler's order (a signal fence) is all an interrupt needs.
#if defined(__ARM_ARCH) && __ARM_ARCH < 6
constexpr std::memory_order kDoneStore = std::memory_order_relaxed, kDoneLoad = std::memory_order_relaxed;
#else
constexpr std::memory_order kDoneStore = std::memory_order_release, kDoneLoad = std::memory_order_acquire;
#endif
} // namespace facet::module

namespace facet::module {

class Presenter {
public:
    // The application's clock, if any (a frame's cost in microseconds).
    struct Clock {
        uint32_t (*now_us)(void* user) = nullptr;
        void* user = nullptr;
        uint32_t operator()() const { return now_us ? now_us(user) : 0; }
    };

    Presenter(const Scene& scene, const Camera& camera, Painter& painter, render::Rasterizer& raster, const Emitter& emit,
              const Clock& clock)
        : scene_(scene), camera_(camera), painter_(painter), raster_(raster), emit_(emit), clock_(clock) {}

    // Checks the display's buffers; nothing is drawn before a model is loaded. `viewer`: the one
    // the display's flush is told of.
    Result configure(const Display& display, uint32_t frame_budget_us, Interface interface, Viewer& viewer);
    Overlay& overlay() { return overlay_; }
    // The model's annotations (PMI), drawn over it before the overlay.
    Annotating& annotating() { return annotating_; }
    const Annotating& annotating() const { return annotating_; }
    const Overlay& overlay() const { return overlay_; }
    // What the status bar shows that the presenter does not know (the level of detail).
    void set_tolerance(float mm) { tolerance_mm_ = mm; }
    void reset();        // a new model: nothing shown, nothing drawn
    void invalidate();   // every buffer must be drawn whole again (view, level of detail), its faces too
    void redraw() { ++version_; } // every buffer drawn whole again over the same faces (edges, overlay)

    static constexpr uint32_t kProgressFrames = 32; // frames filling in a model's faces, at most
    // Whether the screen is behind the model (`finished` faces of `total` done or failed).
    bool wanted(uint32_t finished, uint32_t total) const;
    uint32_t shown_finished() const { return shown_finished_; }
    // Whether a piece of a frame can be done now (a buffer free, or a frame under way).
    bool can_draw();
    // One piece of the frame (about `units` triangles). The last piece hands the frame over.
    void run(uint32_t units, uint32_t pass);
    // Frames begun from now on draw each instance's part box alone (its edges are being
    // sampled: nothing else of it can be drawn yet), or the model.
    void set_boxes(bool boxes) { boxes_ = boxes; }
    // Frames begun while the view is dragged are drawn lighter (Painter::set_dragging).
    void set_dragging(bool on) { dragging_ = on; }
    // Frames begun from now on are of a crowded view (Painter::set_crowded).
    void set_crowded(bool on) { crowded_ = on; }
    // Tests: false makes every transform afresh, none kept (what kept ones must draw the same as).
    void set_keep_transforms(bool keep) { keep_ = keep; }
    // A frame at rest's time: Config::frame_budget_us, else DetailScale's.
    uint32_t frame_budget_us() const { return budget_us_ ? budget_us_ : DetailScale::kRestFrameUs; }
    // Frames begun from now on draw proxies that stray up to this on the screen (pixels:
    // Painter::set_proxy_error).
    void set_proxy_error(float pixels, float left_out_pixels) { proxy_pixels_ = pixels, left_out_pixels_ = left_out_pixels; }
    // The kind of the piece run() would do next.
    Work work() const;
    bool drawing() const { return job_.active(); }
    // The triangles the last whole frame that drew every face took to the rasterizer (drawn or
    // culled), every instance's: what a frame of this view costs (0: none yet; with partial
    // rendering, a band's alone is not the view's, and none is counted).
    uint32_t triangles_in_view() const { return in_view_; }
    uint32_t in_view_us() const { return in_view_us_; } // the time of the frame that counted them
    uint32_t groups_drawn() const { return groups_drawn_; } // (tests) the groups the last whole frame drew as their proxies

    // Any context (a DMA interrupt, another thread): one store. At most one flush is in flight
    // (a frame's flush begins once the last is done), so calls for it are one event however
    // many come: a flag, not a count, which an interrupted increment could lose (ARMv5 has no
    // atomic read-modify-write to make one of).
    void flush_done() {
        std::atomic_signal_fence(std::memory_order_seq_cst); // (the compiler's order, on one core)
        done_.store(1, kDoneStore);
    }
    // Something else projected vertices into the painter's scratch (a pick): the face being
    // drawn starts over (its pixels drawn so far are drawn again, the same).
    void projected_reused() { job_.tri = 0; }
    // Off: a lagging buffer draws the faces it lacks again (the reference catch_up() must
    // match, for tests).
    void set_catch_up(bool on) { catch_up_ = on; }

private:
    Viewer* viewer_ = nullptr; // (configure())
    void run_piece(uint32_t units, uint32_t pass); // run()'s piece, timed by run()
    // A frame's stages, one after another (each a piece or more of work), by the kind of frame:
    //   whole, into the draw buffer:   Begin, BufferAll, Edges, [Annotations], Overlay, Flush
    //   whole, the faces layer kept:   Begin, CopyLayer, Edges, [Annotations], Overlay, Flush
    //   whole, through the layer:      Begin, LayerAll (or LayerNew: the faces it lacks), CopyLayer, Edges, [Annotations], Overlay, Flush
    //   an update (the faces since):   Begin, [LayerNew: the faces the layer lacks], BufferNew, [Annotations], Overlay, Flush
    // (Annotations: the model's PMI shown, annotations.h.)
    // Flush ends the frame (Idle) or, with partial rendering, begins its next band (Begin).
    enum class Stage : uint8_t {
        Idle,      // no frame under way
        Begin,     // waiting for the buffer; then the band cleared and the frame's way chosen
        LayerAll,  // every instance's faces, into the faces layer (cleared)
        LayerNew,  // the faces the layer lacks, into it (no edges)
        BufferAll, // every instance's faces, into the band of the draw buffer (cleared)
        CopyLayer, // the faces layer into the draw buffer (a piece of its own)
        Edges,     // every instance's edges, specks and boxes over the faces
        BufferNew, // the faces the buffer lacks, with their edges
        Annotations, // the PMI shown, over the model (annotations.h)
        Overlay,   // the status bar and the tools (a piece of its own: Work::Overlay)
        Flush,     // handed to the display once the previous flush is done
    };
    // Whether a stage draws into the faces layer (full detail, plain colours).
    static constexpr bool into_layer(Stage s) { return s == Stage::LayerAll || s == Stage::LayerNew; }
    struct Job {
        Stage stage = Stage::Idle;
        bool full = false;            // a whole frame (not an update)
        bool boxes = false, dragging = false, crowded = false; // set_boxes(), set_dragging(), set_crowded() as the frame began
        float proxy_pixels = 0, left_out_pixels = 0; // set_proxy_error() as the frame began
        uint8_t buffer = 0;
        uint16_t band = 0;            // partial rendering: the band being drawn
        uint32_t face_start = 0;      // the New stages: the first done_order index
        // Cursor: the instance, the face within its shell (or done_order index), the next
        // triangle of that face; the Edges stage: the instance's edges reset (and, from a layer,
        // its highlights drawn).
        // (A blocked pack with groups: `instance` is the place in the groups' members, in turn.)
        uint32_t instance = 0, face = 0, tri = 0;
        uint32_t id = 0;              // the instance drawn (Scene::instances)
        uint32_t groups_drawn = 0;    // groups drawn as their proxies (faces stages)
        uint32_t judged_group = kNone; // an update's last group judged (in_group_whole()), and
        bool group_whole = false;      // whether it is drawn whole (off the view, or its proxy)
        bool begun = false;
        bool all_faces = false;       // the frame draws every face (LayerAll or BufferAll), not the layer's copy
        // Drawn without its Edges stage: a new view's faces first, its frames of every face
        // having come near the frame budget (3/4 of it: Config::frame_budget_us, else
        // DetailScale's frame at rest); the next frame draws the edges over the layer's copy.
        bool edges_owed = false;
        bool have_transform = false;
        Transform transform{};
        Transform::Sight sight = Transform::Sight::Across; // where the instance's part lies
        bool tiny = false;            // and whether it is a few pixels across (drawn as its proxy, or box)
        uint32_t level = kNone;       // the proxy level it is drawn at (Painter::proxy_level), or kNone
        uint32_t version = 0, faces_version = 0, finished = 0, applied_to = 0;
        uint32_t cost_us = 0;
        uint32_t pieces = 0;          // pieces of work this frame took so far
        render::RasterStats stats;
        bool active() const { return stage != Stage::Idle; }
        // The next stage's cursor: from the first instance, at done_order index `face`.
        void restart(Stage next, uint32_t from_face) {
            stage = next, instance = 0, face = face_start = from_face, tri = 0, have_transform = false, begun = false;
        }
    };
    // Begin: the band made the target (cleared for a whole frame drawn anew) and the first
    // drawing stage chosen; false when that was the piece (`units` less what it cost).
    bool begin_stage(uint32_t& units);
    bool draw_stage(uint32_t units);   // a drawing stage's piece; true when the stage is done
    Stage after(Stage done) const;     // the stage that follows a drawing stage done
    void start(uint32_t finished);
    void set_band();
    // Whether buffer b's next frame is an update (the faces since it was drawn), not a whole
    // frame: drawn for the picture's state, or the other buffer is (a copy of it, then updates).
    bool updates(uint8_t b) const;
    // An update of one of two buffers that is stale, or lags the other by many faces: the
    // other's picture copied in (its faces then applied), instead of drawing them all again.
    void catch_up();
    void take_done();
    bool buffer_free(uint8_t b) const;
    // job_.sight, job_.tiny and job_.level, by its sphere (none known: Across); `must`: a
    // proxy or box whatever its size (left out, not sampled yet, a frame of boxes): the
    // coarsest proxy while the view's triangles are not known yet (a frame of boxes, or before
    // the first whole frame).
    void judge_part(uint32_t part, const Transform& t, bool must);
    bool full_pieces(uint32_t units);   // the stage's pass over the instances (faces, or edges); true when done
    // Groups (a blocked pack's index): the instance at place k of the groups' members in turn
    // (or k); a group judged whole: off the view, as its proxy (Painter::group_level's, at
    // `level`: none of its members hidden, lit or cut by the section), or its members each.
    uint32_t instance_at(uint32_t k) const;
    enum class GroupVerdict : uint8_t { Members, Out, Proxy };
    GroupVerdict judge_group(uint32_t group, uint32_t& level);
    // At job_.instance, the first member of a group: the members the group passes (0: drawn
    // each), its proxy drawn in a faces stage; `spent` the work.
    uint32_t pass_group(bool faces, uint32_t& spent);
    // An update's: whether the instance's group is drawn whole, none of its members' faces.
    bool in_group_whole(uint32_t instance);
    Transform group_transform_{}; // judge_group()'s: the model's own coordinates
    Annotating annotating_;
    uint32_t groups_drawn_ = 0;   // groups_drawn()
    bool update_pieces(uint32_t units); // the faces since the buffer (or the layer) was last drawn
    void set_target();                  // the stage's: the faces layer, or the band of the draw buffer
    void copy_layer();                  // the faces layer into the draw buffer (colour and depth)
    // Instance i's transform under the camera. What is its own (rotation, shift, light: some
    // 4 k instructions of soft float on the ARM926, issue 52's profile) is kept from frame to
    // frame for the first kKeptPlacements instances while the view, the screen and the model
    // stay the same (each stage of a frame takes every instance's, and a pass's frames share
    // one view); the rest is the view's basis, made once a view or section.
    const Transform& transform_of(uint32_t instance);
    // The view's basis for this view, section, screen and model (made again when one changed;
    // the placements kept then made anew where the placing changed).
    const ViewBasis& view_basis();
    // The view's transform of the placed model's own coordinates (mm / unit): what a group's
    // box and proxy and the annotations are drawn with.
    Transform model_transform(bool closed);
    // job_.transform's eye placed (Transform::place_eye; kept for kKeptEyes instances): before
    // the instance's own faces are drawn.
    void place_eye();
    bool layer_holds(uint32_t applied) const { return layer_.pixels && layer_.version == faces_version_ && layer_.applied >= applied; }
    void flush(uint32_t pass);

    const Scene& scene_;
    const Camera& camera_;
    Painter& painter_;
    render::Rasterizer& raster_;
    Emitter emit_;
    Clock clock_;
    Display display_{};
    uint8_t buffers_ = 1;
    bool incremental_ = false; // full frames with a depth buffer per draw buffer
    bool catch_up_ = true;     // set_catch_up()
    bool boxes_ = false;       // set_boxes()
    bool dragging_ = false;    // set_dragging()
    bool crowded_ = false;     // set_crowded()
    float proxy_pixels_ = 0, left_out_pixels_ = 0; // set_proxy_error()
    uint16_t bands_ = 1;

    uint32_t version_ = 1;      // the picture's state: +1 whenever every buffer must be redrawn
    uint32_t faces_version_ = 1; // the faces' state: +1 whenever their pixels may change (invalidate())
    struct Layer {
        Rgb565* pixels = nullptr; // Display::faces (null: none)
        uint16_t* depth = nullptr;
        uint32_t version = 0;     // the faces_version_ it holds (0: none)
        uint32_t applied = 0;     // the faces of done_order drawn into it
    } layer_;
    struct Buffer {
        uint32_t version = 0;   // drawn for this version (0: nothing)
        uint32_t applied = 0;   // faces of done_order drawn into it
        bool busy = false;      // in flight (Copy), or on the screen (Scanout)
    } buf_[2];
    int8_t shown_ = -1;         // Scanout: the buffer on the screen
    int8_t pending_ = -1;       // the buffer of the flush in flight
    uint32_t shown_version_ = 0, shown_finished_ = 0; // what the screen shows
    uint32_t next_ = 0;         // with two buffers: the next one to draw into (its low bit)
    std::atomic<uint32_t> done_{0}; // a flush_done() since take_done() last looked (loads and stores only)
    uint32_t piece_start_ = 0;  // the clock when the current piece began
    uint32_t budget_us_ = 0;    // Config::frame_budget_us
    uint32_t all_faces_us_ = 0; // the last frame of every face's cost, with its edges (owed or not)
    uint32_t owed_us_ = 0;      // the last frame's cost when it owed its edges
    Job job_;
    static constexpr uint32_t kKeptPlacements = 768, kKeptEyes = 128;
    struct KeptFor { // what every kept transform was made for
        View view;
        Section section;
        uint16_t width = 0, height = 0;
        float radius = 0, centre[3] = {0, 0, 0}, unit = 0;
        float explode = 0; // the scene's exploded view (its placements)
    } kept_for_;
    ViewBasis basis_{};       // what kept_for_'s view gives every transform
    bool keep_ = true;        // set_keep_transforms()
    uint32_t kept_stamp_ = 1; // the kept placements' stamp (one that differs: not kept)
    struct KeptPlacement {    // an instance's own part of its transform (Transform's fields)
        uint32_t stamp = 0;
        int32_t a[9], b[3], light[3];
        bool mirrored, closed;
        void keep(const Transform& t) {
            std::memcpy(a, t.a, sizeof a), std::memcpy(b, t.b, sizeof b), std::memcpy(light, t.light, sizeof light);
            mirrored = t.mirrored, closed = t.closed;
        }
        void into(Transform& t) const {
            std::memcpy(t.a, a, sizeof a), std::memcpy(t.b, b, sizeof b), std::memcpy(t.light, light, sizeof light);
            t.mirrored = mirrored, t.closed = closed;
        }
    } kept_[kKeptPlacements];
    struct KeptEye { // an instance's eye (Transform::place_eye), by instance % kKeptEyes
        uint32_t instance = ~0u, stamp = 0;
        int64_t eye[3];
        int32_t toward[3];
    } eyes_[kKeptEyes];
    Transform made_{}; // transform_of()'s answer
    Overlay overlay_;
    float tolerance_mm_ = 0;
    uint32_t last_frame_us_ = 0; // the last whole frame's cost
    uint32_t in_view_ = 0, in_view_us_ = 0; // triangles_in_view(), in_view_us()
};

} // namespace facet::module
