// The viewer's public face (facet/viewer.h): each call goes to the Core the workspace holds.
// The built-in interface's keys, buttons and taps reach the same Core calls (core.cpp's act(),
// pick.cpp's tap()).
#include "core.h"
#include "describe.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace facet {

namespace {
Core& core(Viewer* v) { return *static_cast<Core*>(v); }
const Core& core(const Viewer* v) { return *static_cast<const Core*>(v); }
} // namespace

Result Viewer::load(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes) {
    return module::public_result(core(this).load(file, file_bytes, memory, memory_bytes));
}
Activity Viewer::step(uint32_t budget_us) { return core(this).step(budget_us); }
void Viewer::flush_done() { core(this).flush_done(); }

// Input.
void Viewer::key(uint32_t k) {
    Core& c = core(this);
    c.command(c.controls().key(k));
}
void Viewer::pointer(int16_t dx, int16_t dy, uint8_t buttons) {
    Core& c = core(this);
    const bool dragging = c.controls().dragging();
    c.command(c.controls().pointer(dx, dy, buttons));
    c.drag_ended(dragging);
}
void Viewer::wheel(int16_t clicks) {
    Core& c = core(this);
    c.command(c.controls().wheel(clicks));
}
void Viewer::touch(uint8_t id, int16_t x, int16_t y, bool down) {
    Core& c = core(this);
    // The screen's coordinates to facet's rectangle's; a finger coming down outside it is the
    // product's (one already down may move out and back).
    const Display& d = c.display();
    const int32_t rx = int32_t(x) - d.x, ry = int32_t(y) - d.y;
    if (down && !c.controls().finger_down(id) && (rx < 0 || ry < 0 || rx >= d.width || ry >= d.height)) return;
    x = int16_t(std::clamp<int32_t>(rx, INT16_MIN, INT16_MAX)), y = int16_t(std::clamp<int32_t>(ry, INT16_MIN, INT16_MAX));
    module::Command out[2];
    const bool dragging = c.controls().dragging();
    const uint32_t n = c.controls().touch(id, x, y, down, out);
    for (uint32_t i = 0; i < n; ++i) c.command(out[i]);
    c.drag_ended(dragging);
}
void Viewer::act(Action a) { core(this).act(a); }

// The model.
Stats Viewer::stats() const { return core(this).stats(); }
ModelInfo Viewer::model() const { return core(this).model(); }
const char* Viewer::model_name() const { return model().name; }

ModelInfo Core::model() const {
    ModelInfo m;
    if (!scene_.loaded()) return m;
    m.name = scene_.model_name();
    m.unit_mm = scene_.source_unit_mm();
    m.unit = module::unit_name(m.unit_mm);
    m.parts = uint32_t(scene_.instances().size());
    m.faces = scene_.face_count(), m.edges = scene_.edge_count();
    m.boxed_parts = scene_.left_out().parts, m.boxed_faces = scene_.left_out().faces;
    for (int k = 0; k < 3; ++k) m.centre_mm[k] = scene_.centre()[k];
    m.radius_mm = scene_.radius();
    return m;
}

