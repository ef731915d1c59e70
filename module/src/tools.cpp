// The viewer's tools beyond the camera, for the on-screen interface and the public API alike:
// the toolbar's actions, a section through a picked face (the plane itself: section.h), and the
// parts list (choose, hide, show, isolate).
#include "core.h"

namespace facet {

static_assert(module::Scene::kMaxHideable == Viewer::kMaxHideableParts);

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
    sectioning_.set(s, module::Sectioning::Kind::Picked);
    return {};
}

void Core::choose(uint32_t part) { picks_.choose(scene_.loaded() && part < scene_.instances().size() ? part : kNone); }

Result Core::show(uint32_t part, bool shown) {
    if (!scene_.loaded() || part >= scene_.instances().size()) {
        return Result::fail(Status::OutOfRange, "no such part", {"part", part});
    }
    if (part >= module::Scene::kMaxHideable) {
        return Result::fail(Status::OutOfRange, "only the first parts can be hidden (Viewer::kMaxHideableParts)", {"part", part});
    }
    scene_.set_shown(part, shown);
    if (!shown) picks_.hidden(part); // what is hidden is not picked
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
    case Action::Section: // (through the picked face's plane, when it is one)
        sectioning_.next([&] {
            const module::Selection& s = picks_.selection();
            return s.count() > 0 && section_through(s[0].instance, s[0].face).ok();
        });
        return;
    case Action::SectionIn: sectioning_.at(-module::Sectioning::kStep, true); return;
    case Action::SectionOut: sectioning_.at(module::Sectioning::kStep, true); return;
    case Action::Parts:
        if (presenter_.overlay().pmi_open()) presenter_.overlay().set_pmi(false); // (the annotations list in its panel: closed)
        else presenter_.overlay().set_parts(!presenter_.overlay().parts_open());
        if (picks_.chosen_node() != kNone) presenter_.overlay().set_chosen_node(picks_.chosen_node());
        else presenter_.overlay().set_chosen(picks_.chosen());
        presenter_.redraw(); // (the list opened or closed)
        return;
    case Action::NextPart: choose(picks_.chosen() == kNone || picks_.chosen() + 1 >= parts ? 0 : picks_.chosen() + 1); return;
    case Action::HidePart: // (the part chosen, or the sub-assembly)
        if (picks_.chosen_node() != kNone) (void)show_node(picks_.chosen_node(), false);
        else if (picks_.chosen() != kNone) (void)show(picks_.chosen(), false); // past kMaxHideable: stays shown (show() says why)
        return;
    case Action::IsolatePart:
        if (picks_.chosen_node() != kNone) (void)isolate_node(picks_.chosen_node());
        else if (picks_.chosen() != kNone) (void)isolate(picks_.chosen()); // (likewise)
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
    case Kind::Row: choose(h.part == picks_.chosen() ? kNone : h.part); return true; // a second tap lets go
    case Kind::NodeRow: // a sub-assembly chosen (a second tap lets go)
        (void)choose_node(h.part == picks_.chosen_node() ? kNone : h.part);
        o.set_chosen_node(picks_.chosen_node());
        return true;
    case Kind::NodeBox: o.toggle_open(h.part); break; // opened or closed
    case Kind::Fit: // the chosen sub-assembly or part framed (none: the model)
        if (picks_.chosen_node() != kNone) (void)fit_node(picks_.chosen_node());
        else if (picks_.chosen() != kNone) (void)fit_part(picks_.chosen());
        else fit();
        return true;
    case Kind::Explode: toggle_explode(); return true;
    case Kind::Box: (void)show(h.part, !scene_.shown(h.part)); return true;     // refused past kMaxHideable
    case Kind::Up: o.scroll(-int32_t(o.part_rows()) + 1); break;
    case Kind::Down: o.scroll(int32_t(o.part_rows()) - 1); break;
    case Kind::Hide: tool(Action::HidePart); return true;
    case Kind::Isolate: tool(Action::IsolatePart); return true;
    case Kind::All: tool(Action::ShowAllParts); return true;
    case Kind::Tab: o.set_pmi(true); break; // the annotations list
    case Kind::KindToggle:
    case Kind::ShowAll:
    case Kind::HideAll: return true; // (the annotations list's)
    }
    presenter_.redraw(); // (the list scrolled)
    return true;
}

} // namespace facet
