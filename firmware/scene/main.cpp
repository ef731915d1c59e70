// facet-scene: the foundation's end-to-end image. Draws the fixed shaded test scene into a
// frame, shows it on the board's display and asks the host for a screenshot, for two views.
// The draw of each view is an instruction-count region ("draw_scene_a", "draw_scene_b").
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "test_scene.h"
#include "hal/report.h"

namespace {

using namespace facet;
constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;

alignas(64) __attribute__((section(".framebuffers"))) Rgb565 frame[uint32_t(kW) * kH];
alignas(64) __attribute__((section(".zbuffer"))) uint16_t depth[uint32_t(kW) * kH];

} // namespace

int facet_main(hal::Board& board) {
    hal::report_board(board);
    render::Rasterizer raster(render::Target{frame, depth, kW, kH, 0, kH});
    const char* names[2] = {"scene-a", "scene-b"};
    const char* regions[2] = {"draw_scene_a", "draw_scene_b"};
    for (int i = 0; i < 2; ++i) {
        const uint64_t t0 = board.clock.ticks();
        hal::measure_begin(board.console, regions[i]);
        const Status s = render::draw_test_scene(raster, render::kSceneViews[i]);
        hal::measure_end(board.console, regions[i]);
        const uint64_t t1 = board.clock.ticks();
        if (!ok(s)) {
            print(board.console, "scene: draw failed: {}\n", s);
            return 1;
        }
        if (Status shown = board.display.show(frame); !ok(shown)) {
            print(board.console, "scene: the display refused the frame: {}\n", shown);
            return 1;
        }
        print(board.console, "{}: {} triangles, {} culled, {} spans, {} pixels, {} us (QEMU wall)\n",
              names[i], raster.stats.triangles, raster.stats.culled, raster.stats.spans,
              raster.stats.pixels, (t1 - t0) * 1'000'000 / board.clock.ticks_per_second());
        raster.stats = {};
        if (!board.capture) {
            print(board.console, "scene: this board has no capture for its screenshots\n");
            return 1;
        }
        if (Status c = board.capture->shot(names[i]); !ok(c)) {
            print(board.console, "scene: capture failed: {}\n", c);
            return 1;
        }
    }
    return 0;
}
