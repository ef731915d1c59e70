// The C API (facet/facet.h): each call converts its arguments and calls the C++ one.
#include "facet/facet.h"

#include "facet/viewer.h"
#include "workspace.h"
#include "core/format.h"

#include <cstring>

namespace {

using namespace facet;

static_assert(int(Status::Io) == FACET_IO && int(Status::Busy) == FACET_BUSY, "the C statuses are facet::Status");
static_assert(int(Event::Kind::WorkEnd) == FACET_EVENT_WORK_END && int(Event::Kind::Picked) == FACET_EVENT_PICKED,
              "the C event kinds are facet::Event::Kind");
static_assert(int(Work::Update) == FACET_WORK_UPDATE, "the C work kinds are facet::Work");
static_assert(int(Work::Fit) == FACET_WORK_FIT, "the C work kinds are facet::Work");
static_assert(int(Work::Overlay) == FACET_WORK_OVERLAY, "the C work kinds are facet::Work");
static_assert(int(Activity::Idle) == FACET_ACTIVITY_IDLE && int(Flush::Scanout) == FACET_FLUSH_SCANOUT,
              "the C enums are the C++ ones");
static_assert(uint32_t(KeyHome) == uint32_t(FACET_KEY_HOME), "the C keys are facet::Key");
static_assert(sizeof(facet_area) == sizeof(Area), "facet_area is facet::Area");

facet_result to_c(const Result& r) {
    return {facet_status(r.status), r.what, r.where.kind, r.where.index, r.at.kind, r.at.index};
}
Result from_c(const facet_result& r) {
    return {Status(r.status), r.what, {r.where_kind, r.where_index}, {r.at_kind, r.at_index}};
}

Capacity capacity_of(const facet_capacity& c) {
    return {c.faces, c.edges, c.samples, c.face_points, c.loops, c.slivers, c.mesh_vertices, c.mesh_triangles};
}

// The C config's callbacks, kept where the C++ callbacks can find them: in the workspace,
// after the viewer (facet_create takes the room for it from the workspace's end).
struct Bridge {
    void (*flush)(void* user, const facet_area* area, const facet_rgb565* pixels);
    void* flush_user;
    void (*on_event)(void* user, const facet_event* event);
    void* event_user;
};

void flush_thunk(void* user, const Area& area, const Rgb565* pixels) {
    const Bridge& b = *static_cast<const Bridge*>(user);
    const facet_area a{area.x, area.y, area.width, area.height};
    b.flush(b.flush_user, &a, pixels);
}

void event_thunk(void* user, const Event& e) {
    const Bridge& b = *static_cast<const Bridge*>(user);
    facet_event c;
    std::memset(&c, 0, sizeof c);
    c.kind = facet_event_kind(e.kind);
    switch (e.kind) {
    case Event::Kind::Loaded: std::memcpy(&c.u.loaded, &e.loaded, sizeof c.u.loaded); break;
    case Event::Kind::Pass:
    case Event::Kind::Sampled:
    case Event::Kind::PassFailed: c.u.pass = {e.pass.pass, e.pass.tolerance_mm, e.pass.samples}; break;
    case Event::Kind::Progress: std::memcpy(&c.u.progress, &e.progress, sizeof c.u.progress); break;
    case Event::Kind::FaceFailed: c.u.failed.face = e.failed.face; break;
    case Event::Kind::Tessellated: {
        const auto& t = e.tessellated;
        c.u.tessellated = {t.pass, t.faces, t.failed, t.triangles, t.vertices, t.mesh_bytes, t.arena_peak_bytes, t.tolerance_mm};
        break;
    }
    case Event::Kind::FrameDone: {
        const auto& f = e.frame;
        c.u.frame = {f.triangles, f.culled, f.pixels, f.cost_us, f.pieces, f.faces_done, f.faces_total, f.pass, uint8_t(f.full), uint8_t(f.boxes)};
        break;
    }
    case Event::Kind::BudgetExceeded: c.u.budget = {uint8_t(e.budget.step), e.budget.budget_us, e.budget.used_us}; break;
    case Event::Kind::Picked: {
        const auto& p = e.pick;
        c.u.pick = {uint8_t(p.hit), p.face, p.instance, p.shell, p.surface_type, p.x, p.y};
        break;
    }
    case Event::Kind::ViewChanged: c.u.view = {e.view.yaw_deg, e.view.pitch_deg, e.view.zoom}; break;
    case Event::Kind::WorkBegin:
    case Event::Kind::WorkEnd: c.u.work = {facet_work(e.work.what), e.work.item}; break;
    }
    c.why = to_c(e.why);
    b.on_event(b.event_user, &c);
}

Viewer* cpp(facet_viewer* v) { return reinterpret_cast<Viewer*>(v); }
const Viewer* cpp(const facet_viewer* v) { return reinterpret_cast<const Viewer*>(v); }

} // namespace

