// The C API (facet/facet.h): each call converts its arguments and calls the C++ one.
#include "facet/facet.h"

#include "c_api_shared.h"

#include "facet/viewer.h"
#include "public_result.h"
#include "workspace.h"
#include "core/format.h"

#include <cstring>

namespace {

using namespace facet;

static_assert(int(Status::Busy) == FACET_BUSY && int(Status::NotFound) == FACET_NOT_FOUND && int(Status::Io) == FACET_IO,
              "the C statuses are facet::Status's public ones");
static_assert(int(Interface::Full) == FACET_INTERFACE_FULL && int(Interface::StatusLine) == FACET_INTERFACE_STATUS_LINE,
              "the C interfaces are facet::Interface");
static_assert(int(Event::Kind::ModelFailed) == FACET_EVENT_MODEL_FAILED && int(Event::Kind::Picked) == FACET_EVENT_PICKED,
              "the C event kinds are facet::Event::Kind");
static_assert(int(Work::Update) == FACET_WORK_UPDATE, "the C work kinds are facet::Work");
static_assert(int(Work::Fit) == FACET_WORK_FIT, "the C work kinds are facet::Work");
static_assert(int(Work::Overlay) == FACET_WORK_OVERLAY, "the C work kinds are facet::Work");
static_assert(int(Activity::Idle) == FACET_ACTIVITY_IDLE && int(Flush::Scanout) == FACET_FLUSH_SCANOUT,
              "the C enums are the C++ ones");
static_assert(uint32_t(KeyHome) == uint32_t(FACET_KEY_HOME), "the C keys are facet::Key");
static_assert(sizeof(facet_area) == sizeof(Area), "facet_area is facet::Area");
static_assert(int(Action::TangentEdges) == FACET_ACTION_TANGENT_EDGES && int(Action::Models) == FACET_ACTION_MODELS && int(Action::ShowAllParts) == FACET_ACTION_SHOW_ALL_PARTS && int(Action::Measure) == FACET_ACTION_MEASURE &&
                  int(Action::Projection) == FACET_ACTION_PROJECTION, "the C actions are facet::Action");
static_assert(int(DisplayMode::SeeThrough) == FACET_MODE_SEE_THROUGH, "the C display modes are facet::DisplayMode");
static_assert(int(StandardView::Iso) == FACET_VIEW_ISO, "the C standard views are facet::StandardView");
static_assert(int(Surface::Extrusion) == FACET_SURFACE_EXTRUSION && int(Surface::BSpline) == FACET_SURFACE_BSPLINE,
              "the C surfaces are facet::Surface");
static_assert(int(Measurement::Kind::Points) == FACET_MEASURE_POINTS, "the C measurement kinds are facet::Measurement's");

using c_api::to_c;
using c_api::cpp;
Result from_c(const facet_result& r) {
    return {Status(r.status), r.what, {r.where_kind, r.where_index}, {r.at_kind, r.at_index}};
}

Capacity capacity_of(const facet_capacity& c) {
    return {c.faces, c.edges, c.samples, c.face_points, c.loops, c.slivers, c.mesh_vertices, c.mesh_triangles};
}

// The C config's callbacks, kept where the C++ callbacks can find them: in the workspace,
// after the viewer (facet_create takes the room for it from the workspace's end).
struct Bridge {
    void (*flush)(facet_viewer* viewer, void* user, const facet_area* area, const facet_rgb565* pixels);
    void* flush_user;
    void (*on_event)(void* user, const facet_event* event);
    void* event_user;
};

void flush_thunk(Viewer& viewer, void* user, const Area& area, const Rgb565* pixels) {
    const Bridge& b = *static_cast<const Bridge*>(user);
    const facet_area a{area.x, area.y, area.width, area.height};
    b.flush(reinterpret_cast<facet_viewer*>(&viewer), b.flush_user, &a, pixels);
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
        c.u.frame = {f.triangles, f.culled, f.pixels, f.cost_us, f.pieces, f.faces_done, f.faces_total, f.pass, f.full, f.boxes};
        break;
    }
    case Event::Kind::BudgetExceeded: c.u.budget = {e.budget.step, e.budget.budget_us, e.budget.used_us}; break;
    case Event::Kind::Picked: {
        const auto& p = e.pick;
        c.u.pick = {p.hit, p.face, p.instance, p.shell, p.surface_type, p.x, p.y};
        break;
    }
    case Event::Kind::ViewChanged: c.u.view = {e.view.yaw_deg, e.view.pitch_deg, e.view.zoom}; break;
    case Event::Kind::WorkBegin:
    case Event::Kind::WorkEnd: c.u.work = {facet_work(e.work.what), e.work.item}; break;
    case Event::Kind::ModelFailed: c.u.model.index = e.model.index; break;
    }
    c.why = to_c(e.why);
    b.on_event(b.event_user, &c);
}

