#pragma once
// The viewer behind facet::Viewer: its parts, in the workspace, and the loop of step().
#include "camera.h"
#include "controls.h"
#include "detail.h"
#include "face_judge.h"
#include "fit.h"
#include "glide.h"
#include "facet/viewer.h"
#include "geom/library.h"
#include "geom/measure.h"
#include "loader.h"
#include "models.h"
#include "painter.h"
#include "picks.h"
#include "presenter.h"
#include "public_result.h"
#include "scene.h"
#include "scheduler.h"
#include "section.h"
#include "swap.h"
#include "workspace.h"

namespace facet {

class Core : public Viewer {
public:
    Core(const Config& config, module::Carver& carver, uint8_t* end);

    Result load(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes);
    void unload();
    // A library's models (library.cpp): the one open, and one a tap on the chooser asked for
    // (opened at the next step, outside the input's handling).
    Result set_library(const void* data, uint32_t bytes, void* memory, uint32_t memory_bytes);
    Result open_model(uint32_t index);
    uint32_t model_index() const { return models_.open(); }
    // Models on the product's storage (storage.cpp).
    Result set_storage(const Storage& storage, const char* folder, void* memory, uint32_t memory_bytes);
    // A pack file on the storage, or (offset, length) a library's model inside one.
    static constexpr uint32_t kWhole = 0xFFFFFFFFu;
    Result open_file(const char* path, void* memory, uint32_t memory_bytes, uint32_t offset = 0, uint32_t length = kWhole);
    void read_done(Status status) {
        if (module::Reader* l = lister_) l->done(status);
        else reader_.done(status);
    }
    Result storage_changed(bool present);
    const module::Models& models() const { return models_; }
    Activity step(uint32_t budget_us);
    void flush_done() { presenter_.flush_done(); }
    void command(const module::Command& c);
    void act(Action a);
    DisplayMode mode() const { return painter_.mode(); }
    void set_mode(DisplayMode m);
    bool tangent_edges() const { return painter_.tangent_edges(); }
    void set_tangent_edges(bool shown);
    Stats stats() const;
    bool carved() const { return carved_; }
    Result configure() { return presenter_.configure(config_.display, config_.frame_budget_us, config_.interface, *this); }

    // Pieces of work, in units: a frame's (a triangle's set-up or 64 pixels: about a thousand
    // instructions on the ARM926) and a face's (geom::FaceJob units: about five thousand).
    // A piece is then about a million instructions: under 2 ms at 600 MHz.
    static constexpr uint32_t kFrameUnits = 600;
    static constexpr uint32_t kTessUnits = 160;

    module::Controls& controls() { return controls_; }
    // The view rests after a drag: drawn again whole, with what a drag leaves out (its edges;
    // its faces were drawn at full detail into a faces layer, if there is one).
    void drag_ended(bool was_dragging) {
        if (was_dragging && !controls_.dragging()) presenter_.redraw();
    }
    // For tests of the parts behind the public API (the fitted view of every model).
    const module::Camera& camera() const { return camera_; }
    const module::Scene& scene() const { return scene_; }
    const module::Detail& detail_level() const { return detail_; } // (tests)
    const module::Scheduler& scheduler() const { return scheduler_; } // (tests)
    const Config& config() const { return config_; }                  // (tests)
    const Display& display() const { return config_.display; }
    const module::Overlay& overlay() const { return presenter_.overlay(); }
    module::Painter& painter() { return painter_; }
    module::Presenter& presenter() { return presenter_; }

    // The public API's calls (api.cpp: the Viewer's calls; views.cpp, pick.cpp, tools.cpp):
    // the built-in interface's buttons, keys and taps use these too.
    Orbit orbit() const;
    Result set_orbit(const Orbit& o);
    void show_view(StandardView v);
    void fit();
    Result fit_part(uint32_t part, uint32_t face = kNone); // a face of it, or the whole part
    void set_parallel(bool parallel);
    float detail() const;
    Result set_detail(float factor);
    FaceFacts pick(int16_t x, int16_t y); // facet's rectangle
    Result facts(uint32_t part, uint32_t face, FaceFacts& out) const;
    Result select(uint32_t part, uint32_t face);
    void clear_selection();
    uint32_t selection(FaceFacts out[2]) const;
    void set_measuring(bool on);
    bool measuring() const { return picks_.measuring(); }
    Measurement measure(const FaceFacts& a, const FaceFacts& b) const;
    Result isolate(uint32_t part);
    void show_all();
    Result section_through(uint32_t part, uint32_t face);
    Result section_across(uint8_t axis) { return sectioning_.across(axis); }
    Result move_section(float by_mm) { return sectioning_.move(by_mm); }
    ModelInfo model() const;
    // Ok when `face` is a face of `part` whose exact geometry is at hand (its block decoded).
    Result check_face(uint32_t part, uint32_t face) const;
    Result check_part(uint32_t part) const;

