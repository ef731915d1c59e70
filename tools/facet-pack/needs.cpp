#include "needs.h"

#include "core/format.h"
#include "facet/viewer.h"

#include <algorithm>
#include <cstring>

namespace facet::packer {
namespace {

// A level of detail as the viewer made it.
struct Level {
    uint32_t samples = 0, vertices = 0, triangles = 0;
    bool short_of_room = false; // a pass found the workspace full, or faces found no room for their mesh
    std::string failed;         // why a pass or the model failed otherwise
};

void no_flush(facet::Viewer&, void*, const Area&, const Rgb565*) {}

void on_event(void* user, const Event& e) {
    auto& level = *static_cast<Level*>(user);
    switch (e.kind) {
    case Event::Kind::Sampled: level.samples = e.pass.samples; break;
    case Event::Kind::PassFailed:
    case Event::Kind::ModelFailed: // (a face that fails is the face's: its CDT, not the workspace)
        if (e.why.status == Status::Full) {
            level.short_of_room = true;
        } else if (level.failed.empty()) {
            char text[200];
            describe(e.why, text, sizeof text);
            level.failed = text;
        }
        break;
    default: break;
    }
}

// Runs the viewer to rest at `factor` times the default tolerance in a workspace of `bytes`.
bool measure_at(const std::vector<uint64_t>& file, uint32_t file_bytes, size_t bytes, float factor, Level& level,
                std::string& error) {
    constexpr uint16_t kW = 64, kH = 48;
    std::vector<Rgb565> pixels(size_t(kW) * kH);
    std::vector<uint16_t> depth(size_t(kW) * kH);
    Config cfg;
    cfg.display.width = kW, cfg.display.height = kH, cfg.display.band_lines = kH;
    cfg.display.buffers[0] = pixels.data(), cfg.display.depth[0] = depth.data();
    cfg.display.flush = no_flush;
    cfg.interface = Interface::Off;
    cfg.screen_error_px = 0; // every face at the model's tolerance
    level = {};
    cfg.on_event = on_event, cfg.event_user = &level;
    std::vector<uint64_t> workspace(bytes / 8);
    Result why;
    Viewer* v = Viewer::create(cfg, workspace.data(), workspace.size() * 8, &why);
    char text[200];
    if (!v) {
        describe(why, text, sizeof text);
        return error = std::string("the module refused its workspace: ") + text, false;
    }
    if (const Result r = v->load(file.data(), file_bytes); !r.ok()) {
        if (r.status == Status::Full) return level.short_of_room = true, true;
        describe(r, text, sizeof text);
        return error = std::string("the module does not load the pack: ") + text, false;
    }
    if (factor != 1.0f) {
        if (const Result r = v->set_detail(factor); !r.ok()) {
            describe(r, text, sizeof text);
            return error = std::string("the module refused the detail: ") + text, false;
        }
    }
    // (A step is 100 ms of the host's time: a model of a million faces comes to rest within minutes.)
    for (uint32_t steps = 0; v->step(100000) != Activity::Idle; ++steps) {
        v->flush_done();
        if (steps > 1000000) return error = "the module did not come to rest", false;
    }
    const Stats s = v->stats();
    level.vertices = s.vertices, level.triangles = s.triangles;
    if (!(v->detail() == factor) || s.done + s.failed + s.deferred < s.faces) level.short_of_room = true; // (coarser, or wireframe, for room)
    return true;
}

} // namespace

bool measure_needs(const std::vector<uint8_t>& pack, pack::Needs& out, std::string& error) {
    out = {};
    std::vector<uint64_t> file(pack.size() / 8 + 1);
    std::memcpy(file.data(), pack.data(), pack.size());
    ModelNeeds estimate;
    if (const Result r = model_needs(file.data(), uint32_t(pack.size()), estimate); !r.ok()) {
        char text[200];
        describe(r, text, sizeof text);
        return error = std::string("the module does not read the pack's head: ") + text, false;
    }
    // Room enough for the pack decoded at the workspace's end and its mesh: doubled till the
    // levels need no more.
    size_t bytes = 4 * (estimate.workspace_bytes + estimate.pack_memory_bytes);
    for (;; bytes *= 2) {
        Level fine, coarse;
        if (!measure_at(file, uint32_t(pack.size()), bytes, 1.0f, fine, error) ||
            !measure_at(file, uint32_t(pack.size()), bytes, pack::kCoarsestFirst, coarse, error)) {
            return false;
        }
        if (!fine.failed.empty() || !coarse.failed.empty()) {
            error = "the module cannot show the model: " + (fine.failed.empty() ? coarse.failed : fine.failed);
            return false;
        }
        if (fine.short_of_room || coarse.short_of_room) {
            if (bytes > (size_t(1) << 34)) return error = "the model takes more than 16 GiB on a device", false;
            continue;
        }
        out.samples = fine.samples, out.mesh_vertices = fine.vertices, out.mesh_triangles = fine.triangles;
        out.coarse_samples = coarse.samples, out.coarse_vertices = coarse.vertices, out.coarse_triangles = coarse.triangles;
        return true;
    }
}

} // namespace facet::packer
