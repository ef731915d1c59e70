#include "memory.h"

#include "cortex_m.h"
#include "hal/board.h"
#include "memory_report.h"

#include <cstdint>

extern "C" uint8_t __itcm_start[], __itcm_end[], __itcm_load[], __itcm_origin[], __itcm_limit[], __dtcm_origin[],
    __dtcm_limit[], __ocram_origin[], __ocram_limit[], __sdram_origin[], __sdram_limit[], __flash_device_start[],
    __flash_device_end[], __data_start[], __data_end[], __bss_start[], __bss_end[], __stack_start[], __stack_end[],
    __zbuffer_start[], __zbuffer_end[], __framebuffers_start[], __framebuffers_end[], __arena_start[], __arena_end[], __free_start[],
    __pack_memory_start[], __pack_memory_end[];

namespace facet::evkb {
namespace {
uint32_t address(const uint8_t* p) { return uint32_t(reinterpret_cast<uintptr_t>(p)); }
uint32_t span(const uint8_t* a, const uint8_t* b) { return address(b) - address(a); }
} // namespace

// A plain word loop the compiler must not turn into a memcpy call: memcpy may itself be ITCM code.
__attribute__((optimize("no-tree-loop-distribute-patterns"))) void load_itcm() {
    const uint32_t* src = reinterpret_cast<const uint32_t*>(__itcm_load);
    for (uint32_t* dst = reinterpret_cast<uint32_t*>(__itcm_start); dst < reinterpret_cast<uint32_t*>(__itcm_end);)
        *dst++ = *src++;
    cortex_m::dsb();
    cortex_m::isb();
}

uint32_t memory_ranges(cortex_m::Range* out, uint32_t max) {
    using cortex_m::Memory;
    const cortex_m::Range ranges[] = {
        // i.MX RT1060 RM, "Memory Maps": AIPS-1..4 peripherals from 0x40000000 (and the
        // mps2's UART and timers there too, for the stand-in).
        {0x40000000u, 0x20000000u, Memory::Device},
        {address(__itcm_origin), span(__itcm_origin, __itcm_limit), Memory::Tcm},
        {address(__dtcm_origin), span(__dtcm_origin, __dtcm_limit), Memory::Data},
        {address(__ocram_origin), span(__ocram_origin, __ocram_limit), Memory::Data},
        {address(__flash_device_start), span(__flash_device_start, __flash_device_end), Memory::Code},
        {address(__sdram_origin), span(__sdram_origin, __sdram_limit), Memory::Data},
        {address(__framebuffers_start), span(__framebuffers_start, __framebuffers_end), Memory::Scanout},
        {address(__itcm_origin), 32, Memory::NoAccess},
    };
    uint32_t n = 0;
    for (const cortex_m::Range& r : ranges) { // a program without frames has no frames' region
        if (r.bytes == 0) continue;
        if (n == max) return 0;
        out[n++] = r;
    }
    return n;
}

uint32_t protect_memory() {
    cortex_m::Range ranges[8];
    cortex_m::MpuRegion regions[8];
    const uint32_t n = cortex_m::plan(ranges, memory_ranges(ranges, 8), regions, 8);
    if (n == 0 || !cortex_m::program(regions, n)) return 0;
    cortex_m::enable_caches();
    return n;
}

} // namespace facet::evkb

namespace facet::hal {

FreeRam free_ram() { return {__free_start, size_t(__arena_end - __free_start)}; }

// RAM only: the code executed in place and the pack stay in flash.
uint32_t memory_map(MemoryRegion* out, uint32_t max) {
    static const boards::LinkerSpan spans[] = {
        {"itcm", __itcm_start, __itcm_end},
        {"data", __data_start, __data_end},
        {"bss", __bss_start, __bss_end},
        {"zbuffer", __zbuffer_start, __zbuffer_end},
        {"framebuffers", __framebuffers_start, __framebuffers_end},
        {"arena", __arena_start, __arena_end},
        {"stack", __stack_start, __stack_end},
        {"pack", __pack_memory_start, __pack_memory_end},
    };
    return boards::fill_memory_map(spans, sizeof spans / sizeof spans[0], out, max);
}

} // namespace facet::hal
