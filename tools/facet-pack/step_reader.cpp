#include "step_reader.h"

#include "step_checks.h"

#include "geom/tree_format.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Shape.hxx>
#include <StepData_StepModel.hxx>
#include <StepShape_ManifoldSolidBrep.hxx>
#include <StepShape_ShellBasedSurfaceModel.hxx>
#include <Interface_Static.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Wire.hxx>
#include <ShapeProcess_ShapeContext.hxx>
#include <TopoDS_Iterator.hxx>
#include <XSAlgo.hxx>
#include <XSAlgo_AlgoContainer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Solid.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>
#include <TDataStd_Name.hxx>
#include <TopLoc_Location.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

namespace facet::packer {
namespace {

// The file's length unit in mm; 0 when the file gives none.
float unit_mm(STEPCAFControl_Reader& reader) {
    TColStd_SequenceOfAsciiString lengths, angles, solids;
    reader.ChangeReader().FileUnits(lengths, angles, solids);
    if (lengths.IsEmpty()) return 0.0f;
    const std::string u = lengths.First().ToCString();
    if (u.find("MILLI") != std::string::npos) return 1.0f;
    if (u.find("CENTI") != std::string::npos) return 10.0f;
    if (u.find("INCH") != std::string::npos) return 25.4f;
    if (u.find("FOOT") != std::string::npos) return 304.8f;
    if (u.find("METRE") != std::string::npos || u.find("METER") != std::string::npos) return 1000.0f;
    return 1.0f;
}


// A face with this many loops or more skips two of Open CASCADE's healing checks, each of which
// rebuilds the whole face once per loop: a plate with 5,625 holes spent five minutes in them.
// Loops that cross are still refused, by facet-pack's own check of every face's loops
// (clearance.h) and by the triangulation.
constexpr int kManyWires = 64;

int most_wires(const TopoDS_Shape& shape) {
    int most = 0;
    for (TopExp_Explorer x(shape, TopAbs_FACE); x.More(); x.Next()) {
        int n = 0;
        for (TopoDS_Iterator w(x.Current()); w.More(); w.Next()) ++n;
        most = std::max(most, n);
    }
    return most;
}

void skip_quadratic_fixes(ShapeFix_Shape& fix) {
    fix.FixFaceTool()->FixIntersectingWiresMode() = 0;
    fix.FixWireTool()->FixSelfIntersectionMode() = 0;
}

// The STEP reader's own healing, with the two checks switched off for the faces of many loops.
// (Debian's Open CASCADE finds no STEP resource file, so the reader heals with a default
// ShapeFix_Shape; this is that default, less the two checks.)
class Processing : public XSAlgo_AlgoContainer {
public:
    TopoDS_Shape ProcessShape(const TopoDS_Shape& shape, const Standard_Real prec, const Standard_Real max_tol,
                              const Standard_CString rscfile, const Standard_CString seq, Handle(Standard_Transient)& info,
                              const Message_ProgressRange& progress, const Standard_Boolean non_manifold) const override {
        if (!info.IsNull() || most_wires(shape) < kManyWires) {
            return XSAlgo_AlgoContainer::ProcessShape(shape, prec, max_tol, rscfile, seq, info, progress, non_manifold);
        }
        const char* file = Interface_Static::CVal(rscfile);
        Handle(ShapeProcess_ShapeContext) context = new ShapeProcess_ShapeContext(shape, file ? file : rscfile);
        context->SetDetalisation(TopAbs_EDGE);
        context->SetNonManifold(non_manifold);
        info = context;
        try {
            Handle(ShapeFix_Shape) fix = new ShapeFix_Shape(shape);
            fix->SetPrecision(prec);
            fix->SetMaxTolerance(max_tol);
            fix->FixWireTool()->FixSameParameterMode() = false;
            fix->FixSolidTool()->CreateOpenSolidMode() = false;
            skip_quadratic_fixes(*fix);
            fix->Perform(progress);
            context->RecordModification(fix->Context());
            context->SetResult(fix->Shape());
            return fix->Shape();
        } catch (const Standard_Failure&) {
            return shape;
        }
    }
};

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

// Sewing tolerances, of the shapes' bounding box diagonal: a solid's gaps, and sheets' (a file
// that wrote a solid face by face comes from a converter: ANC101 as B-splines has gaps up to
// 1/30,000 of its size).
constexpr double kSolidGap = 1e-5, kSheetGap = 10 * kSolidGap;

// A solid whose faces do not share their edges everywhere (an unsewn B-rep) is sewn within a
// small tolerance; closed says whether every edge then has two faces.
void close_gaps(Part& part) {
    if (!part.closed || free_edges(part.shape) == 0) return;
    Bnd_Box box;
    BRepBndLib::Add(part.shape, box);
    const double diag = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
    try {
        BRepBuilderAPI_Sewing sew(kSolidGap * diag);
        sew.Add(part.shape);
        sew.Perform();
        TopoDS_Shape sewn = sew.SewedShape();
        if (!sewn.IsNull() && free_edges(sewn) < free_edges(part.shape)) {
            ShapeFix_Shape fix(sewn);
            if (most_wires(sewn) >= kManyWires) skip_quadratic_fixes(fix);
            fix.Perform();
            sewn = fix.Shape();
            sewn.Location(part.shape.Location());
            part.shape = sewn;
        }
    } catch (const Standard_Failure&) {
    }
    part.closed = free_edges(part.shape) == 0;
}

// Sheets of one occurrence (a surface model: open shells or lone faces, same name and
// placement) that together bound a volume: a file that wrote a solid face by face. They are
// sewn within kSheetGap; when that leaves no free edge, the shells become one solid oriented
// outwards, read as closed (its back faces culled, its inside shown through a section, its
// edges shared and so sampled once). Otherwise they stay as they were. Returns how many
// sheets went into the solid (0: none).
size_t close_sheets(std::vector<Part>& parts) {
    std::vector<size_t> open;
    for (size_t i = 0; i < parts.size(); ++i)
        if (parts[i].shape.ShapeType() != TopAbs_SOLID) open.push_back(i);
    if (open.size() < 2) return 0;
    const Part& first = parts[open[0]];
    for (size_t i : open)
        if (parts[i].name != first.name || parts[i].instance != first.instance ||
            !parts[i].shape.Location().IsEqual(first.shape.Location()))
            return 0;
    try {
        Bnd_Box box; // (a curve Open CASCADE cannot bound throws: the sheets then stay as they are)
        for (size_t i : open) BRepBndLib::Add(parts[i].shape, box);
        const double diag = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
        BRepBuilderAPI_Sewing sew(kSheetGap * diag);
        for (size_t i : open) sew.Add(parts[i].shape.Located(TopLoc_Location()));
        sew.Perform();
        const TopoDS_Shape sewn = sew.SewedShape();
        if (sewn.IsNull() || free_edges(sewn) != 0) return 0;
        BRepBuilderAPI_MakeSolid make;
        int shells = 0;
        for (TopExp_Explorer x(sewn, TopAbs_SHELL); x.More(); x.Next(), ++shells) make.Add(TopoDS::Shell(x.Current()));
        if (shells == 0 || !make.IsDone()) return 0;
        TopoDS_Solid solid = make.Solid();
        BRepLib::OrientClosedSolid(solid);
        Part whole{solid.Located(first.shape.Location()), true, first.name, first.instance, first.node};
        std::vector<Part> kept;
        for (Part& p : parts)
            if (p.shape.ShapeType() == TopAbs_SOLID) kept.push_back(std::move(p));
        kept.push_back(std::move(whole));
        parts = std::move(kept);
        return open.size();
    } catch (const Standard_Failure&) {
        return 0;
    }
}

// A file with no PRODUCT and no shape representation Open CASCADE knows (early AP203 writers)
// still holds solids and shells: transferred one by one, where they are.
void transfer_bodies(STEPControl_Reader& reader, std::vector<TopoDS_Shape>& top) {
    const Handle(StepData_StepModel) m = reader.StepModel();
    for (int i = 1; i <= m->NbEntities(); ++i) {
        const Handle(Standard_Transient)& e = m->Value(i);
        if (!e->IsKind(STANDARD_TYPE(StepShape_ManifoldSolidBrep)) && !e->IsKind(STANDARD_TYPE(StepShape_ShellBasedSurfaceModel))) continue;
        try {
            const int before = reader.NbShapes();
            if (reader.TransferEntity(e) && reader.NbShapes() > before) top.push_back(reader.Shape(reader.NbShapes()));
        } catch (const Standard_Failure&) {
        }
    }
}

float guessed_unit_mm(UnitGuess g, double diagonal) {
    switch (g) {
    case UnitGuess::Millimetre: return 1.0f;
    case UnitGuess::Centimetre: return 10.0f;
    case UnitGuess::Metre: return 1000.0f;
    case UnitGuess::Inch: return 25.4f;
    case UnitGuess::Foot: return 304.8f;
    case UnitGuess::BySize: break;
    }
    // Under one unit across: a part in millimetres that small is rarer than one in metres.
    return diagonal < 1.0 ? 1000.0f : 1.0f;
}

// A label's name as UTF-8 ("" for none, and for the "=>[0:1:1:2]" Open CASCADE gives
// occurrences the file leaves unnamed).
std::string label_name(const TDF_Label& label) {
    Handle(TDataStd_Name) attr;
    if (!label.FindAttribute(TDataStd_Name::GetID(), attr)) return "";
    const TCollection_ExtendedString& text = attr->Get();
    std::string utf8(size_t(text.LengthOfCString()) + 1, '\0');
    Standard_PCharacter out = utf8.data();
    utf8.resize(size_t(text.ToUTF8CString(out)));
    while (!utf8.empty() && (utf8.back() == ' ' || utf8.back() == '\0')) utf8.pop_back();
    if (utf8.rfind("=>", 0) == 0) return "";
    return utf8;
}

// Where each solid, shell and face of the assembly sits and whose it is: the XCAF tree walked
// from the free shapes, placements composed on the way down.
struct Named {
    gp_Trsf placement;
    std::string name, instance;
    uint32_t node; // the sub-assembly it is in (StepModel::nodes), or UINT32_MAX
};
using NameMap = std::multimap<const void*, Named>; // by TShape

// An assembly becomes a node of the tree (under `node`), its components walked in its order.
void walk(const Handle(XCAFDoc_ShapeTool)& shapes, const TDF_Label& label, const TopLoc_Location& at,
          const std::string& instance, NameMap& names, int depth, std::vector<TreeNode>& nodes, uint32_t node) {
    if (depth > int(pack::kMaxTreeDepth)) return; // a malformed file's cycle (and deeper than a pack's tree)
    if (XCAFDoc_ShapeTool::IsAssembly(label)) {
        const uint32_t self = uint32_t(nodes.size());
        nodes.push_back({node, label_name(label), instance});
        TDF_LabelSequence components;
        XCAFDoc_ShapeTool::GetComponents(label, components);
        for (int i = 1; i <= components.Length(); ++i) {
            TDF_Label part;
            if (!XCAFDoc_ShapeTool::GetReferredShape(components.Value(i), part)) continue;
            walk(shapes, part, at * XCAFDoc_ShapeTool::GetLocation(components.Value(i)), label_name(components.Value(i)), names,
                 depth + 1, nodes, self);
        }
        return;
    }
    const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
    if (shape.IsNull()) return;
    const TopoDS_Shape placed = shape.Moved(at);
    const std::string name = label_name(label);
    for (TopAbs_ShapeEnum kind : {TopAbs_SOLID, TopAbs_SHELL, TopAbs_FACE}) {
        for (TopExp_Explorer x(placed, kind); x.More(); x.Next()) {
            names.insert({x.Current().TShape().get(), {x.Current().Location().Transformation(), name, instance, node}});
        }
    }
}

// The names of a part found where the walk put it (its TShape at the same placement), or of
// any occurrence of its TShape.
void name_part(const NameMap& names, Part& p) {
    const auto [lo, hi] = names.equal_range(p.shape.TShape().get());
    if (lo == hi) return;
    const gp_Trsf t = p.shape.Location().Transformation();
    auto best = lo;
    double best_d = 1e300;
    for (auto it = lo; it != hi; ++it) {
        double d = 0;
        for (int r = 1; r <= 3; ++r)
            for (int c = 1; c <= 4; ++c) d += std::abs(it->second.placement.Value(r, c) - t.Value(r, c));
        if (d < best_d) best_d = d, best = it;
    }
    p.name = best->second.name;
    p.instance = best->second.instance;
    p.node = best->second.node;
}

// One root for the tree: the top assembly when it is the only root and holds every part; else
// a node for the model (its name) over the top assemblies and the parts in none.
void root_the_tree(StepModel& model) {
    if (model.nodes.empty()) return;
    uint32_t tops = 0;
    for (const TreeNode& n : model.nodes) tops += n.parent == UINT32_MAX;
    const bool orphans = std::any_of(model.parts.begin(), model.parts.end(), [](const Part& p) { return p.node == UINT32_MAX; });
    if (tops == 1 && !orphans) return;
    for (TreeNode& n : model.nodes) n.parent = n.parent == UINT32_MAX ? 0 : n.parent + 1;
    model.nodes.insert(model.nodes.begin(), TreeNode{UINT32_MAX, model.name, ""});
    for (Part& p : model.parts) p.node = p.node == UINT32_MAX ? 0 : p.node + 1;
}


} // namespace

void progress(const char* what) {
    static const auto start = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "facet-pack: %5.1f s: %s\n", s, what);
}

