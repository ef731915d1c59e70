#pragma once
// A picked face's exact surface and two faces' relation as one line of the measurement panel,
// in the file's unit (geom/measure.h computes them; this only words them). facet-measure says
// the same on the host, at more length.
#include "geom/measure.h"

#include <cstddef>
#include <cstdint>

namespace facet::module {

const char* unit_name(float mm); // a file's length unit (mm in it) as its short name: mm, cm, m, in, ft, units
void describe(const geom::FaceGeometry& g, uint32_t face, float unit_mm, char* out, size_t size);
void describe(const geom::Relation& r, float unit_mm, char* out, size_t size);

} // namespace facet::module
