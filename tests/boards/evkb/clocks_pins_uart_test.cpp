// The EVKB's clock tree, pins and console UART on the host against the register model
// (register_model.h), checked against the reference manual's formulas and the board's schematic.
#include "register_model.h"

#include "clocks.h"
#include "imxrt1062.h"
#include "lpuart.h"
#include "pins.h"

#include <gtest/gtest.h>

#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace facet;
using namespace facet::evkb;
using namespace facet::evkb::test;

// --- Clocks --------------------------------------------------------------------------------

// PLLs lock, dividers never busy, the DCDC reports its output in range.
void clock_hardware(uint32_t initial) {
    for (uint32_t a : {ccm::kCbcdr, ccm::kCbcmr, ccm::kCscmr1, ccm::kCscdr1, ccm::kCscdr2, analog::kMisc2})
        model.regs[a] = initial;
    model.regs[ccm::kCbcdr] = (initial & ~0x000700C0u) | 0x00010040u; // SEMC fields as the DCD left them
    model.read_hook = [](uint32_t a, uint32_t& v) {
        if (a == analog::kPllArm || a == analog::kPllVideo || a == analog::kBase + 0x10) {
            v = model.regs[a] | analog::kLock;
            return true;
        }
        if (a == ccm::kCdhipr) return v = 0, true;
        if (a == dcdc::kReg0) return v = 1u << 31, true;
        return false;
    };
}

class Clocks : public ::testing::TestWithParam<uint32_t> {};

