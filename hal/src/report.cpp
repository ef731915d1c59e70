#include "hal/report.h"

#include "hal/print.h"

namespace facet::hal {

void report_board(Board& board) {
    const DisplayInfo d = board.display.info();
    print(board.console, "@board {} {}x{} scanout {}\n", board.name, d.width, d.height, d.scanout);
    MemoryRegion regions[16];
    const uint32_t n = memory_map(regions, 16);
    uint32_t total = 0;
    for (uint32_t i = 0; i < n; ++i) {
        print(board.console, "@ram {} {} {}\n", regions[i].name, hex(regions[i].start),
              regions[i].bytes);
        total += regions[i].bytes;
    }
    print(board.console, "@ram total 0 {}\n", total);
}

} // namespace facet::hal
