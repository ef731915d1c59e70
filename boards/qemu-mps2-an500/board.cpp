// QEMU mps2-an500 board: reset sequence, driver singletons, captures and the memory report.
#include "clock_dualtimer.h"
#include "console_uart.h"
#include "display_ram.h"
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"
#include "memory_report.h"
#include "input_uart.h"
#include "memory_map.h"
#include "qemu/capture.h"
#include "runtime.h"
#include "semihosting.h"

namespace facet::mps2 {
namespace {
CmsdkUart console;
DualTimerClock clock;
RamDisplay display;
boards::UartInput input(console);
hal::Board the_board{board_config::kName, console, clock, display, input};
} // namespace
} // namespace facet::mps2

extern "C" [[noreturn]] void board_reset() {
    using namespace facet;
    runtime::init_memory();
    // Report MemManage, BusFault and UsageFault as themselves rather than as HardFault.
    mps2::reg(mps2::kShcsr) |= (1u << 16) | (1u << 17) | (1u << 18);
    mps2::console.init();
    mps2::clock.init();
    runtime::run_main();
}

extern "C" uint8_t __text_start[], __text_end[], __data_start[], __data_end[], __bss_start[],
    __bss_end[], __framebuffers_start[], __framebuffers_end[], __zbuffer_start[], __zbuffer_end[],
    __arena_start[], __arena_end[], __stack_start[], __stack_end[], __pack_start[], __pack_end[];

namespace facet::hal {

Board& board() { return mps2::the_board; }

[[noreturn]] void exit(int code) { semihosting::exit(code); }

uint32_t memory_map(MemoryRegion* out, uint32_t max) {
    static const boards::LinkerSpan spans[] = {
        {"text+rodata", __text_start, __text_end},
        {"data", __data_start, __data_end},
        {"bss", __bss_start, __bss_end},
        {"framebuffers", __framebuffers_start, __framebuffers_end},
        {"zbuffer", __zbuffer_start, __zbuffer_end},
        {"arena", __arena_start, __arena_end},
        {"stack", __stack_start, __stack_end},
        {"pack", __pack_start, __pack_end},
    };
    return boards::fill_memory_map(spans, sizeof spans / sizeof spans[0], out, max);
}

} // namespace facet::hal

namespace facet::qemu {

Status capture(const char* name) {
    constexpr uint16_t w = board_config::kDisplayWidth, h = board_config::kDisplayHeight;
    char path[64];
    if (format(path, sizeof path, "{}.f565", name) >= sizeof path) return Status::OutOfRange;
    const int fd = semihosting::open_for_write(path);
    if (fd < 0) {
        print(mps2::console, "capture {}: cannot open {} on the host\n", name, path);
        return Status::Io;
    }
    const uint8_t header[8] = {'F', '5', '6', '5', uint8_t(w), uint8_t(w >> 8), uint8_t(h),
                               uint8_t(h >> 8)};
    // The Cortex-M7 is little-endian, so the framebuffer is already in F565 pixel order.
    const hal::Rgb565* frame = mps2::display.frame();
    if (!frame) {
        semihosting::close(fd);
        print(mps2::console, "capture {}: no frame shown\n", name);
        return Status::NotFound;
    }
    const bool ok = semihosting::write(fd, header, sizeof header) && semihosting::write(fd, frame, size_t(w) * h * 2);
    semihosting::close(fd);
    if (!ok) return Status::Io;
    print(mps2::console, "@dump {} {}\n", name, path);
    return Status::Ok;
}

} // namespace facet::qemu
