#pragma once
// A surface's or curve's parameters by name: the records of pack_format.h read in place from
// a validated pack. Pack::open() checked each record's float count against its type, so the
// record of that type is there to read; the caller picks it by the record's type:
//
//   switch (SurfaceType(s.type)) {
//   case SurfaceType::Cylinder: { const auto& c = params<pack::CylinderParams>(pack, s); ... c.radius ...
//
// Elementary surfaces are better read through geom/src/elementary.h (frame and radii as
// vectors, and every closed form on them); B-splines through the views below.
#include "geom/pack.h"
#include "geom/vec.h"

#include <cstdint>

namespace facet::geom {

// The parameters of surface s (or curve c) as the record Params (its type's; pack_format.h).
template <typename Params>
const Params& params(const Pack& pack, const pack::Surface& s) {
    return *reinterpret_cast<const Params*>(pack.floats().data() + s.params);
}
template <typename Params>
const Params& params(const Pack& pack, const pack::Curve& c) {
    return *reinterpret_cast<const Params*>(pack.floats().data() + c.params);
}

inline Vec3 vec3(const float (&a)[3]) { return {a[0], a[1], a[2]}; }
inline Vec2 vec2(const float (&a)[2]) { return {a[0], a[1]}; }

// A B-spline curve's layout: its head's counts and where its knots, poles (`dim` floats each)
// and weights lie.
struct BSplineCurveView {
    int p, n, k; // degree, poles, knots (expanded)
    bool rational, periodic;
    const float *knots, *poles, *weights;

    // The curve whose head is at `head` (the floats that follow are read as its layout says:
    // Pack::open() checked they are there, or the caller did).
    BSplineCurveView(const pack::BSplineCurveHead& head, int dim)
        : p(int(head.degree)), n(int(head.pole_count)), k(int(head.knot_count)), rational(head.rational != 0),
          periodic(head.periodic != 0), knots(reinterpret_cast<const float*>(&head + 1)), poles(knots + k),
          weights(poles + n * dim) {}
};

// A B-spline surface's layout: poles row after row (u), nv to a row, three floats each.
struct BSplineSurfaceView {
    int pu, pv, nu, nv, ku, kv; // degrees, poles, knots (expanded) in u and v
    bool rational, u_periodic, v_periodic;
    const float *uk, *vk, *poles, *weights;

    explicit BSplineSurfaceView(const pack::BSplineSurfaceHead& head)
        : pu(int(head.u_degree)), pv(int(head.v_degree)), nu(int(head.u_poles)), nv(int(head.v_poles)),
          ku(int(head.u_knots)), kv(int(head.v_knots)), rational(head.rational != 0), u_periodic(head.u_periodic != 0),
          v_periodic(head.v_periodic != 0), uk(reinterpret_cast<const float*>(&head + 1)), vk(uk + ku), poles(vk + kv),
          weights(poles + 3 * nu * nv) {}
};

inline BSplineCurveView bspline(const Pack& pack, const pack::Curve& c) {
    return BSplineCurveView(params<pack::BSplineCurveHead>(pack, c), c.dim);
}
inline BSplineSurfaceView bspline(const Pack& pack, const pack::Surface& s) {
    return BSplineSurfaceView(params<pack::BSplineSurfaceHead>(pack, s));
}

} // namespace facet::geom
