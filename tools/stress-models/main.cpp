// facet-stress-model: writes the parts the reliability tests and benches need and no shared
// model has, made with Open CASCADE and written as STEP (AP214):
//
//   facet-stress-model fillets OUT.step      a plate with 11 x 11 round bosses, each filleted at
//                                            its foot and its top (242 toroidal faces), the
//                                            plate's own edges rounded
//   facet-stress-model lenses OUT.step       a plate with six lens-shaped bosses (two arcs bound
//                                            each top face: no area at coarse tolerances)
//   facet-stress-model holes N OUT.step      a 1 mm plate of N through holes (N a square: 40 x 40
//                                            = 1,600, 75 x 75 = 5,625) in one top face and one
//                                            bottom face
//   facet-stress-model machined OUT.step     a machined block of the kind a mechanical CAD system
//                                            exports: planar faces of many loops (round, elliptical
//                                            and slanted holes, some a hair apart), a cross bore
//                                            whose seam the drilled holes cut, countersinks
//                                            (cones), a filleted boss (tori), rounded corners
//
// The plate is built directly (a face with N inner wires, extruded), not by N boolean cuts:
// it takes a second, where cutting 5,625 cylinders takes Open CASCADE many minutes.
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <GC_MakeEllipse.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <GC_MakeCircle.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

int usage() {
    std::fprintf(stderr, "usage: facet-stress-model fillets OUT.step\n       facet-stress-model lenses OUT.step\n"
                         "       facet-stress-model machined OUT.step\n       facet-stress-model holes N OUT.step   (N = k * k)\n");
    return 2;
}

TopoDS_Wire circle(double x, double y, double z, double r, bool reversed) {
    gp_Ax2 axis(gp_Pnt(x, y, z), reversed ? -gp::DZ() : gp::DZ());
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(GC_MakeCircle(axis, r).Value())).Wire();
}

// 11 x 11 bosses on a 230 x 230 x 8 plate, fused at once; each boss's foot and top edge filleted.
TopoDS_Shape fillets() {
    const int n = 11;
    const double pitch = 20, size = n * pitch + 10, t = 8;
    TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), size, size, t).Shape();
    TopTools_ListOfShape args, tools;
    args.Append(plate);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double r = 4 + 0.25 * ((i + j) % 4);
            tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(15 + i * pitch, 15 + j * pitch, t - 1), gp::DZ()), r, 7 + (i * j) % 5).Shape());
        }
    BRepAlgoAPI_Fuse fuse;
    fuse.SetArguments(args);
    fuse.SetTools(tools);
    fuse.Build();
    if (!fuse.IsDone()) return {};
    TopoDS_Shape part = fuse.Shape();
    // Round every circular edge (the bosses' feet and tops) and the plate's vertical edges.
    BRepFilletAPI_MakeFillet fillet(part);
    for (TopExp_Explorer x(part, TopAbs_EDGE); x.More(); x.Next()) {
        const TopoDS_Edge e = TopoDS::Edge(x.Current());
        BRepAdaptor_Curve c(e);
        if (c.GetType() == GeomAbs_Circle) fillet.Add(c.Circle().Location().Z() > t + 0.5 ? 1.2 : 1.5, e);
        else if (c.GetType() == GeomAbs_Line && std::fabs(c.Line().Direction().Z()) > 0.99) fillet.Add(6, e);
    }
    fillet.Build();
    return fillet.IsDone() ? fillet.Shape() : TopoDS_Shape();
}

// Lens-shaped bosses (two discs' overlap, extruded) on a 200 x 200 plate: each top face is
// bounded by two arcs of 52 degrees, which a coarse tolerance samples as their chords alone.
TopoDS_Shape lenses() {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 200, 200, 5).Shape();
    TopTools_ListOfShape args, tools;
    args.Append(part);
    int k = 0;
    for (const double r : {2.0, 3.0, 5.0, 8.0, 12.0, 20.0}) {
        const double x = 20 + 30 * (k % 6), y = 30 + 50 * (k / 6);
        ++k;
        // Each cylinder's seam (its x direction) turned away from the lens: one edge per arc.
        const TopoDS_Shape a = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x - 0.9 * r, y, 4), gp::DZ(), -gp::DX()), r, 4).Shape();
        const TopoDS_Shape b = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x + 0.9 * r, y, 4), gp::DZ(), gp::DX()), r, 4).Shape();
        BRepAlgoAPI_Common lens(a, b);
        if (!lens.IsDone()) return {};
        tools.Append(lens.Shape());
    }
    BRepAlgoAPI_Fuse fuse;
    fuse.SetArguments(args);
    fuse.SetTools(tools);
    fuse.Build();
    return fuse.IsDone() ? fuse.Shape() : TopoDS_Shape();
}

