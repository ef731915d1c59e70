#pragma once
// How far a mesh strays from the exact surfaces: the measuring code of facet-mesh and the
// tests (portable, but not used by the device's tessellation, which has its own cheaper
// estimates in refine.cpp).
//
// A point's distance to a face's surface is exact on the elementary surfaces (plane, cylinder,
// cone, sphere, torus: closed forms on the untrimmed surface); on the others it is the distance
// to the local closest point found by Gauss-Newton from a (u,v) guess, which is never less
// than the true distance. A triangle is sampled on a barycentric grid, inside and along its
// three edges, so that chords of boundary edges are measured as well as interiors.
#include "geom/eval.h"

namespace facet::geom {

// Distance from p to the surface of face `face`. uv_guess seeds the free-form search.
float distance_to_surface(const Pack& pack, uint32_t face, Vec3 p, Vec2 uv_guess);

// The largest distance to the face's surface over the points (i/n, j/n, k/n), i + j + k = n,
// of the triangle (p, uv per corner), corners excluded (they are on the surface). n >= 2.
float triangle_deviation(const Pack& pack, uint32_t face, const Vec3 p[3], const Vec2 uv[3], int n = 4);

} // namespace facet::geom
