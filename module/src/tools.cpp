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
    for (uint8_t kind = uint8_t((section_kind_ + 1) % 5);; kind = uint8_t((kind + 1) % 5)) {
        if (kind == 0) {
            set_section(module::Section{});
            section_kind_ = 0;
            return;
        }
        if (kind == 1 ? selection_.count() > 0 && section_through(selection_[0].instance, selection_[0].face).ok() : section_across(uint8_t(kind - 2)).ok()) return;
    }
}

// Through a planar face, cutting away what lies beyond it (its outward side): the slider then
// moves the plane into the part.
Result Core::section_through(uint32_t part, uint32_t face) {
    FaceFacts f;
    if (const Result r = facts(part, face, f); !r.ok()) return r;
    if (f.surface != Surface::Plane) return Result::fail(Status::Unsupported, "a section goes through a planar face only", {"face", face});
    module::Section s;
    s.on = true;
    for (int k = 0; k < 3; ++k) s.n[k] = float(f.axis[k]);
    s.offset = float(f.offset_mm);
    set_section(s);
    section_kind_ = 1;
    return {};
}

Result Core::section_across(uint8_t axis) {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    if (axis > 2) return Result::fail(Status::OutOfRange, "the axis is 0 (x), 1 (y) or 2 (z)", {"axis", axis});
    module::Section s;
    s.on = true;
    s.n[0] = axis == 0, s.n[1] = axis == 1, s.n[2] = axis == 2;
    s.offset = scene_.centre()[axis]; // through the model's middle
    set_section(s);
    section_kind_ = uint8_t(axis + 2);
    return {};
}

Result Core::move_section(float by_mm) {
    const module::Section& s = camera_.section();
    if (!scene_.loaded() || !s.on) return Result::fail(Status::NotFound, "no section is on");
    if (!std::isfinite(by_mm)) return Result::fail(Status::OutOfRange, "the distance must be finite");
    float lo, hi;
    section_range(s, lo, hi);
    section_at(hi > lo ? by_mm / (hi - lo) : 0, true);
    return {};
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
    chosen_part_ = scene_.loaded() && part < scene_.instances().size() ? part : kNone;
    presenter_.overlay().set_chosen(chosen_part_);
    focus();
    highlight_changed();
}

void Core::highlight_changed() {
    // The faces keep their pixels but the highlighted ones (drawn over the faces layer), unless
    // see-through mode draws the part in focus solid and the rest see-through.
    if (painter_.mode() == DisplayMode::SeeThrough) presenter_.invalidate();
    else presenter_.redraw();
}

void Core::focus() {
    painter_.set_part(chosen_part_);
    painter_.set_focus(chosen_part_ != kNone ? chosen_part_ : selection_.instance(0));
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
        if (selection_.any([&](const Picked& p) { return p.instance == part; })) selection_.clear(); // (the whole selection goes)
        highlight();
        show_measurement();
    }
    presenter_.invalidate();
    return {};
}

Result Core::isolate(uint32_t part) {
    if (const Result r = check_part(part); !r.ok()) return r;
    if (part >= module::Scene::kMaxHideable) {
        return Result::fail(Status::OutOfRange, "only the first parts can be hidden (Viewer::kMaxHideableParts)", {"part", part});
    }
    const uint32_t parts = uint32_t(scene_.instances().size());
    for (uint32_t i = 0; i < parts && i < module::Scene::kMaxHideable; ++i) (void)show(i, i == part); // (each one hideable)
    return {};
}

void Core::show_all() {
    if (!scene_.loaded()) return;
    scene_.show_all();
    presenter_.invalidate();
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
        presenter_.redraw(); // (the list opened or closed)
        return;
    case Action::NextPart: choose(chosen_part_ == kNone || chosen_part_ + 1 >= parts ? 0 : chosen_part_ + 1); return;
    case Action::HidePart:
        if (chosen_part_ != kNone) (void)show(chosen_part_, false); // past kMaxHideable: stays shown (show() says why)
        return;
    case Action::IsolatePart:
        if (chosen_part_ != kNone) (void)isolate(chosen_part_); // (likewise)
        return;
    case Action::ShowAllParts: show_all(); return;
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
    case Kind::Row: choose(h.part == chosen_part_ ? kNone : h.part); return true; // a second tap lets go
    case Kind::Box: (void)show(h.part, !scene_.shown(h.part)); return true;     // refused past kMaxHideable
    case Kind::Up: o.scroll(-int32_t(o.part_rows()) + 1); break;
    case Kind::Down: o.scroll(int32_t(o.part_rows()) - 1); break;
    case Kind::Hide: tool(Action::HidePart); return true;
    case Kind::Isolate: tool(Action::IsolatePart); return true;
    case Kind::All: tool(Action::ShowAllParts); return true;
    }
    presenter_.redraw(); // (the list scrolled)
    return true;
}

} // namespace facet
