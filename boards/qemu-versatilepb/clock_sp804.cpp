#include "clock_sp804.h"

#include "memory_map.h"

namespace facet::versatilepb {
namespace {
constexpr uintptr_t kLoad = kSp804 + 0x00, kValue = kSp804 + 0x04, kControl = kSp804 + 0x08;
constexpr uint32_t kEnable = 1u << 7, kSize32 = 1u << 1; // free-running (not periodic), 32-bit
} // namespace

void Sp804Clock::init() {
    reg(kControl) = 0;
    reg(kLoad) = 0xFFFFFFFF;
    reg(kControl) = kEnable | kSize32;
    last_ = reg(kValue);
}

uint64_t Sp804Clock::ticks() {
    const uint32_t now = reg(kValue);
    total_ += last_ - now; // counts down; unsigned difference handles the wrap
    last_ = now;
    return total_;
}

} // namespace facet::versatilepb
