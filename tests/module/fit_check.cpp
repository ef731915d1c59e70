// The fitted view of real models: each pack is loaded into a viewer (the host build of the
// module), tessellated, and every vertex of every instance projected through the camera as the
// viewer fitted it after sampling. The projected box must lie on the screen, be centred, and
// fill it (it is a fit, not a speck).
//
//   facet-fit-check WIDTHxHEIGHT[,WxH...] PACK_OR_DIR...     exit 1 if a view is off
#include "core.h"
#include "file_io.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using namespace facet;

namespace {

struct Screen {
    uint16_t w, h;
};

struct Fit {
    bool ok = true;
    double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9; // pixels
    uint32_t hidden = 0;                                      // vertices behind the eye or past the guard band
    double area_w = 0, area_h = 0;                            // the free area (the screen less the interface)
    std::string why;
};

// The viewer frames the outline to fill Framer::kFill (module/src/fit.h, within 2% once it sits; faces
// that bulge past their edges can add a little) and centres it within a pixel.
constexpr double kCentreSlack = 0.02; // box centre within 2% of the short side of the screen centre
constexpr double kMinFill = module::Framer::kFill - 0.05, kMaxFill = module::Framer::kFill + 0.07; // the box's larger extent over the area's

void flush(Viewer&, void*, const Area&, const Rgb565*) {}

Fit check(const std::vector<uint8_t>& file, Screen s) {
    Fit fit;
    Config cfg;
    std::vector<Rgb565> frame(size_t(s.w) * s.h);
    std::vector<uint16_t> depth(size_t(s.w) * s.h);
    cfg.display = {s.w, s.h, s.h, {frame.data(), nullptr}, {depth.data(), nullptr}, Flush::Copy, flush, nullptr};
    cfg.interface = Interface::Full; // framed in the screen less the status bar and the toolbar, as a user sees it
    std::vector<uint64_t> workspace(FACET_WORKSPACE_BYTES_DEFAULT / 8 + 1);
    Result why;
    Viewer* v = Viewer::create(cfg, workspace.data(), workspace.size() * 8, &why);
    if (!v) {
        fit.ok = false, fit.why = "create: " + std::string(why.what);
        return fit;
    }
    std::vector<uint32_t> memory(pack_memory_bytes(file.data(), uint32_t(file.size())) / 4 + 1);
    if (Result r = v->load(file.data(), uint32_t(file.size()), memory.data(), uint32_t(memory.size() * 4)); !r.ok()) {
        fit.ok = false, fit.why = "load: " + std::string(r.what);
        return fit;
    }
    for (int guard = 0; guard < 10000000; ++guard) {
        const Activity a = v->step(0);
        if (a == Activity::Waiting) v->flush_done();
        if (a == Activity::Idle) break;
    }
    const Core& core = *static_cast<const Core*>(v);
    const module::Scene& scene = core.scene();
    for (uint32_t i = 0; i < scene.instances().size(); ++i) {
        const module::Transform t = core.camera().transform(scene, i, s.w, s.h);
        const module::Part sh = scene.part(scene.instances()[i].shell);
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            const module::FaceInfo& F = scene.face(f);
            if (F.state != module::FaceState::Done) continue;
            for (uint32_t k = 0; k < F.vertex_count; ++k) {
                module::Projected p;
                t.project(scene.vertices()[F.first_vertex + k].p, p);
                if (p.out) {
                    ++fit.hidden;
                    continue;
                }
                const double x = p.s.x / 16.0, y = p.s.y / 16.0;
                fit.left = std::min(fit.left, x), fit.right = std::max(fit.right, x);
                fit.top = std::min(fit.top, y), fit.bottom = std::max(fit.bottom, y);
            }
        }
    }
    char buf[256];
    // The free area: the screen less what the interface takes.
    const module::FreeArea taken = core.overlay().taken();
    const double x0 = taken.left, y0 = taken.top, x1 = s.w - taken.right, y1 = s.h - taken.bottom;
    fit.area_w = x1 - x0, fit.area_h = y1 - y0;
    const double cx = 0.5 * (fit.left + fit.right) - 0.5 * (x0 + x1), cy = 0.5 * (fit.top + fit.bottom) - 0.5 * (y0 + y1);
    const double shorter = std::min(x1 - x0, y1 - y0);
    const double fill = std::max((fit.right - fit.left) / (x1 - x0), (fit.bottom - fit.top) / (y1 - y0));
    if (fit.hidden) {
        std::snprintf(buf, sizeof buf, "%u vertices behind the eye or far off the screen", fit.hidden);
        fit.ok = false, fit.why = buf;
    } else if (fit.left < x0 || fit.top < y0 || fit.right > x1 || fit.bottom > y1) {
        fit.ok = false, fit.why = "under the interface or off the screen";
    } else if (std::abs(cx) > kCentreSlack * shorter || std::abs(cy) > kCentreSlack * shorter) {
        std::snprintf(buf, sizeof buf, "off-centre by (%.0f, %.0f) pixels", cx, cy);
        fit.ok = false, fit.why = buf;
    } else if (fill < kMinFill || fill > kMaxFill) {
        std::snprintf(buf, sizeof buf, "fills %.0f%% of the area (framed: %.0f%%)", 100 * fill, 100.0 * module::Framer::kFill);
        fit.ok = false, fit.why = buf;
    }
    return fit;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: facet-fit-check WIDTHxHEIGHT[,WxH...] PACK_OR_DIR...\n");
        return 2;
    }
    std::vector<Screen> screens;
    for (const char* p = argv[1]; *p;) {
        unsigned w = 0, h = 0;
        int n = 0;
        if (std::sscanf(p, "%ux%u%n", &w, &h, &n) != 2 || w < 16 || h < 16 || w > 4096 || h > 4096) {
            std::fprintf(stderr, "facet-fit-check: bad screen size '%s' (WIDTHxHEIGHT)\n", p);
            return 2;
        }
        screens.push_back({uint16_t(w), uint16_t(h)});
        p += n;
        if (*p == ',') ++p;
    }
    std::vector<std::filesystem::path> packs;
    for (int i = 2; i < argc; ++i) {
        std::error_code ec;
        if (std::filesystem::is_directory(argv[i], ec)) {
            for (const auto& e : std::filesystem::directory_iterator(argv[i]))
                if (e.path().extension() == ".fpk") packs.push_back(e.path());
        } else {
            packs.push_back(argv[i]);
        }
    }
    std::sort(packs.begin(), packs.end());
    if (packs.empty()) {
        std::fprintf(stderr, "facet-fit-check: no packs\n");
        return 1;
    }
    int bad = 0;
    std::printf("%-28s %-9s %28s %8s\n", "model", "screen", "projected box (l t r b)", "fill");
    for (const auto& path : packs) {
        std::vector<uint8_t> file;
        std::string error;
        if (!host::read_file(path.string(), 1u << 30, file, error)) {
            std::printf("%-28s cannot read: %s\n", path.filename().c_str(), error.c_str());
            ++bad;
            continue;
        }
        for (const Screen s : screens) {
            const Fit f = check(file, s);
            char size[16];
            std::snprintf(size, sizeof size, "%ux%u", s.w, s.h);
            std::printf("%-28s %-9s %6.0f %6.0f %6.0f %6.0f %7.0f%% %s\n", path.filename().c_str(), size, f.left, f.top, f.right, f.bottom,
                        100 * std::max((f.right - f.left) / f.area_w, (f.bottom - f.top) / f.area_h), f.ok ? "ok" : ("FAIL: " + f.why).c_str());
            bad += !f.ok;
        }
    }
    std::printf("%d of %zu views off\n", bad, packs.size() * screens.size());
    return bad ? 1 : 0;
}
