// facet-icount-test: calibrates the instruction counter. facet_known_loop(n) executes exactly
// 2n + 1 instructions between its markers (boards/common/markers.S); the QEMU test checks
// the plugin reports exactly that, and the same numbers on every run.
#include "hal/board.h"
#include "hal/print.h"

extern "C" void facet_known_loop(uint32_t n);

int facet_main(facet::hal::Board& board) {
    const uint32_t counts[3] = {1, 1000, 123457};
    for (uint32_t n : counts) {
        facet::print(board.console, "@begin known_loop_{}\n", n);
        facet_known_loop(n);
        facet::print(board.console, "@end known_loop_{}\n", n);
        facet::print(board.console, "@expect known_loop_{} {}\n", n, 2 * n + 1);
    }
    return 0;
}
