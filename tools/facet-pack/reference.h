#pragma once
// Open CASCADE's own values of every packed face (in pack order, in its shell's coordinates):
// the surface type and its exact parameters in double, the face's outward normal for planes
// and whether a cylinder or cone is a hole. For checking facet-measure (`--reference FILE`).
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace facet::packer {

std::string reference_json(const std::vector<TopoDS_Shape>& faces, double unit_mm);

} // namespace facet::packer
