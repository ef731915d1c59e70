#pragma once
// GPT1 as the board's clock: free-running at 1 MHz from the 24 MHz crystal, polled; 64-bit
// ticks from the 32-bit counter (it wraps every 71 minutes; ticks() is called far more often).
#include "hal/clock.h"

#include <cstdint>

namespace facet::evkb {

class GptClock final : public hal::Clock {
public:
    void init();
    uint64_t ticks() override;
    uint32_t ticks_per_second() const override { return 1'000'000; }

private:
    uint32_t last_ = 0;
    uint64_t total_ = 0;
};

} // namespace facet::evkb
