#pragma once
// Exact evaluation of the pack's surfaces and curves (points and first derivatives), and the
// inverse of the elementary surfaces. Everything reads parameters in place from a validated
// geom::Pack.
#include "geom/pack.h"
#include "geom/vec.h"

namespace facet::geom {

constexpr int kMaxDegree = 25; // the pack validator's limit

struct SurfacePoint {
    Vec3 p, du, dv; // position and partial derivatives; the natural normal is du x dv
};

struct Curve3Point {
    Vec3 p, d;
};

struct Curve2Point {
    Vec2 p, d;
};

SurfacePoint eval_surface(const Pack& pack, const pack::Surface& s, float u, float v);
// The position alone (cheaper on B-splines: no derivatives).
Vec3 eval_surface_point(const Pack& pack, const pack::Surface& s, float u, float v);
Curve3Point eval_curve3(const Pack& pack, const pack::Curve& c, float t);
// The position alone (the same value as eval_curve3's; on B-splines without the derivative's
// divisions and sums: about a fifth less on a high-degree one, in soft float).
Vec3 eval_curve3_point(const Pack& pack, const pack::Curve& c, float t);
Curve2Point eval_curve2(const Pack& pack, const pack::Curve& c, float t);

// (u,v) of a point on an elementary surface (plane, cylinder, cone, sphere, torus), choosing
// the branch that fits the face's bounds (periodic parameters into [min, min + 2 pi); on a
// self-intersecting torus the solution nearer the face). False for other types.
bool invert_elementary(const Pack& pack, const pack::Surface& s, Vec3 p, const float uv_min[2],
                       const float uv_max[2], Vec2& uv);

// All preimages (1, or 2 on a self-intersecting torus) of a point on an elementary surface;
// returns the count (0 for other types).
int invert_candidates(const Pack& pack, const pack::Surface& s, Vec3 p, const float uv_min[2],
                      const float uv_max[2], Vec2 out[2]);

inline bool is_elementary(const pack::Surface& s) {
    return s.type >= uint8_t(pack::SurfaceType::Plane) && s.type <= uint8_t(pack::SurfaceType::Torus);
}
// Whether u (v) of this surface type is an angle (periodic with 2 pi).
bool u_periodic(const pack::Surface& s);
bool v_periodic(const pack::Surface& s);

} // namespace facet::geom
