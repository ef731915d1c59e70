#pragma once
// Cortex-M7 system registers (ARMv7-M Architecture Reference Manual, "System Control Space";
// Cortex-M7 Technical Reference Manual, "Memory Protection Unit", "Level 1 caches"), for the
// boards with that core: the fault report, the MPU and the caches.
#include <cstdint>

namespace facet::cortex_m {

inline volatile uint32_t& reg(uintptr_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }

// System control block.
constexpr uintptr_t kVtor = 0xE000ED08;   // vector table offset
constexpr uintptr_t kCcr = 0xE000ED14;    // configuration and control: DC bit 16, IC bit 17
constexpr uintptr_t kShcsr = 0xE000ED24;  // MEMFAULTENA 16, BUSFAULTENA 17, USGFAULTENA 18
constexpr uintptr_t kCfsr = 0xE000ED28;
constexpr uintptr_t kHfsr = 0xE000ED2C;
constexpr uintptr_t kMmfar = 0xE000ED34;
constexpr uintptr_t kBfar = 0xE000ED38;
constexpr uintptr_t kCpacr = 0xE000ED88;
constexpr uint32_t kCcrDc = 1u << 16, kCcrIc = 1u << 17;

// Cache identification and maintenance.
constexpr uintptr_t kCcsidr = 0xE000ED80; // sets 27:13, associativity 12:3, line size 2:0
constexpr uintptr_t kCsselr = 0xE000ED84; // 0: level 1 data cache
constexpr uintptr_t kIciallu = 0xE000EF50;
constexpr uintptr_t kDcisw = 0xE000EF60;   // invalidate by set/way
constexpr uintptr_t kDccmvac = 0xE000EF68; // clean by address to the point of coherency

// Memory protection unit (PMSAv7).
constexpr uintptr_t kMpuType = 0xE000ED90; // DREGION 15:8: how many data regions
constexpr uintptr_t kMpuCtrl = 0xE000ED94; // ENABLE 0, HFNMIENA 1, PRIVDEFENA 2
constexpr uintptr_t kMpuRnr = 0xE000ED98;
constexpr uintptr_t kMpuRbar = 0xE000ED9C;
constexpr uintptr_t kMpuRasr = 0xE000EDA0;

#if FACET_TARGET
inline void dsb() { asm volatile("dsb 0xF" ::: "memory"); }
inline void isb() { asm volatile("isb 0xF" ::: "memory"); }
#else // drivers compiled on the host against register models (tests/boards)
inline void dsb() { asm volatile("" ::: "memory"); }
inline void isb() { asm volatile("" ::: "memory"); }
#endif

// Level 1 caches: invalidated, then enabled (a no-op when already on, as a boot loader may
// leave them). QEMU has no caches: its maintenance registers accept writes and do nothing.
void enable_caches();
// Cleans the data cache lines over [start, start + bytes) to memory (a DMA reader's view).
void clean_dcache(const void* start, uint32_t bytes);

} // namespace facet::cortex_m
