#pragma once
// MPS2 AN500 (Cortex-M7) addresses: ARM AN500 application note; QEMU hw/arm/mps2.c.
#include <cstdint>

namespace facet::mps2 {

constexpr uintptr_t kUart0 = 0x40004000;     // CMSDK APB UART
constexpr uintptr_t kDualTimer = 0x40002000; // CMSDK dual timer (SP804-like), 25 MHz
constexpr uint32_t kSysClockHz = 25'000'000;

// System control block.
constexpr uintptr_t kCpacr = 0xE000ED88;
constexpr uintptr_t kShcsr = 0xE000ED24;
constexpr uintptr_t kCfsr = 0xE000ED28;
constexpr uintptr_t kHfsr = 0xE000ED2C;
constexpr uintptr_t kMmfar = 0xE000ED34;
constexpr uintptr_t kBfar = 0xE000ED38;

inline volatile uint32_t& reg(uintptr_t address) {
    return *reinterpret_cast<volatile uint32_t*>(address);
}

} // namespace facet::mps2
