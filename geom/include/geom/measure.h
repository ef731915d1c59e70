#pragma once
// Exact measurement from the pack: what a face's surface is (its type and parameters, placed
// by an instance) and how two faces relate (the distance between parallel planes, between a
// plane and an axis, between two axes; angles), computed from the surfaces' own parameters,
// not from a mesh. In double: on a core without an FPU a measurement is a one-off, and the
// pack's float32 parameters then lose nothing more on the way.
#include "geom/pack.h"
#include "core/status.h"

#include <cstdint>

namespace facet::geom {

struct D3 {
    double x = 0, y = 0, z = 0;
};

// A face's surface, placed. Lengths in millimetres, angles in radians.
struct FaceGeometry {
    pack::SurfaceType type = pack::SurfaceType::Plane;
    bool reversed = false; // the face's normal is opposite the surface's
    D3 origin;             // plane: its origin; cylinder, cone, torus: a point of the axis; sphere: the centre
    D3 axis;               // plane: the face's normal (outward); cylinder, cone, torus, revolution: the axis
                           // direction; extrusion: the direction of extrusion
    double offset = 0;     // plane: axis . p for every point p of the plane
    double radius = 0;     // cylinder, sphere; cone: at the origin; torus: major radius
    double minor = 0;      // torus: the tube's radius
    double half_angle = 0; // cone
    bool hole = false;     // cylinder, cone: the face looks at its axis (a hole, not a boss)
    int u_degree = 0, v_degree = 0, u_poles = 0, v_poles = 0; // B-spline
    bool rational = false;
    bool u_periodic = false, v_periodic = false; // poles: one period unrolled (the pack's open form)
    bool has_axis() const;  // cylinder, cone, torus, revolution
    bool has_point() const; // sphere, torus: the centre is a point to measure from
};

// Face `face` placed by `placement` (a pack::Instance's 3x4 row-major matrix; null: as stored).
Result describe_face(const Pack& pack, uint32_t face, const float* placement, FaceGeometry& out);

// How two faces relate.
struct Relation {
    enum class Kind : uint8_t {
        None,        // nothing exact to say (a free-form face)
        Planes,      // angle between the planes; distance when parallel
        PlaneAxis,   // angle between the plane and the axis; distance when the axis is parallel to the plane
        Axes,        // angle between the axes; distance between them (parallel or skew)
        PlanePoint,  // distance from a centre to the plane
        AxisPoint,   // distance from a centre to the axis
        Points,      // distance between two centres
    } kind = Kind::None;
    double distance = 0;   // mm; valid when has_distance
    double angle = 0;      // radians, 0 to pi/2 (between planes or lines, whichever way they face)
    bool parallel = false; // within kParallel
    bool has_distance = false;
};
constexpr double kParallel = 1e-6; // radians: closer to parallel is parallel

Relation relate(const FaceGeometry& a, const FaceGeometry& b);

const char* surface_name(pack::SurfaceType t);

} // namespace facet::geom
