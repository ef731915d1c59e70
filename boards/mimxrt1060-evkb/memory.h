#pragma once
// The EVKB's memory as its linker script lays it out (linker/mimxrt1060-evkb.ld), shared with
// the QEMU stand-in that links with the same script: loading the ITCM, the MPU plan, the report.
#include "mpu.h"

namespace facet::evkb {

// Copies the hot code from flash to ITCM. First thing at reset: nothing before it may call a
// function placed in ITCM.
void load_itcm();

// The MPU plan of this layout: peripherals, ITCM (with a 32-byte null-pointer guard), DTCM,
// OCRAM, the flash device (firmware and pack), SDRAM and the frames' write-through region.
// Returns how many ranges (at most 8: the Cortex-M7 in QEMU has 8 MPU regions).
uint32_t memory_ranges(cortex_m::Range* out, uint32_t max);

// Plans and loads the MPU, enables the caches. Returns how many regions the plan took, 0 when
// the MPU could not take it (fewer regions than the plan).
uint32_t protect_memory();

} // namespace facet::evkb
