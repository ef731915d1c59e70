// The MIMXRT1060-EVKB's configuration on QEMU's mps2-an500: the EVKB's start-up for memory
// (ITCM loaded from flash, the vector table in flash, the MPU plan, the caches) with the mps2's
// peripherals. What differs from the EVKB is only what QEMU's mps2 lacks: clocks, pins, the
// LCD controller and the touch panel (boards/mimxrt1060-evkb: tested on the host against
// register models, tests/boards/).
#include "cortex_m.h"
#include "hal/board.h"
#include "hal/print.h"
#include "memory.h"
#include "peripherals.h"
#include "runtime.h"

extern "C" uint32_t __vectors_start[], __stack_end[];
extern "C" void Reset_Handler();

// The two words the core reads from address 0 at reset (the EVKB's boot ROM takes them from the
// vector table the IVT names); QEMU loads them with the image.
struct ResetVector {
    uint32_t* sp;
    void (*pc)();
};
extern "C" __attribute__((section(".reset_vector"), used)) const ResetVector facet_reset_vector = {__stack_end,
                                                                                                   Reset_Handler};

extern "C" [[noreturn]] void board_reset() {
    using namespace facet;
    evkb::load_itcm();
    cortex_m::reg(cortex_m::kVtor) = uint32_t(reinterpret_cast<uintptr_t>(__vectors_start));
    runtime::init_memory();
    const uint32_t regions = evkb::protect_memory();
    mps2::start_peripherals();
    if (!regions) {
        print(hal::board().console, "board: the MPU has fewer regions than the memory plan\n");
        hal::exit(70);
    }
    print(hal::board().console, "@mpu {} regions of {}, caches on\n", regions, cortex_m::mpu_regions());
    runtime::run_main();
}
