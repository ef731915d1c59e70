#include "occt_geometry.h"

#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2dConvert_ApproxCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxCurve.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

namespace facet::packer {
namespace {


using namespace facet::pack;
using Floats = std::vector<float>;

// Round-off residue (|x| < 1e-9, in mm, radians or a knot's parameter) stored as an exact 0: a
// direction's 1e-17 or a pole's 2e-15 left by a CAD system's arithmetic costs a compressed pack
// as many bytes as any other float, a 0 almost none. Moves nothing by more than 1e-9.
float clean(double x) { return std::fabs(x) < 1e-9 ? 0.0f : float(x); }

// The records of pack_format.h from OCCT's values (coordinates cleaned, as every float of a
// position or direction), and a record as the floats the pool stores.
void set(float (&out)[3], const gp_XYZ& v) { out[0] = clean(v.X()), out[1] = clean(v.Y()), out[2] = clean(v.Z()); }
void set(float (&out)[2], const gp_XY& v) { out[0] = clean(v.X()), out[1] = clean(v.Y()); }

Frame frame_of(const gp_Ax3& a) {
    Frame f;
    set(f.origin, a.Location().XYZ());
    set(f.x, a.XDirection().XYZ());
    set(f.y, a.YDirection().XYZ());
    set(f.z, a.Direction().XYZ());
    return f;
}

template <typename Params>
Floats floats_of(const Params& p) {
    Floats f(float_count<Params>);
    std::memcpy(f.data(), &p, sizeof p);
    return f;
}

constexpr double kApproxTolerance = 1e-4; // mm, for curves and surfaces with no packed form


void put(Floats& f, const gp_XYZ& v) { f.insert(f.end(), {clean(v.X()), clean(v.Y()), clean(v.Z())}); }
void put(Floats& f, const gp_XY& v) { f.insert(f.end(), {clean(v.X()), clean(v.Y())}); }
void put(Floats& f, const gp_Pnt& p) { put(f, p.XYZ()); }
void put(Floats& f, const gp_Pnt2d& p) { put(f, p.XY()); }

// A 3D or 2D B-spline curve's parameters: head, knots expanded by multiplicity, poles, weights.
// (Geom_BSplineCurve and Geom2d_BSplineCurve share these methods.) Periodic curves are
// unperiodized first.
template <typename Curve>
Floats bspline_curve(opencascade::handle<Curve> c) {
    const bool periodic = c->IsPeriodic();
    if (periodic) {
        c = opencascade::handle<Curve>::DownCast(c->Copy());
        c->SetNotPeriodic(); // same curve over one period; the reader wraps parameters into it
    }
    const int n = c->NbPoles();
    TColStd_Array1OfReal knots(1, c->NbPoles() + c->Degree() + 1);
    c->KnotSequence(knots);
    Floats f = floats_of(BSplineCurveHead{float(c->Degree()), float(n), float(knots.Length()), c->IsRational() ? 1.0f : 0.0f,
                                          periodic ? 1.0f : 0.0f});
    for (int i = knots.Lower(); i <= knots.Upper(); ++i) f.push_back(clean(knots(i)));
    for (int i = 1; i <= n; ++i) put(f, c->Pole(i));
    if (c->IsRational())
        for (int i = 1; i <= n; ++i) f.push_back(float(c->Weight(i)));
    return f;
}

// A point's coordinates as OCCT's vector type of its dimension.
gp_XYZ coords(const gp_Pnt& p) { return p.XYZ(); }
gp_XY coords(const gp_Pnt2d& p) { return p.XY(); }

// A degree-1 B-spline with two poles is a line, exactly: P0 + (t - k0) (P1 - P0) / (k1 - k0).
// (Geom_BSplineCurve and Line3Params, or Geom2d_BSplineCurve and Line2Params.)
template <typename BSpline, typename Line>
bool bspline_line(const opencascade::handle<BSpline>& b, Line& line) {
    if (b->Degree() != 1 || b->NbPoles() != 2 || b->IsRational() || b->IsPeriodic()) return false;
    const double k0 = b->FirstParameter(), k1 = b->LastParameter();
    if (!(k1 > k0)) return false;
    const auto p0 = coords(b->Pole(1));
    const auto d = (coords(b->Pole(2)) - p0) / (k1 - k0);
    set(line.origin, p0 - d * k0);
    set(line.direction, d);
    return true;
}

// A pcurve's parameter space is only where the face's boundary lies in (u,v): the boundary's
// 3D points come from the edge's own curve. So a long B-spline pcurve (healing and projection
// make them with dozens of poles) is re-approximated on the edge's range with as few poles as
// keep it within kApproxTolerance in 3D, checked on the surface, when that saves poles.
Handle(Geom2d_BSplineCurve) simpler_pcurve(const Handle(Geom2d_BSplineCurve)& b, const Handle(Geom_Surface)& surface,
                                           double t0, double t1) {
    constexpr int kWorthIt = 12; // poles: below this, keep the curve as it is
    if (b->NbPoles() < kWorthIt || !(t1 > t0) || surface.IsNull()) return {};
    // The surface's largest speed along the curve: turns the 3D tolerance into one in (u,v).
    constexpr int kChecks = 256;
    double speed = 0;
    for (int i = 0; i <= 32; ++i) {
        gp_Pnt p;
        gp_Vec du, dv;
        const gp_Pnt2d uv = b->Value(t0 + (t1 - t0) * i / 32);
        surface->D1(uv.X(), uv.Y(), p, du, dv);
        speed = std::max({speed, du.Magnitude(), dv.Magnitude()});
    }
    if (!(speed > 0)) return {};
    const double tol_uv = 0.25 * kApproxTolerance / speed;
    Handle(Geom2d_BSplineCurve) simple;
    try {
        Handle(Geom2d_Curve) part = new Geom2d_TrimmedCurve(b, t0, t1);
        Geom2dConvert_ApproxCurve approx(part, tol_uv, GeomAbs_C2, 64, 5);
        if (!approx.HasResult()) return {};
        simple = approx.Curve();
    } catch (const Standard_Failure&) {
        return {};
    }
    const size_t before = size_t(b->NbPoles()) * (b->IsRational() ? 3 : 2) + b->NbPoles() + b->Degree() + 1;
    const size_t after = size_t(simple->NbPoles()) * (simple->IsRational() ? 3 : 2) + simple->NbPoles() + simple->Degree() + 1;
    if (after >= before) return {};
    // Checked where it counts: the two curves' points on the surface, densely over the range.
    for (int i = 0; i <= kChecks; ++i) {
        const double t = t0 + (t1 - t0) * i / kChecks;
        const gp_Pnt2d a = b->Value(t), c = simple->Value(t);
        if (surface->Value(a.X(), a.Y()).Distance(surface->Value(c.X(), c.Y())) > kApproxTolerance) return {};
    }
    return simple;
}

} // namespace

// A 3D curve as a Curves3 record; other kinds become B-splines within kApproxTolerance.
uint32_t add_curve3(geom::PackWriter& w, const Handle(Geom_Curve)& curve, double t0, double t1, Stats& st) {
    GeomAdaptor_Curve a(curve);
    switch (a.GetType()) {
    case GeomAbs_Line: {
        const gp_Lin l = a.Line();
        Line3Params line;
        set(line.origin, l.Location().XYZ());
        set(line.direction, l.Direction().XYZ());
        return w.add_curve(line);
    }
    case GeomAbs_Circle: {
        const gp_Circ c = a.Circle();
        Circle3Params circle;
        set(circle.origin, c.Location().XYZ());
        set(circle.x, c.XAxis().Direction().XYZ());
        set(circle.y, c.YAxis().Direction().XYZ());
        circle.radius = float(c.Radius());
        return w.add_curve(circle);
    }
    case GeomAbs_Ellipse: {
        const gp_Elips e = a.Ellipse();
        Ellipse3Params ellipse;
        set(ellipse.origin, e.Location().XYZ());
        set(ellipse.x, e.XAxis().Direction().XYZ());
        set(ellipse.y, e.YAxis().Direction().XYZ());
        ellipse.major = float(e.MajorRadius()), ellipse.minor = float(e.MinorRadius());
        return w.add_curve(ellipse);
    }
    case GeomAbs_BSplineCurve:
        if (Line3Params line; bspline_line(a.BSpline(), line)) {
            ++st.converted["3D B-spline of degree 1 -> line"];
            return w.add_curve(line);
        }
        return w.add_bspline_curve(3, bspline_curve(a.BSpline()));
    default: break;
    }
    // Other kinds (Bezier, offset, parabola, hyperbola...): approximate the part the edge uses,
    // which keeps the edge's own parameter (an exact rational conversion would not, and the
    // pcurves are parameterised like the edge).
    Handle(Geom_BSplineCurve) b;
    if (a.GetType() == GeomAbs_BezierCurve) {
        b = GeomConvert::CurveToBSplineCurve(curve);
    } else if (t0 < t1) {
        Handle(Geom_Curve) part = new Geom_TrimmedCurve(curve, t0, t1);
        GeomConvert_ApproxCurve approx(part, kApproxTolerance, GeomAbs_C1, 64, 8);
        if (approx.HasResult()) b = approx.Curve();
    }
    if (b.IsNull()) return kNoIndex;
    ++st.converted["3D curve -> B-spline"];
    return w.add_bspline_curve(3, bspline_curve(b));
}

uint32_t add_curve2(geom::PackWriter& w, const Handle(Geom2d_Curve)& curve, double t0, double t1,
                           const Handle(Geom_Surface)& surface, Stats& st) {
    Geom2dAdaptor_Curve a(curve);
    switch (a.GetType()) {
    case GeomAbs_Line: {
        const gp_Lin2d l = a.Line();
        Line2Params line;
        set(line.origin, l.Location().XY());
        set(line.direction, l.Direction().XY());
        return w.add_curve(line);
    }
    case GeomAbs_Circle: {
        const gp_Circ2d c = a.Circle();
        Circle2Params circle;
        set(circle.origin, c.Location().XY());
        set(circle.x, c.XAxis().Direction().XY());
        set(circle.y, c.YAxis().Direction().XY());
        circle.radius = float(c.Radius());
        return w.add_curve(circle);
    }
    case GeomAbs_Ellipse: {
        const gp_Elips2d e = a.Ellipse();
        Ellipse2Params ellipse;
        set(ellipse.origin, e.Location().XY());
        set(ellipse.x, e.XAxis().Direction().XY());
        set(ellipse.y, e.YAxis().Direction().XY());
        ellipse.major = float(e.MajorRadius()), ellipse.minor = float(e.MinorRadius());
        return w.add_curve(ellipse);
    }
    case GeomAbs_BSplineCurve: {
        const Handle(Geom2d_BSplineCurve) b = a.BSpline();
        if (Line2Params line; bspline_line(b, line)) {
            ++st.converted["pcurve B-spline of degree 1 -> line"];
            return w.add_curve(line);
        }
        if (const Handle(Geom2d_BSplineCurve) simple = simpler_pcurve(b, surface, t0, t1); !simple.IsNull()) {
            ++st.converted["pcurve B-spline -> fewer poles"];
            return w.add_bspline_curve(2, bspline_curve(simple));
        }
        return w.add_bspline_curve(2, bspline_curve(b));
    }
    default: break;
    }
    Handle(Geom2d_BSplineCurve) b;
    if (a.GetType() == GeomAbs_BezierCurve) {
        b = Geom2dConvert::CurveToBSplineCurve(curve);
    } else if (t0 < t1) {
        Handle(Geom2d_Curve) part = new Geom2d_TrimmedCurve(curve, t0, t1);
        Geom2dConvert_ApproxCurve approx(part, 1e-7, GeomAbs_C1, 64, 8);
        if (approx.HasResult()) b = approx.Curve();
    }
    if (b.IsNull()) return kNoIndex;
    ++st.converted["pcurve -> B-spline"];
    return w.add_bspline_curve(2, bspline_curve(b));
}

// The surface under any rectangular trim.
namespace {

Handle(Geom_Surface) untrimmed(Handle(Geom_Surface) s) {
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    return s;
}

} // namespace

uint32_t add_surface(geom::PackWriter& w, const Handle(Geom_Surface)& surface, Stats& st) {
    GeomAdaptor_Surface a(surface);
    switch (a.GetType()) {
    case GeomAbs_Plane:
        ++st.surface_types["plane"];
        return w.add_surface(PlaneParams{frame_of(a.Plane().Position())});
    case GeomAbs_Cylinder:
        ++st.surface_types["cylinder"];
        return w.add_surface(CylinderParams{frame_of(a.Cylinder().Position()), float(a.Cylinder().Radius())});
    case GeomAbs_Cone:
        ++st.surface_types["cone"];
        return w.add_surface(ConeParams{frame_of(a.Cone().Position()), float(a.Cone().RefRadius()), float(a.Cone().SemiAngle())});
    case GeomAbs_Sphere:
        ++st.surface_types["sphere"];
        return w.add_surface(SphereParams{frame_of(a.Sphere().Position()), float(a.Sphere().Radius())});
    case GeomAbs_Torus:
        ++st.surface_types["torus"];
        return w.add_surface(TorusParams{frame_of(a.Torus().Position()), float(a.Torus().MajorRadius()),
                                         float(a.Torus().MinorRadius())});
    case GeomAbs_SurfaceOfRevolution: {
        const gp_Ax1 axis = a.AxeOfRevolution();
        Handle(Geom_SurfaceOfRevolution) rev = Handle(Geom_SurfaceOfRevolution)::DownCast(untrimmed(surface));
        if (rev.IsNull()) break;
        const uint32_t c = add_curve3(w, rev->BasisCurve(), rev->BasisCurve()->FirstParameter(), rev->BasisCurve()->LastParameter(), st);
        if (c == kNoIndex) break;
        ++st.surface_types["revolution"];
        RevolutionParams revolution;
        set(revolution.axis_origin, axis.Location().XYZ());
        set(revolution.axis_direction, axis.Direction().XYZ());
        return w.add_surface(revolution, c);
    }
    case GeomAbs_SurfaceOfExtrusion: {
        Handle(Geom_SurfaceOfLinearExtrusion) ext = Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(untrimmed(surface));
        if (ext.IsNull()) break;
        const uint32_t c = add_curve3(w, ext->BasisCurve(), ext->BasisCurve()->FirstParameter(), ext->BasisCurve()->LastParameter(), st);
        if (c == kNoIndex) break;
        ++st.surface_types["extrusion"];
        ExtrusionParams extrusion;
        set(extrusion.direction, a.Direction().XYZ());
        return w.add_surface(extrusion, c);
    }
    default: break;
    }
    Handle(Geom_BSplineSurface) b;
    if (a.GetType() == GeomAbs_BSplineSurface) {
        b = a.BSpline();
        ++st.surface_types["B-spline"];
    } else {
        try {
            b = GeomConvert::SurfaceToBSplineSurface(surface);
        } catch (...) {
        }
        if (b.IsNull()) {
            try {
                GeomConvert_ApproxSurface approx(surface, kApproxTolerance, GeomAbs_C1, GeomAbs_C1, 12, 12, 64, 0);
                if (approx.HasResult()) b = approx.Surface();
            } catch (...) {
            }
        }
        if (b.IsNull()) return kNoIndex;
        ++st.surface_types["B-spline"];
        ++st.converted["surface -> B-spline"];
    }
    b = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
    // Periodic directions are stored over one period; the reader wraps parameters into it (a
    // face may use, say, v in [3.2, 9.5] of a 2 pi-periodic surface).
    const bool u_periodic = b->IsUPeriodic(), v_periodic = b->IsVPeriodic();
    if (u_periodic) b->SetUNotPeriodic();
    if (v_periodic) b->SetVNotPeriodic();
    const int nu = b->NbUPoles(), nv = b->NbVPoles();
    TColStd_Array1OfReal uk(1, nu + b->UDegree() + 1), vk(1, nv + b->VDegree() + 1);
    b->UKnotSequence(uk);
    b->VKnotSequence(vk);
    const bool rational = b->IsURational() || b->IsVRational();
    Floats f = floats_of(BSplineSurfaceHead{float(b->UDegree()), float(b->VDegree()), float(nu), float(nv), float(uk.Length()),
                                            float(vk.Length()), rational ? 1.0f : 0.0f, u_periodic ? 1.0f : 0.0f,
                                            v_periodic ? 1.0f : 0.0f});
    for (int i = uk.Lower(); i <= uk.Upper(); ++i) f.push_back(clean(uk(i)));
    for (int i = vk.Lower(); i <= vk.Upper(); ++i) f.push_back(clean(vk(i)));
    for (int i = 1; i <= nu; ++i)
        for (int j = 1; j <= nv; ++j) put(f, b->Pole(i, j).XYZ());
    if (rational)
        for (int i = 1; i <= nu; ++i)
            for (int j = 1; j <= nv; ++j) f.push_back(float(b->Weight(i, j)));
    return w.add_bspline_surface(f);
}


} // namespace facet::packer
