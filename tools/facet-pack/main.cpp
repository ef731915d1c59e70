// facet-pack: STEP (AP203/AP214/AP242) -> facet pack, with Open CASCADE.
//
//   facet-pack model.step -o model.fpk [--plain|--deflate|--lzma] [--whole] [--unit U] [--partial] [--quiet]
//                                                  pack, print a summary
//   facet-pack --check model.fpk                   validate a pack file (or a library) with the device's code
//   facet-pack --annotations model.fpk             its annotations (PMI) as JSON lines
//   facet-pack --library OUT.flb A.fpk B.fpk ...   several packs in one file, for a device's flash
//
// The pack is blocked (pack_format.h): an index the device reads first (parts with their boxes,
// instances, names), then blocks of about 64 KB decoded, each the pack of a few parts (a larger
// part alone), compressed: with LZMA when the model decodes to at most kLzmaUpTo (1 MiB: the
// smallest file, as every shared model), with DEFLATE above (about a third of LZMA's decoding
// work on the device, 90 instructions a byte against 30 on the ARM926, for a file about 1.6
// times larger: a large assembly's first view waits for its blocks). --lzma, --deflate choose;
// --plain: as they are, read in place from flash. --whole writes the whole pack as one (FPX1,
// FPZ1 or FPK1), as before blocks.
//
// Reads with the XCAF reader (units converted to mm, assemblies, colours from styled items),
// heals each solid and shell with ShapeFix, and writes every face's exact surface, its loops
// of edges with their 3D curves and pcurves, and the colours. Exits non-zero with a clear
// message on unreadable or empty input, and when a face of the file is lost on the way
// (a reference to nothing, a face Open CASCADE cannot make) unless --partial says to pack the
// rest. --unit: the length unit of a file that gives none (default: guessed from its size).
// Exit codes: 0 packed (or valid), 1 error (the reason on stderr; no file left behind), 2 usage.
#include "geom/library.h"
#include "geom/pack.h"
#include "geom/pmi.h"
#include "geom/tree.h"
#include "core/format.h"
#include "file_io.h"
#include "occt_to_pack.h"
#include "reference.h"
#include "assembly_tree.h"
#include "pack_blocks.h"
#include "proxies.h"
#include "pack_io.h"
#include "geom/pack_index.h"
#include "facet/viewer.h"
#include "needs.h"
#include "pack_writer.h"
#include "pmi_report.h"
#include "printable.h"
#include "step_reader.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <OSD.hxx>
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

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <csignal>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

using namespace facet;

namespace {

constexpr size_t kLzmaUpTo = 1u << 20; // decoded bytes a pack is LZMA-compressed up to (above: DEFLATE)
constexpr uint32_t kProxyLevels[] = {12, 48, 192, 768}; // the most triangles a part's proxy has at each level (geom/host/proxies.h)
constexpr uint32_t kGroupLevels[] = {48, 192};          // a group's proxy's, for its (at most 16) parts (geom/host/groups.h)

int usage() {
    std::fprintf(stderr, "usage: facet-pack MODEL.step -o MODEL.fpk [--plain|--deflate|--lzma] [--whole] [--unit mm|cm|m|in|ft] [--partial] [--reference FACES.json] [--quiet]\n"
                         "       facet-pack --check MODEL.fpk|LIBRARY.flb\n"
                         "       facet-pack --annotations MODEL.fpk\n"
                         "       facet-pack --library OUT.flb A.fpk B.fpk ... [--quiet]\n");
    return 2;
}

int die(const std::string& msg) {
    std::fprintf(stderr, "facet-pack: error: %s\n", msg.c_str());
    return 1;
}

// A library: its table, then each model checked as a pack file of its own (all of them).
int check_library(const char* path, const std::vector<uint8_t>& bytes) {
    std::vector<uint64_t> aligned((bytes.size() + 7) / 8);
    std::memcpy(aligned.data(), bytes.data(), bytes.size());
    geom::Library lib;
    if (const Result r = lib.open(aligned.data(), uint32_t(bytes.size())); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        return die(std::string(path) + ": " + text);
    }
    std::printf("%s: library of %u models, %u bytes\n", path, lib.count(), lib.bytes());
    int bad = 0;
    for (uint32_t i = 0; i < lib.count(); ++i) {
        const geom::Library::Entry e = lib.entry(i);
        geom::LoadedPack loaded;
        geom::Pack pack;
        std::string error;
        const bool ok = geom::load_pack_bytes({e.file, e.file + e.bytes}, loaded, error) &&
                        (pack.open(loaded.data(), loaded.bytes).ok() || (error = "not a sound pack", false));
        std::printf("  %u \"%s\": %u bytes, %s\n", i + 1, packer::printable(e.name).c_str(), e.bytes, ok ? "valid" : error.c_str());
        bad += !ok;
    }
    return bad ? die(std::to_string(bad) + " of the library's models are not sound (the others open)") : 0;
}

int library(int argc, char** argv) {
    const char* out = nullptr;
    bool quiet = false;
    std::vector<std::vector<uint8_t>> files;
    std::string error;
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quiet")) quiet = true;
        else if (argv[i][0] == '-') return usage();
        else if (!out) out = argv[i];
        else {
            files.emplace_back();
            if (!host::read_file(argv[i], pack::kMaxBlockedBytes, files.back(), error)) return die(error);
        }
    }
    if (!out || files.empty()) return usage();
    for (int i = 3; i < argc; ++i) {
        if (argv[i][0] != '-' && host::same_file(argv[i], out)) return die(std::string(out) + " is one of the packs: it would be overwritten");
    }
    std::vector<uint8_t> bytes;
    if (!geom::make_library(files, bytes, error) || !host::write_file(out, bytes.data(), bytes.size(), error)) return die(error);
    if (!quiet) std::printf("%s: library of %zu models, %zu bytes\n", out, files.size(), bytes.size());
    return 0;
}

