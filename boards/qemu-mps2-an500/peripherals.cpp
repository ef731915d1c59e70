// QEMU mps2-an500 peripherals: the driver singletons, the board handle (its memory card an image
// on the host, read through semihosting: QEMU's mps2 has no SD slot), the exit through
// semihosting and the screenshot capture. Shared by the mps2 and the EVKB stand-in, which
// differ only in their memory (board.cpp of each).
#include "card_semihosted.h"
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
qemu::SemihostedCard card;
hal::Board the_board{board_config::kName, console, clock, display, input, &qemu::runner(), &card};
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
    const Rgb565* frame = mps2::display.frame();
    if (!frame) {
        print(mps2::console, "capture {}: no frame shown\n", name);
        return Status::NotFound;
    }
    return dump(name, frame, board_config::kDisplayWidth, board_config::kDisplayHeight);
}

} // namespace facet::qemu