facet_face_facts facts_to_c(const FaceFacts& f) {
    facet_face_facts c;
    std::memset(&c, 0, sizeof c);
    c.hit = f.hit, c.part = f.part, c.face = f.face, c.surface = facet_surface(f.surface), c.hole = f.hole;
    std::memcpy(c.origin_mm, f.origin_mm, sizeof c.origin_mm);
    std::memcpy(c.axis, f.axis, sizeof c.axis);
    c.offset_mm = f.offset_mm, c.radius_mm = f.radius_mm, c.minor_mm = f.minor_mm, c.half_angle_deg = f.half_angle_deg;
    c.x = f.x, c.y = f.y;
    return c;
}
FaceFacts facts_from_c(const facet_face_facts& c) { // (measure() reads the part and the face alone)
    FaceFacts f;
    f.hit = c.hit != 0, f.part = c.part, f.face = c.face;
    return f;
}

} // namespace

namespace {
// The C storage's callbacks behind the C++ Storage's (user: the caller's facet_storage, which stays).
Result storage_result(facet_status s, const char* what) {
    return s == FACET_OK ? Result{} : Result::fail(Status(int32_t(s)), what, {"storage"});
}
const facet_storage* of(void* user) { return static_cast<const facet_storage*>(user); }
Storage storage_of(const facet_storage* c) {
    Storage s;
    s.user = const_cast<facet_storage*>(c);
    if (c->open) s.open = [](void* u, const char* path, void** f, uint32_t* n) { return storage_result(of(u)->open(of(u)->user, path, f, n), "the storage's open failed"); };
    if (c->read) s.read = [](void* u, void* f, uint32_t at, void* into, uint32_t n) { return storage_result(of(u)->read(of(u)->user, f, at, into, n), "the storage's read failed"); };
    if (c->close) s.close = [](void* u, void* f) { of(u)->close(of(u)->user, f); };
    if (c->dir_open) s.dir_open = [](void* u, const char* path, void** d) { return storage_result(of(u)->dir_open(of(u)->user, path, d), "the storage's dir_open failed"); };
    if (c->dir_read) {
        s.dir_read = [](void* u, void* d, StorageEntry* e) {
            facet_storage_entry c{};
            const facet_status st = of(u)->dir_read(of(u)->user, d, &c);
            static_assert(sizeof c.name == sizeof e->name, "the C entry's name is the C++ one's");
            std::memcpy(e->name, c.name, sizeof e->name);
            e->name[sizeof e->name - 1] = 0;
            e->bytes = c.bytes, e->folder = c.folder;
            return storage_result(st, "the storage's dir_read failed");
        };
    }
    if (c->dir_close) s.dir_close = [](void* u, void* d) { of(u)->dir_close(of(u)->user, d); };
    return s;
}
} // namespace