// A k x k grid of holes of radius 0.3 pitch in a square plate, 1 mm thick.
TopoDS_Shape holes(int k) {
    const double pitch = 4, margin = 4, size = 2 * margin + (k - 1) * pitch, r = 0.3 * pitch;
    BRepBuilderAPI_MakeFace face(gp_Pln(gp::XOY()), 0, size, 0, size);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) face.Add(circle(margin + i * pitch, margin + j * pitch, 0, r, true));
    if (!face.IsDone()) return {};
    // The holes' circles run clockwise seen from +Z (their axis is -Z): the face is right as made.
    return BRepPrimAPI_MakePrism(face.Face(), gp_Vec(0, 0, 1)).Shape();
}

// A block of 160 x 100 x 24 mm. The top face ends with some 30 loops: holes of 0.6 to 6 mm
// radius, pairs 0.02 mm apart, elliptical slots, holes slanted 30 degrees (elliptical edges on
// the top face), countersunk holes (a cone on a cylinder); a bore along x whose seam faces up, so
// that the holes drilled into it cross its seam; a boss on the top, filleted at its foot (a
// torus) and drilled across its own seam; the block's vertical edges rounded.
TopoDS_Shape machined() {
    const double L = 160, W = 100, H = 24;
    TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), L, W, H).Shape();
    // Round the vertical edges first (cylinders), then add the boss and cut the rest.
    {
        BRepFilletAPI_MakeFillet round(block);
        for (TopExp_Explorer x(block, TopAbs_EDGE); x.More(); x.Next()) {
            BRepAdaptor_Curve c(TopoDS::Edge(x.Current()));
            if (c.GetType() == GeomAbs_Line && std::fabs(c.Line().Direction().Z()) > 0.99) round.Add(5, TopoDS::Edge(x.Current()));
        }
        round.Build();
        if (!round.IsDone()) return {};
        block = round.Shape();
    }
    // The boss: a cylinder whose seam (its x direction) faces -y, filleted where it meets the top.
    {
        const gp_Ax2 axis(gp_Pnt(130, 70, H - 1), gp::DZ(), -gp::DY());
        BRepAlgoAPI_Fuse fuse(block, BRepPrimAPI_MakeCylinder(axis, 12, 15).Shape());
        if (!fuse.IsDone()) return {};
        block = fuse.Shape();
        BRepFilletAPI_MakeFillet foot(block);
        for (TopExp_Explorer x(block, TopAbs_EDGE); x.More(); x.Next()) {
            BRepAdaptor_Curve c(TopoDS::Edge(x.Current()));
            if (c.GetType() == GeomAbs_Circle && std::fabs(c.Circle().Location().Z() - H) < 1e-6 && c.Circle().Radius() > 11)
                foot.Add(2, TopoDS::Edge(x.Current()));
        }
        foot.Build();
        if (!foot.IsDone()) return {};
        block = foot.Shape();
    }
    TopTools_ListOfShape tools;
    auto drill = [&](double x, double y, double r) {
        tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp::DZ()), r, H + 2).Shape());
    };
    // Round holes, small to large, and pairs a hair apart (0.02 and 0.1 mm of wall).
    for (int i = 0; i < 8; ++i) drill(12 + 11 * i, 12, 0.6 + 0.7 * i);
    drill(20, 88, 3), drill(26.02, 88, 3);
    drill(40, 88, 2), drill(44.1, 88, 2);
    drill(60, 90, 1), drill(62.02, 90, 1), drill(61.01, 91.75, 1);
    // Walls thinner than the CDT's grid unit on the top face (160 / 2^15 = 0.005 mm).
    drill(76, 88, 3), drill(82.001, 88, 3);
    drill(92, 88, 2), drill(96.0002, 88, 2);
    // Elliptical slots, turned.
    for (int i = 0; i < 4; ++i) {
        const double a = 0.4 * i;
        const gp_Ax2 axis(gp_Pnt(20 + 16 * i, 40, -1), gp::DZ(), gp_Dir(std::cos(a), std::sin(a), 0));
        const TopoDS_Edge e = BRepBuilderAPI_MakeEdge(GC_MakeEllipse(axis, 6 - i, 1.5 + 0.5 * i).Value());
        const TopoDS_Face f = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(e).Wire());
        tools.Append(BRepPrimAPI_MakePrism(f, gp_Vec(0, 0, H + 2)).Shape());
    }
    // Slanted holes: 30 degrees from the vertical (an ellipse where each meets the top face).
    for (int i = 0; i < 3; ++i) {
        const gp_Dir d(std::sin(M_PI / 6), 0, std::cos(M_PI / 6));
        const gp_Pnt top(90 + 12 * i, 45, H);
        tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(top.Translated(-gp_Vec(d) * 40), d), 1.5 + i, 60).Shape());
    }
    // Countersunk holes: a 90 degree cone over a hole.
    for (int i = 0; i < 3; ++i) {
        const double x = 100 + 14 * i, y = 20, r = 2 + i;
        drill(x, y, r);
        tools.Append(BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(x, y, H - 2 * r), gp::DZ()), 0, 3 * r, 3 * r).Shape());
    }
    // The cross bore along x at mid height, its seam (x direction of its frame) facing up; the
    // holes drilled from the top meet it on its seam, two of them straddling it.
    tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-1, 65, H / 2), gp::DX(), gp::DZ()), 6, L + 2).Shape());
    for (int i = 0; i < 4; ++i) {
        const double x = 30 + 22 * i, r = 1.5 + i;
        tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, 65 + (i % 2 ? 0.0 : 0.01), H / 2), gp::DZ()), r, H).Shape());
    }
    // The boss drilled across, through its seam (-y).
    tools.Append(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(130, 50, H + 8), gp::DY()), 3, 40).Shape());
    TopTools_ListOfShape args;
    args.Append(block);
    BRepAlgoAPI_Cut cut;
    cut.SetArguments(args);
    cut.SetTools(tools);
    cut.Build();
    return cut.IsDone() ? cut.Shape() : TopoDS_Shape();
}

} // namespace

