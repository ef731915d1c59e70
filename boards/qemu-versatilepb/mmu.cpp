// MMU set-up: a flat map of 1 MiB sections covering only the 32 MiB RAM budget and the
// peripherals the board uses. Every other address is a translation fault, so any access past
// the budget aborts (boards/qemu-versatilepb/faults.cpp prints it) instead of silently using
// memory the handheld does not have.
#include "facet_board_config.h"
#include "memory_map.h"

#include <cstdint>

namespace facet::versatilepb {
namespace {

// ARMv5 first-level section descriptor fields.
constexpr uint32_t kSection = 0b10;
constexpr uint32_t kBufferable = 1u << 2;
constexpr uint32_t kCacheable = 1u << 3;
constexpr uint32_t kBit4 = 1u << 4;          // must be 1 on ARM926
constexpr uint32_t kApReadWrite = 3u << 10;  // privileged and user read/write
constexpr uint32_t kDomain0 = 0u << 5;

alignas(16384) __attribute__((section(".mmu_table"))) uint32_t table[4096];

} // namespace

void mmu_enable() {
    for (uint32_t& e : table) e = 0; // fault
    constexpr uint32_t ram_mib = board_config::kRamBytes >> 20;
    for (uint32_t mib = 0; mib < ram_mib; ++mib) {
        table[mib] = (mib << 20) | kApReadWrite | kDomain0 | kBit4 | kCacheable | kBufferable |
                     kSection;
    }
    for (uint32_t i = 0; i < kPeripheralsMiB; ++i) {
        const uint32_t mib = (kPeripheralsStart >> 20) + i;
        table[mib] = (mib << 20) | kApReadWrite | kDomain0 | kBit4 | kSection; // device
    }
    const uint32_t ttb = reinterpret_cast<uintptr_t>(table);
    asm volatile("mcr p15, 0, %0, c2, c0, 0" ::"r"(ttb));        // TTBR0
    asm volatile("mcr p15, 0, %0, c3, c0, 0" ::"r"(1u));         // domain 0: client
    asm volatile("mcr p15, 0, %0, c8, c7, 0" ::"r"(0u));         // invalidate TLBs
    uint32_t sctlr;
    asm volatile("mrc p15, 0, %0, c1, c0, 0" : "=r"(sctlr));
    sctlr |= (1u << 0) | (1u << 2) | (1u << 12);                 // MMU, D-cache, I-cache
    asm volatile("mcr p15, 0, %0, c1, c0, 0" ::"r"(sctlr) : "memory");
}

} // namespace facet::versatilepb