extern "C" {

size_t facet_describe(const facet_result* r, char* buffer, size_t size) { return r ? describe(from_c(*r), buffer, size) : 0; }

void facet_config_init(facet_config* c) {
    std::memset(c, 0, sizeof *c);
    const Capacity d;
    c->capacity = {d.faces, d.edges, d.samples, d.face_points, d.loops, d.slivers, d.mesh_vertices, d.mesh_triangles};
    c->step_slack_us = Config{}.step_slack_us;
    c->interface = FACET_INTERFACE_FULL;
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
    if (unsigned(c->display.mode) > unsigned(FACET_FLUSH_SCANOUT)) return refuse(Result::fail(Status::OutOfRange, "no such flush mode", {"display"}));
    if (unsigned(c->interface) > unsigned(FACET_INTERFACE_FULL)) return refuse(Result::fail(Status::OutOfRange, "no such interface"));
    // Checked before the bridge is stored there: a null or misaligned workspace is refused, as
    // is one under facet_workspace_bytes() (sizes.h), whose slack then holds the bridge.
    if (!workspace || (reinterpret_cast<uintptr_t>(workspace) & 7)) {
        return refuse(Result::fail(Status::OutOfRange, "the workspace must be 8-byte aligned", {"workspace"}));
    }
    if (bytes > SIZE_MAX - reinterpret_cast<uintptr_t>(workspace)) {
        return refuse(Result::fail(Status::OutOfRange, "the workspace's size runs past the end of memory", {"workspace"}));
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
    cfg.display.faces = d.faces, cfg.display.faces_depth = d.faces_depth;
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
    cfg.interface = Interface(c->interface);
    cfg.screen_error_px = c->screen_error_px;
    Result r;
    Viewer* v = create_viewer(cfg, workspace, viewer_bytes, 0, &r);
    if (why) *why = to_c(r);
    return reinterpret_cast<facet_viewer*>(v);
}

facet_result facet_load(facet_viewer* v, const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->load(file, file_bytes, memory, memory_bytes));
}
facet_activity facet_step(facet_viewer* v, uint32_t budget_us) { return v ? facet_activity(cpp(v)->step(budget_us)) : FACET_ACTIVITY_IDLE; }
void facet_unload(facet_viewer* v) {
    if (v) cpp(v)->unload();
}

uint32_t facet_library_count(const void* library, uint32_t bytes) { return library_count(library, bytes); }
facet_result facet_library_model(const void* library, uint32_t bytes, uint32_t index, facet_library_model_t* out) {
    if (!out) return to_c(Result::fail(Status::OutOfRange, "no facet_library_model_t to fill"));
    LibraryModel m;
    const Result r = library_model(library, bytes, index, m);
    *out = {m.file, m.bytes, m.name};
    return to_c(r);
}
facet_result facet_set_library(facet_viewer* v, const void* library, uint32_t bytes, void* memory, uint32_t memory_bytes) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->set_library(library, bytes, memory, memory_bytes));
}
facet_result facet_open_model(facet_viewer* v, uint32_t index) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->open_model(index));
}
uint32_t facet_get_model_index(const facet_viewer* v) { return v ? cpp(v)->model_index() : kNone; }


facet_result facet_set_storage(facet_viewer* v, const facet_storage* storage, const char* folder, void* memory, uint32_t memory_bytes) {
    FACET_NEED_VIEWER(v);
    if (!storage) return to_c(Result::fail(Status::OutOfRange, "no storage"));
    return to_c(cpp(v)->set_storage(storage_of(storage), folder ? folder : "", memory, memory_bytes));
}
facet_result facet_open_file(facet_viewer* v, const char* path) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->open_file(path));
}
void facet_read_done(facet_viewer* v, facet_status status) {
    if (v) cpp(v)->read_done(Status(int32_t(status)));
}
facet_result facet_storage_changed(facet_viewer* v, bool present) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->storage_changed(present));
}
uint32_t facet_get_model_count(const facet_viewer* v) { return v ? cpp(v)->model_count() : 0; }
facet_result facet_get_listed_model(const facet_viewer* v, uint32_t index, facet_listed_model* out) {
    FACET_NEED_VIEWER(v);
    if (!out) return to_c(Result::fail(Status::OutOfRange, "no facet_listed_model to fill"));
    Viewer::ListedModel m;
    const Result r = cpp(v)->listed_model(index, m);
    *out = {m.name, m.bytes, m.faces};
    return to_c(r);
}

void facet_flush_done(facet_viewer* v) {
    if (v) cpp(v)->flush_done();
}
void facet_key(facet_viewer* v, uint32_t key) {
    if (v) cpp(v)->key(key);
}
void facet_pointer(facet_viewer* v, int16_t dx, int16_t dy, uint8_t buttons) {
    if (v) cpp(v)->pointer(dx, dy, buttons);
}
void facet_wheel(facet_viewer* v, int16_t clicks) {
    if (v) cpp(v)->wheel(clicks);
}
void facet_touch(facet_viewer* v, uint8_t id, int16_t x, int16_t y, bool down) {
    if (v) cpp(v)->touch(id, x, y, down);
}

