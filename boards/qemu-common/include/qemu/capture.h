#pragma once
// QEMU boards only: a screenshot for the host runner (tools/qemu/run.py), part of the test
// protocol the QEMU firmware speaks. A real board has no host to take one. Programs reach it as
// the board's hal::Capture (Board::capture): this header is the boards' own.
#include "core/pixel.h"
#include "core/status.h"
#include "hal/capture.h"

#include <cstdint>

namespace facet::qemu {

// Makes the frame on the screen available to the host under `name`: versatilepb prints
// "@shot NAME" and waits (2 s at most) for the runner's acknowledgement, after it took the
// PL110's picture over QMP; mps2 writes NAME.f565 through semihosting and prints "@dump".
Status capture(const char* name);

// Any picture in the guest's memory (width x height RGB565, row after row) for the host under
// `name`: written as NAME.f565 through semihosting, then "@dump NAME FILE" is printed and the
// runner makes it OUT/NAME.png.
Status dump(const char* name, const Rgb565* pixels, uint16_t width, uint16_t height);

// Both as the board's Capture driver (capture.cpp).
hal::Capture& runner();

} // namespace facet::qemu