extern "C" {

size_t facet_describe(const facet_result* r, char* buffer, size_t size) { return r ? describe(from_c(*r), buffer, size) : 0; }

void facet_config_init(facet_config* c) {
    std::memset(c, 0, sizeof *c);
    const Capacity d;
    c->capacity = {d.faces, d.edges, d.samples, d.face_points, d.loops, d.slivers, d.mesh_vertices, d.mesh_triangles};
    c->step_slack_us = Config{}.step_slack_us;
    c->interface = 1;
    c->screen_error_px = Config{}.screen_error_px;
}

// The formula's slack (facet/sizes.h) holds the bridge as well.
size_t facet_workspace_bytes(const facet_capacity* c) { return c ? workspace_bytes(capacity_of(*c)) : workspace_bytes(); }

uint32_t facet_pack_memory_bytes(const void* file, uint32_t file_bytes) { return pack_memory_bytes(file, file_bytes); }

facet_result facet_model_needs(const void* file, uint32_t file_bytes, facet_model_needs_t* out) {
    if (!out) return to_c(Result::fail(Status::OutOfRange, "no facet_model_needs_t to fill"));
    ModelNeeds n{};
    const Result r = model_needs(file, file_bytes, n);
    *out = {n.faces, n.edges, n.parts, n.pack_memory_bytes, n.least_workspace_bytes, n.workspace_bytes};
    return to_c(r);
}

facet_viewer* facet_create(const facet_config* c, void* workspace, size_t bytes, facet_result* why) {
    auto refuse = [&](const Result& r) -> facet_viewer* {
        if (why) *why = to_c(r);
        return nullptr;
    };
    if (!c) return refuse(Result::fail(Status::OutOfRange, "no configuration"));
    // Checked before the bridge is stored there: a null or misaligned workspace is refused, as
    // is one under facet_workspace_bytes() (sizes.h), whose slack then holds the bridge.
    if (!workspace || (reinterpret_cast<uintptr_t>(workspace) & 7)) {
        return refuse(Result::fail(Status::OutOfRange, "the workspace must be 8-byte aligned", {"workspace"}));
    }
    const size_t least = facet_workspace_bytes(&c->capacity);
    if (bytes < least || bytes < sizeof(Bridge) + 8) {
        return refuse(Result::fail(Status::Full, "the workspace is smaller than facet_workspace_bytes()", {"bytes needed", uint32_t(least)}));
    }
    // The bridge at the workspace's end (8-byte aligned), the viewer before it.
    const size_t viewer_bytes = (bytes - sizeof(Bridge)) & ~size_t(7);
    auto* bridge = reinterpret_cast<Bridge*>(static_cast<uint8_t*>(workspace) + viewer_bytes);
    *bridge = {c->display.flush, c->display.user, c->on_event, c->event_user};
    Config cfg;
    const facet_display& d = c->display;
    cfg.display.width = d.width, cfg.display.height = d.height, cfg.display.band_lines = d.band_lines;
    cfg.display.x = d.x, cfg.display.y = d.y;
    cfg.display.buffers[0] = d.buffers[0], cfg.display.buffers[1] = d.buffers[1];
    cfg.display.depth[0] = d.depth[0], cfg.display.depth[1] = d.depth[1];
    cfg.display.mode = Flush(d.mode);
    cfg.display.flush = d.flush ? flush_thunk : nullptr;
    cfg.display.user = bridge;
    cfg.capacity = capacity_of(c->capacity);
    cfg.on_event = c->on_event ? event_thunk : nullptr;
    cfg.event_user = bridge;
    cfg.now_us = c->now_us;
    cfg.clock_user = c->clock_user;
    cfg.frame_budget_us = c->frame_budget_us;
    cfg.step_slack_us = c->step_slack_us;
    cfg.interface = c->interface == 0 ? Interface::Off : c->interface == 2 ? Interface::StatusLine : Interface::Full;
    cfg.screen_error_px = c->screen_error_px;
    Result r;
    Viewer* v = create_viewer(cfg, workspace, viewer_bytes, 0, &r);
    if (why) *why = to_c(r);
    return reinterpret_cast<facet_viewer*>(v);
}

facet_result facet_load(facet_viewer* v, const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes) {
    return to_c(cpp(v)->load(file, file_bytes, memory, memory_bytes));
}
facet_activity facet_step(facet_viewer* v, uint32_t budget_us) { return facet_activity(cpp(v)->step(budget_us)); }
void facet_flush_done(facet_viewer* v) { cpp(v)->flush_done(); }
void facet_key(facet_viewer* v, uint32_t key) { cpp(v)->key(key); }
void facet_pointer(facet_viewer* v, int16_t dx, int16_t dy, uint8_t buttons) { cpp(v)->pointer(dx, dy, buttons); }
void facet_wheel(facet_viewer* v, int16_t clicks) { cpp(v)->wheel(clicks); }
void facet_touch(facet_viewer* v, uint8_t id, int16_t x, int16_t y, int down) { cpp(v)->touch(id, x, y, down != 0); }

facet_stats facet_get_stats(const facet_viewer* v) {
    const Stats s = cpp(v)->stats();
    return {s.faces, s.done, s.failed, s.triangles, s.vertices, s.pass, s.mesh_bytes, s.arena_peak_bytes, s.pack_bytes,
            s.pack_file_bytes, s.workspace_peak_bytes, s.tolerance_mm, s.refused, s.deferred};
}

} // extern "C"