facet_stats facet_get_stats(const facet_viewer* v) {
    if (!v) return facet_stats{};
    const Stats s = cpp(v)->stats();
    return {s.faces, s.done, s.failed, s.triangles, s.vertices, s.pass, s.mesh_bytes, s.arena_peak_bytes, s.pack_bytes,
            s.pack_file_bytes, s.workspace_peak_bytes, s.tolerance_mm, s.refused, s.deferred};
}

void facet_act(facet_viewer* v, facet_action a) {
    if (v && unsigned(a) <= unsigned(FACET_ACTION_EXPLODE)) cpp(v)->act(Action(a));
}
uint32_t facet_get_key_binding_count(void) { return key_bindings().count; }
facet_key_binding facet_get_key_binding(uint32_t i) {
    const KeyBindings k = key_bindings();
    if (i >= k.count) return {0, FACET_ACTION_NONE, nullptr};
    return {k.table[i].key, facet_action(k.table[i].action), k.table[i].help};
}

facet_model_info facet_get_model(const facet_viewer* v) {
    const ModelInfo m = v ? cpp(v)->model() : ModelInfo{};
    return {m.name, m.unit, m.unit_mm, m.parts, m.faces, m.edges, m.boxed_parts, m.boxed_faces,
            {m.centre_mm[0], m.centre_mm[1], m.centre_mm[2]}, m.radius_mm};
}

facet_orbit facet_get_orbit(const facet_viewer* v) {
    facet_orbit z;
    std::memset(&z, 0, sizeof z);
    if (!v) return z;
    const Orbit o = cpp(v)->orbit();
    return {o.yaw_deg, o.pitch_deg, o.dolly, {o.pan_mm[0], o.pan_mm[1]}, o.parallel};
}
facet_result facet_set_orbit(facet_viewer* v, const facet_orbit* o) {
    FACET_NEED_VIEWER(v);
    if (!o) return to_c(Result::fail(Status::OutOfRange, "no orbit"));
    return to_c(cpp(v)->set_orbit({o->yaw_deg, o->pitch_deg, o->dolly, {o->pan_mm[0], o->pan_mm[1]}, o->parallel}));
}
facet_camera facet_get_camera(const facet_viewer* v) {
    facet_camera c;
    std::memset(&c, 0, sizeof c);
    if (!v) return c;
    const Viewer::CameraView k = cpp(v)->camera();
    std::memcpy(c.rotation, k.rotation, sizeof c.rotation);
    std::memcpy(c.target_mm, k.target_mm, sizeof c.target_mm);
    c.distance_mm = k.distance_mm, c.focal_px = k.focal_px, c.parallel = k.parallel;
    return c;
}
facet_result facet_show_view(facet_viewer* v, facet_standard_view view) {
    FACET_NEED_VIEWER(v);
    if (unsigned(view) > unsigned(FACET_VIEW_ISO)) return to_c(Result::fail(Status::OutOfRange, "no such view"));
    return to_c(cpp(v)->show_view(StandardView(view)));
}
void facet_fit(facet_viewer* v) {
    if (v) cpp(v)->fit();
}
facet_result facet_fit_part(facet_viewer* v, uint32_t part) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->fit_part(part));
}
facet_result facet_fit_face(facet_viewer* v, uint32_t part, uint32_t face) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->fit_face(part, face));
}
void facet_set_parallel(facet_viewer* v, bool parallel) {
    if (v) cpp(v)->set_parallel(parallel);
}

facet_display_mode facet_get_display_mode(const facet_viewer* v) {
    return v ? facet_display_mode(cpp(v)->display_mode()) : FACET_MODE_SHADED_EDGES;
}
facet_result facet_set_display_mode(facet_viewer* v, facet_display_mode mode) {
    FACET_NEED_VIEWER(v);
    if (unsigned(mode) > unsigned(FACET_MODE_SEE_THROUGH)) return to_c(Result::fail(Status::OutOfRange, "no such display mode"));
    return to_c(cpp(v)->set_display_mode(DisplayMode(mode)));
}
bool facet_get_tangent_edges(const facet_viewer* v) { return v && cpp(v)->tangent_edges(); }
void facet_set_tangent_edges(facet_viewer* v, bool shown) {
    if (v) cpp(v)->set_tangent_edges(shown);
}
float facet_get_detail(const facet_viewer* v) { return v ? cpp(v)->detail() : 0.0f; }
facet_result facet_set_detail(facet_viewer* v, float factor) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->set_detail(factor));
}

