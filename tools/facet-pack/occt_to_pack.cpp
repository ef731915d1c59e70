#include "occt_to_pack.h"

#include <ShapeAnalysis_Surface.hxx>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>

#include "clearance.h"

#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2dConvert_ApproxCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxCurve.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Quantity_Color.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <cstring>
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

// Whether an edge's two faces meet tangentially: their normals within pack::kSmoothAngle along
// it, as Open CASCADE's regularity judges it (a fillet's sides, a split cylinder's halves). Not
// a seam (one face on both sides), a free edge or one of three faces.
bool tangent_faces(const TopoDS_Edge& e, const TopTools_IndexedDataMapOfShapeListOfShape& faces_of) {
    if (BRep_Tool::Degenerated(e) || !faces_of.Contains(e)) return false;
    TopoDS_Face f[2];
    int n = 0;
    for (const TopoDS_Shape& s : faces_of.FindFromKey(e)) {
        if (n > 0 && s.IsSame(f[0])) continue;
        if (n == 2) {
            if (!s.IsSame(f[1])) return false;
            continue;
        }
        f[n++] = TopoDS::Face(s);
    }
    if (n != 2) return false;
    try {
        TopoDS_Edge edge = e; // (the call takes it to record the continuity in it)
        BRepLib::EncodeRegularity(edge, f[0], f[1], pack::kSmoothAngle);
        return BRep_Tool::HasContinuity(e, f[0], f[1]) && BRep_Tool::Continuity(e, f[0], f[1]) >= GeomAbs_G1;
    } catch (const Standard_Failure&) {
        return false; // (judged sharp: it stays drawn)
    }
}

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
static uint32_t add_curve3(geom::PackWriter& w, const Handle(Geom_Curve)& curve, double t0, double t1, Stats& st) {
    GeomAdaptor_Curve a(curve);
    switch (a.GetType()) {
    case GeomAbs_Line: {
        const gp_Lin l = a.Line();
        Line3Params line;
        set(line.origin, l.Location().XYZ());
        set(line.direction, l.Direction().XYZ());
        return w.add_curve(CurveType::Line, 3, floats_of(line));
    }
    case GeomAbs_Circle: {
        const gp_Circ c = a.Circle();
        Circle3Params circle;
        set(circle.origin, c.Location().XYZ());
        set(circle.x, c.XAxis().Direction().XYZ());
        set(circle.y, c.YAxis().Direction().XYZ());
        circle.radius = float(c.Radius());
        return w.add_curve(CurveType::Circle, 3, floats_of(circle));
    }
    case GeomAbs_Ellipse: {
        const gp_Elips e = a.Ellipse();
        Ellipse3Params ellipse;
        set(ellipse.origin, e.Location().XYZ());
        set(ellipse.x, e.XAxis().Direction().XYZ());
        set(ellipse.y, e.YAxis().Direction().XYZ());
        ellipse.major = float(e.MajorRadius()), ellipse.minor = float(e.MinorRadius());
        return w.add_curve(CurveType::Ellipse, 3, floats_of(ellipse));
    }
    case GeomAbs_BSplineCurve:
        if (Line3Params line; bspline_line(a.BSpline(), line)) {
            ++st.converted["3D B-spline of degree 1 -> line"];
            return w.add_curve(CurveType::Line, 3, floats_of(line));
        }
        return w.add_curve(CurveType::BSpline, 3, bspline_curve(a.BSpline()));
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
    return w.add_curve(CurveType::BSpline, 3, bspline_curve(b));
}

static uint32_t add_curve2(geom::PackWriter& w, const Handle(Geom2d_Curve)& curve, double t0, double t1,
                           const Handle(Geom_Surface)& surface, Stats& st) {
    Geom2dAdaptor_Curve a(curve);
    switch (a.GetType()) {
    case GeomAbs_Line: {
        const gp_Lin2d l = a.Line();
        Line2Params line;
        set(line.origin, l.Location().XY());
        set(line.direction, l.Direction().XY());
        return w.add_curve(CurveType::Line, 2, floats_of(line));
    }
    case GeomAbs_Circle: {
        const gp_Circ2d c = a.Circle();
        Circle2Params circle;
        set(circle.origin, c.Location().XY());
        set(circle.x, c.XAxis().Direction().XY());
        set(circle.y, c.YAxis().Direction().XY());
        circle.radius = float(c.Radius());
        return w.add_curve(CurveType::Circle, 2, floats_of(circle));
    }
    case GeomAbs_Ellipse: {
        const gp_Elips2d e = a.Ellipse();
        Ellipse2Params ellipse;
        set(ellipse.origin, e.Location().XY());
        set(ellipse.x, e.XAxis().Direction().XY());
        set(ellipse.y, e.YAxis().Direction().XY());
        ellipse.major = float(e.MajorRadius()), ellipse.minor = float(e.MinorRadius());
        return w.add_curve(CurveType::Ellipse, 2, floats_of(ellipse));
    }
    case GeomAbs_BSplineCurve: {
        const Handle(Geom2d_BSplineCurve) b = a.BSpline();
        if (Line2Params line; bspline_line(b, line)) {
            ++st.converted["pcurve B-spline of degree 1 -> line"];
            return w.add_curve(CurveType::Line, 2, floats_of(line));
        }
        if (const Handle(Geom2d_BSplineCurve) simple = simpler_pcurve(b, surface, t0, t1); !simple.IsNull()) {
            ++st.converted["pcurve B-spline -> fewer poles"];
            return w.add_curve(CurveType::BSpline, 2, bspline_curve(simple));
        }
        return w.add_curve(CurveType::BSpline, 2, bspline_curve(b));
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
    return w.add_curve(CurveType::BSpline, 2, bspline_curve(b));
}

// The surface under any rectangular trim.
static Handle(Geom_Surface) untrimmed(Handle(Geom_Surface) s) {
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    return s;
}

static uint32_t add_surface(geom::PackWriter& w, const Handle(Geom_Surface)& surface, Stats& st) {
    GeomAdaptor_Surface a(surface);
    switch (a.GetType()) {
    case GeomAbs_Plane:
        ++st.surface_types["plane"];
        return w.add_surface(SurfaceType::Plane, floats_of(PlaneParams{frame_of(a.Plane().Position())}));
    case GeomAbs_Cylinder:
        ++st.surface_types["cylinder"];
        return w.add_surface(SurfaceType::Cylinder,
                             floats_of(CylinderParams{frame_of(a.Cylinder().Position()), float(a.Cylinder().Radius())}));
    case GeomAbs_Cone:
        ++st.surface_types["cone"];
        return w.add_surface(SurfaceType::Cone, floats_of(ConeParams{frame_of(a.Cone().Position()), float(a.Cone().RefRadius()),
                                                                     float(a.Cone().SemiAngle())}));
    case GeomAbs_Sphere:
        ++st.surface_types["sphere"];
        return w.add_surface(SurfaceType::Sphere,
                             floats_of(SphereParams{frame_of(a.Sphere().Position()), float(a.Sphere().Radius())}));
    case GeomAbs_Torus:
        ++st.surface_types["torus"];
        return w.add_surface(SurfaceType::Torus, floats_of(TorusParams{frame_of(a.Torus().Position()), float(a.Torus().MajorRadius()),
                                                                       float(a.Torus().MinorRadius())}));
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
        return w.add_surface(SurfaceType::Revolution, floats_of(revolution), c);
    }
    case GeomAbs_SurfaceOfExtrusion: {
        Handle(Geom_SurfaceOfLinearExtrusion) ext = Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(untrimmed(surface));
        if (ext.IsNull()) break;
        const uint32_t c = add_curve3(w, ext->BasisCurve(), ext->BasisCurve()->FirstParameter(), ext->BasisCurve()->LastParameter(), st);
        if (c == kNoIndex) break;
        ++st.surface_types["extrusion"];
        ExtrusionParams extrusion;
        set(extrusion.direction, a.Direction().XYZ());
        return w.add_surface(SurfaceType::Extrusion, floats_of(extrusion), c);
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
    return w.add_surface(SurfaceType::BSpline, f);
}

uint32_t Packer::colour_of(const TopoDS_Shape& s) {
    Quantity_Color c;
    if (colours_.IsNull()) return kNoIndex;
    if (!colours_->GetColor(s, XCAFDoc_ColorSurf, c) && !colours_->GetColor(s, XCAFDoc_ColorGen, c)) return kNoIndex;
    Standard_Real r, g, b;
    c.Values(r, g, b, Quantity_TOC_sRGB);
    const pack::Colour rgba{uint8_t(std::lround(r * 255)), uint8_t(std::lround(g * 255)), uint8_t(std::lround(b * 255)), 255};
    const uint32_t key = uint32_t(rgba.r) | uint32_t(rgba.g) << 8 | uint32_t(rgba.b) << 16;
    auto it = colour_index_.find(key);
    if (it != colour_index_.end()) return it->second;
    const uint32_t i = w_.add_colour(rgba);
    colour_index_[key] = i;
    return i;
}

namespace {

// How far the edge's 3D curve lies from the surface at most, at five points along it (0 for an
// edge with no 3D curve).
double edge_off_surface(const TopoDS_Edge& e, ShapeAnalysis_Surface& surface) {
    if (BRep_Tool::Degenerated(e)) return 0;
    double t0, t1;
    TopLoc_Location loc;
    Handle(Geom_Curve) c = BRep_Tool::Curve(e, loc, t0, t1);
    if (c.IsNull()) return 0;
    double most = 0;
    for (int k = 0; k <= 4; ++k) {
        gp_Pnt p = c->Value(t0 + (t1 - t0) * k / 4);
        if (!loc.IsIdentity()) p.Transform(loc.Transformation());
        (void)surface.ValueOfUV(p, 1e-7);
        most = std::max(most, surface.Gap());
    }
    return most;
}

// A degenerate edge (a pole or an apex: one point) whose pcurve the surface maps elsewhere than
// its vertex (a circle of radius 0 on a cylinder, which has no pole: healing makes it one): how
// far, at most, at five points of the pcurve.
double pole_off_vertex(const TopoDS_Edge& e, const Handle(Geom2d_Curve)& pc, double f0, double f1, const Handle(Geom_Surface)& s) {
    TopoDS_Vertex a, b;
    TopExp::Vertices(e, a, b);
    if (a.IsNull() || pc.IsNull()) return 0;
    const gp_Pnt v = BRep_Tool::Pnt(a);
    double most = 0;
    for (int k = 0; k <= 4; ++k) {
        const gp_Pnt2d uv = pc->Value(f0 + (f1 - f0) * k / 4);
        most = std::max(most, s->Value(uv.X(), uv.Y()).Distance(v));
    }
    return most;
}

// Empty when the curve's ends (at t0, t1) lie at the edge's vertices, within ten times the
// larger of the edge's and the vertex's tolerances (and a micron); else what is wrong.
std::string curve_misses_vertices(const Handle(Geom_Curve)& c, double t0, double t1, const TopoDS_Vertex& a, const TopoDS_Vertex& b,
                                  double edge_tolerance) {
    const TopoDS_Vertex ends[2] = {a, b};
    const double at[2] = {t0, t1};
    double worst = 0;
    for (int k = 0; k < 2; ++k) {
        if (ends[k].IsNull()) continue;
        const double allowed = 10 * std::max(edge_tolerance, BRep_Tool::Tolerance(ends[k])) + 1e-3;
        const double d = c->Value(at[k]).Distance(BRep_Tool::Pnt(ends[k]));
        if (d > allowed) worst = std::max(worst, d);
    }
    if (worst == 0) return {};
    char text[200];
    const GeomAdaptor_Curve g(c);
    if (g.GetType() == GeomAbs_Circle) {
        std::snprintf(text, sizeof text, "an edge's circle (radius %.4g mm) misses its vertices by %.4g mm: refused", g.Circle().Radius(), worst);
    } else {
        std::snprintf(text, sizeof text, "an edge's curve misses its vertices by %.4g mm: refused", worst);
    }
    return text;
}

} // namespace

uint32_t Packer::add_prototype(const TopoDS_Shape& shape, bool closed) {
    TopTools_IndexedMapOfShape vertex_map, edge_map;
    TopExp::MapShapes(shape, TopAbs_VERTEX, vertex_map);
    TopExp::MapShapes(shape, TopAbs_EDGE, edge_map);
    std::vector<uint32_t> vertex_ids(vertex_map.Extent() + 1, kNoIndex), edge_ids(edge_map.Extent() + 1, kNoIndex);
    const std::vector<float> max_sag = edge_sag_limits(shape, edge_map);
    for (int i = 1; i <= vertex_map.Extent(); ++i) {
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertex_map(i)));
        vertex_ids[i] = w_.add_vertex(float(p.X()), float(p.Y()), float(p.Z()));
    }
    for (int i = 1; i <= edge_map.Extent(); ++i) try {
        const TopoDS_Edge e = TopoDS::Edge(edge_map(i).Oriented(TopAbs_FORWARD));
        TopoDS_Vertex a, b;
        TopExp::Vertices(e, a, b);
        double t0 = 0, t1 = 0;
        uint32_t curve = kNoIndex;
        Handle(Geom_Curve) c;
        if (!BRep_Tool::Degenerated(e)) {
            TopLoc_Location loc;
            c = BRep_Tool::Curve(e, loc, t0, t1);
            if (!c.IsNull()) {
                if (!loc.IsIdentity()) c = Handle(Geom_Curve)::DownCast(c->Transformed(loc.Transformation()));
                // A curve that misses its own vertices (a circle of radius 0 between two
                // vertices apart) would be drawn and meshed somewhere the edge is not: refused,
                // and the faces that use it with it.
                if (const std::string why = curve_misses_vertices(c, t0, t1, a, b, BRep_Tool::Tolerance(e)); !why.empty()) {
                    if (stats_.first_problem.empty()) stats_.first_problem = why;
                    continue;
                }
                // A line's edge is the segment between its vertices (OCCT lines run at unit
                // speed: the parameter is linear along it), with no curve record.
                const bool straight = GeomAdaptor_Curve(c).GetType() == GeomAbs_Line && !a.IsNull() && !b.IsNull() && !a.IsSame(b);
                curve = straight ? kStraight : add_curve3(w_, c, t0, t1, stats_);
            }
        } else {
            BRep_Tool::Range(e, t0, t1);
        }
        // An edge without a vertex at an end (open, infinite edges) gets one from its curve.
        auto end_vertex = [&](const TopoDS_Vertex& v, double t) {
            if (!v.IsNull()) return vertex_ids[vertex_map.FindIndex(v)];
            const gp_Pnt p = c.IsNull() ? gp_Pnt() : c->Value(t);
            return w_.add_vertex(float(p.X()), float(p.Y()), float(p.Z()));
        };
        const uint32_t va = end_vertex(a, t0), vb = end_vertex(b, t1);
        edge_ids[i] = w_.add_edge({curve, float(t0), float(t1), va, vb, float(BRep_Tool::Tolerance(e)), max_sag[i]});
        ++stats_.edges;
    } catch (const Standard_Failure& f) {
        // The edge stays unpacked; faces that use it are skipped below with this reason.
        if (stats_.first_problem.empty()) stats_.first_problem = std::string("an edge failed: ") + f.GetMessageString();
    }
    TopTools_IndexedDataMapOfShapeListOfShape faces_of;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of);
    for (int i = 1; i <= edge_map.Extent(); ++i) {
        if (edge_ids[i] != kNoIndex && tangent_faces(TopoDS::Edge(edge_map(i)), faces_of)) {
            w_.set_smooth_edge(edge_ids[i]);
            ++stats_.smooth_edges;
        }
    }
    const uint32_t first_face = w_.face_count();
    uint32_t faces = 0;
    for (TopExp_Explorer fx(shape, TopAbs_FACE); fx.More(); fx.Next()) try {
        types_before_ = stats_.surface_types; // (a face skipped is counted as skipped, not by its type)
        const TopoDS_Face original = TopoDS::Face(fx.Current());
        const TopoDS_Face face = TopoDS::Face(original.Oriented(TopAbs_FORWARD));
        TopLoc_Location loc;
        Handle(Geom_Surface) s = BRep_Tool::Surface(face, loc);
        if (s.IsNull()) {
            ++stats_.faces_skipped;
            continue;
        }
        if (!loc.IsIdentity()) s = Handle(Geom_Surface)::DownCast(s->Transformed(loc.Transformation()));
        const uint32_t surface = add_surface(w_, s, stats_);
        const GeomAbs_SurfaceType kind = GeomAdaptor_Surface(s).GetType();
        const bool elementary = kind == GeomAbs_Plane || kind == GeomAbs_Cylinder || kind == GeomAbs_Cone ||
                                kind == GeomAbs_Sphere || kind == GeomAbs_Torus;
        if (surface == kNoIndex) {
            stats_.surface_types = types_before_;
            ++stats_.faces_skipped;
            if (stats_.first_problem.empty()) stats_.first_problem = "a surface could not be converted to a B-spline";
            continue;
        }
        // Loops: the outer wire first, each traversed in order on the FORWARD face, so outer
        // loops run counter-clockwise in (u,v) and holes clockwise.
        const uint32_t first_loop = w_.loop_count(), first_pcurve = w_.curve2_count();
        const TopoDS_Wire outer = BRepTools::OuterWire(face);
        std::vector<TopoDS_Wire> wires;
        if (!outer.IsNull()) wires.push_back(outer);
        for (TopExp_Explorer wx(face, TopAbs_WIRE); wx.More(); wx.Next()) {
            if (!wx.Current().IsSame(outer)) wires.push_back(TopoDS::Wire(wx.Current()));
        }
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        ShapeAnalysis_Surface surface_of_face(s); // (projects the edges' points onto it)
        if (!(u1 - u0 > 1e-9) || !(v1 - v0 > 1e-9)) {
            // Its loops run along a line of its (u,v): no area (a cylinder whose second circle
            // had radius 0 and went in healing keeps one circle alone).
            stats_.surface_types = types_before_;
            ++stats_.faces_skipped;
            if (stats_.first_problem.empty()) stats_.first_problem = "a face's boundary encloses no area of its surface";
            continue;
        }
        bool ok = true;
        std::string edge_problem; // why a face's edge was refused (empty: it has no pcurve)
        uint32_t loops = 0;
        for (const TopoDS_Wire& wire : wires) {
            const uint32_t first = w_.coedge_count();
            uint32_t n = 0;
            for (BRepTools_WireExplorer ex(wire, face); ex.More(); ex.Next()) {
                const TopoDS_Edge e = ex.Current();
                double f0, f1;
                Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(e, face, f0, f1);
                const int idx = edge_map.FindIndex(e);
                if (pc.IsNull() || idx == 0 || edge_ids[idx] == kNoIndex) {
                    ok = false;
                    break;
                }
                // The edge must lie on the face: its 3D curve along its pcurve on the surface,
                // within ten times its tolerance (a circle of radius 0 on a cylinder of 16 mm
                // does not; healing leaves it so).
                const double strays = BRep_Tool::Degenerated(e) ? pole_off_vertex(e, pc, f0, f1, s) : edge_off_surface(e, surface_of_face);
                if (strays > 10 * BRep_Tool::Tolerance(e) + 1e-3) {
                    char text[160];
                    std::snprintf(text, sizeof text, "an edge lies %.4g mm off its face's surface (its tolerance %.2g mm)", strays,
                                  BRep_Tool::Tolerance(e));
                    edge_problem = text;
                    ok = false;
                    break;
                }
                // Elementary surfaces keep no pcurve (the device inverts the surface); free-form
                // ones do.
                const uint32_t p = elementary ? kNoIndex : add_curve2(w_, pc, f0, f1, s, stats_);
                if (!elementary && p == kNoIndex) {
                    ok = false;
                    break;
                }
                uint8_t seam = uint8_t(pack::Seam::None);
                if (BRep_Tool::IsClosed(e, face)) {
                    // The side of the face's bounds this coedge runs on, from its pcurve: the
                    // parameter that stays constant along it, and which bound it sits at.
                    const gp_Pnt2d a = pc->Value(f0), b = pc->Value(f1), m = pc->Value(0.5 * (f0 + f1));
                    const bool u_const = std::abs(a.X() - b.X()) <= std::abs(a.Y() - b.Y());
                    if (u_const) seam = uint8_t(std::abs(m.X() - u0) < std::abs(m.X() - u1) ? pack::Seam::ULow : pack::Seam::UHigh);
                    else seam = uint8_t(std::abs(m.Y() - v0) < std::abs(m.Y() - v1) ? pack::Seam::VLow : pack::Seam::VHigh);
                }
                // The coedge's direction is the current edge's own orientation. (The explorer's
                // Orientation() is not: on anc101 face 13 it says FORWARD for a REVERSED edge.)
                w_.add_coedge(pack::Coedge::make(edge_ids[idx], e.Orientation() == TopAbs_REVERSED, pack::Seam(seam)));
                ++n;
            }
            if (!ok) break;
            if (n) {
                w_.add_loop({first, n});
                ++loops;
            }
        }
        if (!ok || loops == 0) {
            // Coedges/loops already written stay unreferenced: harmless.
            stats_.surface_types = types_before_;
            ++stats_.faces_skipped;
            if (stats_.first_problem.empty()) stats_.first_problem = edge_problem.empty() ? "a face has an edge without a pcurve" : edge_problem;
            continue;
        }
        // Its pcurves (if any) were added in coedge order, from first_pcurve on.
        w_.add_face({surface, first_loop, loops, elementary ? kNoIndex : first_pcurve, colour_of(original),
                     uint8_t(original.Orientation() == TopAbs_REVERSED), {0, 0, 0}, {float(u0), float(v0)}, {float(u1), float(v1)}});
        ++faces;
        ++stats_.faces;
        packed_faces.push_back(original); // its orientation kept (the reference values need it)
    } catch (const Standard_Failure& f) {
        stats_.surface_types = types_before_;
        ++stats_.faces_skipped;
        if (stats_.first_problem.empty()) stats_.first_problem = std::string("a face failed: ") + f.GetMessageString();
    }
    if (faces == 0) return kNoIndex; // nothing of it packed: no part (its occurrences say so)
    return w_.add_shell({first_face, faces, colour_of(shape), closed ? 1u : 0u});
}

void Packer::add_occurrence(const TopoDS_Shape& shape, bool closed, const std::string& name, const std::string& instance) {
    const void* key = shape.TShape().get();
    uint32_t shell;
    auto it = prototypes_.find(key);
    if (it != prototypes_.end()) {
        shell = it->second;
    } else {
        shell = add_prototype(shape.Located(TopLoc_Location()), closed);
        prototypes_[key] = shell;
        if (shell == kNoIndex) {
            ++stats_.empty_parts;
        } else {
            w_.name_shell(shell, name);
            prototypes.push_back(shape.Located(TopLoc_Location()));
            if (closed) ++stats_.solids;
            else ++stats_.shells;
        }
    }
    if (shell == kNoIndex) return; // every face of the part lost (faces_skipped says why)
    const gp_Trsf t = shape.Location().Transformation();
    pack::Instance inst{shell, {}};
    for (int r = 1; r <= 3; ++r)
        for (int c = 1; c <= 4; ++c) inst.m[(r - 1) * 4 + (c - 1)] = float(t.Value(r, c));
    w_.name_instance(w_.add_instance(inst), instance);
    ++stats_.instances;
}

std::vector<geom::PartBox> part_boxes(const std::vector<TopoDS_Shape>& prototypes) {
    std::vector<geom::PartBox> boxes;
    for (const TopoDS_Shape& shape : prototypes) {
        Bnd_Box b;
        BRepBndLib::AddOptimal(shape, b, false, false);
        geom::PartBox p{};
        if (!b.IsVoid()) {
            double lo[3], hi[3];
            b.Get(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
            const double grow = 1e-3 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) + 1e-3;
            for (int k = 0; k < 3; ++k) p.min[k] = float(lo[k] - grow), p.max[k] = float(hi[k] + grow);
        }
        boxes.push_back(p);
    }
    return boxes;
}

} // namespace facet::packer