    // The assembly tree and the exploded view (api_tree.cpp).
    Result check_node(uint32_t node) const;
    Result show_node(uint32_t node, bool shown);
    Result isolate_node(uint32_t node);
    Result fit_node(uint32_t node);
    Result choose_node(uint32_t node);
    uint32_t chosen_node() const { return picks_.chosen_node(); }
    Result set_explode(float factor);
    void toggle_explode(); // Action::Explode: out (factor 1, the slider shown) or back
    // Annotations (api_pmi.cpp): the kinds shown, the one chosen.
    void show_annotations(uint32_t kinds);
    Result choose_annotation(uint32_t annotation);
    uint32_t chosen_annotation() const { return picks_.chosen_annotation(); }
    const module::Annotating& annotating() const { return presenter_.annotating(); }

    // Tools (tools.cpp): the section plane and the parts.
    void tool(Action a);
    Result show(uint32_t part, bool shown);
    void choose(uint32_t part);
    uint32_t chosen_part() const { return picks_.chosen(); }
    void set_section(const module::Section& s) { sectioning_.set(s, module::Sectioning::Kind::Z); } // (the cycle goes on to off)

private:
    static void relay(void* self, const Event& e); // the parts' events: act on some, pass all on
    void emit(const Event& e) const; // to the application, its `why` with a public status (public_result.h)
    void drain(); // the events held back while a piece of work ran
    void work(Event::Kind kind, Work what, uint32_t item);
    uint32_t now() const { return config_.now_us ? config_.now_us(config_.clock_user) : 0; }
    module::Reader::Clock clock() const { return {config_.now_us, config_.clock_user}; }
    bool frame_wanted() const;
    bool boxes_while_sampling() const;
    // step()'s sources of work (core.cpp: kSources, in priority order): each says whether it has
    // a piece now, from what the round found, and runs one (false: it had none after all).
    struct Round {
        bool frame = false;     // a frame is wanted and a buffer can take it
        bool mid_bands = false; // the bands of a frame under way: nothing else between them
        bool framing = false;   // the bounds or the framing (of the view or of a glide's end) under way
    };
    Round round();
    // The bands of a frame are under way: nothing else runs between them (they show one state).
    bool mid_bands() const { return presenter_.drawing() && config_.display.band_lines < config_.display.height; }
    struct Source {
        bool (Core::*ready)(const Round&) const;
        bool (Core::*run)();
    };
    static const Source kSources[];
    bool framing_ready(const Round& r) const;
    bool glide_ready(const Round& r) const;
    bool frame_ready(const Round& r) const;
    bool tessellation_ready(const Round& r) const;
    bool decoding_ready(const Round& r) const;
    bool start_ready(const Round& r) const;
    bool run_framing();
    bool run_glide();
    bool run_frame();
    bool run_tessellation();
    bool run_decoding();
    bool run_start();
    Activity activity(); // after a step: Busy, Waiting (for flush_done()) or Idle
    void tap(int16_t x, int16_t y);      // a tap or click on facet's rectangle: a button, the parts list, or a pick
    Event pick_at(int16_t x, int16_t y); // the Picked event of the face under (x, y) (facet's rectangle)
    void view_changed();
    // Frame the placed model (from the default direction, or this one; from_here: starting from
    // the view as it is, framed already for a nearly equal outline).
    void fit_view(bool keep_direction, bool from_here = false);
    void bound(bool sampled);           // the placed model's bounds again, before it is framed

