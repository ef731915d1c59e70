#pragma once
// The Cortex-M7 memory protection unit, planned from the board's memories (ARMv7-M ARM, "Protected
// Memory System Architecture, PMSAv7"): a region is a power-of-two block aligned to its size,
// split in eight subregions that can each be left out; where regions overlap the one with the
// higher number wins; an address in no region faults (the MPU is enabled without the default
// map, PRIVDEFENA = 0) — so nothing past the board's memories can be read or written.
//
// plan() is plain arithmetic (tested on the host: tests/boards/evkb_regs_test.cpp); program()
// writes the registers.
#include <cstdint>

namespace facet::cortex_m {

enum class Memory : uint8_t {
    Device,    // peripherals: strongly ordered enough for registers, never executed
    Code,      // flash: read-only, executable, cached write-through
    Tcm,       // tightly coupled memory: read-write, executable (ITCM code), never cached
    Data,      // RAM: read-write, not executable, cached write-back with write allocate
    Scanout,   // frames a display controller reads: write-through, so it sees every store
    NoAccess,  // a hole inside another region (a null-pointer guard)
};

struct Range {
    uint32_t base;
    uint32_t bytes;
    Memory kind;
};

struct MpuRegion {
    uint32_t rbar; // base | VALID | region number
    uint32_t rasr; // attributes, subregions, size, ENABLE
};

constexpr uint32_t kMaxMpuRegions = 16;

// MPU regions for `ranges`, in order (a later range wins where they overlap): each range in
// the smallest aligned power-of-two block holding it, with the subregions it does not touch
// left out; a range that is not subregion-aligned is rounded outwards. Returns how many, or 0
// when one of the ranges is empty or there are more than `max`.
uint32_t plan(const Range* ranges, uint32_t count, MpuRegion* out, uint32_t max);

// What a region covers, for tests and reports: [base, base + size) minus disabled subregions.
bool covers(const MpuRegion& r, uint32_t address);
uint32_t region_size(const MpuRegion& r);

// Loads the regions and enables the MPU (and the MemManage, BusFault and UsageFault handlers).
// False, with nothing changed, when the core has fewer regions than `count`.
bool program(const MpuRegion* regions, uint32_t count);
// How many data regions the core's MPU has (MPU_TYPE.DREGION).
uint32_t mpu_regions();

} // namespace facet::cortex_m
