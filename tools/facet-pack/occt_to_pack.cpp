#include "occt_to_pack.h"

#include "clearance.h"
#include "occt_geometry.h"

#include <BRepBndLib.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Quantity_Color.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
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

} // namespace

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
    // How far an edge may stray from its face's surface beyond its own tolerance: a tenth of the
    // viewer's default tolerance for the part alone (0.1% of its diagonal), at least 1 um. Files
    // written without their tolerances (1e-7 mm) keep edges a few um off their surfaces, which
    // no level of detail shows; a circle of radius 0 on a cylinder of 16 mm is what is refused.
    double stray_allowance = 1e-3;
    {
        Bnd_Box b;
        BRepBndLib::Add(shape, b, false);
        if (!b.IsVoid()) stray_allowance = std::max(stray_allowance, 1e-4 * std::sqrt(b.SquareExtent()));
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
                // within ten times its tolerance and the allowance (a circle of radius 0 on a
                // cylinder of 16 mm does not; healing leaves it so).
                const double strays = BRep_Tool::Degenerated(e) ? pole_off_vertex(e, pc, f0, f1, s) : edge_off_surface(e, surface_of_face);
                if (strays > 10 * BRep_Tool::Tolerance(e) + stray_allowance) {
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