// The camera.
Orbit Viewer::orbit() const { return core(this).orbit(); }
Result Viewer::set_orbit(const Orbit& o) { return core(this).set_orbit(o); }
Result Viewer::show_view(StandardView v) {
    if (uint8_t(v) > uint8_t(StandardView::Iso)) return Result::fail(Status::OutOfRange, "no such view");
    if (!core(this).scene().loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    core(this).show_view(v);
    return {};
}
void Viewer::fit() { core(this).fit(); }
Result Viewer::fit_part(uint32_t part) { return core(this).fit_part(part); }
Result Viewer::fit_face(uint32_t part, uint32_t face) {
    if (face == kNone) return Result::fail(Status::OutOfRange, "no such face", {"face", face});
    return core(this).fit_part(part, face);
}
void Viewer::set_parallel(bool parallel) {
    if (core(this).scene().loaded()) core(this).set_parallel(parallel);
}

Viewer::CameraView Viewer::camera() const {
    const Core& c = core(this);
    CameraView v{};
    if (!c.scene().loaded()) return v;
    const module::Camera& cam = c.camera();
    cam.rotation(v.rotation);
    // The view is R (p - centre) + pan: the target is the centre less the pan turned back.
    const float* centre = c.scene().centre();
    const module::View& view = cam.view();
    for (int k = 0; k < 3; ++k) v.target_mm[k] = centre[k] - (v.rotation[k] * view.pan_x + v.rotation[3 + k] * view.pan_y);
    v.distance_mm = cam.distance_mm(c.scene());
    v.focal_px = module::Camera::focal_px(c.display().width, c.display().height);
    v.parallel = view.ortho;
    return v;
}

DisplayMode Viewer::display_mode() const { return core(this).mode(); }
bool Viewer::tangent_edges() const { return core(this).tangent_edges(); }
void Viewer::set_tangent_edges(bool shown) { core(this).set_tangent_edges(shown); }
Result Viewer::set_display_mode(DisplayMode m) {
    if (uint8_t(m) > uint8_t(DisplayMode::SeeThrough)) return Result::fail(Status::OutOfRange, "no such display mode");
    core(this).set_mode(m);
    return {};
}
float Viewer::detail() const { return core(this).detail(); }
Result Viewer::set_detail(float factor) { return core(this).set_detail(factor); }

// Picking and measuring.
FaceFacts Viewer::pick(int16_t x, int16_t y) {
    Core& c = core(this);
    const int32_t rx = int32_t(x) - c.display().x, ry = int32_t(y) - c.display().y; // the screen's to facet's rectangle's
    FaceFacts f = rx >= INT16_MIN && rx <= INT16_MAX && ry >= INT16_MIN && ry <= INT16_MAX ? c.pick(int16_t(rx), int16_t(ry)) : FaceFacts{};
    f.x = x, f.y = y;
    return f;
}
Result Viewer::facts(uint32_t part, uint32_t face, FaceFacts& out) const { return core(this).facts(part, face, out); }
Result Viewer::select(uint32_t part, uint32_t face) { return core(this).select(part, face); }
void Viewer::clear_selection() { core(this).clear_selection(); }
uint32_t Viewer::selection(FaceFacts out[2]) const { return core(this).selection(out); }
void Viewer::set_measuring(bool on) { core(this).set_measuring(on); }
bool Viewer::measuring() const { return core(this).measuring(); }
Measurement Viewer::measure(const FaceFacts& a, const FaceFacts& b) const { return core(this).measure(a, b); }
uint32_t Viewer::measurement(const char* lines[3]) const {
    const module::Overlay& o = core(this).overlay();
    for (uint32_t i = 0; i < o.line_count(); ++i) lines[i] = o.line(i);
    return o.line_count();
}

// The parts.
uint32_t Viewer::part_count() const {
    const module::Scene& s = core(this).scene();
    return s.loaded() ? uint32_t(s.instances().size()) : 0;
}
Viewer::Part Viewer::part(uint32_t i) const {
    const Core& c = core(this);
    if (i >= part_count()) return {"", "", 0, false};
    const module::Scene& s = c.scene();
    const uint32_t shell = s.instances()[i].shell;
    return {s.part_name(shell), s.instance_name(i), s.part(shell).face_count, s.shown(i)};
}
Result Viewer::show_part(uint32_t i, bool shown) { return core(this).show(i, shown); }
Result Viewer::isolate_part(uint32_t i) { return core(this).isolate(i); }
void Viewer::show_all_parts() { core(this).show_all(); }
Result Viewer::choose_part(uint32_t i) {
    if (i != kNone && i >= part_count()) return Result::fail(Status::OutOfRange, "no such part", {"part", i});
    core(this).choose(i);
    return {};
}
uint32_t Viewer::chosen_part() const { return core(this).chosen_part(); }

// The section plane.
Viewer::SectionPlane Viewer::section() const {
    const module::Section& s = core(this).camera().section();
    return {s.on, {s.n[0], s.n[1], s.n[2]}, s.offset};
}
Result Viewer::set_section(const SectionPlane& p) {
    module::Section s;
    if (p.on) {
        const float len = std::sqrt(p.normal[0] * p.normal[0] + p.normal[1] * p.normal[1] + p.normal[2] * p.normal[2]);
        if (!(len > 0 && std::isfinite(len))) return Result::fail(Status::OutOfRange, "a section's normal has no length or is not finite");
        if (!std::isfinite(p.offset_mm) || !(std::fabs(p.offset_mm) <= pack::kMaxMagnitude)) {
            return Result::fail(Status::OutOfRange, "a section's offset is not finite or beyond +-1e8 mm");
        }
        s.on = true;
        for (int k = 0; k < 3; ++k) s.n[k] = p.normal[k] / len;
        s.offset = p.offset_mm;
    }
    core(this).set_section(s);
    return {};
}
Result Viewer::section_through(uint32_t part, uint32_t face) { return core(this).section_through(part, face); }
Result Viewer::section_across(uint8_t axis) { return core(this).section_across(axis); }
Result Viewer::move_section(float by_mm) { return core(this).move_section(by_mm); }

} // namespace facet
