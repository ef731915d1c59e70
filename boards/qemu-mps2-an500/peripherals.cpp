// QEMU mps2-an500 peripherals: the driver singletons, the board handle, the exit through
// semihosting and the screenshot capture. Shared by the mps2 and the EVKB stand-in, which
// differ only in their memory (board.cpp of each).
#include "clock_dualtimer.h"
#include "console_uart.h"
#include "display_ram.h"
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"
#include "input_uart.h"
#include "peripherals.h"
#include "qemu/capture.h"
#include "semihosting.h"

namespace facet::mps2 {
namespace {
CmsdkUart console;
DualTimerClock clock;
RamDisplay display;
boards::UartInput input(console);
hal::Board the_board{board_config::kName, console, clock, display, input};
} // namespace

void start_peripherals() {
    console.init();
    clock.init();
}

} // namespace facet::mps2

namespace facet::hal {

Board& board() { return mps2::the_board; }

[[noreturn]] void exit(int code) { semihosting::exit(code); }

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
