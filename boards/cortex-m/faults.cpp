// Fault reports for the Cortex-M7 boards: the fault status registers (CFSR, HFSR), the fault
// addresses when valid (MMFAR for the MPU, BFAR for the bus) and the stacked pc and lr, on the
// console; then hal::exit (QEMU: a non-zero exit code; a board: it halts, reset restarts it).
#include "cortex_m.h"
#include "hal/board.h"
#include "hal/print.h"

#include <cstdint>

extern "C" [[noreturn]] void board_fault(const uint32_t* frame, uint32_t exc_return) {
    using namespace facet;
    using namespace facet::cortex_m;
    uint32_t ipsr;
    asm volatile("mrs %0, ipsr" : "=r"(ipsr));
    hal::Console& con = hal::board().console;
    const uint32_t cfsr = reg(kCfsr);
    print(con, "\n*** fault: exception {} at pc {} (lr {}, EXC_RETURN {})\n", ipsr & 0x1FF,
          hex(frame[6]), hex(frame[5]), hex(exc_return));
    print(con, "*** CFSR {} HFSR {}\n", hex(cfsr), hex(reg(kHfsr)));
    if (cfsr & (1u << 15)) print(con, "*** BFAR {} (bus fault address)\n", hex(reg(kBfar)));
    if (cfsr & (1u << 7)) print(con, "*** MMFAR {} (memory management fault address)\n", hex(reg(kMmfar)));
    hal::exit(64 + static_cast<int>(ipsr & 0xFF));
}

// The stacked exception frame is on MSP or PSP depending on bit 2 of EXC_RETURN (lr).
extern "C" __attribute__((naked)) void Fault_Handler() {
    asm volatile(
        "tst lr, #4\n"
        "ite eq\n"
        "mrseq r0, msp\n"
        "mrsne r0, psp\n"
        "mov r1, lr\n"
        "b board_fault\n");
}

extern "C" void Unexpected_Handler() { Fault_Handler(); }
