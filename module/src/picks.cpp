// What the user has picked, shown (picks.h).
#include "picks.h"
#include "core/format.h"
#include "describe.h"
#include "geom/measure.h"

#include <cstring>

namespace facet::module {

void Picks::reset() {
    selection_.clear();
    presenter_.annotating().choose(kNone);
    chosen_ = chosen_node_ = kNone;
    presenter_.overlay().set_chosen(kNone);
    shown();
}

void Picks::picked(bool hit, const Face& f) {
    if (!hit) selection_.clear(); // a tap on nothing clears the selection
    else selection_.pick(f, measuring());
    presenter_.annotating().choose(kNone);
    shown();
    redraw();
}

void Picks::set_measuring(bool on) {
    presenter_.overlay().set_measuring(on);
    selection_.keep_first();
    shown();
    redraw();
}

void Picks::choose(uint32_t part) {
    chosen_ = part, chosen_node_ = kNone;
    presenter_.overlay().set_chosen(chosen_);
    focus();
    redraw();
}

void Picks::choose_node(uint32_t node) {
    chosen_ = kNone, chosen_node_ = node;
    presenter_.overlay().set_chosen_node(node);
    focus();
    redraw();
}

void Picks::choose_annotation(uint32_t annotation) {
    selection_.clear();
    presenter_.annotating().choose(annotation);
    shown();
    redraw();
}

void Picks::hidden(uint32_t part) {
    if (selection_.any([&](const Face& p) { return p.instance == part; })) selection_.clear(); // (the whole selection goes)
    shown();
}

void Picks::shown() {
    highlight();
    panel();
}

void Picks::highlight() {
    focus();
    painter_.set_highlight(selection_.face(0), selection_.instance(0), selection_.face(1), selection_.instance(1));
    const Annotating& a = presenter_.annotating();
    painter_.set_annotation(a.chosen() != kNone ? a.annotations() : nullptr, a.chosen());
}

void Picks::focus() {
    if (chosen_node_ != kNone && chosen_node_ < scene_.tree().count()) {
        const pack::Node& n = scene_.tree()[chosen_node_];
        painter_.set_parts(n.first_instance, n.instance_count);
    } else {
        painter_.set_part(chosen_);
    }
    painter_.set_focus(chosen_ != kNone ? chosen_ : selection_.instance(0));
}

void Picks::redraw() {
    // The faces keep their pixels but the highlighted ones (drawn over the faces layer), unless
    // see-through mode draws the part in focus solid and the rest see-through.
    if (painter_.mode() == DisplayMode::SeeThrough) presenter_.invalidate();
    else presenter_.redraw();
}

bool Picks::annotation_panel() {
    const Annotating& a = presenter_.annotating();
    if (a.chosen() == kNone) return false;
    const geom::Annotations& pmi = *a.annotations();
    const pack::Annotation& r = pmi[a.chosen()];
    char lines[2][Overlay::kLineChars];
    const char* ptrs[2] = {lines[0], lines[1]};
    format(lines[0], sizeof lines[0], "{}", pmi.text(a.chosen()));
    const uint32_t faces = r.face_count;
    format(lines[1], sizeof lines[1], "{}{}, on {} face{}", geom::annotation_kind_name(pack::AnnotationKind(r.kind)),
           r.flags & pack::kSemantic ? "" : " (drawn only)", faces, faces == 1 ? "" : "s");
    presenter_.overlay().set_lines(ptrs, 2);
    return true;
}

void Picks::panel() {
    if (panel_ && annotation_panel()) return;
    if (!panel_ || selection_.count() == 0) {
        presenter_.overlay().set_lines(nullptr, 0);
        return;
    }
    const float unit = scene_.source_unit_mm();
    char lines[3][Overlay::kLineChars];
    const char* ptrs[3] = {lines[0], lines[1], lines[2]};
    geom::FaceGeometry g[2];
    for (uint32_t i = 0; i < selection_.count(); ++i) {
        const Face& p = selection_[i];
        if (!scene_.face_geometry(p.face, p.instance, g[i]).ok()) return;
        module::describe(g[i], p.face, unit, lines[i], sizeof lines[i]);
    }
    uint32_t n = selection_.count();
    if (n == 2) {
        module::describe(geom::relate(g[0], g[1]), unit, lines[n], sizeof lines[0]);
        // Exploded, the parts are drawn apart: the measurement is the assembled model's.
        if (scene_.explode() != 0) {
            const size_t at = std::strlen(lines[n]);
            format(lines[n] + at, sizeof lines[0] - at, "  (assembled)");
        }
        ++n;
    }
    else if (measuring()) format(lines[n++], sizeof lines[0], "MEAS: tap a second face");
    else if (presenter_.annotating().face_line(selection_[0].face, lines[n], sizeof lines[n]), lines[n][0]) ++n; // its PMI
    presenter_.overlay().set_lines(ptrs, n);
}

} // namespace facet::module
