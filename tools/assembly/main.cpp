// facet-assembly: a large assembly made of the shared models, for ./facet bench scale and for
// trying facet on a machine-sized model. Written as STEP (AP214) with Open CASCADE:
//
//   facet-assembly OUT.step --faces N [--instances | --distinct M] MODEL.step...
//
// Copies of the models, taken in turn, stand on a square grid (z up) until the assembly has at
// least N faces. Distinct copies (the default): each copy is a part of its own, its geometry
// copied (BRepBuilderAPI_Copy), as an assembly of separately modelled parts is. --instances:
// each model is one part, placed once per copy (one product, many occurrences), as repeated
// standard parts are. --distinct M: distinct copies until they hold M faces, then instances of
// those copies, in turn, up to N (a machine of many distinct parts, some repeated: the 100 k-face
// assembly of ./facet bench scale). Each copy keeps its model's parts and their placements; parts are
// coloured by the model they come from and named "MODEL #K".
//
// Exit codes: 0 written, 1 error (the reason on stderr), 2 usage.
#include "step_reader.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TDataStd_Name.hxx>
#include <TDF_Label.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <BRep_Builder.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

int usage() {
    std::fprintf(stderr, "usage: facet-assembly OUT.step --faces N [--instances | --distinct M] MODEL.step...\n");
    return 2;
}

int die(const std::string& why) {
    std::fprintf(stderr, "facet-assembly: error: %s\n", why.c_str());
    return 1;
}

struct Source {
    std::string name;
    TopoDS_Compound shape; // its parts at their placements
    int faces = 0;
    double size = 0;       // the larger side of its box in x and y (mm)
    double centre[3] = {0, 0, 0}, low_z = 0;
};

std::string stem(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    std::string s = slash == std::string::npos ? path : path.substr(slash + 1);
    const size_t dot = s.find_last_of('.');
    return dot == std::string::npos ? s : s.substr(0, dot);
}

// Colours that tell the models apart (sRGB).
const double kColours[][3] = {{0.72, 0.74, 0.78}, {0.80, 0.62, 0.36}, {0.45, 0.62, 0.80}, {0.58, 0.76, 0.50},
                              {0.82, 0.50, 0.48}, {0.70, 0.60, 0.82}};

} // namespace

