// The viewer's tools beyond the camera: the section plane (its slider and keys) and the parts
// list (choose, hide, show, isolate), for the on-screen interface and the public API alike.
#include "core.h"
#include "geom/measure.h"

#include <cmath>

namespace facet {

namespace {

constexpr float kStep = 1.0f / 32; // SectionIn / SectionOut: of the model's diameter
static_assert(module::Scene::kMaxHideable == Viewer::kMaxHideableParts);

} // namespace

// The range a section plane moves in: the placed model's sphere along its normal.
void Core::section_range(const module::Section& s, float& lo, float& hi) const {
    const float* c = scene_.centre();
    const float at = s.n[0] * c[0] + s.n[1] * c[1] + s.n[2] * c[2];
    lo = at - scene_.radius(), hi = at + scene_.radius();
}

void Core::section_changed() {
    const module::Section& s = camera_.section();
    float lo, hi;
    section_range(s, lo, hi);
    presenter_.overlay().set_slider(s.on && config_.interface == Interface::Full, hi > lo ? (s.offset - lo) / (hi - lo) : 0.5f);
    presenter_.invalidate();
}

void Core::section_next() {
    // off -> the picked planar face's plane (when one is picked) -> x -> y -> z -> off
    module::Section s = camera_.section();
    geom::FaceGeometry g;
    const bool plane = picked_count_ > 0 &&
                       describe(picked_[0], g).ok() &&
                       g.type == pack::SurfaceType::Plane;
    uint8_t kind = section_kind_;
    do {
        kind = uint8_t((kind + 1) % 5);
    } while (kind == 1 && !plane);
    section_kind_ = kind;
    s.on = kind != 0;
    if (kind == 1) {
        // Through the face, cutting away what lies beyond it (its outward side): the slider then
        // moves the plane into the part.
        s.n[0] = float(g.axis.x), s.n[1] = float(g.axis.y), s.n[2] = float(g.axis.z);
        s.offset = float(g.offset);
    } else if (kind > 1) {
        s.n[0] = kind == 2, s.n[1] = kind == 3, s.n[2] = kind == 4;
        s.offset = scene_.centre()[kind - 2]; // through the model's middle
    }
    camera_.set_section(s);
    section_changed();
}

// The plane moved to `at` of its range (0: the near end, 1: the far end; clamped), or by
// `by` of it from where it is.
void Core::section_at(float at, bool relative) {
    module::Section s = camera_.section();
    if (!s.on) return;
    float lo, hi;
    section_range(s, lo, hi);
    if (relative && hi > lo) at += (s.offset - lo) / (hi - lo);
    s.offset = lo + (at < 0 ? 0 : at > 1 ? 1 : at) * (hi - lo);
    camera_.set_section(s);
    section_changed();
}

void Core::choose(uint32_t part) {
    chosen_part_ = scene_.loaded() && part < scene_.instances().size() ? part : ~0u;
    presenter_.overlay().set_chosen(chosen_part_);
    focus();
    presenter_.invalidate();
}

void Core::focus() {
    painter_.set_part(chosen_part_);
    painter_.set_focus(chosen_part_ != ~0u ? chosen_part_ : picked_count_ > 0 ? picked_[0].instance : ~0u);
}

Result Core::show(uint32_t part, bool shown) {
    if (!scene_.loaded() || part >= scene_.instances().size()) {
        return Result::fail(Status::OutOfRange, "no such part", {"part", part});
    }
    if (part >= module::Scene::kMaxHideable) {
        return Result::fail(Status::OutOfRange, "only the first parts can be hidden (Viewer::kMaxHideableParts)", {"part", part});
    }
    scene_.set_shown(part, shown);
    if (!shown) { // what is hidden is not picked
        for (uint32_t i = 0; i < picked_count_; ++i)
            if (picked_[i].instance == part) picked_count_ = 0;
        highlight();
        show_measurement();
    }
    presenter_.invalidate();
    return {};
}

void Core::tool(Action a) {
    if (!scene_.loaded()) return;
    const uint32_t parts = uint32_t(scene_.instances().size());
    switch (a) {
    case Action::Section: section_next(); return;
    case Action::SectionIn: section_at(-kStep, true); return;
    case Action::SectionOut: section_at(kStep, true); return;
    case Action::Parts:
        presenter_.overlay().set_parts(!presenter_.overlay().parts_open());
        presenter_.overlay().set_chosen(chosen_part_);
        presenter_.invalidate();
        return;
    case Action::NextPart: choose(chosen_part_ == ~0u || chosen_part_ + 1 >= parts ? 0 : chosen_part_ + 1); return;
    case Action::HidePart:
        if (chosen_part_ != ~0u) (void)show(chosen_part_, false); // past kMaxHideable: stays shown (show() says why)
        return;
    case Action::IsolatePart:
        if (chosen_part_ == ~0u || chosen_part_ >= module::Scene::kMaxHideable) return;
        for (uint32_t i = 0; i < parts && i < module::Scene::kMaxHideable; ++i) scene_.set_shown(i, i == chosen_part_);
        presenter_.invalidate();
        return;
    case Action::ShowAllParts:
        scene_.show_all();
        presenter_.invalidate();
        return;
    default: return;
    }
}

bool Core::tap_parts(int16_t x, int16_t y) {
    using Kind = module::Overlay::PartsHit::Kind;
    module::Overlay& o = presenter_.overlay();
    const module::Overlay::PartsHit h = o.parts_at(x, y);
    switch (h.kind) {
    case Kind::None: return false;
    case Kind::Panel: return true;
    case Kind::Row: choose(h.part == chosen_part_ ? ~0u : h.part); return true; // a second tap lets go
    case Kind::Box: (void)show(h.part, !scene_.shown(h.part)); return true;     // refused past kMaxHideable
    case Kind::Up: o.scroll(-int32_t(o.part_rows()) + 1); break;
    case Kind::Down: o.scroll(int32_t(o.part_rows()) - 1); break;
    case Kind::Hide: tool(Action::HidePart); return true;
    case Kind::Isolate: tool(Action::IsolatePart); return true;
    case Kind::All: tool(Action::ShowAllParts); return true;
    }
    presenter_.invalidate();
    return true;
}

// The public face of the tools.
uint32_t Viewer::part_count() const {
    const Core& c = *static_cast<const Core*>(this);
    return c.scene().loaded() ? uint32_t(c.scene().instances().size()) : 0;
}

Viewer::Part Viewer::part(uint32_t i) const {
    const Core& c = *static_cast<const Core*>(this);
    if (i >= part_count()) return {"", "", 0, false};
    const module::Scene& s = c.scene();
    const uint32_t shell = s.instances()[i].shell;
    return {s.part_name(shell), s.instance_name(i), s.part(shell).face_count, s.shown(i)};
}

Result Viewer::show_part(uint32_t i, bool shown) { return static_cast<Core*>(this)->show(i, shown); }
void Viewer::choose_part(uint32_t i) { static_cast<Core*>(this)->choose(i); }
uint32_t Viewer::chosen_part() const { return static_cast<const Core*>(this)->chosen_part(); }
const char* Viewer::model_name() const {
    const Core& c = *static_cast<const Core*>(this);
    return c.scene().loaded() ? c.scene().model_name() : "";
}

Viewer::SectionPlane Viewer::section() const {
    const module::Section& s = static_cast<const Core*>(this)->camera().section();
    return {s.on, {s.n[0], s.n[1], s.n[2]}, s.offset};
}

void Viewer::set_section(const SectionPlane& p) {
    Core& c = *static_cast<Core*>(this);
    module::Section s;
    const float len = std::sqrt(p.normal[0] * p.normal[0] + p.normal[1] * p.normal[1] + p.normal[2] * p.normal[2]);
    s.on = p.on && len > 0 && std::isfinite(len) && std::isfinite(p.offset_mm);
    if (s.on) {
        for (int k = 0; k < 3; ++k) s.n[k] = p.normal[k] / len;
        s.offset = p.offset_mm;
    }
    c.set_section(s);
}

Viewer::CameraView Viewer::camera() const {
    const Core& c = *static_cast<const Core*>(this);
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

} // namespace facet
