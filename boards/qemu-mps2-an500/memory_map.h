#pragma once
// MPS2 AN500 (Cortex-M7) addresses: ARM AN500 application note; QEMU hw/arm/mps2.c.
#include <cstdint>

namespace facet::mps2 {

constexpr uintptr_t kUart0 = 0x40004000;     // CMSDK APB UART
constexpr uintptr_t kDualTimer = 0x40002000; // CMSDK dual timer (SP804-like), 25 MHz
constexpr uint32_t kSysClockHz = 25'000'000;

inline volatile uint32_t& reg(uintptr_t address) {
    return *reinterpret_cast<volatile uint32_t*>(address);
}

} // namespace facet::mps2
