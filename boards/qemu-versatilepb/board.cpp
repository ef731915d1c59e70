// QEMU versatilepb board: reset sequence, driver singletons, captures and the memory report.
#include "card_pl181.h"
#include "clock_sp804.h"
#include "console_pl011.h"
#include "display_pl110.h"
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"
#include "memory_report.h"
#include "input_uart.h"
#include "mouse_pl050.h"
#include "qemu/capture.h"
#include "runtime.h"
#include "semihosting.h"
#include "stack.h"

namespace facet::versatilepb {
void mmu_enable();

namespace {
Pl011Console console;
Sp804Clock clock;
Pl110Display display;
boards::UartInput uart_input(console);
Pl050Mouse mouse;
bool mouse_ok = false;
Pl181Card card;

// Keys from the UART and the PS/2 mouse, in one stream.
class BoardInput final : public hal::Input {
public:
    bool poll(hal::InputEvent& event) override {
        return (mouse_ok && mouse.poll(event)) || uart_input.poll(event);
    }
} input;
hal::Board the_board{board_config::kName, console, clock, display, input, &qemu::runner(), &card};
} // namespace
} // namespace facet::versatilepb

extern "C" [[noreturn]] void board_reset() {
    using namespace facet;
    runtime::init_memory();
    versatilepb::mmu_enable();
    versatilepb::console.init();
    versatilepb::clock.init();
    versatilepb::display.init();
    versatilepb::mouse_ok = versatilepb::mouse.init();
    runtime::run_main();
}

// Linker-script symbols describing RAM use.
extern "C" uint8_t __text_start[], __text_end[], __data_start[], __data_end[], __bss_start[],
    __bss_end[], __framebuffers_start[], __framebuffers_end[], __zbuffer_start[], __zbuffer_end[],
    __arena_start[], __arena_end[], __free_start[], __mmu_table_start[], __mmu_table_end[], __stack_start[],
    __stack_end[];

namespace facet::hal {

Board& board() { return versatilepb::the_board; }

[[noreturn]] void exit(int code) { semihosting::exit(code); }

FreeRam free_ram() { return {__free_start, size_t(__arena_end - __free_start)}; }

uint32_t memory_map(MemoryRegion* out, uint32_t max) {
    static const boards::LinkerSpan spans[] = {
        {"text+rodata", __text_start, __text_end},
        {"data", __data_start, __data_end},
        {"bss", __bss_start, __bss_end},
        {"framebuffers", __framebuffers_start, __framebuffers_end},
        {"zbuffer", __zbuffer_start, __zbuffer_end},
        {"arena", __arena_start, __arena_end},
        {"mmu_table", __mmu_table_start, __mmu_table_end},
        {"stack", __stack_start, __stack_end},
    };
    return boards::fill_memory_map(spans, sizeof spans / sizeof spans[0], out, max);
}

} // namespace facet::hal

namespace facet::qemu {

Status capture(const char* name) {
    // The host runner takes the screendump over QMP when it reads this line, then sends ACK.
    // Without a runner (no ACK within 2 s) the firmware carries on.
    versatilepb::Pl011Console& con = versatilepb::console;
    print(con, "@shot {}\n", name);
    const uint64_t deadline = versatilepb::clock.ticks() + 2 * uint64_t(versatilepb::clock.ticks_per_second());
    while (versatilepb::clock.ticks() < deadline) {
        const int c = con.read_hardware();
        if (c == 0x06) return Status::Ok;
        if (c >= 0) con.keep(static_cast<uint8_t>(c));
    }
    print(con, "capture {}: no acknowledgement from the host\n", name);
    return Status::Io;
}

} // namespace facet::qemu
