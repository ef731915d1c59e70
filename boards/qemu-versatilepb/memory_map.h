#pragma once
// Versatile/PB peripheral addresses (ARM DUI 0224I; QEMU hw/arm/versatilepb.c).
#include <cstdint>

namespace facet::versatilepb {

constexpr uintptr_t kSysRegs = 0x10000000;   // system controller registers
constexpr uintptr_t kSysClcd = kSysRegs + 0x50; // SYS_CLCD: bits[1:0] select the CLCD pixel mux
constexpr uintptr_t kPl181 = 0x10005000;     // MMCI0: the SD card
constexpr uintptr_t kPl110 = 0x10120000;     // colour LCD controller
constexpr uintptr_t kSp804 = 0x101E2000;     // dual timer 0/1 (1 MHz in QEMU)
constexpr uintptr_t kPl011 = 0x101F1000;     // UART0
constexpr uintptr_t kPeripheralsStart = 0x10000000;
constexpr uint32_t kPeripheralsMiB = 2;      // 0x10000000-0x101FFFFF: all we use

inline volatile uint32_t& reg(uintptr_t address) {
    return *reinterpret_cast<volatile uint32_t*>(address);
}

} // namespace facet::versatilepb
