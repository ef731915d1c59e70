// Cortex-M7 vector table and reset handler (libopencm3 style: a plain table with named slots,
// weak-free because every slot is ours), for every Cortex-M7 board: 16 system slots and 160
// interrupt slots (the i.MX RT1062 has 160 interrupts, the mps2 32; unused slots cost nothing).
// The table is placed by the board's linker script (.vectors): at 0 on the mps2, at flash
// offset 0x2000 on the EVKB, where the boot ROM takes SP and PC from it.
#include <cstdint>

extern "C" {
extern uint32_t __stack_end[];
void Reset_Handler();
void Fault_Handler();
void Unexpected_Handler();
}

namespace {

using Handler = void (*)();
constexpr unsigned kIrqs = 160;

struct VectorTable {
    uint32_t* initial_sp;
    Handler reset, nmi, hard_fault, mem_manage, bus_fault, usage_fault;
    Handler reserved1[4];
    Handler svcall, debug_monitor;
    Handler reserved2;
    Handler pendsv, systick;
    Handler irq[kIrqs];
};

constexpr VectorTable make_table() {
    VectorTable t{};
    t.initial_sp = __stack_end;
    t.reset = Reset_Handler;
    t.nmi = Unexpected_Handler;
    t.hard_fault = Fault_Handler;
    t.mem_manage = Fault_Handler;
    t.bus_fault = Fault_Handler;
    t.usage_fault = Fault_Handler;
    t.svcall = t.debug_monitor = t.pendsv = t.systick = Unexpected_Handler;
    // Interrupts stay disabled in facet (polled drivers keep instruction counts exact), so every
    // IRQ slot points at the handler that reports an unexpected exception.
    for (Handler& h : t.irq) h = Unexpected_Handler;
    return t;
}

} // namespace

extern "C" __attribute__((section(".vectors"), used, aligned(1024))) const VectorTable facet_vector_table = make_table();

extern "C" void board_reset();

// Runs before .data and .bss exist and before the FPU is on: no floating point here, and
// nothing that reads a static. The FPU must be enabled before any hard-float code runs.
// Interrupts: every NVIC source off (ICER0..7), SysTick stopped, pending SysTick and PendSV
// cleared — whatever a boot ROM left — and PRIMASK clear, so the faults (MemManage, BusFault,
// UsageFault) are taken as themselves and report their cause rather than escalating to
// HardFault (PRIMASK would mask them).
extern "C" __attribute__((naked, noreturn)) void Reset_Handler() {
    asm volatile(
        "ldr r0, =0xE000ED88\n"  // CPACR
        "ldr r1, [r0]\n"
        "orr r1, r1, #(0xF << 20)\n" // CP10, CP11: full access
        "str r1, [r0]\n"
        "ldr r0, =0xE000E180\n"  // NVIC_ICER0..7: disable every interrupt source
        "mvn r1, #0\n"
        "movs r2, #8\n"
        "1: str r1, [r0], #4\n"
        "subs r2, r2, #1\n"
        "bne 1b\n"
        "ldr r0, =0xE000E010\n"  // SYST_CSR: SysTick off
        "movs r1, #0\n"
        "str r1, [r0]\n"
        "ldr r0, =0xE000ED04\n"  // ICSR: PENDSTCLR, PENDSVCLR
        "ldr r1, =0x0A000000\n"
        "str r1, [r0]\n"
        "dsb\n"
        "isb\n"
        "cpsie i\n"
        "b board_reset\n");
}
