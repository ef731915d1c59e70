// What the boards provide on the target, for host builds: the instruction markers (no-ops
// without QEMU). The assert hook's host version is core's (core/src/host_assert.cpp).
#include "hal/measure.h"

extern "C" void facet_mark_begin(void) {}
extern "C" void facet_mark_end(void) {}
