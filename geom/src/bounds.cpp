#include "geom/bounds.h"

#include "geom/params.h"

#include <cmath>

namespace facet::geom {
namespace {

using namespace facet::pack;

// The poles of a B-spline curve (weight-free coordinates: the curve lies in their hull).
void add_poles(Box3& b, const BSplineCurveView& c, int dim) {
    for (int i = 0; i < c.n; ++i) {
        const float* p = c.poles + dim * i;
        const float q[3] = {p[0], p[1], dim == 3 ? p[2] : 0.0f};
        b.add(q);
    }
}

void add_curve(Box3& b, const Pack& pack, const Curve& c) {
    switch (CurveType(c.type)) {
    case CurveType::Line: return; // its edge's vertices bound it
    case CurveType::Circle: {
        const auto& k = params<Circle3Params>(pack, c);
        b.add_ball(k.origin, std::fabs(k.radius));
        return;
    }
    case CurveType::Ellipse: {
        const auto& k = params<Ellipse3Params>(pack, c);
        b.add_ball(k.origin, std::fmax(std::fabs(k.major), std::fabs(k.minor)));
        return;
    }
    case CurveType::BSpline: add_poles(b, bspline(pack, c), 3); return;
    }
}

// How far the points of curve c reach from `at`: an upper bound.
float reach(const Pack& pack, const Curve& c, const float at[3]) {
    Box3 b;
    add_curve(b, pack, c);
    if (CurveType(c.type) == CurveType::Line) { // an unbounded line: its record's origin only
        const auto& k = params<Line3Params>(pack, c);
        b.add(k.origin);
    }
    float r2 = 0;
    for (int corner = 0; corner < 8 && !b.empty(); ++corner) {
        float d2 = 0;
        for (int k = 0; k < 3; ++k) {
            const float d = ((corner >> k) & 1 ? b.hi[k] : b.lo[k]) - at[k];
            d2 += d * d;
        }
        r2 = d2 > r2 ? d2 : r2;
    }
    return std::sqrt(r2);
}

} // namespace

Box3 shell_box(const Pack& pack, uint32_t shell) {
    Box3 b;
    const Shell& sh = pack.shells()[shell];
    for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
        const pack::Face& F = pack.faces()[f];
        for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
            const Loop& L = pack.loops()[l];
            for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
                const Edge& e = pack.edges()[pack.coedges()[c].edge()];
                b.add(pack.vertices()[e.v0].p), b.add(pack.vertices()[e.v1].p);
                if (e.curve != kNoIndex && e.curve != kStraight) add_curve(b, pack, pack.curves3()[e.curve]);
            }
        }
        const Surface& s = pack.surfaces()[F.surface];
        switch (SurfaceType(s.type)) {
        case SurfaceType::Plane:
        case SurfaceType::Cylinder:
        case SurfaceType::Cone: break; // within its edges' curves' boxes (circles whole)
        case SurfaceType::Sphere: {
            const auto& k = params<SphereParams>(pack, s);
            b.add_ball(k.frame.origin, std::fabs(k.radius));
            break;
        }
        case SurfaceType::Torus: {
            const auto& k = params<TorusParams>(pack, s);
            b.add_ball(k.frame.origin, std::fabs(k.major_radius) + std::fabs(k.minor_radius));
            break;
        }
        case SurfaceType::BSpline: {
            const BSplineSurfaceView v = bspline(pack, s);
            for (int i = 0; i < v.nu * v.nv; ++i) b.add(v.poles + 3 * i);
            break;
        }
        case SurfaceType::Revolution: { // the curve turned about the axis: a ball about a point of it
            const auto& k = params<RevolutionParams>(pack, s);
            b.add_ball(k.axis_origin, reach(pack, pack.curves3()[s.ref], k.axis_origin));
            break;
        }
        case SurfaceType::Extrusion: { // the curve's box at both ends of the face's v range
            const auto& k = params<ExtrusionParams>(pack, s);
            Box3 c;
            add_curve(c, pack, pack.curves3()[s.ref]);
            if (c.empty()) break; // a line: the face's edges bound it
            for (const float v : {F.uv_min[1], F.uv_max[1]}) {
                const float lo[3] = {c.lo[0] + v * k.direction[0], c.lo[1] + v * k.direction[1], c.lo[2] + v * k.direction[2]};
                const float hi[3] = {c.hi[0] + v * k.direction[0], c.hi[1] + v * k.direction[1], c.hi[2] + v * k.direction[2]};
                b.add(lo), b.add(hi);
            }
            break;
        }
        }
    }
    return b;
}

} // namespace facet::geom
