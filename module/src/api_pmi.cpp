// The Viewer's calls for annotations (facet/viewer.h), and the Core's behind them.
#include "core.h"

namespace facet {
namespace {
Core& core(Viewer* v) { return *static_cast<Core*>(v); }
const Core& core(const Viewer* v) { return *static_cast<const Core*>(v); }
} // namespace

void Core::show_annotations(uint32_t kinds) {
    module::Annotating& a = presenter_.annotating();
    if (a.shown() == (kinds & pack::kAllKinds)) return;
    a.show(kinds);
    presenter_.redraw(); // (the same faces: the layer's copy, then the lines and labels over it)
}

Result Core::choose_annotation(uint32_t annotation) {
    if (annotation != kNone && annotation >= presenter_.annotating().count()) {
        return Result::fail(Status::OutOfRange, "no such annotation", {"annotation", annotation});
    }
    picks_.choose_annotation(annotation);
    return {};
}

bool Core::tap_pmi(int16_t x, int16_t y) {
    using Kind = module::Overlay::PartsHit::Kind;
    module::Overlay& o = presenter_.overlay();
    const module::Overlay::PartsHit h = o.pmi_at(x, y);
    const uint32_t shown = presenter_.annotating().shown();
    switch (h.kind) {
    case Kind::None: return false;
    case Kind::Panel: return true;
    case Kind::Row: (void)choose_annotation(h.part == chosen_annotation() ? kNone : h.part); return true; // a second tap lets go
    case Kind::KindToggle: show_annotations(shown ^ (1u << h.part)); break;
    case Kind::ShowAll: show_annotations(pack::kAllKinds); break;
    case Kind::HideAll: show_annotations(0); break;
    case Kind::Up: o.scroll_pmi(-int32_t(o.pmi_rows()) + 1); break;
    case Kind::Down: o.scroll_pmi(int32_t(o.pmi_rows()) - 1); break;
    case Kind::Tab: o.set_parts(true); break; // the parts list
    case Kind::Box:
    case Kind::Hide:
    case Kind::Isolate:
    case Kind::All:
    case Kind::NodeRow:
    case Kind::NodeBox:
    case Kind::Fit:
    case Kind::Explode: return true; // (the parts list's)
    }
    presenter_.redraw(); // (the list changed)
    return true;
}

uint32_t Viewer::annotation_count() const { return core(this).annotating().count(); }

Result Viewer::annotation(uint32_t index, Annotation& out) const {
    const geom::Annotations* pmi = core(this).annotating().annotations();
    if (!pmi || index >= pmi->count()) return Result::fail(Status::OutOfRange, "no such annotation", {"annotation", index});
    const pack::Annotation& a = (*pmi)[index];
    const auto faces = pmi->faces(index);
    out = {AnnotationKind(a.kind), a.type, (a.flags & pack::kSemantic) != 0, (a.flags & pack::kPresented) != 0, pmi->text(index),
           a.value, a.lower, a.upper, faces.data(), uint32_t(faces.size())};
    return {};
}

uint32_t Viewer::annotations_shown() const { return core(this).annotating().shown(); }
void Viewer::show_annotations(uint32_t kinds) { core(this).show_annotations(kinds); }

uint32_t Viewer::face_annotations(uint32_t part, uint32_t face, uint32_t* out, uint32_t max) const {
    const Core& c = core(this);
    if (!c.check_face(part, face).ok() && !(c.check_part(part).ok() && face < c.scene().face_count())) return 0;
    return c.annotating().of_face(face, out, out ? max : 0);
}

Result Viewer::choose_annotation(uint32_t index) { return core(this).choose_annotation(index); }
uint32_t Viewer::chosen_annotation() const { return core(this).chosen_annotation(); }

} // namespace facet
