#pragma once
// SP804 timer 0 as a free-running 32-bit down-counter at 1 MHz of QEMU's virtual clock,
// extended to 64 bits by polling (no interrupts, so instruction counts stay exact). Its ticks
// are reported in the 600 MHz target's time (qemu/virtual_clock.h): 600,000 a second.
#include "hal/clock.h"
#include "qemu/virtual_clock.h"

namespace facet::versatilepb {

class Sp804Clock final : public hal::Clock {
public:
    void init();
    uint64_t ticks() override;
    uint32_t ticks_per_second() const override { return qemu::target_ticks_per_second(1'000'000); }

private:
    uint32_t last_ = 0;
    uint64_t total_ = 0;
};

} // namespace facet::versatilepb