facet_face_facts facet_pick(facet_viewer* v, int16_t x, int16_t y) {
    if (!v) return facts_to_c(FaceFacts{});
    return facts_to_c(cpp(v)->pick(x, y));
}
facet_result facet_get_face(const facet_viewer* v, uint32_t part, uint32_t face, facet_face_facts* out) {
    FACET_NEED_VIEWER(v);
    if (!out) return to_c(Result::fail(Status::OutOfRange, "no facet_face_facts to fill"));
    FaceFacts f;
    const Result r = cpp(v)->facts(part, face, f);
    *out = facts_to_c(f);
    return to_c(r);
}
facet_result facet_select(facet_viewer* v, uint32_t part, uint32_t face) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->select(part, face));
}
void facet_clear_selection(facet_viewer* v) {
    if (v) cpp(v)->clear_selection();
}
uint32_t facet_get_selection(const facet_viewer* v, facet_face_facts out[2]) {
    if (!v || !out) return 0;
    FaceFacts f[2];
    const uint32_t n = cpp(v)->selection(f);
    for (uint32_t i = 0; i < n; ++i) out[i] = facts_to_c(f[i]);
    return n;
}
void facet_set_measuring(facet_viewer* v, bool on) {
    if (v) cpp(v)->set_measuring(on != 0);
}
bool facet_get_measuring(const facet_viewer* v) { return v && cpp(v)->measuring(); }
facet_measurement facet_measure(const facet_viewer* v, const facet_face_facts* a, const facet_face_facts* b) {
    facet_measurement m;
    std::memset(&m, 0, sizeof m);
    if (!v || !a || !b) return m;
    const Measurement r = cpp(v)->measure(facts_from_c(*a), facts_from_c(*b));
    m.kind = facet_measure_kind(r.kind), m.parallel = r.parallel, m.has_distance = r.has_distance;
    m.distance_mm = r.distance_mm, m.angle_deg = r.angle_deg;
    return m;
}
uint32_t facet_get_measurement_lines(const facet_viewer* v, const char* lines[3]) { return v && lines ? cpp(v)->measurement(lines) : 0; }

uint32_t facet_get_part_count(const facet_viewer* v) { return v ? cpp(v)->part_count() : 0; }
facet_part facet_get_part(const facet_viewer* v, uint32_t i) {
    if (!v) return {"", "", 0, 0};
    const Viewer::Part p = cpp(v)->part(i);
    return {p.name, p.instance, p.faces, p.shown};
}
facet_result facet_show_part(facet_viewer* v, uint32_t i, bool shown) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->show_part(i, shown != 0));
}
facet_result facet_isolate_part(facet_viewer* v, uint32_t i) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->isolate_part(i));
}
void facet_show_all_parts(facet_viewer* v) {
    if (v) cpp(v)->show_all_parts();
}
facet_result facet_choose_part(facet_viewer* v, uint32_t i) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->choose_part(i));
}
uint32_t facet_get_chosen_part(const facet_viewer* v) { return v ? cpp(v)->chosen_part() : kNone; }

facet_section facet_get_section(const facet_viewer* v) {
    const Viewer::SectionPlane p = v ? cpp(v)->section() : Viewer::SectionPlane{};
    return {p.on, {p.normal[0], p.normal[1], p.normal[2]}, p.offset_mm};
}
facet_result facet_set_section(facet_viewer* v, const facet_section* p) {
    FACET_NEED_VIEWER(v);
    if (!p) return to_c(Result::fail(Status::OutOfRange, "no facet_section"));
    return to_c(cpp(v)->set_section({p->on != 0, {p->normal[0], p->normal[1], p->normal[2]}, p->offset_mm}));
}
facet_result facet_section_through(facet_viewer* v, uint32_t part, uint32_t face) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->section_through(part, face));
}
facet_result facet_section_across(facet_viewer* v, uint8_t axis) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->section_across(axis));
}
facet_result facet_move_section(facet_viewer* v, float by_mm) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->move_section(by_mm));
}

} // extern "C"
