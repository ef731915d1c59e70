#pragma once
// The text of an annotation as a drawing writes it (UTF-8, with the GD&T symbols facet's font
// draws): a dimension's ("⌀52 ±0.15", "⌀10 H7", "60° ±0.5"), a tolerance's ("⌖ ⌀1.5 Ⓜ"), the
// datums a tolerance refers to (" A B C"); each sets the record's type and values.
#include "geom/pmi_format.h"

#include <TDF_Label.hxx>
#include <XCAFDimTolObjects_DimensionObject.hxx>
#include <XCAFDimTolObjects_GeomToleranceObject.hxx>
#include <XCAFDoc_DimTolTool.hxx>

#include <string>

namespace facet::packer {

std::string dimension_text(const XCAFDimTolObjects_DimensionObject& o, pack::Annotation& r);
std::string tolerance_text(const XCAFDimTolObjects_GeomToleranceObject& o, pack::Annotation& r);
std::string datum_system(const Handle(XCAFDoc_DimTolTool)& tool, const TDF_Label& tolerance);

} // namespace facet::packer
