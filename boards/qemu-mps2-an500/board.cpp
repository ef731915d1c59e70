// QEMU mps2-an500 board: reset sequence and the memory report.
#include "cortex_m.h"
#include "hal/board.h"
#include "memory_report.h"
#include "peripherals.h"
#include "runtime.h"

extern "C" [[noreturn]] void board_reset() {
    using namespace facet;
    runtime::init_memory();
    // Report MemManage, BusFault and UsageFault as themselves rather than as HardFault.
    cortex_m::reg(cortex_m::kShcsr) |= (1u << 16) | (1u << 17) | (1u << 18);
    mps2::start_peripherals();
    runtime::run_main();
}

extern "C" uint8_t __text_start[], __text_end[], __data_start[], __data_end[], __bss_start[],
    __bss_end[], __framebuffers_start[], __framebuffers_end[], __zbuffer_start[], __zbuffer_end[],
    __arena_start[], __arena_end[], __free_start[], __stack_start[], __stack_end[];

namespace facet::hal {

FreeRam free_ram() { return {__free_start, size_t(__arena_end - __free_start)}; }

uint32_t memory_map(MemoryRegion* out, uint32_t max) {
    static const boards::LinkerSpan spans[] = {
        {"text+rodata", __text_start, __text_end},
        {"data", __data_start, __data_end},
        {"bss", __bss_start, __bss_end},
        {"framebuffers", __framebuffers_start, __framebuffers_end},
        {"zbuffer", __zbuffer_start, __zbuffer_end},
        {"arena", __arena_start, __arena_end},
        {"stack", __stack_start, __stack_end},
    };
    return boards::fill_memory_map(spans, sizeof spans / sizeof spans[0], out, max);
}

} // namespace facet::hal
