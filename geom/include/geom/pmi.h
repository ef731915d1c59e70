#pragma once
// A pack's annotations (geom/pmi_format.h), read in place after checking all of them.
//
//   geom::Annotations pmi;
//   if (Result r = pmi.open(pack); !r.ok()) ... // "section Annotations record 12: a face index is out of range"
//   for (uint32_t i = 0; i < pmi.count(); ++i) use(pmi.text(i), pmi.faces(i), pmi.polylines(i));
//
// A pack without the sections has none (count() 0). open() checks every record's kind, type
// and flags, that its text is a 0-ended string of at most kMaxAnnotationText bytes, its faces
// the pack's, its polylines and points inside their sections (two points or more, every
// coordinate within +-1e8), `drawn_by` an earlier annotation, and its floats finite.
#include "core/status.h"
#include "geom/pack.h"
#include "geom/pmi_format.h"
#include "geom/sections.h"

#include <cstdint>
#include <span>

namespace facet::geom {

class PackIndex;

class Annotations {
public:
    Result open(const Pack& pack);
    // A blocked pack's: its index carries them (faces numbered across its blocks, as a whole
    // pack's are: the blocks' parts are the model's in order).
    Result open(const PackIndex& index);

    uint32_t count() const { return uint32_t(records_.size()); }
    const pack::Annotation& operator[](uint32_t i) const { return records_[i]; }
    const char* text(uint32_t i) const { return text_.data() + records_[i].text; }
    std::span<const uint32_t> faces(uint32_t i) const { return faces_.subspan(records_[i].first_face, records_[i].face_count); }
    std::span<const pack::Polyline> polylines(uint32_t i) const {
        return polylines_.subspan(records_[i].first_polyline, records_[i].polyline_count);
    }
    std::span<const pack::Polyline> coarse_polylines(uint32_t i) const {
        return polylines_.subspan(records_[i].first_coarse, records_[i].coarse_count);
    }
    // A polyline's steps (pack::PmiStep: its points in its annotation's sphere).
    std::span<const pack::PmiStep> points(const pack::Polyline& l) const { return points_.subspan(l.first_point, l.point_count); }
    // Whether annotation i applies to face f (a pack face index).
    bool applies_to(uint32_t i, uint32_t f) const;

private:
    Result fail(const char* what, pack::PmiSectionId section, uint32_t index);
    Result read(const SectionTable& table, uint32_t faces);
    Result check(uint32_t faces);

    std::span<const pack::Annotation> records_;
    std::span<const char> text_;
    std::span<const uint32_t> faces_;
    std::span<const pack::Polyline> polylines_;
    std::span<const pack::PmiStep> points_;
};

const char* annotation_kind_name(pack::AnnotationKind kind); // "dimension", "tolerance", "datum", "note"

} // namespace facet::geom
