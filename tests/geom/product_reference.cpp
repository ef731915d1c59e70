// A STEP file's product structure and PMI as Open CASCADE reads them, written apart from
// facet-pack's readers (tools/facet-pack/step_reader.cpp, pmi.cpp), for product_test.py to
// check a pack against: the assembly tree (each assembly depth-first: its depth, name, and
// the solids, shells and faces under it, as parts), the counts of dimension, tolerance and
// datum records, each semantic dimension's type and value, each tolerance's, each datum's name.
// One JSON object on stdout.
//
//   facet-product-reference MODEL.step
#include <IFSelect_ReturnStatus.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDimTolObjects_DatumObject.hxx>
#include <XCAFDimTolObjects_DimensionObject.hxx>
#include <XCAFDimTolObjects_GeomToleranceObject.hxx>
#include <XCAFDoc_Datum.hxx>
#include <XCAFDoc_DimTolTool.hxx>
#include <XCAFDoc_Dimension.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_GeomTolerance.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp_Explorer.hxx>

#include <cstdio>
#include <string>

namespace {

// Solids, shells outside solids, faces outside shells: what a packer makes parts of.
int parts_of(const TopoDS_Shape& s) {
    int n = 0;
    for (TopExp_Explorer x(s, TopAbs_SOLID); x.More(); x.Next()) ++n;
    for (TopExp_Explorer x(s, TopAbs_SHELL, TopAbs_SOLID); x.More(); x.Next()) ++n;
    for (TopExp_Explorer x(s, TopAbs_FACE, TopAbs_SHELL); x.More(); x.Next()) ++n;
    return n;
}

std::string quoted(const TDF_Label& l) {
    Handle(TDataStd_Name) name;
    std::string s;
    if (l.FindAttribute(TDataStd_Name::GetID(), name)) s = TCollection_AsciiString(name->Get()).ToCString();
    std::string out = "\"";
    for (char c : s) out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    return out + "\"";
}

// Each assembly under `label`, depth-first: [depth, name, parts].
void assemblies(const TDF_Label& label, int depth, std::string& out) {
    if (!XCAFDoc_ShapeTool::IsAssembly(label) || depth > 32) return;
    out += std::string(out.empty() ? "" : ", ") + "[" + std::to_string(depth) + ", " + quoted(label) + ", " +
           std::to_string(parts_of(XCAFDoc_ShapeTool::GetShape(label))) + "]";
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(label, components);
    for (int i = 1; i <= components.Length(); ++i) {
        TDF_Label part;
        if (XCAFDoc_ShapeTool::GetReferredShape(components.Value(i), part)) assemblies(part, depth + 1, out);
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: facet-product-reference MODEL.step\n");
        return 2;
    }
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader reader;
    reader.SetGDTMode(true);
    reader.SetViewMode(true);
    if (reader.ReadFile(argv[1]) != IFSelect_RetDone || !reader.Transfer(doc)) {
        std::fprintf(stderr, "facet-product-reference: %s: not read\n", argv[1]);
        return 1;
    }
    const Handle(XCAFDoc_DimTolTool) tool = XCAFDoc_DocumentTool::DimTolTool(doc->Main());
    TDF_LabelSequence dims, tols, datums;
    tool->GetDimensionLabels(dims);
    tool->GetGeomToleranceLabels(tols);
    tool->GetDatumLabels(datums);
    std::string dimensions, tolerances, names;
    for (int i = 1; i <= dims.Length(); ++i) {
        Handle(XCAFDoc_Dimension) a;
        if (!dims.Value(i).FindAttribute(XCAFDoc_Dimension::GetID(), a)) continue;
        const Handle(XCAFDimTolObjects_DimensionObject) o = a->GetObject();
        const int type = int(o->GetType());
        if (o->GetType() == XCAFDimTolObjects_DimensionType_CommonLabel || o->GetType() == XCAFDimTolObjects_DimensionType_DimensionPresentation) continue;
        char item[64];
        std::snprintf(item, sizeof item, "%s[%d, %.9g]", dimensions.empty() ? "" : ", ", type, o->GetValue());
        dimensions += item;
    }
    for (int i = 1; i <= tols.Length(); ++i) {
        Handle(XCAFDoc_GeomTolerance) a;
        if (!tols.Value(i).FindAttribute(XCAFDoc_GeomTolerance::GetID(), a)) continue;
        const Handle(XCAFDimTolObjects_GeomToleranceObject) o = a->GetObject();
        char item[64];
        std::snprintf(item, sizeof item, "%s[%d, %.9g]", tolerances.empty() ? "" : ", ", int(o->GetType()), o->GetValue());
        tolerances += item;
    }
    for (int i = 1; i <= datums.Length(); ++i) {
        Handle(XCAFDoc_Datum) a;
        if (!datums.Value(i).FindAttribute(XCAFDoc_Datum::GetID(), a)) continue;
        const Handle(XCAFDimTolObjects_DatumObject) o = a->GetObject();
        names += std::string(names.empty() ? "" : ", ") + "\"" + (o->GetName().IsNull() ? "" : o->GetName()->ToCString()) + "\"";
    }
    std::string tree;
    TDF_LabelSequence roots;
    XCAFDoc_DocumentTool::ShapeTool(doc->Main())->GetFreeShapes(roots);
    for (int r = 1; r <= roots.Length(); ++r) assemblies(roots.Value(r), 0, tree);
    std::printf("{\"roots\": %d, \"assemblies\": [%s], ", roots.Length(), tree.c_str());
    std::printf("\"dimension_labels\": %d, \"tolerances\": %d, \"datums\": %d, \"semantic_dimensions\": [%s], "
                "\"tolerance_values\": [%s], \"datum_names\": [%s]}\n",
                dims.Length(), tols.Length(), datums.Length(), dimensions.c_str(), tolerances.c_str(), names.c_str());
    return 0;
}
