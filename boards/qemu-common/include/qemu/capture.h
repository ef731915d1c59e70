#pragma once
// QEMU boards only: a screenshot for the host runner (tools/qemu/run.py), part of the test
// protocol the QEMU firmware speaks. A real board has no host to take one.
#include "hal/status.h"

namespace facet::qemu {

// Makes the frame on the screen available to the host under `name`: versatilepb prints
// "@shot NAME" and waits (2 s at most) for the runner's acknowledgement, after it took the
// PL110's picture over QMP; mps2 writes NAME.f565 through semihosting and prints "@dump".
Status capture(const char* name);

} // namespace facet::qemu