TEST_P(Clocks, CoreAt600MHzAndEveryRootByTheManualsFormulas) {
    reset_model();
    clock_hardware(GetParam());
    clocks_init();
    // VDD_SOC: 0.8 V + TRG x 25 mV = 1.25 V, the 600 MHz (overdrive) operating point, set before
    // the ARM PLL changes.
    EXPECT_EQ(field(model.last(dcdc::kReg3), 4, 0), 0x12u);
    EXPECT_LT(model.index_of_first(dcdc::kReg3), model.index_of_first(analog::kPllArm));
    // The core leaves the PLL for the oscillator (PERIPH_CLK_SEL 1) before the ARM PLL is
    // touched, and comes back (0) after it locked and the dividers were set.
    const int to_osc = model.index_of_first(ccm::kCbcdr, [](uint32_t v) { return (v >> 25) & 1; });
    const int pll = model.index_of_first(analog::kPllArm);
    const int podf = model.index_of_first(ccm::kCacrr);
    int back = -1;
    for (size_t i = pll; i < model.log.size(); ++i)
        if (model.log[i].address == ccm::kCbcdr && !((model.log[i].value >> 25) & 1)) back = int(i);
    ASSERT_GE(to_osc, 0);
    EXPECT_LT(to_osc, pll);
    EXPECT_GT(back, podf);
    EXPECT_EQ(field(model.last(ccm::kCbcmr), 13, 12), 1u) << "periph_clk2 from the oscillator while switching";

    // ARM PLL: Fout = 24 MHz x DIV_SELECT / 2, DIV_SELECT in 54..108; enabled, not bypassed.
    const uint32_t arm = model.last(analog::kPllArm);
    const uint32_t div = field(arm, 6, 0);
    EXPECT_GE(div, 54u);
    EXPECT_LE(div, 108u);
    EXPECT_TRUE(arm & analog::kEnable);
    EXPECT_FALSE(arm & (analog::kBypass | analog::kPowerdown));
    const uint64_t pll1 = 24'000'000ull * div / 2;
    const uint32_t cbcdr = model.last(ccm::kCbcdr), cbcmr = model.last(ccm::kCbcmr);
    EXPECT_EQ(field(cbcmr, 19, 18), 3u) << "pre_periph_clk = PLL1";
    EXPECT_EQ(field(cbcdr, 25, 25), 0u) << "periph_clk = pre_periph_clk";
    const uint64_t core = pll1 / (field(model.last(ccm::kCacrr), 2, 0) + 1);
    const uint64_t ahb = core / (field(cbcdr, 12, 10) + 1);
    const uint64_t ipg = ahb / (field(cbcdr, 9, 8) + 1);
    EXPECT_EQ(core, 600'000'000u);
    EXPECT_EQ(ahb, 600'000'000u);
    EXPECT_EQ(ipg, 150'000'000u);
    // The SEMC clock (the SDRAM in use) is the DCD's: SEMC_CLK_SEL 1, SEMC_ALT_CLK_SEL 0, SEMC_PODF 1.
    EXPECT_EQ(cbcdr & 0x000700C0u, 0x00010040u);

    // UART root: pll3_80m (480 MHz / 6) / (UART_CLK_PODF + 1), UART_CLK_SEL 0.
    const uint32_t cscdr1 = model.last(ccm::kCscdr1);
    EXPECT_EQ(field(cscdr1, 6, 6), 0u);
    EXPECT_EQ(80'000'000u / (field(cscdr1, 5, 0) + 1), 80'000'000u);
    EXPECT_EQ(uart_hz(kClocks), 80'000'000u);
    // LPI2C root: pll3_60m (480 / 8) / (LPI2C_CLK_PODF + 1) = 10 MHz.
    const uint32_t cscdr2 = model.last(ccm::kCscdr2);
    EXPECT_EQ(field(cscdr2, 18, 18), 0u);
    EXPECT_EQ(60'000'000u / (field(cscdr2, 24, 19) + 1), 10'000'000u);
    // PERCLK = IPG / (PERCLK_PODF + 1), PERCLK_CLK_SEL 0.
    EXPECT_EQ(field(model.last(ccm::kCscmr1), 6, 0), 0u);

    // Video PLL: 24 MHz x DIV_SELECT (27..54) in the 648..1300 MHz VCO range, / POST_DIV / VIDEO_DIV;
    // LCDIF root: PLL5 (PRE_CLK_SEL 2) / (PRED + 1) / (PODF + 1).
    const uint32_t video = model.last(analog::kPllVideo);
    const uint32_t vdiv = field(video, 6, 0);
    EXPECT_GE(vdiv, 27u);
    EXPECT_LE(vdiv, 54u);
    EXPECT_TRUE(video & analog::kEnable);
    EXPECT_FALSE(video & (analog::kBypass | analog::kPowerdown));
    const uint64_t vco = 24'000'000ull * vdiv;
    EXPECT_GE(vco, 648'000'000u);
    EXPECT_LE(vco, 1'300'000'000u);
    const uint32_t post = field(video, 20, 19), misc = field(model.last(analog::kMisc2), 31, 30);
    const uint64_t pll5 = vco / (post == 0 ? 4 : post == 1 ? 2 : 1) / (misc == 3 ? 4 : misc == 1 ? 2 : 1);
    EXPECT_EQ(field(cscdr2, 17, 15), 2u);
    EXPECT_EQ(field(cscdr2, 11, 9), 0u);
    const uint64_t pixel = pll5 / (field(cscdr2, 14, 12) + 1) / (field(cbcmr, 25, 23) + 1);
    EXPECT_EQ(pixel, 9'300'000u);
    EXPECT_EQ(pixel_hz(kClocks), 9'300'000u);
}

INSTANTIATE_TEST_SUITE_P(FromAnyStartingValue, Clocks, ::testing::Values(0u, 0xFFFFFFFFu),
                         [](const ::testing::TestParamInfo<uint32_t>& i) {
                             return i.param ? std::string("AllOnes") : std::string("AllZeros");
                         });

// --- Pins (the board's schematic; addresses: RM, IOMUXC, SW_MUX_CTL_PAD_* / SW_PAD_CTL_PAD_*) --

struct ExpectedPin {
    const char* what;
    uint32_t mux, mux_value, pad, pad_value, daisy, daisy_value;
};

TEST(Pins, EveryPinTheBoardUsesAsTheSchematicRoutesIt) {
    std::vector<ExpectedPin> want = {
        {"LPUART1_TX on GPIO_AD_B0_12", 0x401F80EC, 2, 0x401F82DC, 0x10B0, 0, 0},
        {"LPUART1_RX on GPIO_AD_B0_13", 0x401F80F0, 2, 0x401F82E0, 0x10B0, 0, 0},
        {"LPI2C1_SCL on GPIO_AD_B1_00", 0x401F80FC, 0x13, 0x401F82EC, 0xD8B0, 0x401F84CC, 1},
        {"LPI2C1_SDA on GPIO_AD_B1_01", 0x401F8100, 0x13, 0x401F82F0, 0xD8B0, 0x401F84D0, 1},
        {"GPIO1_IO02 (LCD DISP, touch RESET) on GPIO_AD_B0_02", 0x401F80C4, 5, 0x401F82B4, 0x10B0, 0, 0},
        {"GPIO1_IO11 (touch INT) on GPIO_AD_B0_11", 0x401F80E8, 5, 0x401F82D8, 0x10B0, 0, 0},
        {"GPIO2_IO31 (backlight) on GPIO_B1_15", 0x401F81B8, 5, 0x401F83A8, 0x10B0, 0, 0},
        {"GPIO5_IO00 (SW8) on WAKEUP", 0x400A8000, 5, 0x400A8018, 0x1B0A0, 0, 0},
    };
    // LCD_CLK, ENABLE, HSYNC, VSYNC, DATA00..15: GPIO_B0_00..15 and GPIO_B1_00..03, ALT0.
    for (uint32_t n = 0; n < 20; ++n)
        want.push_back({"LCD", 0x401F813C + 4 * n, 0, 0x401F832C + 4 * n, 0x1B0B0, 0, 0});
    reset_model();
    pins_init();
    for (const ExpectedPin& p : want) {
        SCOPED_TRACE(p.what);
        EXPECT_EQ(model.last(p.mux), p.mux_value);
        EXPECT_EQ(model.last(p.pad), p.pad_value);
        if (p.daisy) {
            EXPECT_EQ(model.last(p.daisy), p.daisy_value);
        }
    }
    uint32_t count = 0;
    (void)pin_settings(count);
    EXPECT_EQ(count, want.size()) << "a pin set that this table does not know";
}

// --- LPUART ---------------------------------------------------------------------------------

TEST(Lpuart, Console115200Baud8N1FromThe80MHzRoot) {
    reset_model();
    Lpuart uart(lpuart::kLpuart1);
    uart.init(80'000'000, 115200);
    const uint32_t baud = model.last(lpuart::kLpuart1 + lpuart::kBaud);
    const uint32_t osr = field(baud, 28, 24), sbr = field(baud, 12, 0);
    ASSERT_GE(osr + 1, 4u);
    ASSERT_LE(osr + 1, 32u);
    ASSERT_GE(sbr, 1u);
    // Baud = clock / ((OSR + 1) x SBR) (RM, LPUART "Baud rate generation"), within 1 %.
    const double rate = 80e6 / ((osr + 1) * double(sbr));
    EXPECT_NEAR(rate, 115200.0, 115200.0 * 0.01);
    EXPECT_EQ(bool(baud & (1u << 17)), osr + 1 < 8) << "BOTHEDGE exactly when oversampling is 4..7";
    EXPECT_FALSE(baud & (1u << 13)) << "one stop bit";
    const uint32_t ctrl = model.last(lpuart::kLpuart1 + lpuart::kCtrl);
    EXPECT_TRUE(ctrl & lpuart::kTe);
    EXPECT_TRUE(ctrl & lpuart::kRe);
    EXPECT_FALSE(ctrl & ((1u << 4) | (1u << 1))) << "8 data bits (M 0), no parity (PE 0)";
    // The divisors the driver computes hold at other clocks too.
    for (uint32_t clock : {24'000'000u, 60'000'000u, 80'000'000u, 100'000'000u}) {
        const BaudDivisors d = baud_divisors(clock, 115200);
        EXPECT_NEAR(clock / ((d.osr + 1) * double(d.sbr)), 115200.0, 115200.0 * 0.02) << clock;
    }
}

TEST(Lpuart, ABytesWithAFramingErrorIsDroppedAndTheFlagCleared) {
    reset_model();
    Lpuart uart(lpuart::kLpuart1);
    const uint32_t stat = lpuart::kLpuart1 + lpuart::kStat, data = lpuart::kLpuart1 + lpuart::kData;
    model.regs[stat] = lpuart::kRdrf | (1u << 17); // RDRF and FE
    model.regs[data] = 0xA5;
    EXPECT_EQ(uart.read_byte(), -1);
    EXPECT_EQ(model.last(stat), 1u << 17) << "FE written back (write 1 to clear)";
    EXPECT_EQ(uart.dropped(), 1u);
    model.regs[stat] = lpuart::kRdrf;
    model.regs[data] = 'q';
    EXPECT_EQ(uart.read_byte(), 'q');
    model.regs[stat] = 0;
    EXPECT_EQ(uart.read_byte(), -1);
}


} // namespace
