#include "geom/measure.h"

#include "geom/params.h"

#include <cmath>

namespace facet::geom {

// A D3's component k, for left_handed() (geom/params.h).
constexpr double component(const D3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

namespace {

D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(D3 a) { return std::sqrt(dot(a, a)); }
D3 unit(D3 a) {
    const double l = length(a);
    return l > 0 ? a * (1 / l) : a;
}

constexpr double kHalfPi = 1.57079632679489661923;

D3 d3(const float* q) { return {q[0], q[1], q[2]}; }

// A point and a direction through the placement (rows: x, y, z; column 3: translation).
D3 place_point(const float* m, D3 p) {
    if (!m) return p;
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}
D3 place_direction(const float* m, D3 d) {
    if (!m) return d;
    return {m[0] * d.x + m[1] * d.y + m[2] * d.z, m[4] * d.x + m[5] * d.y + m[6] * d.z, m[8] * d.x + m[9] * d.y + m[10] * d.z};
}

// The angle between two lines (or planes' normals), 0 to pi/2, whichever way they point.
double line_angle(D3 a, D3 b) {
    const double s = length(cross(a, b)), c = std::fabs(dot(a, b));
    return std::atan2(s, c);
}

double point_to_axis(D3 p, D3 origin, D3 dir) { return length(cross(p - origin, dir)); }

} // namespace

bool FaceGeometry::has_axis() const {
    return type == pack::SurfaceType::Cylinder || type == pack::SurfaceType::Cone || type == pack::SurfaceType::Torus ||
           type == pack::SurfaceType::Revolution;
}
bool FaceGeometry::has_point() const { return type == pack::SurfaceType::Sphere || type == pack::SurfaceType::Torus; }

const char* surface_name(pack::SurfaceType t) {
    switch (t) {
    case pack::SurfaceType::Plane: return "plane";
    case pack::SurfaceType::Cylinder: return "cylinder";
    case pack::SurfaceType::Cone: return "cone";
    case pack::SurfaceType::Sphere: return "sphere";
    case pack::SurfaceType::Torus: return "torus";
    case pack::SurfaceType::BSpline: return "B-spline";
    case pack::SurfaceType::Revolution: return "revolution";
    case pack::SurfaceType::Extrusion: return "extrusion";
    }
    return "surface";
}

Result describe_face(const Pack& pack, uint32_t face, const float* m, FaceGeometry& g) {
    if (face >= pack.faces().size()) return Result::fail(Status::OutOfRange, "no such face", {"face", face});
    const pack::Face& F = pack.faces()[face];
    const pack::Surface& S = pack.surfaces()[F.surface];
    g = {};
    g.type = pack::SurfaceType(S.type);
    g.reversed = F.reversed != 0;
    const double sense = g.reversed ? -1 : 1;
    switch (g.type) {
    case pack::SurfaceType::Plane:
    case pack::SurfaceType::Cylinder:
    case pack::SurfaceType::Cone:
    case pack::SurfaceType::Sphere:
    case pack::SurfaceType::Torus: {
        ElementaryRecord e;
        (void)elementary(pack, S, e);
        const pack::Frame& f = *e.frame;
        const D3 O = d3(f.origin), X = d3(f.x), Y = d3(f.y), Z = d3(f.z);
        g.origin = place_point(m, O);
        if (g.type == pack::SurfaceType::Plane) {
            g.axis = unit(place_direction(m, cross(X, Y) * sense));
            g.offset = dot(g.axis, g.origin);
            break;
        }
        g.axis = unit(place_direction(m, Z));
        g.radius = e.radius, g.minor = e.minor, g.half_angle = e.semi_angle;
        g.hole = e.inward(g.reversed); // (its natural normal turned in: a hole's wall)
        break;
    }
    case pack::SurfaceType::BSpline: {
        const BSplineSurfaceView B = bspline(pack, S);
        g.u_degree = B.pu, g.v_degree = B.pv, g.u_poles = B.nu, g.v_poles = B.nv;
        g.rational = B.rational;
        g.u_periodic = B.u_periodic, g.v_periodic = B.v_periodic;
        break;
    }
    case pack::SurfaceType::Revolution: {
        const pack::RevolutionParams& R = params<pack::RevolutionParams>(pack, S);
        g.origin = place_point(m, d3(R.axis_origin));
        g.axis = unit(place_direction(m, d3(R.axis_direction)));
        break;
    }
    case pack::SurfaceType::Extrusion: g.axis = unit(place_direction(m, d3(params<pack::ExtrusionParams>(pack, S).direction))); break;
    }
    return {};
}

Relation relate(const FaceGeometry& a, const FaceGeometry& b) {
    using T = pack::SurfaceType;
    Relation r;
    const bool pa = a.type == T::Plane, pb = b.type == T::Plane;
    if (pa && pb) {
        r.kind = Relation::Kind::Planes;
        r.angle = line_angle(a.axis, b.axis);
        r.parallel = r.angle < kParallel;
        if (r.parallel) r.distance = std::fabs(dot(a.axis, b.origin - a.origin)), r.has_distance = true;
        return r;
    }
    if (pa || pb) {
        const FaceGeometry& plane = pa ? a : b;
        const FaceGeometry& other = pa ? b : a;
        if (other.has_axis()) {
            r.kind = Relation::Kind::PlaneAxis;
            // The axis against the plane: 0 when it lies along it, pi/2 along the normal.
            r.angle = kHalfPi - line_angle(plane.axis, other.axis);
            r.parallel = r.angle < kParallel;
            if (r.parallel) r.distance = std::fabs(dot(plane.axis, other.origin - plane.origin)), r.has_distance = true;
            return r;
        }
        if (other.has_point()) {
            r.kind = Relation::Kind::PlanePoint;
            r.distance = std::fabs(dot(plane.axis, other.origin - plane.origin)), r.has_distance = true;
            return r;
        }
        return r;
    }
    if (a.has_axis() && b.has_axis()) {
        r.kind = Relation::Kind::Axes;
        r.angle = line_angle(a.axis, b.axis);
        r.parallel = r.angle < kParallel;
        const D3 n = cross(a.axis, b.axis);
        r.distance = r.parallel ? point_to_axis(b.origin, a.origin, a.axis) : std::fabs(dot(b.origin - a.origin, n)) / length(n);
        r.has_distance = true;
        return r;
    }
    if ((a.has_axis() && b.has_point()) || (a.has_point() && b.has_axis())) {
        const FaceGeometry& axis = a.has_axis() ? a : b;
        const FaceGeometry& point = a.has_axis() ? b : a;
        r.kind = Relation::Kind::AxisPoint;
        r.distance = point_to_axis(point.origin, axis.origin, axis.axis), r.has_distance = true;
        return r;
    }
    if (a.has_point() && b.has_point()) {
        r.kind = Relation::Kind::Points;
        r.distance = length(b.origin - a.origin), r.has_distance = true;
    }
    return r;
}

} // namespace facet::geom
