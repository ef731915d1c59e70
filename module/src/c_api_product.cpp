// The C API of the product's structure and annotations (facet/facet.h): the assembly tree, the
// exploded view, the PMI. Each call converts its arguments and calls the C++ one.
#include "c_api_shared.h"

#include <cstring>

namespace {
using namespace facet;
using c_api::cpp;
using c_api::to_c;

static_assert(int(AnnotationKind::Note) == FACET_ANNOTATION_NOTE && kAllAnnotationKinds == FACET_ALL_ANNOTATION_KINDS,
              "the C annotation kinds are facet::AnnotationKind");
static_assert(int(Action::Annotations) == FACET_ACTION_ANNOTATIONS && int(Action::Explode) == FACET_ACTION_EXPLODE,
              "the C actions are facet::Action");
} // namespace

extern "C" {

uint32_t facet_get_node_count(const facet_viewer* v) { return v ? cpp(v)->node_count() : 0; }
facet_result facet_get_node(const facet_viewer* v, uint32_t index, facet_node* out) {
    FACET_NEED_VIEWER(v);
    if (!out) return to_c(Result::fail(Status::OutOfRange, "no facet_node"));
    Viewer::Node n{};
    if (const Result r = cpp(v)->node(index, n); !r.ok()) return to_c(r);
    *out = {n.name, n.occurrence, n.parent, n.first_child, n.next_sibling, n.first_part, n.part_count, n.depth};
    return to_c({});
}
uint32_t facet_get_part_node(const facet_viewer* v, uint32_t part) { return v ? cpp(v)->part_node(part) : FACET_NONE; }
facet_result facet_show_node(facet_viewer* v, uint32_t index, bool shown) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->show_node(index, shown));
}
facet_result facet_isolate_node(facet_viewer* v, uint32_t index) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->isolate_node(index));
}
facet_result facet_fit_node(facet_viewer* v, uint32_t index) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->fit_node(index));
}
facet_result facet_choose_node(facet_viewer* v, uint32_t index) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->choose_node(index));
}
uint32_t facet_get_chosen_node(const facet_viewer* v) { return v ? cpp(v)->chosen_node() : FACET_NONE; }
float facet_get_explode(const facet_viewer* v) { return v ? cpp(v)->explode() : 0.0f; }
facet_result facet_set_explode(facet_viewer* v, float factor) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->set_explode(factor));
}

uint32_t facet_get_annotation_count(const facet_viewer* v) { return v ? cpp(v)->annotation_count() : 0; }
facet_result facet_get_annotation(const facet_viewer* v, uint32_t index, facet_annotation* out) {
    FACET_NEED_VIEWER(v);
    if (!out) return to_c(Result::fail(Status::OutOfRange, "no facet_annotation"));
    Viewer::Annotation a{};
    if (const Result r = cpp(v)->annotation(index, a); !r.ok()) return to_c(r);
    *out = {facet_annotation_kind(a.kind), a.type, a.semantic, a.presented, a.text, a.value, a.lower, a.upper, a.faces, a.face_count};
    return to_c({});
}
uint32_t facet_get_annotations_shown(const facet_viewer* v) { return v ? cpp(v)->annotations_shown() : 0; }
void facet_show_annotations(facet_viewer* v, uint32_t kinds) {
    if (v) cpp(v)->show_annotations(kinds);
}
uint32_t facet_get_face_annotations(const facet_viewer* v, uint32_t part, uint32_t face, uint32_t* out, uint32_t max) {
    return v ? cpp(v)->face_annotations(part, face, out, out ? max : 0) : 0;
}
facet_result facet_choose_annotation(facet_viewer* v, uint32_t index) {
    FACET_NEED_VIEWER(v);
    return to_c(cpp(v)->choose_annotation(index));
}
uint32_t facet_get_chosen_annotation(const facet_viewer* v) { return v ? cpp(v)->chosen_annotation() : FACET_NONE; }

} // extern "C"
