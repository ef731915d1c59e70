#pragma once
// Instruction-count regions for the QEMU plugin (tools/qemu/icount).
//
// The plugin counts guest instructions executed between a call of facet_mark_begin() and the
// matching facet_mark_end(); regions nest. Each marker is a single return instruction so the
// count is exact; the board defines them in assembly, the host as empty functions.
// measure_begin/end also print "@begin NAME" / "@end NAME" on the console so the host runner
// can put names on the plugin's numbered regions.
#include "hal/console.h"

extern "C" void facet_mark_begin(void);
extern "C" void facet_mark_end(void);

namespace facet::hal {

void measure_begin(Console& console, const char* name);
void measure_end(Console& console, const char* name);

} // namespace facet::hal
