// facet-scene-ref: renders the foundation's test scene on the host with the same render/ code
// the firmware runs, into raw RGB565 files (see hal/fake.h) that tools/img.py turns into PNG.
//
//   facet-scene-ref WIDTH HEIGHT OUT_PREFIX   ->  OUT_PREFIX-scene-a.f565, OUT_PREFIX-scene-b.f565
#include "hal/fake.h"
#include "test_scene.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s WIDTH HEIGHT OUT_PREFIX\n", argv[0]);
        return 2;
    }
    const int w = std::atoi(argv[1]), h = std::atoi(argv[2]);
    if (w <= 0 || h <= 0 || w > 4096 || h > 4096) {
        std::fprintf(stderr, "facet-scene-ref: bad size %sx%s\n", argv[1], argv[2]);
        return 2;
    }
    using namespace facet;
    std::vector<Rgb565> frame(size_t(w) * h);
    std::vector<uint16_t> depth(size_t(w) * h);
    render::Rasterizer raster(render::Target{frame.data(), depth.data(), uint16_t(w), uint16_t(h), 0, uint16_t(h)});
    const char* names[2] = {"scene-a", "scene-b"};
    for (int i = 0; i < 2; ++i) {
        if (Status s = render::draw_test_scene(raster, render::kSceneViews[i]); !ok(s)) {
            std::fprintf(stderr, "facet-scene-ref: draw failed: %s\n", status_name(s));
            return 1;
        }
        const std::string path = std::string(argv[3]) + "-" + names[i] + ".f565";
        if (!hal::fake::write_f565(path, frame, uint16_t(w), uint16_t(h))) {
            std::fprintf(stderr, "facet-scene-ref: cannot write %s\n", path.c_str());
            return 1;
        }
        std::printf("%s: %u triangles, %u culled, %u spans, %u pixels\n", path.c_str(),
                    raster.stats.triangles, raster.stats.culled, raster.stats.spans,
                    raster.stats.pixels);
        raster.stats = {};
    }
    return 0;
}
