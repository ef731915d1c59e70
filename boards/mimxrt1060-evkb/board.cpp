// NXP MIMXRT1060-EVKB: the reset sequence, the driver singletons, the board's hal functions.
//
// The boot ROM has run the image's DCD (SDRAM is up, every module clock on) and jumped to
// Reset_Handler (boards/cortex-m/vectors.cpp) with SP from the vector table; the core runs at
// the ROM's speed from flash. Then, in order: the watchdogs off, the hot code into ITCM, the
// vector table, .data and .bss, the MPU and the caches, 600 MHz, the pins, the console and the
// clock, the panel's reset, the touch controller (which one answers says which panel is on the
// connector, and so its timings), the LCD controller, the backlight, the microSD slot; then
// facet_main.
#include "clocks.h"
#include "cortex_m.h"
#include "facet_board_config.h"
#include "gpt.h"
#include "hal/board.h"
#include "hal/print.h"
#include "imxrt1062.h"
#include "input.h"
#include "lcdif.h"
#include "lpi2c.h"
#include "lpuart.h"
#include "memory.h"
#include "mmio.h"
#include "pins.h"
#include "runtime.h"
#include "touch.h"
#include "usdhc.h"

#include <initializer_list>

extern "C" uint32_t __vectors_start[];

namespace facet::evkb {
namespace {
Lpuart console(lpuart::kLpuart1);
GptClock clock;
Lcdif display;
Lpi2c i2c(lpi2c::kLpi2c1);
Touch touch;
BoardInput input(console, touch, clock);
UsdhcCard card;
hal::Board the_board{board_config::kName, console, clock, display, input, nullptr, &card};

// The watchdogs the ROM may have left running (WDOG1/2 by fuse; the RTWDOG runs out of reset on
// some parts): off, as NXP's SystemInit does (RM, WDOG: WCR.WDE; RTWDOG: unlock with
// 0xD928C520 in CNT, then CS without EN, with UPDATE).
void watchdogs_off() {
    for (uint32_t wcr : {wdog::kWdog1Wcr, wdog::kWdog2Wcr}) {
        const uint16_t v = mmio::read16(wcr);
        if (v & (1u << 2)) mmio::write16(wcr, uint16_t(v & ~(1u << 2)));
    }
    mmio::write(wdog::kRtwdogCnt, 0xD928C520u);
    mmio::write(wdog::kRtwdogToval, 0xFFFF);
    mmio::write(wdog::kRtwdogCs, (mmio::read(wdog::kRtwdogCs) & ~(1u << 7)) | (1u << 5));
}

void gpio_output(uint32_t port, uint32_t pin, bool high) {
    mmio::modify(port + gpio::kDr, 1u << pin, high ? 1u << pin : 0);
    mmio::modify(port + gpio::kGdir, 1u << pin, 1u << pin);
}

// The panel's reset (GPIO1_IO02: LCD DISP and the GT911's RESET) with the GT911's INT
// (GPIO1_IO11) held low as RESET rises: the GT911 then answers at 0x5D (GT911 datasheet,
// "I2C address selection"; NXP's fsl_gt911.c, address mode 0). Then INT is released.
void panel_reset() {
    gpio_output(gpio::kGpio2, 31, false); // backlight off meanwhile
    gpio_output(gpio::kGpio1, 11, false);
    gpio_output(gpio::kGpio1, 2, false);
    mmio::delay_us(1000);
    mmio::modify(gpio::kGpio1 + gpio::kDr, 1u << 2, 1u << 2);
    mmio::delay_us(5000);
    mmio::modify(gpio::kGpio1 + gpio::kGdir, 1u << 11, 0); // INT: an input again
    mmio::delay_us(50000);
}

} // namespace
} // namespace facet::evkb

namespace facet::evkb::mmio {
void delay_us(uint32_t us) {
    const uint64_t end = clock.ticks() + us;
    while (clock.ticks() < end) {
    }
}
} // namespace facet::evkb::mmio

extern "C" [[noreturn]] void board_reset() {
    using namespace facet;
    using namespace facet::evkb;
    watchdogs_off();
    load_itcm();
    cortex_m::reg(cortex_m::kVtor) = uint32_t(reinterpret_cast<uintptr_t>(__vectors_start));
    runtime::init_memory();
    const uint32_t regions = protect_memory();
    clocks_init();
    pins_init();
    console.init(uart_hz(kClocks), 115200);
    clock.init();
    print(console, "\n@boot {} core {} MHz\n", board_config::kName, core_hz(kClocks) / 1'000'000);
    if (regions) print(console, "@mpu {} regions of {}, caches on\n", regions, cortex_m::mpu_regions());
    else print(console, "board: the MPU has fewer regions than the memory plan; running unprotected\n");

    panel_reset();
    i2c.init(kI2c100kHzAt10MHz);
    const PanelTiming* panel = &kRk043fn66hs;
    if (Result r = touch.probe(i2c, board_config::kDisplayWidth, board_config::kDisplayHeight); r.ok()) {
        if (touch.chip() == Touch::Chip::Ft5406) panel = &kRk043fn02h;
        print(console, "@touch {} panel {}\n", touch.name(), panel->name);
    } else {
        print(console, "@touch none: {} ({}); panel {} assumed, keys and SW8 only\n", r, r.status, panel->name);
    }
    display.init(*panel);
    mmio::modify(gpio::kGpio2 + gpio::kDr, 1u << 31, 1u << 31); // backlight on
    // SW8 (GPIO5_IO00): an input (GDIR bit 0 clear, its reset state).
    mmio::modify(gpio::kGpio5 + gpio::kGdir, 1u, 0);
    card.init(); // the microSD slot: its pins, power and clock (the card is started when the viewer asks)
    print(console, "@card_slot uSDHC1 {}\n", card.present() ? "card in" : "empty");
    runtime::run_main();
}

namespace facet::hal {

Board& board() { return evkb::the_board; }

// A board has no host to return to: say so, and halt (the RESET button restarts).
[[noreturn]] void exit(int code) {
    print(evkb::console, "@halt {} (press RESET to start again)\n", code);
    for (;;) asm volatile("wfi");
}

} // namespace facet::hal
