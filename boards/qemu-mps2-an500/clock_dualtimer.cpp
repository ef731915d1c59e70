#include "clock_dualtimer.h"

#include "memory_map.h"
#include "qemu/virtual_clock.h"

namespace facet::mps2 {
namespace {
constexpr uintptr_t kLoad = kDualTimer + 0x00, kValue = kDualTimer + 0x04,
                    kControl = kDualTimer + 0x08;
constexpr uint32_t kEnable = 1u << 7, kSize32 = 1u << 1;
} // namespace

void DualTimerClock::init() {
    reg(kControl) = 0;
    reg(kLoad) = 0xFFFFFFFF;
    reg(kControl) = kEnable | kSize32;
    last_ = reg(kValue);
}

uint64_t DualTimerClock::ticks() {
    const uint32_t now = reg(kValue);
    total_ += last_ - now;
    last_ = now;
    return total_;
}

uint32_t DualTimerClock::ticks_per_second() const { return qemu::target_ticks_per_second(kSysClockHz); }

} // namespace facet::mps2
