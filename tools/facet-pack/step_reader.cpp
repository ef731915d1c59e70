#include "step_reader.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>

#include <cmath>
#include <cstdio>

namespace facet::packer {
namespace {

float unit_mm(STEPCAFControl_Reader& reader) {
    TColStd_SequenceOfAsciiString lengths, angles, solids;
    reader.ChangeReader().FileUnits(lengths, angles, solids);
    if (lengths.IsEmpty()) return 1.0f;
    const std::string u = lengths.First().ToCString();
    if (u.find("MILLI") != std::string::npos) return 1.0f;
    if (u.find("CENTI") != std::string::npos) return 10.0f;
    if (u.find("INCH") != std::string::npos) return 25.4f;
    if (u.find("FOOT") != std::string::npos) return 304.8f;
    if (u.find("METRE") != std::string::npos || u.find("METER") != std::string::npos) return 1000.0f;
    return 1.0f;
}


// Edges of the shape used by one face only (a seam, used twice by its face, and a degenerate
// edge at a pole count as closed): where a solid's B-rep has gaps.
int free_edges(const TopoDS_Shape& shape) {
    TopTools_IndexedDataMapOfShapeListOfShape faces_of;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of);
    int n = 0;
    for (int i = 1; i <= faces_of.Extent(); ++i) {
        const TopoDS_Edge& e = TopoDS::Edge(faces_of.FindKey(i));
        if (BRep_Tool::Degenerated(e) || faces_of(i).Extent() != 1) continue;
        if (BRep_Tool::IsClosed(e, TopoDS::Face(faces_of(i).First()))) continue; // a seam
        ++n;
    }
    return n;
}

// A solid whose faces do not share their edges everywhere (an unsewn B-rep) is sewn within a
// small tolerance; closed says whether every edge then has two faces.
void close_gaps(Part& part) {
    if (!part.closed || free_edges(part.shape) == 0) return;
    Bnd_Box box;
    BRepBndLib::Add(part.shape, box);
    const double diag = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
    try {
        BRepBuilderAPI_Sewing sew(1e-5 * diag);
        sew.Add(part.shape);
        sew.Perform();
        TopoDS_Shape sewn = sew.SewedShape();
        if (!sewn.IsNull() && free_edges(sewn) < free_edges(part.shape)) {
            ShapeFix_Shape fix(sewn);
            fix.Perform();
            sewn = fix.Shape();
            sewn.Location(part.shape.Location());
            part.shape = sewn;
        }
    } catch (const Standard_Failure&) {
    }
    part.closed = free_edges(part.shape) == 0;
}

} // namespace

bool read_step(const std::string& in, StepModel& model, std::string& error, bool quiet) {
    auto progress = [&](const char* what) {
        if (!quiet) std::fprintf(stderr, "facet-pack: %s\n", what);
    };
    progress("reading STEP");
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    if (reader.ReadFile(in.c_str()) != IFSelect_RetDone) {
        error = in + ": not a readable STEP file";
        return false;
    }
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    model.colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
    model.unit_mm = unit_mm(reader);
    std::vector<TopoDS_Shape> top;
    if (reader.Transfer(doc)) {
        TDF_LabelSequence roots;
        shapes->GetFreeShapes(roots);
        for (int r = 1; r <= roots.Length(); ++r) top.push_back(shapes->GetShape(roots.Value(r)));
    }
    if (top.empty()) {
        // Files without PRODUCT structure (early AP203 writers) give the assembly-aware reader
        // nothing; the plain reader can still transfer their shape representations.
        progress("no product structure: reading shape representations directly");
        STEPControl_Reader plain;
        if (plain.ReadFile(in.c_str()) == IFSelect_RetDone && plain.TransferRoots() > 0) {
            const TopoDS_Shape shape = plain.OneShape();
            if (!shape.IsNull()) top.push_back(shape);
        }
        model.colours.Nullify();
    }
    if (top.empty()) {
        error = in + ": the STEP file holds no shape Open CASCADE can transfer";
        return false;
    }
    progress("healing");
    for (const TopoDS_Shape& root : top) {
        std::vector<Part> raw;
        for (TopExp_Explorer x(root, TopAbs_SOLID); x.More(); x.Next()) raw.push_back({x.Current(), true});
        for (TopExp_Explorer x(root, TopAbs_SHELL, TopAbs_SOLID); x.More(); x.Next()) raw.push_back({x.Current(), false});
        for (TopExp_Explorer x(root, TopAbs_FACE, TopAbs_SHELL); x.More(); x.Next()) raw.push_back({x.Current(), false});
        for (Part& p : raw) {
            try {
                ShapeFix_Shape fix(p.shape);
                fix.Perform();
                TopoDS_Shape healed = fix.Shape();
                healed.Location(p.shape.Location()); // keep the occurrence's placement
                p.shape = healed;
            } catch (const Standard_Failure&) {
            }
            if (p.closed) {
                close_gaps(p);
                if (!p.closed) ++model.open_solids;
            }
            model.parts.push_back(p);
        }
    }
    return true;
}

} // namespace facet::packer
