// The PMI of a STEP file as Open CASCADE reads it, written apart from facet-pack's reader
// (tools/facet-pack/pmi.cpp), for pmi_test.py to check the pack's annotations against: the
// counts of dimension, tolerance and datum records, each semantic dimension's type and value,
// each tolerance's type and value, each datum's name. One JSON object on stdout.
//
//   facet-pmi-reference MODEL.step
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

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: facet-pmi-reference MODEL.step\n");
        return 2;
    }
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader reader;
    reader.SetGDTMode(true);
    reader.SetViewMode(true);
    if (reader.ReadFile(argv[1]) != IFSelect_RetDone || !reader.Transfer(doc)) {
        std::fprintf(stderr, "facet-pmi-reference: %s: not read\n", argv[1]);
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
    std::printf("{\"dimension_labels\": %d, \"tolerances\": %d, \"datums\": %d, \"semantic_dimensions\": [%s], "
                "\"tolerance_values\": [%s], \"datum_names\": [%s]}\n",
                dims.Length(), tols.Length(), datums.Length(), dimensions.c_str(), tolerances.c_str(), names.c_str());
    return 0;
}