    Config config_;
    module::Emitter emitter_;
    module::Scene scene_;
    module::Camera camera_;
    module::Controls controls_;
    render::Rasterizer raster_;
    module::Painter painter_;
    module::Scheduler scheduler_;
    module::Presenter presenter_;
    module::Framer framer_;
    module::View framed_from_; // the view when the framing began: a framing that ends there redraws nothing
    std::span<module::Projected> projected_;
    // The workspace past the base arrays: the model's arrays from model_start_ (planned at
    // load), the pack's decoded blocks at its end (end_) when load() is given no memory.
    uint8_t *model_start_ = nullptr, *end_ = nullptr;
    // The model's arrays in [model_start_, end): every face and edge numbered, room at least for
    // the wireframe of `sampled_edges` (those of the blocks opened).
    Result plan(uint32_t faces, uint32_t edges, uint32_t sampled_edges, uint8_t* end);
    // Where the pack memory goes: `need` bytes (pack_memory_need()).
    Result place_pack(const void* file, uint32_t file_size, uint32_t need, void*& memory, uint32_t& memory_bytes,
                      uint8_t*& model_end) const;
    // A blocked pack larger than the memory: the blocks it keeps (the largest), so that their
    // decoded packs and arrays fit with room to tessellate; the default (all) when all fit.
    module::BlockCut cut_blocks(const void* file, uint32_t file_bytes, uint32_t file_size, void* memory, uint32_t memory_bytes,
                                const module::Reader* reader) const;
    Result open_pack(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes, module::Reader* reader);
    // The blocks' levels (detail.h) and the blocks brought in as the view nears them (swap.h).
    module::FaceJudge judge_; // which faces the view wants (face_judge.h)
    module::Detail detail_;
    module::Swapper swapper_;
    module::Sectioning sectioning_; // the section plane as a tool (section.h)
    // Nothing moves the view on its own: no bounds or framing under way, no glide.
    bool settled() const { return !scene_.bounding() && !framer_.busy() && glide_.idle(); }
    bool swap_pending() const { return swapper_.pending() && !controls_.dragging(); } // blocks to look at, no drag
    bool swap_piece();     // a block brought in begun, as a piece of work (Work::Unpack): true when begun
    bool refine_for_view(); // a block's level begun again for the view: true when begun (or tried)
    static void blocks_left_out(void* self); // (Swapper::LeftOut) the picks in them go
    void forget_left_out_picks();
    module::Models models_; // a library's models, or a storage folder's (models.h)
    // The product's storage (set_storage()), the model's file open on it (its path), and a
    // file being listed (its reads' read_done()).
    Storage storage_{};
    bool has_storage_ = false, storage_present_ = false;
    module::Reader reader_;
    module::Reader* volatile lister_ = nullptr;
    char open_path_[module::Models::kFolderBytes + kStorageNameBytes] = {};
    uint32_t open_offset_ = 0, open_length_ = kWhole; // (a library's model)
    uint32_t open_crc_ = 0; // a blocked pack's index CRC | 1 (a card put back holds the same file); 0: none
    Result list_storage();
    Result load_listed(uint32_t index); // the chooser's model `index` (library.cpp)
    Result reopen_storage_file(); // the storage came back: the open model's file again, if unchanged
    uint32_t seen_moves_ = 0, seen_refined_ = 0; // the scene's moves and refinements the frames know of
    bool whole_frame_owed_ = false;              // a refinement's whole frame, once the blocks coming in are in
    void pay_whole_frame();
    uint32_t pack_bytes_ = 0, pack_file_bytes_ = 0;
    bool carved_ = false;
    bool user_moved_ = false; // the view was moved since load (no framing again when the faces are in)
    module::Glide glide_; // a glide to a new view (glide.h)
    static constexpr uint32_t kDoubleTapUs = 400000;
    static constexpr int kDoubleTapSlop = 12; // pixels
    void glide_to(const module::View& v, uint32_t instance = kNone, uint32_t face = kNone, uint32_t instances = 1);
    bool glide_step(); // Moving: the camera advanced (a frame is wanted); false when it has arrived
    module::Picks picks_; // the faces picked and the part chosen, shown (picks.h)
    uint8_t next_view_ = 0; // the toolbar's VIEW button: the next standard view
    bool tap_parts(int16_t x, int16_t y); // a tap on the parts list (true: it was the list's)
    bool tap_pmi(int16_t x, int16_t y);   // a tap on the annotations list (api_pmi.cpp)
    bool tap_models(int16_t x, int16_t y); // a tap on the models chooser (library.cpp)
    void toggle_models();
    // Double tap: the last tap's place and time (without a clock: a second tap on the same spot).
    int16_t tap_x_ = -1000, tap_y_ = -1000;
    uint32_t tap_t_ = 0;
    // Events of a piece of work are handed on after it (so a profiler's region around the
    // piece measures the work, not what the application does with its events).
    static constexpr uint32_t kHeld = 8;
    Event held_[kHeld];
    uint32_t held_count_ = 0;
    bool in_piece_ = false;
};

} // namespace facet