// What the model takes on a device: the packer's measure (pack::Needs) and the workspace
// facet::model_needs() says from it.
void print_device_needs(const std::vector<uint8_t>& bytes, const geom::Pack& pack) {
    if (const pack::Needs* n = pack.needs()) {
        const float* lo = pack.header().bbox_min, *hi = pack.header().bbox_max;
        const float diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
        std::printf("  on a device: at 0.1%% of the diagonal (%.4g mm), %u edge samples, %u mesh vertices, %u triangles; at %g times it, %u, %u, %u\n",
                    1e-3f * diagonal, n->samples, n->mesh_vertices, n->mesh_triangles, pack::kCoarsestFirst, n->coarse_samples,
                    n->coarse_vertices, n->coarse_triangles);
    } else {
        std::printf("  on a device: not measured (a pack of an older facet-pack): the workspace is estimated\n");
    }
    std::vector<uint64_t> words(bytes.size() / 8 + 1);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    ModelNeeds needs;
    if (const Result r = model_needs(words.data(), uint32_t(bytes.size()), needs); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        std::printf("  facet::model_needs refuses it: %s\n", text);
        return;
    }
    std::printf("  workspace: %zu bytes for the default detail, %zu at least; pack memory %u bytes\n", needs.workspace_bytes,
                needs.least_workspace_bytes, needs.pack_memory_bytes);
}

