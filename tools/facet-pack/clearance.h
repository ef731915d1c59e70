#pragma once
// How close the edges of each face come to each other, so the device can keep a thin face's
// sides apart when it samples them coarsely (pack::Edge::max_sag).
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <vector>

namespace facet::packer {

// For each edge of edge_map (1-based, as the map), the largest chord sag that keeps its
// faces' loops simple: 40% of the distance to the nearest edge of one of its faces that shares
// no vertex with it and lies on its concave side there (where its chords sag to); 0 where no
// such edge exists. Each to 8 significant bits, rounded down. Entry 0 is unused.
std::vector<float> edge_sag_limits(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& edge_map);

} // namespace facet::packer
