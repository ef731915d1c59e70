// facet-fault-test: stores one word where the board has no RAM to give, and must fault there.
// By default just past the RAM budget (versatilepb: the MMU maps only the 32 MiB) or, on a board
// that says so (board.json "fault_probe"), just past its SDRAM (the EVKB's MPU has no region
// there). An address typed on the console within two seconds (hex, Enter) is used instead:
// the tests also store into flash, which the MPU makes read-only. Reaching the end of this
// function is a failure.
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"

namespace {

// Hex digits typed before Enter, or `fallback` when nothing comes within `wait_us`.
uint32_t typed_address(facet::hal::Board& board, uint32_t fallback, uint32_t wait_us) {
    facet::hal::Clock& clock = board.clock;
    const uint64_t end = clock.ticks() + uint64_t(wait_us) * clock.ticks_per_second() / 1'000'000;
    uint32_t value = 0, digits = 0;
    while (clock.ticks() < end) {
        const int c = board.console.read_byte();
        if (c < 0) continue;
        if (c == '\n' || c == '\r') return digits ? value : fallback;
        const int d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10
                                                        : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : -1;
        if (d >= 0) value = value * 16 + uint32_t(d), ++digits;
    }
    return fallback;
}

} // namespace

int facet_main(facet::hal::Board& board) {
    facet::print(board.console, "fault-test: an address (hex, Enter) or wait for {}\n@idle\n",
                 facet::hex(facet::board_config::kFaultProbe));
    const uint32_t probe = typed_address(board, facet::board_config::kFaultProbe, 2'000'000);
    facet::print(board.console, "fault-test: storing to {}\n", facet::hex(probe));
    volatile uint32_t* past = reinterpret_cast<volatile uint32_t*>(uintptr_t(probe));
    *past = 0xDEADBEEF;
    facet::print(board.console, "fault-test: the store to {} did not fault\n", facet::hex(probe));
    return 0;
}
