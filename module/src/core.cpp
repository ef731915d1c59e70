// The viewer's core: load and unload, the loop of step(), input's commands and the actions.
#include "core.h"
#include "detail_scale.h"
#include "geom/pack_file.h"
#include "loader.h"

#include <cstring>
#include <new>

namespace facet {

void Core::relay(void* self, const Event& e) {
    Core& c = *static_cast<Core*>(self);
    switch (e.kind) {
    case Event::Kind::Pass: c.presenter_.set_tolerance(e.pass.tolerance_mm); break;
    case Event::Kind::PassFailed: c.presenter_.set_tolerance(c.scheduler_.tolerance()); break; // back to the previous level
    case Event::Kind::Sampled: // the new level's wireframe; the first one frames the placed model
        if (e.pass.pass == 0) { // in the direction the user chose meanwhile, if any (each bounds the sampled model)
            if (!c.glide_.idle()) c.glide_to(c.glide_.target().view());
            else c.fit_view(c.user_moved_);
        }
        c.presenter_.invalidate();
        break;
    case Event::Kind::Tessellated: // the progress bar goes; the first pass's outline is final
        // (a cylinder's silhouette is no edge): framed again unless the user has moved the view
        // Then a whole frame: the frames drawn over the last as the faces came in keep the
        // wireframe's lines where no face drawn since hides them (the edges of a face left out
        // as too small, which a whole frame draws as a speck).
        if (e.tessellated.pass == 0 && !c.user_moved_) c.fit_view(true, true);
        c.presenter_.redraw(); // (the same faces; the framer invalidates them if the view moves)
        break;
    default: break;
    }
    if (!c.config_.on_event) return;
    if (c.in_piece_ && c.held_count_ < kHeld) {
        c.held_[c.held_count_++] = e;
        return;
    }
    c.emit(e);
}

void Core::emit(const Event& e) const {
    if (!config_.on_event) return;
    if (module::is_public(e.why.status)) return config_.on_event(config_.event_user, e);
    Event told = e;
    told.why = module::public_result(e.why);
    config_.on_event(config_.event_user, told);
}

void Core::drain() {
    for (uint32_t i = 0; i < held_count_; ++i) emit(held_[i]);
    held_count_ = 0;
}

void Core::work(Event::Kind kind, Work what, uint32_t item) {
    in_piece_ = kind == Event::Kind::WorkBegin;
    if (!config_.on_event) return;
    Event e;
    e.kind = kind;
    e.work = {what, item};
    emit(e);
    if (!in_piece_) drain();
}

void Core::unload() {
    scheduler_.stop();
    framer_.stop();
    swapper_.open({});
    glide_.stop();
    presenter_.reset();
    scene_.close();
    pack_bytes_ = pack_file_bytes_ = 0;
    reader_.close();
    open_path_[0] = 0, open_crc_ = 0;
    models_.forget();
    sectioning_.reset();
    presenter_.annotating().set(nullptr);
    presenter_.overlay().set_pmi(false);
    presenter_.overlay().set_explode_slider(false, 0);
    picks_.reset();
}

Result Core::load(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes) {
    unload();
    return open_pack(file, file_bytes, memory, memory_bytes, nullptr);
}

// A pack file opened into the scene (nothing loaded): in memory, or with a reader on storage a
// blocked pack's index read into the pack memory (storage.cpp).
Result Core::open_pack(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes, module::Reader* reader) {
    if (geom::is_library(file, file_bytes)) {
        return Result::fail(Status::Unsupported, "a library of several models: set_library() and open_model() open one");
    }
    const geom::PackFileKind kind = file ? geom::pack_file_kind(file, file_bytes) : geom::PackFileKind::Unknown;
    if (reader && kind != geom::PackFileKind::Blocked) return Result::fail(Status::Corrupt, "no blocked pack's index here");
    const bool decoding = kind != geom::PackFileKind::Pack && kind != geom::PackFileKind::Unknown;
    // (a file in the pack memory is decoded over; an index read from storage is counted in the need)
    const uint32_t file_size = reader ? 0 : file ? geom::pack_file_bytes(file, file_bytes) : 0;
    uint8_t* model_end = end_;
    // A blocked pack larger than the memory: its largest blocks, the rest as boxes.
    const module::BlockCut cut =
        kind == geom::PackFileKind::Blocked ? cut_blocks(file, file_bytes, file_size, memory, memory_bytes, reader) : module::BlockCut{};
    const uint32_t need = file ? module::pack_memory_need(file, file_bytes, cut, reader) : 0;
    if (Result r = place_pack(file, file_size, need, memory, memory_bytes, model_end); !r.ok()) return r;
    if (decoding) work(Event::Kind::WorkBegin, Work::Unpack, 0);
    module::Unpacked unpacked;
    const Result decoded = module::unpack(file, file_bytes, memory, memory_bytes, cut, unpacked, reader);
    if (decoding) work(Event::Kind::WorkEnd, Work::Unpack, 0);
    if (!decoded.ok()) return decoded;
    if (Result r = module::open_unpacked(unpacked, scene_); !r.ok()) return r;
    presenter_.annotating().set(&scene_.annotations());
    presenter_.overlay().set_annotating(&presenter_.annotating());
    swapper_.open(unpacked);
    if (Result r = plan(scene_.face_count(), scene_.edge_count(), scene_.edge_count() - scene_.left_out().edges, model_end); !r.ok()) return r;
    pack_file_bytes_ = reader ? reader->bytes() : file_size;
    pack_bytes_ = unpacked.bytes;
    const uint32_t bytes = pack_bytes_;
    detail_.reset(geom::default_tolerance(scene_.box_min(), scene_.box_max())); // (judged afresh)
    camera_.fit();
    user_moved_ = false;
    Event e{};
    e.kind = Event::Kind::Loaded;
    e.loaded = {scene_.face_count() - scene_.left_out().faces, scene_.edge_count() - scene_.left_out().edges, scene_.part_count(),
                uint32_t(scene_.instances().size()), bytes,
                pack_file_bytes_, scene_.left_out().parts, scene_.left_out().faces};
    emit(e);
    scheduler_.begin_pass(detail_.default_tolerance());
    return {};
}

bool Core::frame_wanted() const {
    if (!scene_.loaded() || scene_.bounding() || framer_.busy() || glide_.framing()) return false;
    if (scheduler_.sampling() && !boxes_while_sampling()) return false; // no edge may be drawn meanwhile
    const module::Totals& t = scene_.totals();
    return presenter_.wanted(t.finished(), t.faces);
}

// While the first pass samples the edges of a blocked pack, its parts' boxes (the index's) are
// drawn: the model's layout on the screen right after load, turned and zoomed as the user likes.
bool Core::boxes_while_sampling() const {
    return scheduler_.sampling() && scheduler_.pass() == 0 && scene_.blocked();
}

// What step() finds at the top of each round, in this order (presenter_.can_draw() takes a
// finished flush: it is asked once a round, and only when a frame is wanted).
Core::Round Core::round() {
    Round r;
    r.frame = frame_wanted() && presenter_.can_draw();
    r.mid_bands = mid_bands();
    r.framing = scene_.bounding() || framer_.busy() || glide_.framing();
    return r;
}

// The sources of work, in priority order: each round runs a piece of the first that has one
// (docs/viewer.md shows the table). Nothing but a frame's own bands runs between the bands of
// one frame (they show one state of the model).
const Core::Source Core::kSources[] = {
    {&Core::framing_ready, &Core::run_framing},           // framing: the view being framed, no frame until it sits
    {&Core::glide_ready, &Core::run_glide},               // glide: the last frame is out, the glide's next step
    {&Core::frame_ready, &Core::run_frame},               // frame: the screen is behind and a buffer is free
    {&Core::tessellation_ready, &Core::run_tessellation}, // tessellation: the scheduler's pass, sweep or refinement
    {&Core::decoding_ready, &Core::run_decoding},         // decoding: a block the view brings in, a piece at a time
    {&Core::start_ready, &Core::run_start},               // start: a block to bring in, or one to refine, begun
};

bool Core::framing_ready(const Round& r) const { return r.framing && !r.mid_bands; }
bool Core::glide_ready(const Round& r) const { return glide_.moving() && !frame_wanted() && !r.mid_bands; }
bool Core::frame_ready(const Round& r) const { return r.frame; }
bool Core::tessellation_ready(const Round& r) const { return scheduler_.busy() && !r.mid_bands; }
bool Core::decoding_ready(const Round& r) const { return swapper_.decoding() && !r.mid_bands; }
bool Core::start_ready(const Round& r) const { return !r.mid_bands; }

bool Core::run_framing() {
    work(Event::Kind::WorkBegin, Work::Fit, 0);
    if (scene_.bounding()) {
        (void)scene_.bound(kFrameUnits * module::Framer::kPointsPerUnit * 4); // (a bounded point: a quarter of a projected one)
    } else if (glide_.framing()) {
        if (framer_.run(scene_, glide_.target(), kFrameUnits)) {
            glide_.framed(camera_.view(), now());
        }
    } else if (framer_.run(scene_, camera_, kFrameUnits)) {
        if (!module::same_view(camera_.view(), framed_from_)) presenter_.invalidate();
    }
    work(Event::Kind::WorkEnd, Work::Fit, 0);
    return true;
}

bool Core::run_glide() {
    glide_step();
    return true;
}

bool Core::run_frame() {
    detail_.look_first();
    presenter_.set_boxes(boxes_while_sampling());
    presenter_.set_dragging(controls_.dragging() || glide_.moving());
    presenter_.set_crowded(detail_.crowd() > 1);
    // (A part left out whose proxy is not within the view's error is on its way in: it stands
    // as one at the crowd's coarsest error, so a first frame, every part left out, is not
    // drawn at the finest.)
    presenter_.set_proxy_error(config_.screen_error_px * detail_.crowd(), config_.screen_error_px * module::DetailScale::kCrowdCoarsest);
    const Work w = presenter_.work();
    work(Event::Kind::WorkBegin, w, 0);
    presenter_.run(kFrameUnits, scheduler_.pass());
    work(Event::Kind::WorkEnd, w, 0);
    return true;
}

bool Core::run_tessellation() {
    const Work w = scheduler_.work();
    const uint32_t item = scheduler_.item();
    work(Event::Kind::WorkBegin, w, item);
    const bool sweeping = scheduler_.sweeping();
    (void)scheduler_.run(kTessUnits); // busy: there was a piece to do
    // A sweep's faces show as they come (Presenter::wanted) and all at its end.
    // (The same faces: the frames since drew each as it came, the whole one its edges and specks.)
    if (sweeping && !scheduler_.sweeping() && scene_.totals().finished() != presenter_.shown_finished()) presenter_.redraw();
    // Meshes moved (a cache compacted, a block dropped): the frames whole again. A block made
    // again or brought in: the same, or, while more are coming in, once the last of them is
    // (whole_frame_owed_; the updates meanwhile draw each face as it comes).
    if (scene_.moves() != seen_moves_) {
        seen_moves_ = scene_.moves(), seen_refined_ = scheduler_.refined();
        presenter_.invalidate();
        whole_frame_owed_ = false;
    } else if (scheduler_.refined() != seen_refined_) {
        seen_refined_ = scheduler_.refined();
        whole_frame_owed_ = true;
        pay_whole_frame();
    }
    work(Event::Kind::WorkEnd, w, item);
    return true;
}

bool Core::run_decoding() {
    const uint32_t block = swapper_.block();
    work(Event::Kind::WorkBegin, Work::Unpack, block);
    swapper_.step();
    work(Event::Kind::WorkEnd, Work::Unpack, block);
    return true;
}

// The whole frame owed once the blocks coming in are in (none waiting, none being decoded or
// tessellated).
void Core::pay_whole_frame() {
    if (!whole_frame_owed_ || swap_pending() || swapper_.decoding() || scheduler_.busy()) return;
    whole_frame_owed_ = false;
    presenter_.invalidate();
}

// False: nothing to begin. Over the triangles' bound, blocks are made coarser before another comes in.
bool Core::run_start() {
    const float crowd = detail_.crowd();
    const bool over =
        settled() && detail_.bound_triangles(presenter_.triangles_in_view(), presenter_.in_view_us(), presenter_.frame_budget_us());
    if (detail_.crowd() != crowd) presenter_.redraw(); // (edges of small faces in or out: Painter::set_crowded)
    if (over) return refine_for_view() || swap_piece();
    return swap_piece() || refine_for_view();
}

// The choice and the room made (blocks left out, the pack memory compacted) as a piece of
// unpacking work, when there is a choice to make.
bool Core::swap_piece() {
    if (!swap_pending()) return false;
    work(Event::Kind::WorkBegin, Work::Unpack, 0);
    const bool begun = settled() && swapper_.begin();
    work(Event::Kind::WorkEnd, Work::Unpack, 0);
    return begun;
}

bool Core::refine_for_view() { return !controls_.dragging() && settled() && detail_.refine(swapper_); }

void Core::blocks_left_out(void* self) { static_cast<Core*>(self)->forget_left_out_picks(); }

// A face picked in a block left out is no longer there to describe or highlight: the
// selection and the measurement go (as after a tap on nothing).
void Core::forget_left_out_picks() {
    picks_.forget([&](const module::Picks::Face& p) { return scene_.block_of_face(p.face).left_out; });
}

// The level of detail as a factor of the default tolerance (the screen error scales with it).
float Core::detail() const { return detail_.factor(); }

Result Core::set_detail(float factor) {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    return detail_.set_factor(factor);
}

Activity Core::step(uint32_t budget_us) {
    if (const uint32_t m = models_.take_asked(); m != kNone) { // a model the chooser asked for (a failure is its event)
        (void)open_model(m);
        return Activity::Busy;
    }
    if (!scene_.loaded()) return Activity::Idle;
    const uint32_t t0 = now();
    for (;;) {
        // Faces left to their edges are judged again when the view has moved (not while it is being framed).
        if (settled() && detail_.view_changed()) swapper_.view_changed();
        const Round r = round();
        bool ran = false;
        for (const Source& s : kSources) {
            if (!(this->*s.ready)(r)) continue;
            ran = (this->*s.run)();
            break;
        }
        if (!ran) break; // nothing to do now (or only the bands of a frame waiting for a buffer)
        if (!config_.now_us || now() - t0 >= budget_us) break;
    }
    const uint32_t used = now() - t0;
    if (config_.now_us && used > budget_us + config_.step_slack_us) {
        Event e{};
        e.kind = Event::Kind::BudgetExceeded;
        e.budget = {true, budget_us, used};
        emit(e);
    }
    return activity();
}

// What is left after a step: work that can go on, or only a flush_done() that can free a
// buffer. With nothing else left, a block the view wants at another level is begun now, so
// that the next step has its work (a step without a clock is one piece of work).
Activity Core::activity() {
    const bool mid_bands = this->mid_bands();
    if (!mid_bands && !frame_wanted() && !scheduler_.busy()) (void)run_start();
    pay_whole_frame();
    if ((frame_wanted() && presenter_.can_draw()) ||
        ((scheduler_.busy() || swapper_.decoding() || swap_pending() || !settled()) &&
         !mid_bands)) {
        return Activity::Busy;
    }
    if (frame_wanted()) return Activity::Waiting;
    return Activity::Idle;
}

void Core::command(const module::Command& c) {
    using Kind = module::Command::Kind;
    const Display& d = config_.display;
    switch (c.kind) {
    case Kind::None: return;
    case Kind::Act: act(c.action); return;
    case Kind::Orbit: camera_.orbit(c.yaw, c.pitch); break;
    case Kind::Pan: camera_.pan_pixels(c.dx, c.dy, scene_.radius(), d.width, d.height); break;
    case Kind::Dolly: camera_.dolly(c.factor); break;
    case Kind::Pick: tap(c.x, c.y); return;
    case Kind::Slide:
        if (presenter_.overlay().slider_explodes()) (void)set_explode(presenter_.overlay().slider_at(c.y) * module::Scene::kMostExplode);
        else sectioning_.at(presenter_.overlay().slider_at(c.y), false);
        return;
    }
    view_changed();
}

void Core::view_changed() {
    camera_.keep_in_range(scene_.radius()); // (a pan accumulated past kPanRadii stops there)
    user_moved_ = true;
    presenter_.invalidate();
    Event e{};
    e.kind = Event::Kind::ViewChanged;
    const module::View& v = camera_.view();
    e.view = {v.yaw * 57.29578f, v.pitch * 57.29578f, v.zoom};
    emit(e);
}

void Core::act(Action a) {
    if (a == Action::Models) return toggle_models(); // (with no model too: after one failed to open)
    if (!scene_.loaded()) return;
    const float pan = 0.1f * scene_.radius(), turn = module::Camera::kTurn;
    switch (a) {
    case Action::None:
    case Action::Models: return;
    case Action::TurnLeft: camera_.orbit(-turn, 0); break;
    case Action::TurnRight: camera_.orbit(turn, 0); break;
    case Action::TiltUp: camera_.orbit(0, -turn); break;
    case Action::TiltDown: camera_.orbit(0, turn); break;
    case Action::ZoomIn: camera_.dolly(0.8f); break;
    case Action::ZoomOut: camera_.dolly(1.25f); break;
    case Action::PanLeft: camera_.pan(-pan, 0); break;
    case Action::PanRight: camera_.pan(pan, 0); break;
    case Action::PanUp: camera_.pan(0, pan); break;
    case Action::PanDown: camera_.pan(0, -pan); break;
    case Action::Fit: fit(); return;
    case Action::ViewFront: show_view(StandardView::Front); return;
    case Action::ViewBack: show_view(StandardView::Back); return;
    case Action::ViewRight: show_view(StandardView::Right); return;
    case Action::ViewLeft: show_view(StandardView::Left); return;
    case Action::ViewTop: show_view(StandardView::Top); return;
    case Action::ViewBottom: show_view(StandardView::Bottom); return;
    case Action::ViewIso: show_view(StandardView::Iso); return;
    case Action::NextDisplayMode: set_mode(DisplayMode((uint8_t(painter_.mode()) + 1) % 5)); return;
    case Action::TangentEdges: set_tangent_edges(!painter_.tangent_edges()); return;
    case Action::Annotations: show_annotations(presenter_.annotating().shown() ? 0 : pack::kAllKinds); return;
    case Action::Explode: toggle_explode(); return;
    case Action::Section:
    case Action::SectionIn:
    case Action::SectionOut:
    case Action::Parts:
    case Action::NextPart:
    case Action::HidePart:
    case Action::IsolatePart:
    case Action::ShowAllParts: tool(a); return;
    case Action::NextView: {
        static constexpr StandardView kOrder[] = {StandardView::Iso, StandardView::Front, StandardView::Right, StandardView::Top,
                                                  StandardView::Back, StandardView::Left, StandardView::Bottom};
        show_view(kOrder[next_view_]);
        next_view_ = uint8_t((next_view_ + 1) % 7);
        return;
    }
    case Action::Measure: set_measuring(!measuring()); return;
    case Action::Help:
        presenter_.overlay().toggle_help();
        presenter_.invalidate();
        return;
    case Action::Projection:
        set_parallel(!(glide_.going_to(camera_.view())).ortho);
        return;
    case Action::Coarser:
    case Action::Finer:
    case Action::NextDetail: {
        const float r = detail();
        auto near = [r](float x) { return r > x * 0.98f && r < x * 1.02f; };
        float f = a == Action::Coarser ? r * 2 : r * 0.5f;
        if (a == Action::NextDetail) f = near(1) ? 0.5f : near(0.5f) ? 0.25f : near(0.25f) ? 2.0f : 1.0f; // x1 -> x1/2 -> x1/4 -> x2 -> x1
        (void)set_detail(f); // refused at its limits: stays
        return;
    }
    }
    view_changed();
}

} // namespace facet
