#include "presenter.h"

#include <cstring> // (std::memcpy)

#include "render/text.h"

namespace facet::module {

Result Presenter::configure(const Display& d, uint32_t frame_budget_us, Interface interface, Viewer& viewer) {
    viewer_ = &viewer;
    auto bad = [](const char* what) { return Result::fail(Status::OutOfRange, what, {"display"}); };
    if (d.width == 0 || d.height == 0 || d.width > 4096 || d.height > 4096) return bad("width and height must be 1 to 4096");
    if (d.band_lines == 0 || d.band_lines > d.height) return bad("band_lines must be 1 to the height (the height: full frames)");
    if (!d.buffers[0]) return bad("no draw buffer (buffers[0])");
    if (!d.depth[0]) return bad("no depth buffer (depth[0])");
    if (!d.flush) return bad("no flush callback");
    if (d.mode == Flush::Scanout && d.band_lines != d.height) return bad("scan-out displays take full frames (band_lines = height)");
    if (d.mode == Flush::Scanout && (d.x || d.y)) return bad("a scan-out display is the whole screen (x and y 0)");
    if (d.x + uint32_t(d.width) > 65535 || d.y + uint32_t(d.height) > 65535) return bad("the rectangle must lie within 65,535 pixels");
    if (!d.faces != !d.faces_depth) return bad("a faces layer takes both its colour and its depth (faces, faces_depth)");
    if (d.faces && d.band_lines != d.height) return bad("a faces layer takes full frames (band_lines = height)");
    display_ = d;
    budget_us_ = frame_budget_us;
    const bool on = interface != Interface::Off;
    overlay_.layout(on ? d.width : 0, on ? d.height : 0, interface == Interface::StatusLine);
    buffers_ = d.buffers[1] ? 2 : 1;
    const bool full = d.band_lines == d.height;
    incremental_ = full && (buffers_ == 1 || d.depth[1] != nullptr);
    bands_ = uint16_t((d.height + d.band_lines - 1) / d.band_lines);
    layer_ = {d.faces, d.faces_depth, 0, 0};
    reset();
    return {};
}

void Presenter::reset() {
    // What a flush in flight still reads stays busy until its flush_done(); the rest is free.
    for (Buffer& b : buf_) b.version = 0, b.applied = 0;
    version_ = 1;
    ++faces_version_, layer_.version = 0, layer_.applied = 0;
    shown_version_ = shown_finished_ = 0;
    job_ = {};
    in_view_ = 0, in_view_us_ = 0, all_faces_us_ = 0, owed_us_ = 0;
    ++kept_stamp_; // (another model: none kept)
}

void Presenter::invalidate() { ++version_, ++faces_version_; }

bool Presenter::wanted(uint32_t finished, uint32_t total) const {
    if (job_.active()) return true;
    if (shown_version_ != version_) return true;
    if (finished == shown_finished_) return false;
    // Progress is shown every 1/kProgressFrames of the faces (and at the last one): filling in
    // the latest faces costs those faces, but each frame also costs the overlay and a flush
    // (about 170 k instructions on the ARM926: a frame per face would double a large model's
    // load). Whole frames (no depth buffer per draw buffer) every sixteenth.
    const uint32_t parts = incremental_ ? kProgressFrames : 16;
    const uint32_t step = total / parts > 1 ? total / parts : 1;
    // (Past the total, a sweep adding deferred faces: a frame every step of them.)
    return (finished >= total && shown_finished_ < total) || finished - shown_finished_ >= step;
}

void Presenter::take_done() {
    if (done_.load(kDoneLoad)) {
        done_.store(0, std::memory_order_relaxed); // (a call between the two was for this same flush)
        std::atomic_signal_fence(std::memory_order_seq_cst);
        if (pending_ < 0) return; // a flush_done() with no flush in flight: nothing to free
        if (display_.mode == Flush::Copy || buffers_ == 1) {
            buf_[pending_].busy = false; // copied out (or a single frame drawn where it is shown)
        } else {
            if (shown_ >= 0 && shown_ != pending_) buf_[shown_].busy = false; // the previous frame is off the screen
            shown_ = pending_;
        }
        pending_ = -1;
    }
}

bool Presenter::buffer_free(uint8_t b) const { return !buf_[b].busy; }

bool Presenter::can_draw() {
    take_done();
    if (!job_.active()) return buffer_free(buffers_ == 2 ? uint8_t(next_ & 1) : 0);
    if (job_.stage == Stage::Begin) return buffer_free(job_.buffer);
    if (job_.stage == Stage::Flush) return pending_ < 0;
    return true;
}

void Presenter::start(uint32_t finished) {
    const uint8_t b = buffers_ == 2 ? uint8_t(next_ & 1) : 0;
    job_ = {};
    job_.stage = Stage::Begin;
    job_.buffer = b;
    job_.boxes = boxes_;
    job_.dragging = dragging_, job_.crowded = crowded_, job_.proxy_pixels = proxy_pixels_, job_.left_out_pixels = left_out_pixels_;
    job_.full = !updates(b);
    job_.version = version_;
    job_.finished = finished;
    job_.applied_to = scene_.totals().done;
    job_.faces_version = faces_version_;
    job_.face = job_.full ? 0 : buf_[b].applied;
    job_.pieces = 1; // this one
    raster_.stats = {};
    painter_.begin_frame(uint32_t(scene_.instances().size()));
}

void Presenter::set_target() {
    if (into_layer(job_.stage)) raster_.set_target({layer_.pixels, layer_.depth, display_.width, display_.height, 0, display_.height});
    else set_band();
}

void Presenter::copy_layer() {
    const uint32_t pixels = uint32_t(display_.width) * display_.height;
    const render::Target& t = raster_.target();
    render::copy_pixels(t.pixels, layer_.pixels, pixels);
    static_assert(sizeof(Rgb565) == sizeof(uint16_t));
    render::copy_pixels(reinterpret_cast<Rgb565*>(t.depth), reinterpret_cast<const Rgb565*>(layer_.depth), pixels);
}

void Presenter::set_band() {
    const uint16_t y0 = uint16_t(job_.band * display_.band_lines);
    const uint16_t rows = uint16_t(display_.height - y0 < display_.band_lines ? display_.height - y0 : display_.band_lines);
    uint16_t* depth = incremental_ && buffers_ == 2 ? display_.depth[job_.buffer] : display_.depth[0];
    raster_.set_target({display_.buffers[job_.buffer], depth, display_.width, display_.height, y0, rows});
}

bool Presenter::updates(uint8_t b) const {
    if (boxes_ || !incremental_) return false;
    if (buf_[b].version == version_) return true;
    // Drawn for an earlier state, the other buffer for this one: a copy of it, then updates.
    return catch_up_ && buffers_ == 2 && buf_[b ^ 1].version == version_;
}

void Presenter::catch_up() {
    const uint8_t b = job_.buffer, o = uint8_t(b ^ 1);
    if (buffers_ != 2) return;
    const uint32_t pixels = uint32_t(display_.width) * display_.height;
    if (buf_[b].version == version_) { // (else updates() chose the copy: a whole frame costs far more)
        if (!catch_up_ || buf_[o].version != version_ || buf_[o].applied <= buf_[b].applied) return;
        // The faces the other buffer has and this one lacks, drawn again, against a copy of its
        // colour and depth: a copy costs about an instruction and a half a pixel on the ARM926,
        // a triangle drawn about a thousand with its vertices and edges, so the copy wins once
        // they hold a triangle for every 700 pixels or so (taken from one for every 512).
        const uint32_t worth = pixels / 512;
        uint32_t triangles = 0;
        for (uint32_t k = buf_[b].applied; k < buf_[o].applied && triangles < worth; ++k) triangles += scene_.face(scene_.done_face(k)).triangle_count;
        if (triangles < worth) return;
    }
    render::copy_pixels(display_.buffers[b], display_.buffers[o], pixels);
    render::copy_pixels(display_.depth[b], display_.depth[o], pixels);
    buf_[b].version = version_;
    buf_[b].applied = buf_[o].applied;
}

void Presenter::judge_part(uint32_t part, const Transform& t, bool must) {
    int32_t centre[3], radius;
    const bool known = scene_.part_sphere(part, centre, radius);
    job_.sight = known ? t.sight(centre, radius, painter_.rows(t)) : Transform::Sight::Across;
    job_.tiny = known && job_.sight != Transform::Sight::Out && painter_.tiny(centre, radius, t);
    job_.level = kNone;
    if (job_.sight == Transform::Sight::Out) return;
    if (!known) centre[0] = centre[1] = centre[2] = 0, radius = 0;
    using Need = Painter::ProxyNeed;
    const Need need = !(must || job_.tiny) ? Need::Optional : job_.boxes || in_view_ == 0 ? Need::Coarsest : Need::Must;
    job_.level = painter_.proxy_level(part, centre, radius, t, need);
}

bool Presenter::full_pieces(uint32_t units) {
    const auto instances = scene_.instances();
    const bool faces = job_.stage != Stage::Edges;
    uint32_t spent = 0;
    while (job_.instance < instances.size()) {
        if (!job_.have_transform && job_.face == 0) { // at a group's first member: the group whole, off the view or as its proxy
            if (const uint32_t passed = pass_group(faces, spent)) {
                job_.instance += passed;
                if (spent >= units) return false;
                continue;
            }
        }
        const uint32_t id = job_.id = instance_at(job_.instance);
        if (!scene_.shown(id)) { // a hidden part
            ++job_.instance;
            continue;
        }
        const uint32_t shell = instances[id].shell;
        const Part sh = scene_.part(shell);
        if (!job_.have_transform) {
            job_.transform = transform_of(id);
            job_.have_transform = true;
            painter_.set_instance(id);
            judge_part(shell, job_.transform, job_.boxes || scene_.part_boxed(shell));
            painter_.set_inside(job_.sight == Transform::Sight::In);
        }
        const Transform& t = job_.transform;
        const Rows rows = painter_.rows(t);
        if (job_.sight == Transform::Sight::Out) { // the whole part off the view (or the band): none of it
            ++job_.instance;
            job_.face = 0;
            job_.have_transform = false;
            ++spent;
            if (spent >= units) return false;
            continue;
        }
        if (job_.boxes || scene_.part_boxed(shell) || job_.tiny || job_.level != kNone) {
            // (a part left out, or brought in and not sampled yet, a tiny one until it grows,
            // and one a crowded view shows small: its proxy with the faces, or, with none, its
            // box with the edges)
            const bool proxy = job_.level != kNone;
            if (faces && proxy) spent += painter_.part_proxy(shell, t, job_.level);
            if (!faces && proxy) spent += painter_.proxy_outline(shell, t, job_.level);
            if (!faces && !proxy) spent += painter_.part_box(shell, t);
            ++job_.instance;
            job_.have_transform = false;
            if (spent >= units) return false;
            continue;
        }
        place_eye(); // (drawn from its own faces: which of them face the eye)
        if (faces) { // each face's triangles
            while (job_.face < sh.face_count && spent < units) {
                const uint32_t f = sh.first_face + job_.face;
                if (scene_.face(f).state == FaceState::Done) { // (the others have no triangles: their edges, or a speck)
                    uint32_t used;
                    job_.tri = painter_.face(f, t, rows, job_.tri, units - spent, used);
                    spent += used;
                    if (job_.tri < scene_.face(f).triangle_count) return false; // more of this face next time
                    job_.tri = 0;
                }
                ++spent;
                ++job_.face;
            }
        } else { // each edge once in this instance (an edge has two faces), a face too small as a speck
            if (!job_.begun) { // (once: a piece that ends here goes on with the edges)
                painter_.reset_edges(shell);
                spent += 1 + sh.face_count / 256;
                // Faces from the layer: the highlighted ones in their colour over them.
                if (layer_.pixels) spent += painter_.highlighted_faces(sh.first_face, sh.face_count, t, rows);
                job_.begun = true;
            }
            for (; job_.face < sh.face_count && spent < units; ++job_.face) spent += painter_.face_edges(sh.first_face + job_.face, t, rows, true);
        }
        if (job_.face < sh.face_count) return false;
        ++job_.instance;
        job_.face = 0;
        job_.have_transform = false, job_.begun = false;
    }
    return true;
}

bool Presenter::update_pieces(uint32_t units) {
    const auto instances = scene_.instances();
    uint32_t spent = 0;
    // The faces finished since this buffer was last drawn, in every instance of their shell:
    // each face's triangles, then its edges over them. (A layer update: the faces the faces
    // layer lacks, into it, without their edges.)
    while (job_.instance < instances.size()) {
        const Part sh = scene_.part(instances[job_.instance].shell);
        job_.id = job_.instance;
        if (!scene_.shown(job_.instance)) job_.face = job_.applied_to; // a hidden part: none of its faces
        for (; job_.face < job_.applied_to && spent < units; ++job_.face) {
            const uint32_t f = scene_.done_face(job_.face);
            if (f < sh.first_face || f >= sh.first_face + sh.face_count) continue;
            if (!job_.have_transform) {
                job_.transform = transform_of(job_.instance);
                job_.have_transform = true;
                painter_.set_instance(job_.instance);
                painter_.set_inside(false); // (a face or two at a time: each tested)
                judge_part(instances[job_.instance].shell, job_.transform, false);
                if (job_.level != kNone || in_group_whole(job_.instance)) { // drawn as its proxy, or in its group's: none of its faces
                    job_.face = job_.applied_to;
                    break;
                }
                place_eye();
            }
            const Rows rows = painter_.rows(job_.transform);
            uint32_t used;
            job_.tri = painter_.face(f, job_.transform, rows, job_.tri, units - spent, used);
            spent += used + 1;
            if (job_.tri < scene_.face(f).triangle_count) return false;
            job_.tri = 0;
            if (job_.stage == Stage::BufferNew) spent += painter_.face_edges(f, job_.transform, rows, false);
        }
        if (job_.face < job_.applied_to) return false;
        ++job_.instance;
        job_.face = job_.face_start;
        job_.have_transform = false;
    }
    return true;
}

void Presenter::flush(uint32_t pass) {
    const render::Target& t = raster_.target();
    const uint8_t b = job_.buffer;
    pending_ = int8_t(b);
    buf_[b].busy = true;
    if (buffers_ == 2) ++next_;
    const bool last = job_.band + 1 >= bands_;
    if (last) {
        buf_[b].version = !job_.edges_owed && (job_.full || buf_[b].version == job_.version) ? job_.version : 0;
        buf_[b].applied = job_.applied_to;
    }
    // (in the screen's coordinates: facet's rectangle at (x, y) of it)
    display_.flush(*viewer_, display_.user, Area{display_.x, uint16_t(display_.y + t.y0), t.width, t.rows}, t.pixels); // may call flush_done()
    if (!last) {
        ++job_.band;
        job_.stage = Stage::Begin;
        job_.buffer = buffers_ == 2 ? uint8_t(next_ & 1) : 0;
        return;
    }
    shown_version_ = job_.edges_owed ? 0 : job_.version; // (edges owed: another frame is wanted)
    shown_finished_ = job_.finished;
    job_.stage = Stage::Idle;
    Event e{};
    e.kind = Event::Kind::FrameDone;
    const render::RasterStats& s = raster_.stats;
    const uint32_t cost = job_.cost_us + (clock_() - piece_start_);
    if (job_.full) last_frame_us_ = cost, groups_drawn_ = job_.groups_drawn;
    if (job_.full && job_.all_faces && !job_.edges_owed) all_faces_us_ = cost;
    // (A view's faces first: what the frame would have cost, its faces and then its edges.)
    if (job_.full && !job_.all_faces && owed_us_) all_faces_us_ = owed_us_ + cost;
    owed_us_ = job_.edges_owed ? cost : 0;
    if (job_.full && job_.all_faces && !job_.boxes && bands_ == 1) { // (not a frame of boxes: of the layout alone)
        in_view_ = s.triangles + s.culled, in_view_us_ = cost;
    }
    const uint32_t total = scene_.totals().faces, finished = job_.finished < total ? job_.finished : total;
    e.frame = {s.triangles, s.culled, s.pixels, cost, job_.pieces, finished, total, pass, job_.full, job_.boxes};
    emit_(e);
    if (budget_us_ && cost > budget_us_) {
        Event b{};
        b.kind = Event::Kind::BudgetExceeded;
        b.budget = {false, budget_us_, cost};
        emit_(b);
    }
}

Work Presenter::work() const {
    if (job_.active() && job_.version == version_) {
        if (job_.stage == Stage::Overlay) return Work::Overlay;
        return job_.full ? Work::Frame : Work::Update;
    }
    const uint8_t b = buffers_ == 2 ? uint8_t(next_ & 1) : 0;
    return updates(b) ? Work::Update : Work::Frame;
}

void Presenter::run(uint32_t units, uint32_t pass) {
    piece_start_ = clock_();
    if (!job_.active() || job_.version != version_) job_.pieces = 0; // (a new frame: start() resets it)
    ++job_.pieces;
    run_piece(units, pass);
    if (job_.active()) job_.cost_us += clock_() - piece_start_;
}

void Presenter::run_piece(uint32_t units, uint32_t pass) {
    take_done();
    if (job_.active() && job_.version != version_) job_.stage = Stage::Idle; // outdated: start over
    if (!job_.active()) start(scene_.totals().finished());
    if (job_.stage == Stage::Begin) {
        if (!buffer_free(job_.buffer)) return;
        if (!begin_stage(units)) return; // (the clearing was the piece)
    }
    // (One frame, one look: its bands and pieces alike. Faces drawn into the layer are drawn at
    // full detail, the layer serving the frames once a drag ends, and in their own colours.)
    painter_.set_dragging(job_.dragging && !into_layer(job_.stage));
    painter_.set_crowded(job_.crowded);
    painter_.set_proxy_error(job_.proxy_pixels, job_.left_out_pixels);
    painter_.set_plain(into_layer(job_.stage));
    switch (job_.stage) {
    case Stage::CopyLayer: // the view's faces, kept, into the draw buffer
        set_band();
        copy_layer();
        job_.edges_owed = job_.all_faces && bands_ == 1 && all_faces_us_ > frame_budget_us() / 4 * 3;
        job_.restart(job_.edges_owed ? after(Stage::Edges) : Stage::Edges, 0);
        return;
    case Stage::LayerAll:
    case Stage::LayerNew:
    case Stage::BufferAll:
    case Stage::Edges:
    case Stage::BufferNew:
        if (!draw_stage(units)) return;
        if (into_layer(job_.stage)) layer_.version = job_.faces_version, layer_.applied = job_.applied_to; // (the view's faces)
        job_.restart(after(job_.stage), job_.stage == Stage::LayerNew && !job_.full ? buf_[job_.buffer].applied : 0);
        return; // (the next stage in a piece of its own: a copy, or the overlay, is measured apart)
    case Stage::Annotations: {
        set_target(); // (the band)
        if (!job_.have_transform) {
            job_.transform = model_transform(false);
            job_.have_transform = true;
        }
        uint32_t spent = 0;
        const Transform& t = job_.transform;
        const Rows screen{t.cy16 - render::subpixel::start(0), render::subpixel::start(display_.height) - t.cy16};
        job_.face = annotating_.draw(raster_, t, painter_.rows(t), screen, scene_.unit(), 2 * scene_.radius(), job_.face, units, spent);
        if (job_.face > annotating_.count()) job_.restart(Stage::Overlay, 0);
        return; // (the overlay in a piece of its own)
    }
    case Stage::Overlay: {
        StatusInfo s;
        s.name = scene_.model_name();
        // (A sweep's faces count again as they come in: the bar never shows more than all.)
        s.total = scene_.totals().faces, s.finished = job_.finished < s.total ? job_.finished : s.total;
        s.triangles = scene_.totals().triangles, s.boxed_faces = scene_.left_out().faces;
        s.frame_us = last_frame_us_, s.tolerance_mm = tolerance_mm_, s.mode = painter_.mode(), s.ortho = camera_.view().ortho;
        s.tangent_edges = painter_.tangent_edges();
        overlay_.draw(raster_.target(), s);
        job_.stage = Stage::Flush;
        [[fallthrough]];
    }
    case Stage::Flush:
        take_done();
        if (pending_ >= 0) return; // the previous flush is still in flight
        flush(pass);
        return;
    case Stage::Idle:
    case Stage::Begin: return;
    }
}

bool Presenter::begin_stage(uint32_t& units) {
    set_band();
    Stage first;
    if (job_.full && layer_holds(job_.applied_to)) {
        first = Stage::CopyLayer; // the faces kept for the view: its copy, then the edges alone
    } else if (job_.full && layer_.pixels && !job_.dragging) {
        // (A frame while the view moves is drawn lighter, into the buffer: the layer keeps full
        // detail, and the frame once the view rests draws it anew.) The faces it lacks (drawn
        // in a pass since), or all of them.
        first = layer_.version == job_.faces_version ? Stage::LayerNew : Stage::LayerAll;
    } else if (job_.full) {
        first = Stage::BufferAll;
    } else {
        catch_up();
        // The faces the layer lacks first (at full detail: it serves the frames when a drag
        // ends), then the buffer's: the layer stays the view's faces through a pass.
        first = layer_.pixels && layer_.version == job_.faces_version && layer_.applied < job_.applied_to ? Stage::LayerNew
                                                                                                          : Stage::BufferNew;
    }
    job_.restart(first, first == Stage::LayerNew ? layer_.applied : job_.full ? 0 : buf_[job_.buffer].applied);
    set_target();
    if (first == Stage::LayerAll || first == Stage::BufferAll) painter_.background(), raster_.clear_depth();
    job_.all_faces = first == Stage::LayerAll || first == Stage::BufferAll;
    // Clearing a band costs about an instruction a pixel (colour and depth): a whole 640x480
    // frame is 0.4 M on the ARM926, a piece of its own (a piece stays near 1 M).
    const uint32_t spent = 1 + uint32_t(raster_.target().rows) * display_.width / 1024;
    if (spent * 2 >= units) return false;
    units -= spent;
    return true;
}

bool Presenter::draw_stage(uint32_t units) {
    set_target(); // (the faces layer, or the band)
    const bool whole = job_.stage == Stage::LayerAll || job_.stage == Stage::BufferAll || job_.stage == Stage::Edges;
    const bool done = whole ? full_pieces(units) : update_pieces(units);
    if (into_layer(job_.stage)) set_band(); // (between pieces the target is the draw buffer's)
    return done;
}

Presenter::Stage Presenter::after(Stage done) const {
    switch (done) {
    case Stage::LayerAll: return Stage::CopyLayer;
    case Stage::LayerNew: return job_.full ? Stage::CopyLayer : Stage::BufferNew;
    case Stage::BufferAll: return Stage::Edges;
    default: return annotating_.drawing() ? Stage::Annotations : Stage::Overlay; // (Edges, BufferNew)
    }
}

} // namespace facet::module
