// facet-render-views: the render bench's facet pictures drawn on the host, by the sequence the
// bench firmware draws on the boards (views.h), with the same workspace and pack memory, into
// F565 files named as the firmware's dumps (DIR/{full,zoomed}-WxH-facet[-shaded].f565).
// render.py --host-views compares every board's pictures with these byte for byte: the module
// draws the same pixels on the ARM926, the Cortex-M7 and the host.
//
//   facet-render-views PACK FINER DIR      exit 0: written; 1: the pack or a view failed; 2: usage
//   (FINER: 0 to 3 steps finer than the default level of detail)
#include "facet/sizes.h"
#include "facet/viewer.h"
#include "hal/fake.h"
#include "views.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace facet;

struct Views {
    Viewer* viewer = nullptr;
    Event last_frame{};
};

void on_event(void* user, const Event& e) {
    if (e.kind == Event::Kind::FrameDone) static_cast<Views*>(user)->last_frame = e;
}

void flush(Viewer& viewer, void*, const Area&, const Rgb565*) { viewer.flush_done(); }

} // namespace

int main(int argc, char** argv) {
    // FINER: the steps finer than the default level of detail, as the bench firmware takes them (0 to 3).
    if (argc != 4 || argv[2][0] < '0' || argv[2][0] > '3' || argv[2][1] != '\0') {
        std::fprintf(stderr, "usage: facet-render-views PACK FINER(0-3) DIR\n");
        return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    const std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        std::fprintf(stderr, "facet-render-views: cannot read %s\n", argv[1]);
        return 1;
    }
    const uint32_t finer = uint32_t(argv[2][0] - '0');
    const std::string dir = argv[3];
    std::vector<uint64_t> pack(file.size() / 8 + 1), workspace(FACET_WORKSPACE_BYTES_DEFAULT / 8 + 1), memory(bench::kPackMemoryBytes / 8);
    std::memcpy(pack.data(), file.data(), file.size());
    for (const bench::ViewSize s : bench::kViewSizes) {
        std::vector<Rgb565> frame(size_t(s.width) * s.height);
        std::vector<uint16_t> depth(frame.size());
        Views views;
        const Config cfg = bench::view_config(s, frame.data(), depth.data(), flush, on_event, &views);
        Result why;
        views.viewer = Viewer::create(cfg, workspace.data(), FACET_WORKSPACE_BYTES_DEFAULT, &why);
        if (!views.viewer) {
            std::fprintf(stderr, "facet-render-views: %s\n", why.what);
            return 1;
        }
        Viewer& v = *views.viewer;
        if (Result r = v.load(pack.data(), uint32_t(file.size()), memory.data(), bench::kPackMemoryBytes); !r.ok()) {
            std::fprintf(stderr, "facet-render-views: %s: %s\n", argv[1], r.what);
            return 1;
        }
        bench::prepare(v, finer);
        const bool drawn = bench::draw_views(
            v,
            [&](const char* name, bool edges) {
                if (!bench::whole_model_drawn(views.last_frame)) {
                    std::fprintf(stderr, "facet-render-views: no full frame of the finished model for %s\n", name);
                    return false;
                }
                const std::string path = dir + "/" + name + "-" + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                         "-facet" + (edges ? "" : "-shaded") + ".f565";
                if (!hal::fake::write_f565(path, frame, s.width, s.height)) {
                    std::fprintf(stderr, "facet-render-views: cannot write %s\n", path.c_str());
                    return false;
                }
                return true;
            },
            [](const char*) { return true; });
        if (!drawn) return 1;
    }
    return 0;
}
