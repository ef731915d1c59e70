#pragma once
// The edges of a triangle mesh, counted the same way for facet's meshes and for Open CASCADE's
// (tools/facet-mesh, bench/): vertices welded where their positions are exactly equal, within
// one group (a shell, a part); then each edge is used by one triangle (free), two (manifold)
// or more (non-manifold). An edge with more than two triangles where one of them appears,
// with the same three corners, in two different faces lies where two faces of the B-rep
// overlap (tail_section_asm: an extrusion on a cylinder): counted apart, as overlap. Host only.
#include <cstdint>
#include <functional>
#include <vector>

namespace facet::geom {

struct TopoTriangle {
    uint32_t group; // edges are welded within a group only
    uint32_t face;
    float p[3][3];
};

struct EdgeTopology {
    uint64_t free = 0, nonmanifold = 0, overlap = 0;
};

// An edge used by other than two triangles: its ends and the triangles (indices) using it.
struct BadEdge {
    const float* a;
    const float* b;
    const std::vector<uint32_t>& triangles;
};

EdgeTopology edge_topology(const std::vector<TopoTriangle>& triangles,
                           const std::function<void(const BadEdge&)>& on_bad_edge = nullptr);

} // namespace facet::geom
