#pragma once
// A triangle mesh simplified by edge collapses, least quadric error first (Garland & Heckbert,
// "Surface simplification using quadric error metrics", SIGGRAPH 1997), and the distance
// between two meshes measured: how a part's proxy is made and how far it is known to stray
// (proxies.h).
#include "geom/vec.h"

#include <cstdint>
#include <vector>

namespace facet::geom {

struct TriangleMesh {
    std::vector<Vec3> points;
    std::vector<uint32_t> triangles; // three corners per triangle
    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
};

// `mesh` with its points at one place made one and its triangles that then have no area
// dropped.
TriangleMesh welded(const TriangleMesh& mesh);

// `mesh` (welded) simplified until at most `max_triangles` remain, or no collapse is left that
// keeps every triangle facing as it did. Each collapse moves two corners to the one of their
// ends or middle whose planes' squared distances are least; first only collapses that keep
// the surface's topology (the link condition), then, still over the cap, those that close
// holes and merge sheets. Triangles keep their winding; the points no triangle uses are dropped.
TriangleMesh simplified(const TriangleMesh& mesh, uint32_t max_triangles);

// The largest distance from a point of `from` (its corners, and each triangle's centre and
// its sides' middles) to the surface of `to`: with the other way round, how far one strays
// from the other.
float farthest(const TriangleMesh& from, const TriangleMesh& to);

} // namespace facet::geom