int main(int argc, char** argv) {
    const char* out = nullptr;
    long faces = 0, distinct = 0;
    bool instances = false;
    std::vector<std::string> models;
    for (int i = 1; i < argc; ++i) {
        if ((!std::strcmp(argv[i], "--faces") || !std::strcmp(argv[i], "--distinct")) && i + 1 < argc) {
            const bool of_distinct = argv[i][2] == 'd';
            char* end = nullptr;
            const long n = std::strtol(argv[++i], &end, 10);
            if (!end || *end || n <= 0 || n > 10000000) {
                std::fprintf(stderr, "facet-assembly: error: %s %s: a count from 1 to 10,000,000\n", argv[i - 1], argv[i]);
                return 2;
            }
            (of_distinct ? distinct : faces) = n;
        } else if (!std::strcmp(argv[i], "--instances")) {
            instances = true;
        } else if (argv[i][0] == '-') {
            return usage();
        } else if (!out) {
            out = argv[i];
        } else {
            models.push_back(argv[i]);
        }
    }
    if (!out || faces == 0 || models.empty() || (instances && distinct)) return usage();
    for (auto& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);

    std::vector<Source> sources;
    for (const std::string& path : models) {
        facet::packer::StepModel m;
        std::string error;
        if (!facet::packer::read_step(path, m, error, true)) return die(error);
        Source s;
        s.name = stem(path);
        BRep_Builder b;
        b.MakeCompound(s.shape);
        for (const facet::packer::Part& part : m.parts) b.Add(s.shape, part.shape);
        for (TopExp_Explorer e(s.shape, TopAbs_FACE); e.More(); e.Next()) ++s.faces;
        if (s.faces == 0) return die(path + ": no faces");
        Bnd_Box box;
        BRepBndLib::Add(s.shape, box);
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        s.size = std::max(x1 - x0, y1 - y0);
        s.centre[0] = 0.5 * (x0 + x1), s.centre[1] = 0.5 * (y0 + y1), s.centre[2] = 0.5 * (z0 + z1);
        s.low_z = z0;
        sources.push_back(s);
    }
    // The copies, in turn, until there are enough faces.
    std::vector<int> copies;
    size_t fresh = 0; // --distinct: the distinct copies (the first ones), the rest instances of them in turn
    for (long total = 0; total < faces;) {
        const bool again = distinct && total >= distinct && fresh > 0;
        const int k = again ? copies[(copies.size() - fresh) % fresh] : int(copies.size() % sources.size());
        fresh += !again && copies.size() == fresh;
        copies.push_back(k);
        total += sources[size_t(k)].faces;
    }
    const int side = int(std::ceil(std::sqrt(double(copies.size()))));
    double cell = 0;
    for (const Source& s : sources) cell = std::max(cell, s.size);
    cell *= 1.15;

    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
    const TDF_Label top = shapes->NewShape();
    TDataStd_Name::Set(top, TCollection_ExtendedString((stem(out)).c_str()));
    std::vector<TDF_Label> shared(sources.size()); // --instances: one part per model
    std::vector<TDF_Label> made;                   // --distinct: the distinct copies
    long total = 0, distinct_total = 0;
    try {
        for (size_t i = 0; i < copies.size(); ++i) {
            const Source& s = sources[size_t(copies[i])];
            // An instance: of a distinct copy, in turn (--distinct), or of its model (--instances).
            TDF_Label part = distinct && i >= fresh ? made[(i - fresh) % fresh] : instances ? shared[size_t(copies[i])] : TDF_Label();
            if (part.IsNull()) {
                const TopoDS_Shape shape = instances ? TopoDS_Shape(s.shape) : BRepBuilderAPI_Copy(s.shape).Shape();
                part = shapes->AddShape(shape, false);
                const std::string name = instances ? s.name : s.name + " #" + std::to_string(i + 1);
                TDataStd_Name::Set(part, TCollection_ExtendedString(name.c_str()));
                const double* c = kColours[size_t(copies[i]) % (sizeof kColours / sizeof kColours[0])];
                colours->SetColor(part, Quantity_Color(c[0], c[1], c[2], Quantity_TOC_sRGB), XCAFDoc_ColorSurf);
                if (instances) shared[size_t(copies[i])] = part;
                if (distinct) made.push_back(part), distinct_total += s.faces;
            }
            // Its cell: the model's box centred on it, standing on z = 0.
            gp_Trsf at;
            at.SetTranslation(gp_Vec(double(int(i) % side) * cell - s.centre[0], double(int(i) / side) * cell - s.centre[1], -s.low_z));
            shapes->AddComponent(top, part, TopLoc_Location(at));
            total += s.faces;
        }
        shapes->UpdateAssemblies();
        STEPCAFControl_Writer writer;
        writer.SetColorMode(true);
        writer.SetNameMode(true);
        if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(out) != IFSelect_RetDone) return die(std::string("cannot write ") + out);
    } catch (const Standard_Failure& f) {
        return die(std::string("Open CASCADE: ") + f.GetMessageString());
    }
    if (distinct) {
        std::printf("%s: %zu distinct copies of %zu models (%ld faces) and %zu instances of them, %ld faces, on a %d x %d grid of %.0f mm\n",
                    out, made.size(), sources.size(), distinct_total, copies.size() - made.size(), total, side, side, cell);
    } else {
        std::printf("%s: %zu %s of %zu models, %ld faces, on a %d x %d grid of %.0f mm\n", out, copies.size(),
                    instances ? "instances" : "distinct copies", sources.size(), total, side, side, cell);
    }
    return 0;
}
