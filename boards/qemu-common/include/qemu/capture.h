#pragma once
// QEMU boards only: a screenshot for the host runner (tools/qemu/run.py), part of the test
// protocol the QEMU firmware speaks. A real board has no host to take one.
#include "hal/pixel.h"
#include "hal/status.h"

#include <cstdint>

namespace facet::qemu {

// Makes the frame on the screen available to the host under `name`: versatilepb prints
// "@shot NAME" and waits (2 s at most) for the runner's acknowledgement, after it took the
// PL110's picture over QMP; mps2 writes NAME.f565 through semihosting and prints "@dump".
Status capture(const char* name);

// Any picture in the guest's memory (width x height RGB565, row after row) for the host under
// `name`: written as NAME.f565 through semihosting, then "@dump NAME FILE" is printed and the
// runner makes it OUT/NAME.png.
Status dump(const char* name, const hal::Rgb565* pixels, uint16_t width, uint16_t height);

} // namespace facet::qemu