int check(const char* path) {
    geom::LoadedPack file;
    std::string error;
    std::vector<uint8_t> bytes;
    if (!host::read_file(path, pack::kMaxBlockedBytes, bytes, error)) return die(error);
    if (geom::is_library(bytes.data(), uint32_t(bytes.size()))) return check_library(path, bytes);
    if (!geom::load_pack_file(path, file, error)) return die(error);
    geom::Pack pack;
    if (const Result r = pack.open(file.data(), file.bytes); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        return die(std::string(path) + ": " + text);
    }
    geom::Annotations pmi;
    if (const Result r = pmi.open(pack); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        return die(std::string(path) + ": " + text);
    }
    std::printf("%s: valid pack, %zu faces, %zu edges, %zu shells, %zu instances, %u bytes", path, pack.faces().size(),
                pack.edges().size(), pack.shells().size(), pack.instances().size(), file.bytes);
    if (geom::compressed(file.kind)) {
        std::printf(" (%s file: %u bytes)", file.kind == geom::PackFileKind::Lzma ? "LZMA" : "deflated", file.file_bytes);
    }
    std::printf("\n  model \"%s\"\n", packer::printable(pack.model_name()).c_str());
    print_device_needs(bytes, pack);
    // The parts list the viewer shows: each instance, its part's name and its own.
    for (uint32_t i = 0; i < pack.instances().size(); ++i) {
        const uint32_t s = pack.instances()[i].shell;
        std::printf("  instance %u: shell %u \"%s\"", i, s, packer::printable(pack.shell_name(s)).c_str());
        if (*pack.instance_name(i)) std::printf(" as \"%s\"", packer::printable(pack.instance_name(i)).c_str());
        std::printf("\n");
    }
    // The assembly tree: each sub-assembly, indented by its depth, with its instances.
    geom::ProductTree tree;
    if (const Result r = tree.open(pack); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        return die(std::string(path) + ": " + text);
    }
    for (uint32_t n = 0; n < tree.count(); ++n) {
        std::printf("  %*snode %u \"%s\"", int(2 * tree.depth(n)), "", n, packer::printable(tree.name(n)).c_str());
        if (*tree.occurrence(n)) std::printf(" as \"%s\"", packer::printable(tree.occurrence(n)).c_str());
        std::printf(": instances %u-%u\n", tree[n].first_instance, tree[n].first_instance + tree[n].instance_count - 1);
    }
    // The annotations (PMI): each one's kind, text and faces.
    for (uint32_t i = 0; i < pmi.count(); ++i) {
        const pack::Annotation& a = pmi[i];
        std::printf("  annotation %u: %s%s \"%s\"", i, geom::annotation_kind_name(pack::AnnotationKind(a.kind)),
                    a.flags & pack::kSemantic ? "" : " (presentation)", packer::printable(pmi.text(i)).c_str());
        if (a.face_count) {
            std::printf(" on face%s", a.face_count == 1 ? "" : "s");
            for (uint32_t f : pmi.faces(i)) std::printf(" %u", f);
        }
        if (a.drawn_by != pack::kNoIndex) std::printf(", drawn as %u", a.drawn_by);
        else if (a.polyline_count) std::printf(", %u polylines", a.polyline_count);
        std::printf("\n");
    }
    return 0;
}