int main(int argc, char** argv) {
    for (auto& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
    TopoDS_Shape part;
    const char* out = nullptr;
    if (argc == 3 && !std::strcmp(argv[1], "fillets")) {
        part = fillets();
        out = argv[2];
    } else if (argc == 3 && !std::strcmp(argv[1], "lenses")) {
        part = lenses();
        out = argv[2];
    } else if (argc == 3 && !std::strcmp(argv[1], "machined")) {
        part = machined();
        out = argv[2];
    } else if (argc == 4 && !std::strcmp(argv[1], "holes")) {
        const int n = std::atoi(argv[2]);
        const int k = int(std::lround(std::sqrt(double(n))));
        if (n < 1 || k * k != n || k > 200) return usage();
        part = holes(k);
        out = argv[3];
    } else {
        return usage();
    }
    // The analyser checks every pair of a face's wires: seconds for 1,600 holes, many minutes for 5,625.
    if (part.IsNull() || (argc == 3 && !BRepCheck_Analyzer(part).IsValid())) {
        std::fprintf(stderr, "facet-stress-model: Open CASCADE could not build a valid part\n");
        return 1;
    }
    int faces = 0, tori = 0;
    for (TopExp_Explorer x(part, TopAbs_FACE); x.More(); x.Next()) {
        ++faces;
        BRepAdaptor_Surface s(TopoDS::Face(x.Current()));
        tori += s.GetType() == GeomAbs_Torus;
    }
    STEPControl_Writer writer;
    if (writer.Transfer(part, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(out) != IFSelect_RetDone) {
        std::fprintf(stderr, "facet-stress-model: cannot write %s\n", out);
        return 1;
    }
    std::printf("%s: %d faces (%d toroidal)\n", out, faces, tori);
    return 0;
}
