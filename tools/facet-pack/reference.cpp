#include "reference.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>

#include <cstdio>

namespace facet::packer {
namespace {

std::string vec(const gp_XYZ& v) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", v.X(), v.Y(), v.Z());
    return buf;
}

// The face's outward normal at the middle of its (u,v) bounds.
bool normal_at_middle(const TopoDS_Face& face, gp_Pnt& p, gp_Dir& n) {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    TopLoc_Location loc;
    Handle(Geom_Surface) s = BRep_Tool::Surface(face, loc);
    if (s.IsNull()) return false;
    GeomLProp_SLProps props(s, 0.5 * (u0 + u1), 0.5 * (v0 + v1), 1, 1e-9);
    if (!props.IsNormalDefined()) return false;
    p = props.Value().Transformed(loc.Transformation());
    n = props.Normal().Transformed(loc.Transformation());
    if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
    return true;
}

// A cylinder or cone face is a hole when its outward normal looks at the axis.
bool is_hole(const TopoDS_Face& face, const gp_Ax1& axis) {
    gp_Pnt p;
    gp_Dir n;
    if (!normal_at_middle(face, p, n)) return false;
    const gp_XYZ d = axis.Direction().XYZ(), rel = p.XYZ() - axis.Location().XYZ();
    const gp_XYZ radial = rel - d * rel.Dot(d);
    return n.XYZ().Dot(radial) < 0;
}

} // namespace

std::string reference_json(const std::vector<TopoDS_Shape>& faces, double unit_mm) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "{\"unit_mm\": %.17g, \"faces\": [\n", unit_mm);
    std::string out = buf;
    for (size_t i = 0; i < faces.size(); ++i) {
        const TopoDS_Face face = TopoDS::Face(faces[i]);
        BRepAdaptor_Surface a(face);
        std::string f = "{\"face\": " + std::to_string(i) + ", \"reversed\": " + (face.Orientation() == TopAbs_REVERSED ? "true" : "false");
        switch (a.GetType()) {
        case GeomAbs_Plane: {
            const gp_Pln P = a.Plane();
            gp_Dir n = P.Axis().Direction();
            if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
            std::snprintf(buf, sizeof buf, ", \"type\": \"plane\", \"normal\": %s, \"origin\": %s, \"offset\": %.17g", vec(n.XYZ()).c_str(),
                          vec(P.Location().XYZ()).c_str(), n.XYZ().Dot(P.Location().XYZ()));
            break;
        }
        case GeomAbs_Cylinder: {
            const gp_Cylinder C = a.Cylinder();
            std::snprintf(buf, sizeof buf, ", \"type\": \"cylinder\", \"radius\": %.17g, \"origin\": %s, \"axis\": %s, \"hole\": %s", C.Radius(),
                          vec(C.Axis().Location().XYZ()).c_str(), vec(C.Axis().Direction().XYZ()).c_str(), is_hole(face, C.Axis()) ? "true" : "false");
            break;
        }
        case GeomAbs_Cone: {
            const gp_Cone C = a.Cone();
            std::snprintf(buf, sizeof buf, ", \"type\": \"cone\", \"radius\": %.17g, \"half_angle\": %.17g, \"origin\": %s, \"axis\": %s, \"hole\": %s",
                          C.RefRadius(), C.SemiAngle(), vec(C.Axis().Location().XYZ()).c_str(), vec(C.Axis().Direction().XYZ()).c_str(),
                          is_hole(face, C.Axis()) ? "true" : "false");
            break;
        }
        case GeomAbs_Sphere: {
            const gp_Sphere S = a.Sphere();
            std::snprintf(buf, sizeof buf, ", \"type\": \"sphere\", \"radius\": %.17g, \"origin\": %s", S.Radius(), vec(S.Location().XYZ()).c_str());
            break;
        }
        case GeomAbs_Torus: {
            const gp_Torus T = a.Torus();
            std::snprintf(buf, sizeof buf, ", \"type\": \"torus\", \"radius\": %.17g, \"minor_radius\": %.17g, \"origin\": %s, \"axis\": %s",
                          T.MajorRadius(), T.MinorRadius(), vec(T.Location().XYZ()).c_str(), vec(T.Axis().Direction().XYZ()).c_str());
            break;
        }
        case GeomAbs_BSplineSurface: {
            // Poles of the open form (a periodic direction unrolled over one period), as packed.
            Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(a.BSpline()->Copy());
            const bool up = b->IsUPeriodic(), vp = b->IsVPeriodic();
            if (up) b->SetUNotPeriodic();
            if (vp) b->SetVNotPeriodic();
            std::snprintf(buf, sizeof buf,
                          ", \"type\": \"B-spline\", \"u_degree\": %d, \"v_degree\": %d, \"u_poles\": %d, \"v_poles\": %d, \"rational\": %s, "
                          "\"u_periodic\": %s, \"v_periodic\": %s",
                          b->UDegree(), b->VDegree(), b->NbUPoles(), b->NbVPoles(), (b->IsURational() || b->IsVRational()) ? "true" : "false",
                          up ? "true" : "false", vp ? "true" : "false");
            break;
        }
        default: std::snprintf(buf, sizeof buf, ", \"type\": \"other\"");
        }
        out += f + buf + (i + 1 < faces.size() ? "},\n" : "}\n");
    }
    return out + "]}\n";
}

} // namespace facet::packer
