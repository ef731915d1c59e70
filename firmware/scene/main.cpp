// facet-scene: the foundation's end-to-end image. Draws the fixed shaded test scene through
// the board's display driver (spans), flips, and asks the host for a screenshot, for two views.
// The draw of each view is an instruction-count region ("draw_scene_a", "draw_scene_b").
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "render/test_scene.h"
#include "report.h"

namespace {

using namespace facet;
constexpr uint32_t kPixels = uint32_t(board_config::kDisplayWidth) * board_config::kDisplayHeight;

alignas(64) __attribute__((section(".zbuffer"))) uint16_t depth[kPixels];
hal::Rgb565 line[board_config::kDisplayWidth];

} // namespace

int facet_main(hal::Board& board) {
    fw::report_board(board);
    render::Rasterizer raster(board.display, depth, line);
    if (Status s = raster.check(); !ok(s)) {
        print(board.console, "scene: buffers too small for the display ({})\n", status_name(s));
        return 1;
    }
    const char* names[2] = {"scene-a", "scene-b"};
    const char* regions[2] = {"draw_scene_a", "draw_scene_b"};
    for (int i = 0; i < 2; ++i) {
        const uint64_t t0 = board.clock.ticks();
        hal::measure_begin(board.console, regions[i]);
        const Status s = render::draw_test_scene(raster, board.display, render::kSceneViews[i]);
        hal::measure_end(board.console, regions[i]);
        const uint64_t t1 = board.clock.ticks();
        if (!ok(s)) {
            print(board.console, "scene: draw failed: {}\n", status_name(s));
            return 1;
        }
        (void)board.display.flip();
        print(board.console, "{}: {} triangles, {} culled, {} spans, {} pixels, {} us (QEMU wall)\n",
              names[i], raster.stats.triangles, raster.stats.culled, raster.stats.spans,
              raster.stats.pixels, (t1 - t0) * 1'000'000 / board.clock.ticks_per_second());
        raster.stats = {};
        if (Status c = hal::capture(names[i]); !ok(c)) {
            print(board.console, "scene: capture failed: {}\n", status_name(c));
            return 1;
        }
    }
    return 0;
}
