#pragma once
// The lines a watching host reads about the board (docs/protocol.md): "@board NAME WxH scanout
// BOOL" and one "@ram NAME START BYTES" per RAM region, then "@ram total 0 BYTES".
#include "hal/board.h"

namespace facet::hal {

void report_board(Board& board);

} // namespace facet::hal
