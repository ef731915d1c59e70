// facet-pack: STEP (AP203/AP214/AP242) -> facet pack, with Open CASCADE.
//
//   facet-pack model.step -o model.fpk [--plain]   pack (deflated unless --plain), print a summary
//   facet-pack --check model.fpk                   validate a pack file with the device's code
//
// Reads with the XCAF reader (units converted to mm, assemblies, colours from styled items),
// heals each solid and shell with ShapeFix, and writes every face's exact surface, its loops
// of edges with their 3D curves and pcurves, and the colours. Exits non-zero with a clear
// message on unreadable or empty input.
#include "geom/pack.h"
#include "hal/print.h"
#include "occt_to_pack.h"
#include "pack_io.h"
#include "pack_writer.h"
#include "step_reader.h"

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
    std::fprintf(stderr, "usage: facet-pack MODEL.step -o MODEL.fpk [--plain] [--quiet]\n       facet-pack --check MODEL.fpk\n");
    return 2;
}

int die(const std::string& msg) {
    std::fprintf(stderr, "facet-pack: error: %s\n", msg.c_str());
    return 1;
}

int check(const char* path) {
    geom::LoadedPack file;
    std::string error;
    if (!geom::load_pack_file(path, file, error)) return die(std::string(path) + ": " + error);
    geom::Pack pack;
    if (const Result r = pack.open(file.data(), file.bytes); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        return die(std::string(path) + ": " + text);
    }
    std::printf("%s: valid pack, %zu faces, %zu edges, %zu shells, %zu instances, %u bytes", path, pack.faces().size(),
                pack.edges().size(), pack.shells().size(), pack.instances().size(), file.bytes);
    if (file.deflated) std::printf(" (deflated file: %u bytes)", file.file_bytes);
    std::printf("\n");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const char *in = nullptr, *out = nullptr;
    bool quiet = false, plain = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--check") && i + 1 < argc) return check(argv[i + 1]);
        if (!std::strcmp(argv[i], "-o") && i + 1 < argc) out = argv[++i];
        else if (!std::strcmp(argv[i], "--quiet")) quiet = true;
        else if (!std::strcmp(argv[i], "--plain")) plain = true;
        else if (argv[i][0] == '-') return usage();
        else in = argv[i];
    }
    if (!in || !out) return usage();
    struct stat st {};
    if (stat(in, &st) != 0) return die(std::string("cannot read ") + in);
    // OCCT's own trace messages are noise for a command-line user; keep warnings and worse.
    for (auto& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);

    packer::StepModel model;
    std::string error;
    if (!packer::read_step(in, model, error, quiet)) return die(error);
    geom::PackWriter writer;
    writer.set_source_unit_mm(model.unit_mm);
    packer::Stats stats;
    packer::Packer packer(writer, model.colours, stats);
    uint32_t count = 0;
    for (const packer::Part& part : model.parts) {
        try {
            packer.add_occurrence(part.shape, part.closed);
        } catch (const Standard_Failure& f) {
            return die(std::string(in) + ": Open CASCADE failed on a part: " + f.GetMessageString());
        }
        if (!quiet && ++count % 50 == 0) std::fprintf(stderr, "facet-pack: %u parts\n", count);
    }
    if (stats.faces == 0) {
        return die(std::string(in) + ": no face could be packed" +
                   (stats.first_problem.empty() ? "" : " (" + stats.first_problem + ")"));
    }
    const std::vector<uint8_t> pack = writer.finish();
    const std::vector<uint8_t> bytes = plain ? pack : geom::deflate_pack(pack);
    if (bytes.empty()) return die("zlib could not deflate the pack");
    std::ofstream o(out, std::ios::binary);
    if (!o.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()))) {
        return die(std::string("cannot write ") + out);
    }
    std::string types;
    for (auto& [k, v] : stats.surface_types) types += (types.empty() ? "" : ", ") + std::to_string(v) + " " + k;
    std::printf("%s: %u solids, %u open shells, %u instances, %u faces (%s), %u edges", in, stats.solids, stats.shells,
                stats.instances, stats.faces, types.c_str(), stats.edges);
    if (stats.faces_skipped) std::printf(", %u faces skipped (%s)", stats.faces_skipped, stats.first_problem.c_str());
    std::printf("\n  pack %zu bytes = %.1f%% of the STEP file (%lld bytes)", bytes.size(),
                100.0 * double(bytes.size()) / double(st.st_size), (long long)st.st_size);
    if (!plain) std::printf("; %zu bytes inflated", pack.size());
    std::printf("\n");
    for (auto& [k, v] : stats.converted) std::printf("  converted: %u %s\n", v, k.c_str());
    if (model.open_solids) {
        std::printf("  %u solids have gaps between their faces that healing could not close: packed as open shells\n",
                    model.open_solids);
    }
    return 0;
}
