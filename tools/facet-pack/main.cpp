// facet-pack: STEP (AP203/AP214/AP242) -> facet pack, with Open CASCADE.
//
//   facet-pack model.step -o model.fpk      pack, print a summary
//   facet-pack --check model.fpk            validate a pack with the device's reader
//
// Reads with the XCAF reader (units converted to mm, assemblies, colours from styled items),
// heals each solid and shell with ShapeFix, and writes every face's exact surface, its loops
// of edges with their 3D curves and pcurves, and the colours. Exits non-zero with a clear
// message on unreadable or empty input.
#include "geom/pack.h"
#include "occt_to_pack.h"
#include "pack_writer.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Gravity.hxx>
#include <Message_Messenger.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <vector>

using namespace facet;

namespace {

int usage() {
    std::fprintf(stderr, "usage: facet-pack MODEL.step -o MODEL.fpk [--quiet]\n       facet-pack --check MODEL.fpk\n");
    return 2;
}

int die(const std::string& msg) {
    std::fprintf(stderr, "facet-pack: error: %s\n", msg.c_str());
    return 1;
}

int check(const char* path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return die(std::string("cannot open ") + path);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
    std::vector<uint32_t> aligned((bytes.size() + 3) / 4);
    std::memcpy(aligned.data(), bytes.data(), bytes.size());
    geom::Pack pack;
    geom::PackProblem problem;
    if (pack.open(aligned.data(), uint32_t(bytes.size()), problem) != Status::Ok) {
        return die(std::string(path) + ": " + problem.message);
    }
    std::printf("%s: valid pack, %zu faces, %zu edges, %zu shells, %zu instances, %zu bytes\n", path,
                pack.faces().size(), pack.edges().size(), pack.shells().size(), pack.instances().size(), bytes.size());
    return 0;
}

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

} // namespace

int main(int argc, char** argv) {
    const char *in = nullptr, *out = nullptr;
    bool quiet = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--check") && i + 1 < argc) return check(argv[i + 1]);
        if (!std::strcmp(argv[i], "-o") && i + 1 < argc) out = argv[++i];
        else if (!std::strcmp(argv[i], "--quiet")) quiet = true;
        else if (argv[i][0] == '-') return usage();
        else in = argv[i];
    }
    if (!in || !out) return usage();
    struct stat st {};
    if (stat(in, &st) != 0) return die(std::string("cannot read ") + in);
    // OCCT's own trace messages are noise for a command-line user; keep warnings and worse.
    for (auto& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);

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
    if (reader.ReadFile(in) != IFSelect_RetDone) return die(std::string(in) + ": not a readable STEP file");
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
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
        if (plain.ReadFile(in) == IFSelect_RetDone && plain.TransferRoots() > 0) {
            const TopoDS_Shape shape = plain.OneShape();
            if (!shape.IsNull()) top.push_back(shape);
        }
        colours.Nullify();
    }
    if (top.empty()) return die(std::string(in) + ": the STEP file holds no shape Open CASCADE can transfer");

    geom::PackWriter writer;
    writer.set_source_unit_mm(unit_mm(reader));
    packer::Stats stats;
    packer::Packer packer(writer, colours, stats);
    progress("healing and packing");
    uint32_t count = 0;
    for (const TopoDS_Shape& root : top) {
        std::vector<std::pair<TopoDS_Shape, bool>> parts;
        for (TopExp_Explorer x(root, TopAbs_SOLID); x.More(); x.Next()) parts.push_back({x.Current(), true});
        for (TopExp_Explorer x(root, TopAbs_SHELL, TopAbs_SOLID); x.More(); x.Next()) parts.push_back({x.Current(), false});
        for (TopExp_Explorer x(root, TopAbs_FACE, TopAbs_SHELL); x.More(); x.Next()) parts.push_back({x.Current(), false});
        for (auto& [shape, closed] : parts) {
            TopoDS_Shape healed = shape;
            try {
                ShapeFix_Shape fix(shape);
                fix.Perform();
                healed = fix.Shape();
                healed.Location(shape.Location()); // keep the occurrence's placement
            } catch (...) {
                healed = shape;
            }
            try {
                packer.add_occurrence(healed, closed);
            } catch (const Standard_Failure& f) {
                return die(std::string(in) + ": Open CASCADE failed on a part: " + f.GetMessageString());
            }
            if (!quiet && ++count % 50 == 0) std::fprintf(stderr, "facet-pack: %u parts\n", count);
        }
    }
    if (stats.faces == 0) {
        return die(std::string(in) + ": no face could be packed" +
                   (stats.first_problem.empty() ? "" : " (" + stats.first_problem + ")"));
    }
    const std::vector<uint8_t> bytes = writer.finish();
    std::ofstream o(out, std::ios::binary);
    if (!o.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()))) {
        return die(std::string("cannot write ") + out);
    }
    std::string types;
    for (auto& [k, v] : stats.surface_types) types += (types.empty() ? "" : ", ") + std::to_string(v) + " " + k;
    std::printf("%s: %u solids, %u open shells, %u instances, %u faces (%s), %u edges", in, stats.solids, stats.shells,
                stats.instances, stats.faces, types.c_str(), stats.edges);
    if (stats.faces_skipped) std::printf(", %u faces skipped (%s)", stats.faces_skipped, stats.first_problem.c_str());
    std::printf("\n  pack %zu bytes = %.1f%% of the STEP file (%lld bytes)\n", bytes.size(),
                100.0 * double(bytes.size()) / double(st.st_size), (long long)st.st_size);
    for (auto& [k, v] : stats.converted) std::printf("  converted: %u %s\n", v, k.c_str());
    return 0;
}