bool parse_unit(const std::string& t, UnitGuess& unit) {
    if (t == "mm") unit = UnitGuess::Millimetre;
    else if (t == "cm") unit = UnitGuess::Centimetre;
    else if (t == "m") unit = UnitGuess::Metre;
    else if (t == "in") unit = UnitGuess::Inch;
    else if (t == "ft") unit = UnitGuess::Foot;
    else if (t == "size") unit = UnitGuess::BySize;
    else return false;
    return true;
}

bool read_step(const std::string& in, StepModel& model, std::string& error, bool quiet, UnitGuess no_unit) {
    auto say = [&](const char* what) {
        if (!quiet) progress(what);
    };
    say("reading STEP");
    static const bool processing = [] {
        XSAlgo::Init();
        XSAlgo::SetAlgoContainer(new Processing);
        return true;
    }();
    (void)processing;
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    std::optional<STEPCAFControl_Reader> opened;
    auto open = [&](bool colours) {
        opened.emplace();
        opened->SetColorMode(colours);
        opened->SetNameMode(true);
        opened->SetLayerMode(false);
        opened->SetGDTMode(true);  // the PMI's semantic records
        opened->SetViewMode(true); // and their presentation
        app->NewDocument("MDTV-XCAF", doc);
        return opened->ReadFile(in.c_str()) == IFSelect_RetDone;
    };
    if (!open(true)) {
        error = in + ": not a readable STEP file";
        return false;
    }
    if (const std::string why = out_of_range_number(Handle(StepData_StepModel)::DownCast(opened->ChangeReader().Model())); !why.empty()) {
        error = in + ": " + why;
        return false;
    }
    bool transferred = false;
    try {
        transferred = opened->Transfer(doc);
    } catch (const Standard_Failure& f) {
        // A colour out of range throws from within the transfer (its styles are read last):
        // the file read again without its colours, which are lost (a failure, unless
        // --partial). What throws then is the shapes' own.
        model.failed.push_back(std::string("the file's colours: ") + f.DynamicType()->Name() + ": " + f.GetMessageString() +
                               " (read again without them)");
        if (!open(false)) {
            error = in + ": not a readable STEP file";
            return false;
        }
        transferred = opened->Transfer(doc);
    }
    STEPCAFControl_Reader& reader = *opened;
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    model.colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
    model.unit_mm = unit_mm(reader);
    std::vector<TopoDS_Shape> top;
    NameMap names;
    if (transferred) {
        TDF_LabelSequence roots;
        shapes->GetFreeShapes(roots);
        for (int r = 1; r <= roots.Length(); ++r) {
            top.push_back(shapes->GetShape(roots.Value(r)));
            walk(shapes, roots.Value(r), XCAFDoc_ShapeTool::GetLocation(roots.Value(r)), "", names, 0, model.nodes, UINT32_MAX);
        }
        if (roots.Length() == 1) model.name = label_name(roots.Value(1));
        account_faces(reader.ChangeReader(), top, model);
        account_failures(reader.ChangeReader(), model);
    }
    if (model.name.empty()) { // the file's stem
        const size_t slash = in.find_last_of('/'), start = slash == std::string::npos ? 0 : slash + 1;
        const size_t dot = in.find_last_of('.');
        model.name = in.substr(start, dot == std::string::npos || dot < start ? std::string::npos : dot - start);
    }
    if (top.empty()) {
        // Files without PRODUCT structure (early AP203 writers) give the assembly-aware reader
        // nothing; the plain reader can still transfer their shape representations.
        say("no product structure: reading shape representations directly");
        STEPControl_Reader plain;
        if (plain.ReadFile(in.c_str()) == IFSelect_RetDone) {
            if (plain.TransferRoots() > 0) {
                const TopoDS_Shape shape = plain.OneShape();
                if (!shape.IsNull()) top.push_back(shape);
            }
            if (top.empty()) {
                say("no shape representation Open CASCADE knows: reading the solids and shells themselves");
                transfer_bodies(plain, top);
                if (!top.empty()) model.notes += "read without a shape representation: its solids and shells one by one\n";
            }
            account_faces(plain, top, model);
            account_failures(plain, model);
        }
        model.colours.Nullify();
    }
    if (top.empty()) {
        error = in + ": the STEP file holds no shape Open CASCADE can transfer";
        return false;
    }
    if (model.faces_outside) {
        model.notes += std::to_string(model.faces_outside) + " faces of shells no shape uses (construction geometry) left out\n";
    }
    double pmi_scale = 1.0;
    if (model.unit_mm == 0) {
        // No unit context: Open CASCADE takes the numbers as they are (as millimetres).
        Bnd_Box box;
        for (const TopoDS_Shape& s : top) BRepBndLib::Add(s, box);
        const double diag = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
        model.unit_mm = guessed_unit_mm(no_unit, diag);
        char note[200];
        std::snprintf(note, sizeof note, "the file gives no length unit; its parts measure %.4g units across: read as %s%s\n", diag,
                      model.unit_mm == 1000.0f ? "metres" : model.unit_mm == 1.0f ? "millimetres" : "the unit given",
                      no_unit == UnitGuess::BySize ? " (--unit mm|cm|m|in|ft says otherwise)" : " (--unit)");
        model.notes += note;
        if (model.unit_mm != 1.0f) {
            pmi_scale = model.unit_mm;
            gp_Trsf scale;
            scale.SetScale(gp_Pnt(0, 0, 0), model.unit_mm);
            for (TopoDS_Shape& s : top) {
                try {
                    s = BRepBuilderAPI_Transform(s, scale, true).Shape();
                } catch (const Standard_Failure& f) {
                    error = in + ": cannot scale the parts to millimetres: " + f.GetMessageString();
                    return false;
                }
            }
        }
    }
    if (transferred && !model.colours.IsNull()) read_pmi(doc, pmi_scale, model.pmi);
    say("healing");
    for (const TopoDS_Shape& root : top) {
        std::vector<Part> raw;
        for (TopExp_Explorer x(root, TopAbs_SOLID); x.More(); x.Next()) raw.push_back({x.Current(), true, {}, {}});
        for (TopExp_Explorer x(root, TopAbs_SHELL, TopAbs_SOLID); x.More(); x.Next()) raw.push_back({x.Current(), false, {}, {}});
        for (TopExp_Explorer x(root, TopAbs_FACE, TopAbs_SHELL); x.More(); x.Next()) raw.push_back({x.Current(), false, {}, {}});
        for (Part& p : raw) {
            name_part(names, p); // before healing: the healed shape is a new one
            try {
                ShapeFix_Shape fix(p.shape);
                if (most_wires(p.shape) >= kManyWires) skip_quadratic_fixes(fix);
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
        }
        if (const size_t n = close_sheets(raw))
            model.notes += std::to_string(n) + " sheets of " + (raw.back().name.empty() ? std::string("one part") : "'" + raw.back().name + "'") +
                           " bound a volume: sewn into one closed solid\n";
        for (Part& p : raw) model.parts.push_back(std::move(p));
    }
    root_the_tree(model);
    // The parts in the tree's depth-first order (each node's parts, then its sub-assemblies'):
    // every node's parts one run (in the file's order within a node).
    std::stable_sort(model.parts.begin(), model.parts.end(), [](const Part& a, const Part& b) { return a.node < b.node; });
    return true;
}

} // namespace facet::packer