int run(int argc, char** argv) {
    const char *in = nullptr, *out = nullptr, *reference = nullptr;
    bool quiet = false, plain = false, deflated = false, lzma = false, partial = false, whole = false;
    packer::UnitGuess unit = packer::UnitGuess::BySize;
    if (argc > 1 && !std::strcmp(argv[1], "--library")) return library(argc, argv);
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--check") && i + 1 < argc) return argc == 3 ? check(argv[i + 1]) : usage();
        if (!std::strcmp(argv[i], "--annotations") && i + 1 < argc) {
            if (argc != 3) return usage();
            std::string error;
            return packer::print_annotations(argv[i + 1], error) ? die(error) : 0;
        }
        if (!std::strcmp(argv[i], "-o") && i + 1 < argc && !out) out = argv[++i];
        else if (!std::strcmp(argv[i], "--quiet")) quiet = true;
        else if (!std::strcmp(argv[i], "--plain")) plain = true;
        else if (!std::strcmp(argv[i], "--deflate")) deflated = true;
        else if (!std::strcmp(argv[i], "--lzma")) lzma = true;
        else if (!std::strcmp(argv[i], "--partial")) partial = true;
        else if (!std::strcmp(argv[i], "--whole")) whole = true;
        else if (!std::strcmp(argv[i], "--blocked")) whole = false;
        else if (!std::strcmp(argv[i], "--reference") && i + 1 < argc && !reference) reference = argv[++i];
        else if (!std::strcmp(argv[i], "--unit") && i + 1 < argc) {
            if (!packer::parse_unit(argv[++i], unit)) {
                std::fprintf(stderr, "facet-pack: error: --unit %s: one of mm, cm, m, in, ft\n", argv[i]);
                return 2;
            }
        } else if (argv[i][0] == '-' || in) return usage();
        else in = argv[i];
    }
    if (!in || !out || int(plain) + int(deflated) + int(lzma) > 1) return usage();
    struct stat st {};
    if (stat(in, &st) != 0) return die(std::string("cannot read ") + in + ": " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) return die(std::string(in) + " is a directory, not a STEP file");
    if (!S_ISREG(st.st_mode)) return die(std::string(in) + " is not a regular file");
    if (host::same_file(in, out)) return die(std::string("-o ") + out + " is the STEP file itself: it would be overwritten");
    {
        // Say so now, not after minutes of reading: the folder the pack goes in must exist.
        std::string dir = out;
        const size_t slash = dir.find_last_of('/');
        dir = slash == std::string::npos ? "." : slash == 0 ? "/" : dir.substr(0, slash);
        struct stat ds {};
        if (stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode)) return die(std::string("cannot write ") + out + ": no folder " + dir);
        struct stat os {};
        if (stat(out, &os) == 0 && S_ISDIR(os.st_mode)) return die(std::string("cannot write ") + out + ": it is a folder");
    }
    // A file Open CASCADE cannot finish (its healing can loop on a shape no file should hold)
    // ends the run with a message, not a hang: two minutes, and a second more for every 8 KB of
    // the file (the largest shared model, 3.4 MB, packs in 15 s).
    const unsigned limit = unsigned(120 + st.st_size / 8192);
    {
        static char message[300];
        std::snprintf(message, sizeof message, "facet-pack: error: %s: Open CASCADE did not finish with this file within %u s\n", in, limit);
        struct sigaction sa {};
        sa.sa_handler = [](int) {
            (void)!write(2, message, std::strlen(message));
            _exit(1);
        };
        sigaction(SIGALRM, &sa, nullptr);
        alarm(limit);
    }
    // OCCT's own trace messages are noise for a command-line user; keep warnings and worse.
    for (auto& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
    // A malformed file can send Open CASCADE's readers through a null reference (a dangling
    // #id, an entity that refers to itself): signals become its exceptions, caught where it
    // transfers each entity (that entity fails, the rest is read) and here (exit 1, not a crash).
    OSD::SetSignal(false);

    packer::StepModel model;
    std::string error;
    if (!packer::read_step(in, model, error, quiet, unit)) return die(error);
    if (!model.lost.empty() || !model.failed.empty()) {
        auto list = [](std::string& why, const std::vector<std::string>& items) {
            for (size_t k = 0; k < items.size() && k < 3; ++k) why += "\n  " + packer::printable(items[k]);
            if (items.size() > 3) why += "\n  (and " + std::to_string(items.size() - 3) + " more)";
        };
        std::string why;
        if (!model.lost.empty()) {
            why = std::to_string(model.lost.size()) + " of " + std::to_string(model.face_entities) + " faces in the STEP file could not be read";
            list(why, model.lost);
        }
        if (!model.failed.empty()) {
            why += std::string(why.empty() ? "" : "\n  ") + "Open CASCADE could not translate parts of the STEP file (what they hold is lost):";
            list(why, model.failed);
        }
        if (!partial) return die(std::string(in) + ": " + why + "\n  --partial packs the faces that could be read");
        std::fprintf(stderr, "facet-pack: warning: %s: %s\n", in, why.c_str());
    }
    geom::PackWriter writer;
    writer.set_source_unit_mm(model.unit_mm);
    writer.set_model_name(model.name);
    packer::Stats stats;
    packer::Packer packer(writer, model.colours, stats);
    uint32_t count = 0;
    std::vector<uint32_t> instance_nodes; // each instance's node of the assembly tree
    for (const packer::Part& part : model.parts) {
        try {
            const uint32_t before = stats.instances;
            packer.add_occurrence(part.shape, part.closed, part.name, part.instance);
            if (stats.instances > before) instance_nodes.push_back(part.node);
        } catch (const Standard_Failure& f) {
            return die(std::string(in) + ": Open CASCADE failed on a part: " + f.GetMessageString());
        }
        if (!quiet && (++count % 50 == 0 || count == model.parts.size())) {
            packer::progress(("packed " + std::to_string(count) + " of " + std::to_string(model.parts.size()) + " parts (" +
                      std::to_string(stats.faces) + " faces)").c_str());
        }
    }
    if (stats.faces == 0) {
        return die(std::string(in) + ": no face could be packed" +
                   (stats.first_problem.empty() ? "" : " (" + stats.first_problem + ")"));
    }
    if (stats.faces_skipped) { // a face lost is a failure, whatever the pack's form, unless asked for
        std::string why = std::to_string(stats.faces_skipped) + " of " + std::to_string(stats.faces + stats.faces_skipped) +
                          " faces could not be packed (" + stats.first_problem + ")";
        if (stats.empty_parts) why += "; " + std::to_string(stats.empty_parts) + " parts lost every face and are left out";
        if (!partial) return die(std::string(in) + ": " + why + "\n  --partial packs the faces that could be");
        std::fprintf(stderr, "facet-pack: warning: %s: %s\n", in, why.c_str());
    }
    std::vector<uint8_t> pack = writer.finish();
    uint32_t faces_missed = 0;
    if (!model.nodes.empty() && !instance_nodes.empty()) { // the assembly tree, over the instances as packed
        geom::Pack opened;
        if (const Result r = opened.open(pack.data(), uint32_t(pack.size())); !r.ok()) return die("the pack written does not read back");
        if (!packer::set_tree(model.nodes, instance_nodes, opened, packer::part_boxes(packer.prototypes), writer, error)) return die(error);
        pack = writer.finish();
    }
    if (!model.pmi.notes.empty()) {
        // The annotations' faces found among those packed (the pack as written so far).
        geom::Pack opened;
        if (const Result r = opened.open(pack.data(), uint32_t(pack.size())); !r.ok()) return die("the pack written does not read back");
        writer.set_annotations(packer::pmi_tables(model.pmi, opened, packer.packed_faces, faces_missed));
        if (faces_missed) {
            const std::string why = std::to_string(faces_missed) + " faces the PMI applies to are not among the packed faces";
            if (!partial) return die(std::string(in) + ": " + why + "\n  --partial packs the annotations without them");
            std::fprintf(stderr, "facet-pack: warning: %s: %s\n", in, why.c_str());
        }
        pack = writer.finish();
    }
    {
        // What it takes on a device, measured with the module's own code (facet::model_needs()
        // reads it from the pack's head).
        if (!quiet) packer::progress("measuring what the model takes on a device");
        pack::Needs needs;
        if (!packer::measure_needs(pack, needs, error)) return die(std::string(in) + ": " + error);
        writer.set_needs(needs);
        pack = writer.finish();
    }
    if (!quiet) packer::progress(plain ? "writing" : "compressing");
    if (!plain && !deflated && !lzma) deflated = pack.size() > kLzmaUpTo; // a large model: decoded faster
    std::vector<uint8_t> bytes;
    uint32_t blocks = 0;
    if (!whole) {
        geom::Pack opened;
        if (const Result r = opened.open(pack.data(), uint32_t(pack.size())); !r.ok()) {
            char text[160];
            describe(r, text, sizeof text);
            return die(std::string("the pack written does not read back: ") + text);
        }
        geom::BlockOptions options;
        options.store = plain ? geom::BlockStore::Plain : deflated ? geom::BlockStore::Deflated : geom::BlockStore::Lzma;
        // Each part's proxies in the index, drawn where the view shows it small
        // (geom/host/proxies.h), where they may pay their bytes: a model whose mesh at the
        // default level, every instance's (the parts' mean), passes the fewest triangles a
        // screen bounds a view to, so a view of it can be crowded.
        std::vector<geom::Proxy> proxies;
        const pack::Needs* needs = opened.needs();
        const size_t parts = std::max<size_t>(opened.shells().size(), 1);
        if (!needs || uint64_t(needs->mesh_triangles) * opened.instances().size() / parts > pack::kLeastTriangleBound) {
            if (!quiet) packer::progress("making the parts' proxies");
            if (!geom::make_proxies(opened, kProxyLevels, proxies, error)) return die(error);
            options.proxies = &proxies;
            options.group_caps = kGroupLevels;
        }
        if (!geom::make_blocked(opened, packer::part_boxes(packer.prototypes), options, bytes, error)) return die(error);
        geom::PackIndex index;
        if (const Result r = index.open(bytes.data(), uint32_t(bytes.size())); !r.ok()) {
            char text[160];
            describe(r, text, sizeof text);
            return die(std::string("the blocked pack made does not open: ") + text);
        }
        blocks = uint32_t(index.blocks().size());
        if (blocks == 1) whole = true; // one block: the whole pack as it is, without an index

    }
    if (whole) {
        bytes = plain ? pack : (deflated ? geom::deflate_pack(pack) : geom::lzma_pack(pack));
        if (bytes.empty()) return die(deflated ? "zlib could not deflate the pack" : "liblzma could not compress the pack");
    }
    {
        // Read back as --check and the device would, before it is written: a pack that does not
        // open, or holds less than was packed, is no pack.
        geom::LoadedPack back;
        geom::Pack opened;
        if (!geom::load_pack_bytes(bytes, back, error)) return die("the pack made does not read back: " + error);
        if (const Result r = opened.open(back.data(), back.bytes); !r.ok()) {
            char text[160];
            describe(r, text, sizeof text);
            return die(std::string("the pack made does not open: ") + text);
        }
        if (opened.faces().size() != stats.faces || opened.instances().size() != stats.instances) {
            return die("the pack made holds " + std::to_string(opened.faces().size()) + " faces and " +
                       std::to_string(opened.instances().size()) + " instances, not the " + std::to_string(stats.faces) + " and " +
                       std::to_string(stats.instances) + " packed");
        }
    }
    if (!host::write_file(out, bytes.data(), bytes.size(), error)) return die(error);
    if (reference && !host::write_file(reference, packer::reference_json(packer.packed_faces, model.unit_mm), error)) return die(error);
    std::string types;
    for (auto& [k, v] : stats.surface_types) types += (types.empty() ? "" : ", ") + std::to_string(v) + " " + k;
    std::printf("%s: %u solids, %u open shells, %u instances, %u faces (%s), %u edges (%u tangent)", in, stats.solids, stats.shells,
                stats.instances, stats.faces, types.c_str(), stats.edges, stats.smooth_edges);
    if (stats.faces_skipped) std::printf(", %u faces skipped (%s)", stats.faces_skipped, stats.first_problem.c_str());
    if (stats.empty_parts) std::printf(", %u parts left out (no face of theirs packed)", stats.empty_parts);
    std::printf("\n  pack %zu bytes = %.1f%% of the STEP file (%lld bytes)", bytes.size(),
                100.0 * double(bytes.size()) / double(st.st_size), (long long)st.st_size);
    if (!plain || !whole) std::printf("; %zu bytes decoded", pack.size());
    if (!plain) std::printf(", %s", deflated ? "DEFLATE" : "LZMA");
    if (!whole) std::printf(" in %u block%s", blocks, blocks == 1 ? "" : "s");
    std::printf("\n");
    for (auto& [k, v] : stats.converted) std::printf("  converted: %u %s\n", v, k.c_str());
    if (const packer::Pmi& p = model.pmi; !p.notes.empty()) {
        const geom::AnnotationTables& a = writer.annotations();
        const size_t drawn = size_t(std::count_if(a.records.begin(), a.records.end(), [](const pack::Annotation& r) { return r.drawn_by == pack::kNoIndex && r.polyline_count; }));
        std::printf("  PMI: %u dimensions, %u geometric tolerances, %u datums: %zu annotations (%zu presentations, %zu polylines), on %zu faces\n",
                    p.dimensions, p.tolerances, p.datums, a.records.size(), drawn, a.polylines.size(), a.faces.size());
    }
    for (size_t a = 0, b; a < model.notes.size(); a = b + 1) {
        b = model.notes.find('\n', a);
        if (b == std::string::npos) b = model.notes.size();
        std::printf("  %s\n", model.notes.substr(a, b - a).c_str());
    }
    if (model.open_solids) {
        std::printf("  %u solids have gaps between their faces that healing could not close: packed as open shells\n",
                    model.open_solids);
    }
    return 0;
}

} // namespace

// Open CASCADE throws where a broken file leads its reader or its healing astray (an index past
// a list's end, a curve it cannot build): most of it is caught part by part, and what escapes
// ends here, with its reason and nothing written (the pack is written last).
int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const Standard_Failure& f) {
        return die(std::string("Open CASCADE failed on the file (") + f.DynamicType()->Name() + ": " +
                   packer::printable(f.GetMessageString()) + "); nothing written");
    } catch (const std::bad_alloc&) {
        return die("out of memory");
    } catch (const std::exception& e) {
        return die(std::string("failed: ") + e.what());
    }
}
