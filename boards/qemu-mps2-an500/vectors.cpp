// Cortex-M7 vector table and reset handler for QEMU mps2-an500 (libopencm3 style: a plain
// table with named slots, weak-free because every slot is ours).
#include "memory_map.h"

#include <cstdint>

extern "C" {
extern uint32_t __stack_end[];
void Reset_Handler();
void Fault_Handler();
void Unexpected_Handler();
}

namespace {

using Handler = void (*)();

struct VectorTable {
    uint32_t* initial_sp;
    Handler reset, nmi, hard_fault, mem_manage, bus_fault, usage_fault;
    Handler reserved1[4];
    Handler svcall, debug_monitor;
    Handler reserved2;
    Handler pendsv, systick;
    Handler irq[32];
};

} // namespace

// Interrupts stay disabled in facet (polled drivers keep instruction counts exact), so every
// IRQ slot points at the handler that reports an unexpected exception.
__attribute__((section(".vectors"), used)) const VectorTable vector_table = {
    .initial_sp = __stack_end,
    .reset = Reset_Handler,
    .nmi = Unexpected_Handler,
    .hard_fault = Fault_Handler,
    .mem_manage = Fault_Handler,
    .bus_fault = Fault_Handler,
    .usage_fault = Fault_Handler,
    .reserved1 = {},
    .svcall = Unexpected_Handler,
    .debug_monitor = Unexpected_Handler,
    .reserved2 = nullptr,
    .pendsv = Unexpected_Handler,
    .systick = Unexpected_Handler,
    .irq = {Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler,
            Unexpected_Handler, Unexpected_Handler, Unexpected_Handler, Unexpected_Handler},
};

extern "C" void board_reset();

// Runs before .data and .bss exist and before the FPU is on: no floating point here, and
// nothing that reads a static. The FPU must be enabled before any hard-float code runs.
extern "C" __attribute__((naked, noreturn)) void Reset_Handler() {
    asm volatile(
        "ldr r0, =0xE000ED88\n"  // CPACR
        "ldr r1, [r0]\n"
        "orr r1, r1, #(0xF << 20)\n" // CP10, CP11: full access
        "str r1, [r0]\n"
        "dsb\n"
        "isb\n"
        "cpsid i\n"              // polled drivers: no interrupts
        "b board_reset\n");
}
