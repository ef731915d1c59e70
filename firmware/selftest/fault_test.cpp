// facet-fault-test: stores one word just past the RAM budget. On versatilepb the MMU maps only
// the 32 MiB, so this must abort with a message and a non-zero exit code; reaching the end of
// this function is a failure.
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"

int facet_main(facet::hal::Board& board) {
    facet::print(board.console, "fault-test: storing to {}\n",
                 facet::hex(facet::board_config::kRamBytes));
    volatile uint32_t* past = reinterpret_cast<volatile uint32_t*>(facet::board_config::kRamBytes);
    *past = 0xDEADBEEF;
    facet::print(board.console, "fault-test: the store past the budget did not fault\n");
    return 0;
}
