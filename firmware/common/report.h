#pragma once
// Report lines the host runner parses ("@ram ...", "@info ..."), shared by every firmware.
#include "hal/board.h"

namespace facet::fw {

// Prints "@board NAME WxH" and one "@ram NAME START BYTES" line per RAM region of the board.
void report_board(hal::Board& board);

} // namespace facet::fw
