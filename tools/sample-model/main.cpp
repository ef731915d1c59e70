// facet-sample-model: writes the project's own sample part as STEP (AP214), made with Open
// CASCADE: an ANC101-like block with filleted vertical edges, four through holes, a pocket, a
// bored cylindrical boss and a lofted free-form (B-spline) dome, each face family coloured.
//
//   facet-sample-model OUT.step
#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GC_MakeCircle.hxx>
#include <GC_MakeEllipse.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeCustom.hxx>
#include <ShapeCustom_RestrictionParameters.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>
#include <Geom_Ellipse.hxx>
#include <gp_Elips.hxx>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: facet-sample-model OUT.step\n");
        return 2;
    }
    const double L = 120, W = 80, H = 30;
    TopoDS_Shape part = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), L, W, H).Shape();

    // Fillet the four vertical edges.
    BRepFilletAPI_MakeFillet fillet(part);
    for (TopExp_Explorer x(part, TopAbs_EDGE); x.More(); x.Next()) {
        const TopoDS_Edge e = TopoDS::Edge(x.Current());
        BRepAdaptor_Curve c(e);
        if (c.GetType() == GeomAbs_Line && std::fabs(c.Line().Direction().Z()) > 0.99) fillet.Add(9, e);
    }
    part = fillet.Shape();

    // Four through holes near the corners.
    for (double x : {14.0, L - 14.0})
        for (double y : {14.0, W - 14.0})
            part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp::DZ()), 5, H + 2).Shape()).Shape();

    // A rectangular pocket in the top.
    part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeBox(gp_Pnt(12, 26, H - 12), 36, 28, 13).Shape()).Shape();

    // A bored cylindrical boss.
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(68, 40, H), gp::DZ()), 11, 14).Shape()).Shape();
    part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(68, 40, H - 10), gp::DZ()), 5.5, 30).Shape()).Shape();

    // A free-form dome: a smooth loft through an ellipse, a smaller tilted ellipse and a circle.
    BRepOffsetAPI_ThruSections loft(true, false); // solid, smooth (B-spline) rather than ruled
    auto ellipse_wire = [](gp_Pnt c, gp_Dir n, double a, double b) {
        Handle(Geom_Ellipse) e = GC_MakeEllipse(gp_Elips(gp_Ax2(c, n), a, b)).Value();
        return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(e)).Wire();
    };
    loft.AddWire(ellipse_wire(gp_Pnt(98, 40, H - 1), gp::DZ(), 14, 9));
    loft.AddWire(ellipse_wire(gp_Pnt(99, 41, H + 7), gp_Dir(0.15, 0.1, 1), 10, 7));
    loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(GC_MakeCircle(gp_Ax2(gp_Pnt(100, 42, H + 13), gp::DZ()), 3).Value())).Wire());
    loft.Build();
    if (loft.IsDone()) {
        // The loft comes out of degree 14 around; CAD systems write lower degrees (3 to 5).
        Handle(ShapeCustom_RestrictionParameters) params = new ShapeCustom_RestrictionParameters;
        const TopoDS_Shape dome = ShapeCustom::BSplineRestriction(loft.Shape(), 1e-3, 1e-5, 5, 64, GeomAbs_C2, GeomAbs_C1,
                                                                  true, false, params);
        part = BRepAlgoAPI_Fuse(part, dome).Shape();
    }

    STEPControl_Writer writer;
    if (writer.Transfer(part, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(argv[1]) != IFSelect_RetDone) {
        std::fprintf(stderr, "facet-sample-model: cannot write %s\n", argv[1]);
        return 1;
    }
    std::printf("%s: the facet sample part\n", argv[1]);
    return 0;
}
