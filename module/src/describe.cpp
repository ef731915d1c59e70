#include "describe.h"

#include "core/format.h"

namespace facet::module {

const char* unit_name(float mm) {
    if (mm > 0.999f && mm < 1.001f) return "mm";
    if (mm > 9.99f && mm < 10.01f) return "cm";
    if (mm > 999.f && mm < 1001.f) return "m";
    if (mm > 25.39f && mm < 25.41f) return "in";
    if (mm > 304.7f && mm < 304.9f) return "ft";
    return "units";
}

namespace {

// A length in the file's unit: 3 decimals (4 in inches and feet, whose units are larger).
Fixed length(double mm, float unit_mm) {
    const int decimals = unit_mm > 20 ? 4 : 3;
    double v = mm / unit_mm;
    for (int i = 0; i < decimals; ++i) v *= 10;
    return fixed(int64_t(v < 0 ? v - 0.5 : v + 0.5), uint8_t(decimals));
}
Fixed degrees(double rad) {
    const double v = rad * 57.29577951308232 * 1000;
    return fixed(int64_t(v < 0 ? v - 0.5 : v + 0.5), 3);
}
Fixed component(double c) { return fixed(int64_t(c * 1000 + (c < 0 ? -0.5 : 0.5)), 3); }

} // namespace

void describe(const geom::FaceGeometry& g, uint32_t face, float unit_mm, char* out, size_t size) {
    using T = pack::SurfaceType;
    const char* u = unit_name(unit_mm);
    switch (g.type) {
    case T::Plane:
        format(out, size, "#{} plane  normal ({}, {}, {})  offset {} {}", face, component(g.axis.x), component(g.axis.y), component(g.axis.z),
               length(g.offset, unit_mm), u);
        return;
    case T::Cylinder:
        format(out, size, "#{} cylinder {}  D {} {}  axis ({}, {}, {})", face, g.hole ? "hole" : "boss", length(2 * g.radius, unit_mm), u,
               component(g.axis.x), component(g.axis.y), component(g.axis.z));
        return;
    case T::Cone:
        format(out, size, "#{} cone {}  half-angle {} deg  R {} {}", face, g.hole ? "hole" : "boss", degrees(g.half_angle),
               length(g.radius, unit_mm), u);
        return;
    case T::Sphere: format(out, size, "#{} sphere  R {} {}", face, length(g.radius, unit_mm), u); return;
    case T::Torus:
        format(out, size, "#{} torus  R {} {}  r {} {}", face, length(g.radius, unit_mm), u, length(g.minor, unit_mm), u);
        return;
    case T::BSpline:
        format(out, size, "#{} B-spline{}  degree {} x {}  {} x {} poles", face, g.rational ? " (rational)" : "", g.u_degree, g.v_degree,
               g.u_poles, g.v_poles);
        return;
    case T::Revolution: format(out, size, "#{} surface of revolution  axis ({}, {}, {})", face, component(g.axis.x), component(g.axis.y), component(g.axis.z)); return;
    case T::Extrusion: format(out, size, "#{} extrusion  along ({}, {}, {})", face, component(g.axis.x), component(g.axis.y), component(g.axis.z)); return;
    }
    format(out, size, "#{}", face);
}

void describe(const geom::Relation& r, float unit_mm, char* out, size_t size) {
    using K = geom::Relation::Kind;
    const char* u = unit_name(unit_mm);
    switch (r.kind) {
    case K::None: format(out, size, "no exact distance to a free-form face"); return;
    case K::Planes:
        if (r.parallel) format(out, size, "parallel planes: distance {} {}", length(r.distance, unit_mm), u);
        else format(out, size, "planes at {} deg", degrees(r.angle));
        return;
    case K::PlaneAxis:
        if (r.parallel) format(out, size, "axis parallel to the plane: distance {} {}", length(r.distance, unit_mm), u);
        else format(out, size, "axis at {} deg to the plane", degrees(r.angle));
        return;
    case K::Axes:
        if (r.parallel) format(out, size, "parallel axes: {} {} apart", length(r.distance, unit_mm), u);
        else format(out, size, "axes at {} deg, closest {} {} apart", degrees(r.angle), length(r.distance, unit_mm), u);
        return;
    case K::PlanePoint: format(out, size, "centre {} {} from the plane", length(r.distance, unit_mm), u); return;
    case K::AxisPoint: format(out, size, "centre {} {} from the axis", length(r.distance, unit_mm), u); return;
    case K::Points: format(out, size, "centres {} {} apart", length(r.distance, unit_mm), u); return;
    }
}

} // namespace facet::module
