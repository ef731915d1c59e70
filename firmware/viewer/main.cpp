// facet-viewer: the handheld viewer. The pack comes from the board's pack address; the viewer
// (viewer.h) shows its wireframe, fills in the faces one by one, and then follows the keys on
// the UART and the mouse (versatilepb's PL050) until 'q'.
//
// UART protocol for the host runner: "@idle" when the viewer waits for input (the runner sends
// its next scripted entry then, ending with ENQ), "@progress", "@tessellation", "@view" status lines,
// and the instruction-count regions "edges", "face" (one per face) and "frame" (a full
// redraw).
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"
#include "report.h"
#include "viewer.h"

namespace {

using namespace facet;

constexpr uint32_t kPixels = uint32_t(board_config::kDisplayWidth) * board_config::kDisplayHeight;

__attribute__((section(".zbuffer"))) uint16_t depth[2][kPixels]; // one per display buffer
hal::Rgb565 line[board_config::kDisplayWidth];
__attribute__((section(".arena"))) viewer::Storage storage;

Status capture(void*, const char* name) { return hal::capture(name); }

} // namespace

int facet_main(hal::Board& board) {
    hal::Console& con = board.console;
    fw::report_board(board);
    viewer::Memory mem = storage.memory(depth[0], depth[1], line);
    static viewer::Viewer v(board, mem, capture, nullptr);
    auto* region = reinterpret_cast<uint8_t*>(board_config::kPackAddress);
    if (!ok(v.open(region, board_config::kPackBytes))) {
        print(con, "viewer: nothing to show (load a pack with run.py --load MODEL.fpk@{})\n", hex(board_config::kPackAddress));
        return 1;
    }
    // "@idle" once the viewer has nothing left to do, then again after each ENQ (0x05) from
    // the host runner: a scripted session sends its next entry only then.
    bool prompt = true;
    while (!v.quit()) {
        hal::InputEvent e;
        while (!v.quit() && board.input.poll(e)) {
            if (e.kind == hal::InputEvent::Kind::Key && e.key == 0x05) prompt = true;
            else v.handle(e);
        }
        if (v.quit()) break;
        if (v.step()) continue;
        if (prompt) {
            print(con, "@idle\n");
            prompt = false;
        }
    }
    const viewer::Totals& t = v.totals();
    // What this model needed: the pack (inflated, and the file it came from, both held while
    // inflating) and the viewer's storage at its peak (the host adds the display buffers, code
    // and stack high-water: the model's peak RAM).
    print(con, "@memory pack_bytes {} pack_file_bytes {} storage_peak_bytes {}\n", v.pack_bytes(), v.pack_file_bytes(),
          v.storage_in_use());
    print(con, "viewer: {} faces ({} failed), {} triangles; bye\n", t.faces, t.failed, t.triangles);
    return 0;
}
