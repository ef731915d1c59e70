#include "scheduler.h"

#include <algorithm>
#include <cmath>

namespace facet::module {

void Scheduler::begin_pass(float tolerance) {
    if (!started_) first_tolerance_ = tolerance;
    pass_ = started_ ? pass_ + 1 : 0;
    started_ = true;
    restoring_ = false;
    previous_ = opt_.tolerance;
    opt_.tolerance = tolerance;
    stage_ = Stage::Sampling;
    next_edge_ = 0;
    in_edge_ = false;
    face_ = 0;
    in_face_ = false;
    refine_block_ = kNone;
    sweep_ = revisit_ = room_awaited_ = false;
    scene_.samples().used = 0;
    for (uint32_t b = 0; b < scene_.block_count(); ++b) {
        Block& block = scene_.block(b);
        block.previous_tolerance = block.tolerance, block.tolerance = 0, block.refused = false;
    }
    Event e{};
    e.kind = Event::Kind::Pass;
    e.pass = {pass_, tolerance, 0};
    emit_(e);
}

void Scheduler::set_level(Block& b) {
    if (b.tolerance > 0) return;
    const float t = block_tolerance_.fn ? block_tolerance_.fn(block_tolerance_.user, scene_.block_index(b), opt_.tolerance) : 0;
    b.tolerance = t > 0 ? t : opt_.tolerance;
}

static_assert(sizeof(geom::TessOptions) == 2 * sizeof(float), "options_at()'s key holds every option (tolerance, max_angle)");

geom::TessOptions Scheduler::options_at(float tolerance) const {
    return options_({tolerance, opt_.tolerance, opt_.max_angle}, [&] { return options_for(tolerance); });
}

geom::TessOptions Scheduler::options_for(float tolerance) const {
    geom::TessOptions o = opt_;
    if (!(tolerance > 0) || tolerance == opt_.tolerance) return o;
    o.tolerance = tolerance; // (finer than the pass's: a block refined as the view came near)
    // A far block's arcs turn more between samples, as its tolerance is coarser (a small hole
    // far off needs no seven sides), up to kMaxFarAngle.
    if (tolerance > opt_.tolerance) o.max_angle = std::min(kMaxFarAngle, opt_.max_angle * std::sqrt(tolerance / opt_.tolerance));
    return o;
}

bool Scheduler::run(uint32_t units) {
    switch (stage_) {
    case Stage::Idle: return false;
    case Stage::Sampling: sample(units); return true;
    case Stage::Refining: refine_sample(units); return true;
    case Stage::Faces: break;
    }
    if (!in_face_) {
        if (!next_face()) return true;
        mem_.face_mesh.vertex_count = mem_.face_mesh.triangle_count = 0;
        const Block& b = scene_.block_of_face(face_);
        view_ = scene_.samples_of(b);
        job_.start(b.pack, face_ - b.first_face, view_, options(b), mem_.storage, mem_.face_mesh); // (its level set by its edges)
        in_face_ = true;
    }
    const Result r = job_.run(units);
    if (r.status != Status::Busy) finish_face(r);
    return true;
}

// Edges from next_edge_ to `end`, or a piece of one, until about `units` are spent (a unit: a
// curve evaluation, weighted by its cost, or an edge). Each edge is begun through view_: the
// pool as the edge's block numbers its edges (a pass), or with the refined block's new (first,
// count) in the scratch (a refinement); the pool's use is carried both ways. Busy while an
// edge is under way; Full when the pool is.
Result Scheduler::sample_edges(uint32_t end, uint32_t units) {
    geom::EdgeSamples& s = scene_.samples();
    const uint32_t work0 = s.work;
    Result r;
    for (uint32_t n = 0; next_edge_ < end && s.work - work0 + n < units && r.ok(); ++n) {
        if (!in_edge_) {
            if (refining()) {
                view_.used = s.used, view_.work = s.work;
                sampler_.start(scene_.block(refine_block_).pack, options_at(refine_tolerance_), view_, next_edge_);
            } else {
                Block& b = scene_.block_of_edge(next_edge_);
                if (b.left_out) { // (its edges none: a block the view brings in is sampled then)
                    for (uint32_t e = b.first_edge; e < b.first_edge + b.edges; ++e) s.first[e] = 0, s.count[e] = 0;
                    next_edge_ = b.first_edge + b.edges;
                    continue;
                }
                view_ = scene_.samples_of(b);
                set_level(b);
                sampler_.start(b.pack, options(b), view_, next_edge_ - b.first_edge);
            }
            s.used = view_.used, s.work = view_.work;
            in_edge_ = true;
        }
        const uint32_t used = s.work - work0 + n; // (start() evaluates the curve's ends)
        view_.used = s.used, view_.work = s.work;
        r = sampler_.run(used < units ? units - used : 0);
        s.used = view_.used, s.work = view_.work;
        if (r.status == Status::Busy) break; // this edge goes on next time
        in_edge_ = false;
        if (r.ok()) ++next_edge_;
    }
    return r;
}

// A pass's edges, a piece at a time.
void Scheduler::sample(uint32_t units) {
    geom::EdgeSamples& s = scene_.samples();
    const uint32_t edges = scene_.edge_count();
    if (next_edge_ == 0 && !in_edge_) s.work = 0, quantized_ = 0;
    const Result r = sample_edges(edges, units);
    // The finished edges' samples, quantized for drawing (an edge under way may still thin its own).
    const uint32_t final_to = in_edge_ ? sampler_.first() : s.used;
    scene_.quantize_samples(quantized_, final_to);
    quantized_ = final_to;
    if (r.status == Status::Busy) return;
    if (r.status == Status::Full && pass_ == 0 && opt_.tolerance < DetailScale::kFirstPassCoarsest * first_tolerance_) {
        // The first level, short of room for the model's edges: a coarser one (twice the
        // tolerance, up to DetailScale::kFirstPassCoarsest times the asked one), rather than nothing on the screen.
        const float first = first_tolerance_;
        started_ = false;
        begin_pass(std::min(2 * opt_.tolerance, DetailScale::kFirstPassCoarsest * first));
        first_tolerance_ = first;
        return;
    }
    if (!r.ok()) {
        // No room for the model's edges at this tolerance. Later passes go back to the previous
        // one's samples (the same bits: its mesh stays valid); at load, with no room even at
        // DetailScale::kFirstPassCoarsest times the tolerance, nothing can be shown.
        Event e{};
        e.kind = Event::Kind::PassFailed;
        e.pass = {pass_, opt_.tolerance, s.used};
        e.why = r;
        emit_(e);
        stage_ = Stage::Idle;
        in_edge_ = false;
        if (pass_ > 0 && !restoring_) {
            opt_.tolerance = previous_;
            for (uint32_t b = 0; b < scene_.block_count(); ++b) { // each block back at its own previous level
                Block& block = scene_.block(b);
                block.tolerance = block.previous_tolerance;
            }
            restoring_ = true;
            stage_ = Stage::Sampling;
            next_edge_ = 0;
            s.used = 0;
        }
        return;
    }
    if (next_edge_ < edges) return;
    if (restoring_) { // the previous pass's samples are back, and its mesh with them
        restoring_ = false;
        stage_ = Stage::Idle;
        return;
    }
    scene_.reset_mesh(pass_ > 0);
    stage_ = scene_.face_count() ? Stage::Faces : Stage::Idle;
    all_blocks();
    Event e{};
    e.kind = Event::Kind::Sampled;
    e.pass = {pass_, opt_.tolerance, s.used};
    emit_(e);
}

void Scheduler::revisit() {
    if (!started_ || stage_ == Stage::Sampling) return; // the pass's faces meet the view as it is then
    if (stage_ == Stage::Idle) {
        if (scene_.totals().deferred == 0) return;
        stage_ = Stage::Faces, sweep_ = true, in_face_ = false, room_awaited_ = false;
        all_blocks();
        return;
    }
    revisit_ = true;
}

void Scheduler::all_blocks() {
    face_ = face_end_ = 0, next_block_ = kNone, ordered_ = false;
}

bool Scheduler::next_block() {
    if (!ordered_) { // (once the pass or sweep reaches its first face: the view framed by then)
        ordered_ = true;
        next_block_ = order_.fn ? order_.fn(order_.user) : scene_.block_count() ? 0 : kNone;
        if (!order_.fn) {
            for (uint32_t b = 0; b < scene_.block_count(); ++b) scene_.block(b).next = b + 1 < scene_.block_count() ? b + 1 : kNone;
        }
    }
    while (next_block_ != kNone) {
        const Block& b = scene_.block(next_block_);
        next_block_ = b.next;
        if (b.left_out || b.faces == 0) continue;
        face_ = b.first_face, face_end_ = b.first_face + b.faces;
        return true;
    }
    return false;
}

// Faces already in (a sweep) are passed; a face the view does not want now is bounded by its
// edges and deferred. True at a face to tessellate; false when this piece's checks are spent
// or the faces are done.
bool Scheduler::next_face() {
    for (uint32_t checked = 0; face_ < face_end_ || (!refining() && next_block()); ++face_) {
        const FaceState state = scene_.face(face_).state;
        if (state == FaceState::Failed || state == FaceState::Absent || (state == FaceState::Done && !refining())) continue;
        // (A refined block's by its new samples; a waiting face's sphere may have come with the
        // model's bounds, from the same samples.)
        if ((state == FaceState::Pending && scene_.face(face_).radius == 0) || refining()) scene_.bound_by_edges(face_);
        if (filter_(face_)) return true;
        scene_.evict(face_); // (a refined block's face the view no longer wants: its old mesh would not meet the new ones)
        scene_.defer(face_);
        if (++checked >= kChecksPerPiece) {
            ++face_;
            return false;
        }
    }
    end_faces();
    return false;
}

void Scheduler::finish_face(const Result& done) {
    Result r = done;
    const geom::Mesh& fm = mem_.face_mesh;
    if (r.ok() && fm.vertex_count > mem_.max_face_vertices) {
        r = Result::fail(Status::Full, "more vertices than the viewer projects per face (Capacity::face_points)", {"face", face_});
    }
    if (r.ok()) {
        r = scene_.append(face_, fm, job_.stats());
        // The mesh full: what faces tessellated again left behind is moved out of the way first,
        // then the meshes of faces the view no longer wants (off the screen, under two pixels).
        if (r.status == Status::Full && scene_.compact()) r = scene_.append(face_, fm, job_.stats());
        if (r.status == Status::Full && evict_unwanted() && scene_.compact()) r = scene_.append(face_, fm, job_.stats());
        r = r.within({"face", face_});
    }
    const Totals& t = scene_.totals();
    if (!r.ok()) {
        // No room even so, after the pass: a refined face keeps its old mesh, a face the view
        // brought in stays with its edges until a later sweep finds room (the event says which);
        // any other failure leaves it out.
        const bool later = (refining() || sweep_) && r.status == Status::Full;
        if (later && scene_.face(face_).state == FaceState::Done) {
            r = Result::fail(Status::Full, "no room for the face's finer mesh: kept at its previous level", {"face", face_});
        } else if (later) {
            r = Result::fail(Status::Full, "no room in the mesh: left to its edges until there is", {"face", face_});
            room_awaited_ = true;
            scene_.defer(face_); // (a face of a block just brought in was pending)
        } else {
            scene_.evict(face_);
            scene_.mark_failed(face_);
        }
        Event e{};
        e.kind = Event::Kind::FaceFailed;
        e.failed = {face_};
        e.why = r;
        emit_(e);
    }
    Event p;
    p.kind = Event::Kind::Progress;
    p.progress = {t.done, t.failed, t.faces, t.triangles};
    emit_(p);
    in_face_ = false;
    if (++face_ < face_end_ || (!refining() && next_block())) return;
    end_faces();
}

// The pass (or a sweep) has been through every face. The pass says so once; a view changed
// meanwhile sends a sweep over the deferred faces.
void Scheduler::end_faces() {
    const Totals& t = scene_.totals();
    const bool was_refine = refining(), was_sweep = sweep_ || was_refine;
    if (was_refine) refine_block_ = kNone, ++refined_;
    stage_ = Stage::Idle, sweep_ = false;
    // A sweep follows a view change, and a refinement while faces wait for room (what it freed
    // may bring them in). (A block refined or brought in judged its own faces for the view.)
    if ((revisit_ || (was_refine && room_awaited_)) && t.deferred > 0) {
        stage_ = Stage::Faces, sweep_ = true, room_awaited_ = false, all_blocks();
    }
    revisit_ = false;
    if (was_sweep) return;
    Event e{};
    e.kind = Event::Kind::Tessellated;
    e.tessellated = {pass_, t.faces, t.failed, t.triangles, t.vertices, t.mesh_bytes(), t.arena_peak_bytes, opt_.tolerance};
    emit_(e);
}

bool Scheduler::evict_unwanted() {
    uint32_t evicted = 0;
    for (uint32_t f = 0; f < scene_.face_count(); ++f) {
        if ((in_face_ && f == face_) || scene_.face(f).state != FaceState::Done || filter_(f)) continue;
        scene_.evict(f);
        ++evicted;
    }
    return evicted > 0;
}

bool Scheduler::make_sample_room(uint32_t need) {
    if (scene_.samples_room() >= need) return true;
    if (stage_ != Stage::Idle) return false;
    std::span<uint32_t> words(reinterpret_cast<uint32_t*>(mem_.scratch.data()), mem_.scratch.size() / 4);
    (void)scene_.compact_samples(words);
    return scene_.samples_room() >= need;
}

bool Scheduler::begin_refine(uint32_t b, float tolerance) {
    Block& block = scene_.block(b);
    if (stage_ != Stage::Idle || !started_) return false;
    if (block.refused || !(tolerance > 0) || tolerance == block.tolerance) {
        block.refused = true;
        return false;
    }
    const uint32_t edges = uint32_t(block.pack.edges().size());
    if (size_t(edges) * 6 > mem_.scratch.size()) { // no room for the block's new (first, count)
        block.refused = true;
        return false;
    }
    const geom::EdgeSamples& s = scene_.samples();
    // The new samples' room: arcs take samples as the root of the tolerance's ratio (their sag
    // goes as the square of their steps), and a fifth more for the angle's limit.
    uint32_t now = 0;
    for (uint32_t e = block.first_edge; e < block.first_edge + edges; ++e) now += s.count[e];
    // (A block just brought in has none: room for six an edge, what load plans for a block.)
    const uint32_t need = block.tolerance > 0 ? uint32_t(float(now) * 1.2f * std::sqrt(block.tolerance / tolerance)) + 2 * edges
                                              : kNewBlockSamplesPerEdge * edges + 2;
    std::span<uint32_t> words(reinterpret_cast<uint32_t*>(mem_.scratch.data()), mem_.scratch.size() / 4);
    if (scene_.samples_room() < need) scene_.compact_samples(words);
    // The mesh's room, counting what compaction would give back: the block's faces grow about
    // as the root of the ratio (a cylinder's strips; a sphere's grow faster, and a face that
    // then does not fit is left to its edges). Short of it, the meshes the view does not want
    // go first.
    const float ratio = std::max(1.0f, block.tolerance / tolerance);
    float vertices = 0, triangles = 0, grown_vertices = 0, grown_triangles = 0;
    for (uint32_t f = block.first_face; f < block.first_face + block.pack.faces().size(); ++f) {
        const FaceInfo& F = scene_.face(f);
        if (F.state != FaceState::Done) continue;
        const auto type = pack::SurfaceType(scene_.surface_type(f));
        const float grow = type == pack::SurfaceType::Plane ? 1.0f
                           : type == pack::SurfaceType::Sphere || type == pack::SurfaceType::Torus || type == pack::SurfaceType::BSpline
                               ? ratio                 // curved both ways
                               : std::sqrt(ratio);     // a cylinder's, a cone's strips
        vertices += float(F.vertex_count), triangles += float(F.triangle_count);
        grown_vertices += grow * float(F.vertex_count), grown_triangles += grow * float(F.triangle_count);
    }
    auto mesh_fits = [&] {
        return float(scene_.mesh_free_vertices()) + vertices >= grown_vertices && float(scene_.mesh_free_triangles()) + triangles >= grown_triangles;
    };
    if (!mesh_fits()) (void)evict_unwanted();
    if (scene_.samples_room() < need || !mesh_fits()) {
        block.refused = true;
        return false;
    }
    view_ = s;
    view_.first = words.first(edges);
    view_.count = std::span<uint16_t>(reinterpret_cast<uint16_t*>(words.data() + edges), edges);
    refine_block_ = b, refine_tolerance_ = tolerance, refine_from_ = s.used;
    stage_ = Stage::Refining, next_edge_ = 0, in_edge_ = false;
    return true;
}

// The refined block's edges, a few at a time, into the scratch's (first, count): the drawn
// edges and the faces still use the old ones meanwhile.
void Scheduler::refine_sample(uint32_t units) {
    Block& b = scene_.block(refine_block_);
    geom::EdgeSamples& s = scene_.samples();
    const uint32_t edges = uint32_t(b.pack.edges().size());
    const Result r = sample_edges(edges, units);
    if (r.status == Status::Busy) return;
    if (!r.ok()) { // the pool is full: the new samples dropped, the block as it was
        s.used = refine_from_;
        b.refused = true;
        // (A block just brought in has no level to go back to: left out again, its parts boxes.)
        if (!(b.tolerance > 0)) scene_.drop_block(refine_block_);
        Event e{};
        e.kind = Event::Kind::PassFailed;
        e.pass = {pass_, refine_tolerance_, s.used};
        e.why = r.within({"refining block", refine_block_});
        emit_(e);
        refine_block_ = kNone, stage_ = Stage::Idle;
        return;
    }
    if (next_edge_ < edges) return;
    // Every new sample in: the block's edges take them, and its faces are tessellated again.
    scene_.quantize_samples(refine_from_, s.used);
    for (uint32_t e = 0; e < edges; ++e) s.first[b.first_edge + e] = view_.first[e], s.count[b.first_edge + e] = view_.count[e];
    b.tolerance = refine_tolerance_;
    stage_ = Stage::Faces, face_ = b.first_face, face_end_ = b.first_face + uint32_t(b.pack.faces().size()), in_face_ = false;
    if (face_ == face_end_) end_faces();
}

} // namespace facet::module
