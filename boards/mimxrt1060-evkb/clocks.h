#pragma once
// The EVKB's clock tree (IMXRT1060RM, "Clock Controller Module (CCM)", "CCM Analog"): the
// core at 600 MHz from the ARM PLL, the bus clocks, and the roots of the peripherals facet
// uses. The SEMC (SDRAM) clock is the boot ROM's, from the image's DCD (boot_header.cpp):
// PLL2 PFD2 (528 MHz x 18 / 29) / 2 = 163.86 MHz, and is left alone.
#include <cstdint>

namespace facet::evkb {

struct ClockPlan {
    uint32_t osc_hz;          // the 24 MHz crystal
    uint32_t vdd_soc_trg;     // DCDC REG3 TRG: 0.8 V + TRG x 25 mV; 0x12 = 1.25 V, what 600 MHz needs
    uint32_t arm_div_select;  // ARM PLL (PLL1) = osc x DIV_SELECT / 2
    uint32_t arm_podf;        // core = PLL1 / (ARM_PODF + 1)
    uint32_t ahb_podf;        // AHB = core / (AHB_PODF + 1)
    uint32_t ipg_podf;        // IPG = AHB / (IPG_PODF + 1)
    uint32_t perclk_podf;     // PERCLK = IPG / (PERCLK_PODF + 1)
    uint32_t uart_podf;       // UART root = pll3_80m (480 / 6) / (UART_CLK_PODF + 1)
    uint32_t lpi2c_podf;      // LPI2C root = pll3_60m (480 / 8) / (LPI2C_CLK_PODF + 1)
    uint32_t video_div_select;// video PLL (PLL5) = osc x DIV_SELECT, then / post divider
    uint32_t video_post_div;  // POST_DIV_SELECT: 0 = /4, 1 = /2, 2 = /1
    uint32_t video_misc2_div; // MISC2 VIDEO_DIV: 0 = /1, 1 = /2, 3 = /4
    uint32_t lcdif_pred;      // LCDIF pixel clock = PLL5 out / (LCDIF_PRED + 1) / (LCDIF_PODF + 1)
    uint32_t lcdif_podf;
};

// 600 MHz core, 150 MHz IPG, 80 MHz UART, 10 MHz LPI2C, 9.3 MHz pixel clock: NXP's
// BOARD_BootClockRUN settings for this board (its SDK), and the pixel clock of the LCD examples.
constexpr ClockPlan kClocks{24'000'000, 0x12, 100, 1, 0, 3, 0, 0, 5, 31, 0, 1, 4, 1};

constexpr uint32_t core_hz(const ClockPlan& p) {
    return uint32_t(uint64_t(p.osc_hz) * p.arm_div_select / 2 / (p.arm_podf + 1));
}
constexpr uint32_t ahb_hz(const ClockPlan& p) { return core_hz(p) / (p.ahb_podf + 1); }
constexpr uint32_t ipg_hz(const ClockPlan& p) { return ahb_hz(p) / (p.ipg_podf + 1); }
constexpr uint32_t uart_hz(const ClockPlan& p) { return 80'000'000 / (p.uart_podf + 1); }
constexpr uint32_t lpi2c_hz(const ClockPlan& p) { return 60'000'000 / (p.lpi2c_podf + 1); }
constexpr uint32_t video_post(const ClockPlan& p) { return p.video_post_div == 0 ? 4 : p.video_post_div == 1 ? 2 : 1; }
constexpr uint32_t video_misc(const ClockPlan& p) { return p.video_misc2_div == 3 ? 4 : p.video_misc2_div == 1 ? 2 : 1; }
constexpr uint32_t pixel_hz(const ClockPlan& p) {
    return uint32_t(uint64_t(p.osc_hz) * p.video_div_select / video_post(p) / video_misc(p) / (p.lcdif_pred + 1) /
                    (p.lcdif_podf + 1));
}

static_assert(core_hz(kClocks) == 600'000'000, "the budgets are set at 600 MHz");
static_assert(ipg_hz(kClocks) == 150'000'000, "IPG at most 150 MHz (RM, CCM: clock root limits)");

// Raises VDD_SOC, brings the core to 600 MHz, sets the peripheral roots and the video PLL.
// Runs from flash (XIP) before anything else is clocked from these roots; leaves the SEMC
// clock and the FlexSPI clock (the code being executed) as the boot ROM set them.
void clocks_init(const ClockPlan& plan = kClocks);

} // namespace facet::evkb
