// Cortex-M7 caches and MPU: the register writes behind cortex_m.h and mpu.h (target only).
#include "cortex_m.h"
#include "mpu.h"

namespace facet::cortex_m {

void enable_caches() {
    if (!(reg(kCcr) & kCcrIc)) {
        dsb();
        isb();
        reg(kIciallu) = 0;
        dsb();
        isb();
        reg(kCcr) = reg(kCcr) | kCcrIc;
        dsb();
        isb();
    }
    if (!(reg(kCcr) & kCcrDc)) {
        reg(kCsselr) = 0; // level 1 data cache
        dsb();
        const uint32_t ccsidr = reg(kCcsidr);
        const uint32_t sets = ((ccsidr >> 13) & 0x7FFF) + 1, ways = ((ccsidr >> 3) & 0x3FF) + 1;
        // DCISW: set in bits 13:5 (32-byte lines), way in bits 31:30 (four ways) on the M7.
        for (uint32_t set = 0; set < sets; ++set)
            for (uint32_t way = 0; way < ways; ++way) reg(kDcisw) = ((set & 0x1FF) << 5) | ((way & 3) << 30);
        dsb();
        reg(kCcr) = reg(kCcr) | kCcrDc;
        dsb();
        isb();
    }
}

void clean_dcache(const void* start, uint32_t bytes) {
    uintptr_t a = reinterpret_cast<uintptr_t>(start) & ~uintptr_t(31);
    const uintptr_t end = reinterpret_cast<uintptr_t>(start) + bytes;
    dsb();
    for (; a < end; a += 32) reg(kDccmvac) = uint32_t(a);
    dsb();
    isb();
}

uint32_t mpu_regions() { return (reg(kMpuType) >> 8) & 0xFF; }

bool program(const MpuRegion* regions, uint32_t count) {
    const uint32_t available = mpu_regions();
    if (count > available) return false;
    dsb();
    reg(kMpuCtrl) = 0;
    for (uint32_t i = 0; i < available; ++i) { // the regions not planned: disabled
        reg(kMpuRnr) = i;
        reg(kMpuRasr) = 0;
    }
    for (uint32_t i = 0; i < count; ++i) {
        reg(kMpuRbar) = regions[i].rbar;
        reg(kMpuRasr) = regions[i].rasr;
    }
    reg(kShcsr) = reg(kShcsr) | (1u << 16) | (1u << 17) | (1u << 18);
    reg(kMpuCtrl) = 1u; // ENABLE; no default map; off in HardFault and NMI handlers
    dsb();
    isb();
    return true;
}

} // namespace facet::cortex_m
