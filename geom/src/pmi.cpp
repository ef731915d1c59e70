#include "geom/pmi.h"

#include "geom/pack_index.h"

#include <cmath>
#include <cstring>

namespace facet::geom {
namespace {

using pack::PmiSectionId;

struct SectionShape {
    PmiSectionId id;
    const char* place; // the place of one of its records
    uint32_t record_bytes;
};
constexpr SectionShape kSections[] = {
    {PmiSectionId::Annotations, "section Annotations record", sizeof(pack::Annotation)},
    {PmiSectionId::PmiText, "section PmiText byte", 1},
    {PmiSectionId::PmiFaces, "section PmiFaces record", 4},
    {PmiSectionId::PmiPolylines, "section PmiPolylines record", sizeof(pack::Polyline)},
    {PmiSectionId::PmiPoints, "section PmiPoints record", sizeof(pack::PmiStep)},
};
constexpr uint32_t kFirst = uint32_t(PmiSectionId::Annotations);

bool finite(float f) { return std::fabs(f) <= pack::kMaxMagnitude; }

bool run_inside(uint32_t first, uint32_t count, size_t size) { return uint64_t(first) + count <= size; }

uint8_t types_of(pack::AnnotationKind kind) {
    switch (kind) {
    case pack::AnnotationKind::Dimension: return pack::kDimensionTypes;
    case pack::AnnotationKind::Tolerance: return pack::kToleranceTypes;
    case pack::AnnotationKind::Datum: return 2;
    case pack::AnnotationKind::Note: return 1;
    }
    return 0;
}

} // namespace

const char* annotation_kind_name(pack::AnnotationKind kind) {
    switch (kind) {
    case pack::AnnotationKind::Dimension: return "dimension";
    case pack::AnnotationKind::Tolerance: return "tolerance";
    case pack::AnnotationKind::Datum: return "datum";
    case pack::AnnotationKind::Note: return "note";
    }
    return "annotation";
}

Result Annotations::fail(const char* what, PmiSectionId section, uint32_t index) {
    *this = Annotations{};
    return Result::fail(Status::Corrupt, what, {kSections[uint32_t(section) - kFirst].place, index});
}

Result Annotations::open(const Pack& pack) {
    *this = Annotations{};
    return read(SectionTable::of(pack), uint32_t(pack.faces().size()));
}

Result Annotations::open(const PackIndex& index) {
    *this = Annotations{};
    uint64_t faces = 0;
    for (const pack::Part& p : index.parts()) faces += p.face_count;
    return read(SectionTable::of(index), faces > UINT32_MAX ? UINT32_MAX : uint32_t(faces));
}

Result Annotations::read(const SectionTable& table, uint32_t faces) {
    uint32_t seen = 0;
    for (uint32_t i = 0; i < table.entries.size(); ++i) {
        const pack::SectionEntry& s = table.entries[i];
        if (s.id < kFirst || s.id >= kFirst + std::size(kSections)) continue;
        const SectionShape& shape = kSections[s.id - kFirst];
        if (seen & (1u << (s.id - kFirst))) return fail("section appears twice", shape.id, 0);
        seen |= 1u << (s.id - kFirst);
        if (const char* why = table.problem(s, shape.record_bytes)) return fail(why, shape.id, 0);
        switch (shape.id) {
        case PmiSectionId::Annotations: records_ = table.records<pack::Annotation>(s); break;
        case PmiSectionId::PmiText: text_ = table.records<char>(s); break;
        case PmiSectionId::PmiFaces: faces_ = table.records<uint32_t>(s); break;
        case PmiSectionId::PmiPolylines: polylines_ = table.records<pack::Polyline>(s); break;
        case PmiSectionId::PmiPoints: points_ = table.records<pack::PmiStep>(s); break;
        }
    }
    return check(faces);
}

Result Annotations::check(uint32_t pack_faces) {
    using pack::kNoIndex;
    if (records_.size() > pack::kMaxAnnotations) return fail("more annotations than a reader holds", PmiSectionId::Annotations, 0);
    if (!text_.empty() && (text_.back() != 0 || (text_.size() & 3))) {
        return fail("the texts are not ended by a 0 byte and padded to 4 bytes", PmiSectionId::PmiText, uint32_t(text_.size()));
    }
    for (uint32_t i = 0; i < faces_.size(); ++i)
        if (faces_[i] >= pack_faces) return fail("a face index is out of range", PmiSectionId::PmiFaces, i);
    // Each polyline's points follow the one before's, and add up to points in its sphere.
    uint32_t next_point = 0;
    for (uint32_t i = 0; i < polylines_.size(); ++i) {
        const pack::Polyline& l = polylines_[i];
        if (l.point_count < 2 || l.first_point != next_point || !run_inside(l.first_point, l.point_count, points_.size())) {
            return fail("a polyline's points are fewer than 2, not after the one before's, or outside PmiPoints", PmiSectionId::PmiPolylines, i);
        }
        next_point += l.point_count;
        int32_t at[3] = {0, 0, 0};
        for (uint32_t k = l.first_point; k < l.first_point + l.point_count; ++k) {
            for (int a = 0; a < 3; ++a) {
                at[a] += points_[k].d[a];
                if (at[a] < -pack::kStepUnits || at[a] > pack::kStepUnits) return fail("a point lies outside its annotation's sphere", PmiSectionId::PmiPoints, k);
            }
        }
    }
    constexpr PmiSectionId A = PmiSectionId::Annotations;
    uint32_t next_polyline = 0; // (each annotation's polylines after the one before's: each polyline one annotation's)
    for (uint32_t i = 0; i < records_.size(); ++i) {
        const pack::Annotation& a = records_[i];
        if (a.first_polyline != next_polyline || a.first_coarse != a.first_polyline + a.polyline_count) {
            return fail("its polylines do not follow the annotation before's, its coarse ones its fine ones", A, i);
        }
        next_polyline = a.first_coarse + a.coarse_count;
        if (a.kind >= pack::kAnnotationKinds || a.type >= types_of(pack::AnnotationKind(a.kind))) return fail("unknown kind or type", A, i);
        if ((a.flags & ~pack::kAnnotationFlags) || a.material > uint8_t(pack::Material::Least)) return fail("unknown flags or material", A, i);
        // The text starts a string (at the pool's start or after a 0 byte) that ends in time.
        if (a.text >= text_.size() || (a.text > 0 && text_[a.text - 1] != 0)) return fail("the text does not start a string of PmiText", A, i);
        const void* end = std::memchr(text_.data() + a.text, 0, text_.size() - a.text);
        if (static_cast<const char*>(end) - (text_.data() + a.text) > int32_t(pack::kMaxAnnotationText)) return fail("the text is too long", A, i);
        if (!run_inside(a.first_face, a.face_count, faces_.size())) return fail("its faces lie outside PmiFaces", A, i);
        if (!run_inside(a.first_polyline, a.polyline_count, polylines_.size()) || !run_inside(a.first_coarse, a.coarse_count, polylines_.size())) {
            return fail("its polylines lie outside PmiPolylines", A, i);
        }
        if (a.polyline_count != a.coarse_count) return fail("not as many coarse polylines as fine ones", A, i);
        if (a.outline_count > a.polyline_count) return fail("an outline of more polylines than it has", A, i);
        if (a.polyline_count > 0 && !(a.radius > 0)) return fail("polylines without a sphere that holds them", A, i);
        // Presented: by its own polylines, or by an earlier annotation's (drawn_by), not both.
        const bool presented = (a.flags & pack::kPresented) != 0;
        if (a.drawn_by != kNoIndex && (a.drawn_by >= i || !presented || a.polyline_count > 0)) {
            return fail("drawn by an annotation not before it, or with polylines of its own", A, i);
        }
        if (presented != (a.polyline_count > 0 || a.drawn_by != kNoIndex)) return fail("the presented flag does not match its polylines", A, i);
        const float floats[] = {a.value,     a.lower,     a.upper,     a.anchor[0], a.anchor[1], a.anchor[2], a.normal[0],
                                a.normal[1], a.normal[2], a.centre[0], a.centre[1], a.centre[2], a.radius,    a.stroke};
        for (float f : floats)
            if (!finite(f)) return fail("a value or point is NaN, infinite or beyond +-1e8", A, i);
        if (a.radius < 0 || a.stroke < 0) return fail("a sphere or strokes of negative size", A, i);
        if (a.flags & pack::kHasPlane) {
            const float n2 = a.normal[0] * a.normal[0] + a.normal[1] * a.normal[1] + a.normal[2] * a.normal[2];
            if (!(n2 > 0.98f && n2 < 1.02f)) return fail("the plane's normal is not of unit length", A, i);
        }
    }
    return {};
}

bool Annotations::applies_to(uint32_t i, uint32_t f) const {
    for (uint32_t g : faces(i))
        if (g == f) return true;
    return false;
}

} // namespace facet::geom
