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
#include "core/status.h"
#include "geom/eval.h"
#include "geom/pack.h"
#include "geom/vec.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace facet::geom {

// Whether a surface's (a curve's) record is a Params: its type's record (pack_format.h).
template <typename Params>
constexpr bool holds(const pack::Surface& s) {
    using T = pack::SurfaceType;
    const T t = T(s.type);
    if constexpr (std::is_same_v<Params, pack::PlaneParams>) return t == T::Plane;
    else if constexpr (std::is_same_v<Params, pack::CylinderParams>) return t == T::Cylinder;
    else if constexpr (std::is_same_v<Params, pack::ConeParams>) return t == T::Cone;
    else if constexpr (std::is_same_v<Params, pack::SphereParams>) return t == T::Sphere;
    else if constexpr (std::is_same_v<Params, pack::TorusParams>) return t == T::Torus;
    else if constexpr (std::is_same_v<Params, pack::RevolutionParams>) return t == T::Revolution;
    else if constexpr (std::is_same_v<Params, pack::ExtrusionParams>) return t == T::Extrusion;
    else if constexpr (std::is_same_v<Params, pack::BSplineSurfaceHead>) return t == T::BSpline;
    else static_assert(sizeof(Params) == 0, "not a surface's record");
}
template <typename Params>
constexpr bool holds(const pack::Curve& c) {
    using T = pack::CurveType;
    const T t = T(c.type);
    if constexpr (std::is_same_v<Params, pack::Line3Params>) return t == T::Line && c.dim == 3;
    else if constexpr (std::is_same_v<Params, pack::Circle3Params>) return t == T::Circle && c.dim == 3;
    else if constexpr (std::is_same_v<Params, pack::Ellipse3Params>) return t == T::Ellipse && c.dim == 3;
    else if constexpr (std::is_same_v<Params, pack::Line2Params>) return t == T::Line && c.dim == 2;
    else if constexpr (std::is_same_v<Params, pack::Circle2Params>) return t == T::Circle && c.dim == 2;
    else if constexpr (std::is_same_v<Params, pack::Ellipse2Params>) return t == T::Ellipse && c.dim == 2;
    else if constexpr (std::is_same_v<Params, pack::BSplineCurveHead>) return t == T::BSpline;
    else static_assert(sizeof(Params) == 0, "not a curve's record");
}

// The parameters of surface s (or curve c) as the record Params, which must be its type's
// (checked where assertions are on: reading a cylinder's record as a plane's is a bug).
template <typename Params>
const Params& params(const Pack& pack, const pack::Surface& s) {
    FACET_DEBUG_ASSERT("geom", holds<Params>(s));
    return *reinterpret_cast<const Params*>(pack.floats().data() + s.params);
}
template <typename Params>
const Params& params(const Pack& pack, const pack::Curve& c) {
    FACET_DEBUG_ASSERT("geom", holds<Params>(c));
    return *reinterpret_cast<const Params*>(pack.floats().data() + c.params);
}

// The frame every elementary surface's record starts with (plane, cylinder, cone, sphere, torus).
inline const pack::Frame& frame_of(const Pack& pack, const pack::Surface& s) {
    FACET_DEBUG_ASSERT("geom", is_elementary(s));
    return reinterpret_cast<const pack::PlaneParams*>(pack.floats().data() + s.params)->frame;
}

// A vector's component k (0 x, 1 y, 2 z), for left_handed() on arrays and on xyz vectors alike.
template <typename T, size_t N>
constexpr T component(const T (&v)[N], int k) { return v[k]; }
constexpr float component(const Vec3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

// Whether a frame is left-handed: (x cross y) . z < 0. A surface's own normal, du x dv, is
// outward (along z on a plane; away from the axis or the centre on the round ones) in a
// right-handed frame and inward in a left-handed one: every caller takes its sense from here.
// The components: float, double, or exact integers (a frame quantized to Q14); any type that
// component() reads (geom/measure.cpp adds its doubles').
template <typename V>
constexpr bool left_handed(const V& x, const V& y, const V& z) {
    const auto c = [](const V& v, int k) { return component(v, k); };
    const auto cross0 = c(x, 1) * c(y, 2) - c(x, 2) * c(y, 1), cross1 = c(x, 2) * c(y, 0) - c(x, 0) * c(y, 2),
               cross2 = c(x, 0) * c(y, 1) - c(x, 1) * c(y, 0);
    return cross0 * c(z, 0) + cross1 * c(z, 1) + cross2 * c(z, 2) < 0;
}
inline bool left_handed(const pack::Frame& f) { return left_handed(f.x, f.y, f.z); }

// An elementary surface's record as one view (plane, cylinder, cone, sphere, torus): its frame
// and radii, read in one place for every reader (the tessellation's closed forms, measuring,
// the view's judging of faces).
struct ElementaryRecord {
    const pack::Frame* frame = nullptr;
    float radius = 0;     // cylinder, sphere; cone: at v = 0; torus: the major radius (the tube's centre)
    float minor = 0;      // torus: the tube's radius
    float semi_angle = 0; // cone (rad)
    // Whether a face on it (reversed or not) has its natural normal, du x dv, pointing into the
    // material (a hole's wall, a left-handed frame): left_handed()'s rule.
    bool inward(bool reversed) const { return reversed != left_handed(*frame); }
};
// Surface s's record as an ElementaryRecord; false (and `out` untouched) for any other type.
inline bool elementary(const Pack& pack, const pack::Surface& s, ElementaryRecord& out) {
    if (!is_elementary(s)) return false;
    out.frame = &frame_of(pack, s);
    switch (pack::SurfaceType(s.type)) {
    case pack::SurfaceType::Cylinder: out.radius = params<pack::CylinderParams>(pack, s).radius; break;
    case pack::SurfaceType::Sphere: out.radius = params<pack::SphereParams>(pack, s).radius; break;
    case pack::SurfaceType::Cone: {
        const pack::ConeParams& c = params<pack::ConeParams>(pack, s);
        out.radius = c.ref_radius, out.semi_angle = c.semi_angle;
        break;
    }
    case pack::SurfaceType::Torus: {
        const pack::TorusParams& t = params<pack::TorusParams>(pack, s);
        out.radius = t.major_radius, out.minor = t.minor_radius;
        break;
    }
    default: break;
    }
    return true;
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
