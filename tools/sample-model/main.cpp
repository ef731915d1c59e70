// facet-sample-model: writes the project's own sample part as STEP (AP214), made with Open
// CASCADE: an ANC101-like block with filleted vertical edges, four through holes, a pocket, a
// bored cylindrical boss and a lofted free-form (B-spline) dome, face families coloured.
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
#include <BRepAdaptor_Surface.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDF_Label.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
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
    // Open CASCADE's own statistics on the console are noise here.
    for (auto& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
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

    // Colours, as a CAD system writes them (STEP styled items through an XCAF document): the
    // body one colour, the bores and holes another, the boss and the dome their own.
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
    const TDF_Label label = shapes->AddShape(part, false);
    TDataStd_Name::Set(label, "facet sample block"); // the product's name: the pack's model and part name
    colours->SetColor(label, Quantity_Color(0.72, 0.74, 0.78, Quantity_TOC_sRGB), XCAFDoc_ColorSurf);
    for (TopExp_Explorer x(part, TopAbs_FACE); x.More(); x.Next()) {
        const TopoDS_Face face = TopoDS::Face(x.Current());
        BRepAdaptor_Surface s(face);
        Quantity_Color c;
        if (s.GetType() == GeomAbs_BSplineSurface) c = Quantity_Color(0.90, 0.55, 0.20, Quantity_TOC_sRGB); // the dome
        else if (s.GetType() == GeomAbs_Cylinder && s.Cylinder().Radius() < 6) c = Quantity_Color(0.85, 0.75, 0.35, Quantity_TOC_sRGB); // bores
        else if (s.GetType() == GeomAbs_Cylinder && s.Cylinder().Radius() > 10) c = Quantity_Color(0.30, 0.55, 0.80, Quantity_TOC_sRGB); // the boss
        else continue;
        const TDF_Label sub = shapes->AddSubShape(label, face);
        if (!sub.IsNull()) colours->SetColor(sub, c, XCAFDoc_ColorSurf);
    }
    STEPCAFControl_Writer writer;
    writer.SetColorMode(true);
    writer.SetNameMode(true);
    if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(argv[1]) != IFSelect_RetDone) {
        std::fprintf(stderr, "facet-sample-model: cannot write %s\n", argv[1]);
        return 1;
    }
    std::printf("%s: the facet sample part\n", argv[1]);
    return 0;
}
