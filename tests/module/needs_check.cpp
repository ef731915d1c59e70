// facet::model_needs() keeps its word (issue 49), on real models: each pack loaded into a viewer
// whose workspace is exactly what model_needs() says.
//   * At least_workspace_bytes: every face shows at some level of detail (up to 16 times the
//     default tolerance): load() takes the model, no part is left out as a box, no level of
//     detail fails (PassFailed) and no face either, every face is meshed (none left wireframe
//     for want of room), and the viewer comes to rest.
//   * At workspace_bytes ("room to refine"): the same, and every face reaches the default
//     level of detail (the first pass's tolerance is the model's default, no face is left
//     wireframe for want of room).
// The pack memory is pack_memory_bytes (aligned), given apart; then the same again with none
// given and the workspace larger by it (load() then takes it from the workspace's end).
//
//   facet-needs-check PACK_OR_DIR...     exit 1 if a model is short of what it was promised
#include "core/format.h"
#include "facet/viewer.h"
#include "file_io.h"
#include "geom/pack.h"
#include "pack_io.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using namespace facet;

namespace {

constexpr uint16_t kW = 160, kH = 120;

struct Run {
    std::string why; // empty: kept its word
    Stats stats{};
};

void flush(Viewer&, void*, const Area&, const Rgb565*) {}

Run run_at(const std::vector<uint8_t>& file, size_t workspace_bytes, uint32_t pack_memory_bytes, bool refined) {
    Run out;
    static std::vector<Rgb565> buffer(size_t(kW) * kH);
    static std::vector<uint16_t> depth(size_t(kW) * kH);
    struct Log {
        std::string failed;
    } log;
    Config cfg;
    cfg.display.width = kW, cfg.display.height = kH, cfg.display.band_lines = kH;
    cfg.display.buffers[0] = buffer.data(), cfg.display.depth[0] = depth.data();
    cfg.display.flush = flush;
    cfg.interface = Interface::Off;
    cfg.screen_error_px = 0; // every face at the level's tolerance, however small it is on the screen (the most it takes)
    cfg.on_event = [](void* user, const Event& e) {
        auto& l = *static_cast<Log*>(user);
        if ((e.kind == Event::Kind::PassFailed || e.kind == Event::Kind::ModelFailed || e.kind == Event::Kind::FaceFailed) &&
            l.failed.empty()) {
            char text[200];
            describe(e.why, text, sizeof text);
            l.failed = std::string(e.kind == Event::Kind::PassFailed ? "PassFailed: " : e.kind == Event::Kind::FaceFailed ? "FaceFailed: " : "ModelFailed: ") + text;
        }
    };
    cfg.event_user = &log;
    std::vector<uint64_t> workspace(workspace_bytes / 8);
    std::vector<uint64_t> file_words(file.size() / 8 + 1);
    std::memcpy(file_words.data(), file.data(), file.size());
    std::vector<uint64_t> memory(pack_memory_bytes / 8 + 1);
    Result why;
    Viewer* v = Viewer::create(cfg, workspace.data(), workspace.size() * 8, &why);
    if (!v) {
        char text[200];
        describe(why, text, sizeof text);
        out.why = std::string("create: ") + text;
        return out;
    }
    const Result r = v->load(file_words.data(), uint32_t(file.size()), pack_memory_bytes ? memory.data() : nullptr, pack_memory_bytes);
    if (!r.ok()) {
        char text[200];
        describe(r, text, sizeof text);
        out.why = std::string("load: ") + text;
        return out;
    }
    int steps = 0;
    for (; steps < 2000000; ++steps) {
        v->flush_done();
        if (v->step(100000) == Activity::Idle) break;
    }
    out.stats = v->stats();
    const ModelInfo m = v->model();
    if (!log.failed.empty()) out.why = log.failed;
    else if (m.boxed_parts) out.why = std::to_string(m.boxed_parts) + " of " + std::to_string(m.parts) + " parts left out as boxes";
    else if (out.stats.done == 0) out.why = "no face drawn";
    else if (out.stats.done + out.stats.deferred < out.stats.faces) {
        out.why = std::to_string(out.stats.faces - out.stats.done - out.stats.deferred) + " faces not meshed";
    } else if (refined && !(v->detail() == 1.0f)) {
        out.why = "the first level " + std::to_string(v->detail()) + " times the default tolerance";
    }
    return out;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path p = argv[i];
        if (std::filesystem::is_directory(p)) {
            for (const auto& e : std::filesystem::directory_iterator(p))
                if (e.path().extension() == ".fpk") files.push_back(e.path().string());
        } else {
            files.push_back(p.string());
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: facet-needs-check PACK_OR_DIR...\n");
        return 2;
    }
    std::sort(files.begin(), files.end());
    int bad = 0;
    for (const std::string& f : files) {
        std::vector<uint8_t> bytes;
        std::string error;
        if (!host::read_file(f, 1u << 30, bytes, error)) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 1;
        }
        std::vector<uint64_t> words(bytes.size() / 8 + 1);
        std::memcpy(words.data(), bytes.data(), bytes.size());
        ModelNeeds n;
        if (const Result r = model_needs(words.data(), uint32_t(bytes.size()), n); !r.ok()) {
            char text[200];
            describe(r, text, sizeof text);
            std::printf("FAIL %s: model_needs refused it: %s\n", f.c_str(), text);
            ++bad;
            continue;
        }
        {
            // (facet-pack measures every pack it writes: a pack without it was sized from estimates)
            geom::LoadedPack loaded;
            geom::Pack pack;
            std::string error;
            if (!geom::load_pack_bytes(bytes, loaded, error) || !pack.open(loaded.data(), loaded.bytes).ok() || !pack.needs()) {
                std::printf("FAIL %s: no measure of what it takes on a device (pack::Needs)\n", f.c_str());
                ++bad;
                continue;
            }
        }
        // The pack memory given apart, and taken from the workspace's end (the workspace that
        // much larger, none given).
        const std::string name = std::filesystem::path(f).filename().string();
        for (const bool apart : {true, false}) {
            const uint32_t memory = apart ? n.pack_memory_bytes : 0;
            const size_t more = apart ? 0 : (n.pack_memory_bytes + 7) / 8 * 8;
            const Run least = run_at(bytes, n.least_workspace_bytes + more, memory, false);
            const Run room = run_at(bytes, n.workspace_bytes + more, memory, true);
            std::printf("%s%s: least %zu bytes: %s; room to refine %zu bytes: %s\n", name.c_str(),
                        apart ? "" : " (pack memory at the workspace's end)", n.least_workspace_bytes + more,
                        least.why.empty() ? "every part shows" : least.why.c_str(), n.workspace_bytes + more,
                        room.why.empty() ? "every face at the default detail" : room.why.c_str());
            bad += !least.why.empty() || !room.why.empty();
        }
    }
    return bad ? 1 : 0;
}
