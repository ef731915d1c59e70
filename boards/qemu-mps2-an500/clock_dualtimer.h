#pragma once
// CMSDK dual timer 1 as a free-running 32-bit down-counter at 25 MHz of QEMU's virtual
// clock, polled; its ticks are reported in the 600 MHz target's time (qemu/virtual_clock.h).
#include "hal/clock.h"

namespace facet::mps2 {

class DualTimerClock final : public hal::Clock {
public:
    void init();
    uint64_t ticks() override;
    uint32_t ticks_per_second() const override;

private:
    uint32_t last_ = 0;
    uint64_t total_ = 0;
};

} // namespace facet::mps2
