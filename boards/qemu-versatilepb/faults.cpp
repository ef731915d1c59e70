// Exception reports: every unexpected exception prints what happened and exits non-zero, so a
// fault in QEMU reaches the shell and the test instead of hanging.
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"

#include <cstdint>

namespace {

const char* const kKinds[] = {"undefined instruction", "unexpected SVC", "prefetch abort",
                              "data abort", "unexpected IRQ", "unexpected FIQ"};

// ARMv5 fault status (FS bits [3:0] of DFSR/IFSR).
const char* fault_status(uint32_t fsr) {
    switch (fsr & 0xF) {
    case 0x1: return "alignment fault";
    case 0x5: return "translation fault (section)";
    case 0x7: return "translation fault (page)";
    case 0x9: return "domain fault (section)";
    case 0xD: return "permission fault (section)";
    case 0x8: return "external abort";
    default: return "fault";
    }
}

} // namespace

extern "C" [[noreturn]] void board_fault(uint32_t kind, uint32_t pc) {
    using namespace facet;
    hal::Console& con = hal::board().console;
    print(con, "\n*** {} at pc {}\n", kKinds[kind < 6 ? kind : 0], hex(pc));
    if (kind == 2 || kind == 3) {
        uint32_t fsr, far;
        if (kind == 3) {
            asm volatile("mrc p15, 0, %0, c5, c0, 0" : "=r"(fsr)); // DFSR
            asm volatile("mrc p15, 0, %0, c6, c0, 0" : "=r"(far)); // FAR
        } else {
            asm volatile("mrc p15, 0, %0, c5, c0, 1" : "=r"(fsr)); // IFSR
            far = pc;
        }
        print(con, "*** FSR {} ({}), address {}\n", hex(fsr), fault_status(fsr), hex(far));
        if (far >= board_config::kRamBytes && far < 0x10000000u) {
            print(con, "*** address {} is past the {} MiB RAM budget\n", hex(far),
                  board_config::kRamBytes >> 20);
        }
    }
    hal::exit(64 + static_cast<int>(kind));
}
