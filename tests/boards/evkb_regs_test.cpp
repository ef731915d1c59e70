// The EVKB's drivers run on the host against register models: every write recorded, the bits
// they poll answered, an I2C bus with a simulated GT911 or FT5406 behind the LPI2C. What they
// wrote is decoded and checked against the reference manual's formulas and the documented
// values — the panels' timings, the I2C specification's limits, the pins of the board's
// schematic — written out here, apart from the drivers' own constants.
#include "clocks.h"
#include "imxrt1062.h"
#include "lcdif.h"
#include "lpi2c.h"
#include "lpuart.h"
#include "mmio.h"
#include "mpu.h"
#include "pins.h"
#include "touch.h"

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

struct Write {
    uint32_t address, value;
};

// The register model: a value per address, the writes in order, hooks for the bits a driver
// polls and for peripherals with behaviour (SET/CLR aliases, the LPI2C's FIFOs).
struct Model {
    std::map<uint32_t, uint32_t> regs;
    std::vector<Write> log;
    std::function<bool(uint32_t, uint32_t&)> read_hook;  // true: answered
    std::function<bool(uint32_t, uint32_t)> write_hook; // true: handled (not stored)
    uint64_t delayed_us = 0;

    uint32_t last(uint32_t address) const {
        for (auto it = log.rbegin(); it != log.rend(); ++it)
            if (it->address == address) return it->value;
        ADD_FAILURE() << "no write to " << std::hex << address;
        return 0;
    }
    bool written(uint32_t address) const {
        for (const Write& w : log)
            if (w.address == address) return true;
        return false;
    }
    int index_of_first(uint32_t address, std::function<bool(uint32_t)> pred = nullptr) const {
        for (size_t i = 0; i < log.size(); ++i)
            if (log[i].address == address && (!pred || pred(log[i].value))) return int(i);
        return -1;
    }
} model;

} // namespace

namespace facet::evkb::mmio {
uint32_t read(uint32_t address) {
    uint32_t v = 0;
    if (model.read_hook && model.read_hook(address, v)) return v;
    return model.regs[address];
}
void write(uint32_t address, uint32_t value) {
    model.log.push_back({address, value});
    if (model.write_hook && model.write_hook(address, value)) return;
    model.regs[address] = value;
}
uint16_t read16(uint32_t address) { return uint16_t(read(address)); }
void write16(uint32_t address, uint16_t value) { write(address, value); }
void delay_us(uint32_t us) { model.delayed_us += us; }
} // namespace facet::evkb::mmio

namespace {

void reset_model() {
    model = Model{};
}

uint32_t field(uint32_t v, int hi, int lo) { return (v >> lo) & ((1u << (hi - lo + 1)) - 1); }

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

// --- eLCDIF and the panels ----------------------------------------------------------------------

// The panels' timings as their makers and NXP give them (independent of lcdif.h's table).
struct PanelSheet {
    const PanelTiming* driver;
    uint32_t hsw, hfp, hbp, vsw, vfp, vbp;
};

void lcdif_hardware() {
    model.write_hook = [](uint32_t a, uint32_t v) {
        if (a == lcdif::kCtrlSet) {
            model.regs[lcdif::kCtrl] |= v;
            if (v & lcdif::kSftrst) model.regs[lcdif::kCtrl] |= lcdif::kClkgate; // the block gates itself
            return true;
        }
        if (a == lcdif::kCtrlClr) return model.regs[lcdif::kCtrl] &= ~v, true;
        if (a == lcdif::kCtrl1Clr) return model.regs[lcdif::kCtrl1] &= ~v, true;
        return false;
    };
}

class Panels : public ::testing::TestWithParam<PanelSheet> {};

TEST_P(Panels, TheControllerSendsThePanelsTimingsAndPolarities) {
    const PanelSheet& s = GetParam();
    const PanelTiming& p = *s.driver;
    reset_model();
    lcdif_hardware();
    Lcdif lcd;
    lcd.init(p);
    static Rgb565 frames[2][4];
    EXPECT_EQ(lcd.show(frames[0]), Status::Ok);
    const uint32_t ctrl = model.regs[lcdif::kCtrl];
    EXPECT_TRUE(ctrl & lcdif::kRun);
    EXPECT_TRUE(ctrl & lcdif::kDotclkMode);
    EXPECT_TRUE(ctrl & lcdif::kMaster);
    EXPECT_TRUE(ctrl & lcdif::kBypassCount);
    EXPECT_FALSE(ctrl & (lcdif::kSftrst | lcdif::kClkgate)) << "out of reset, clock on";
    EXPECT_EQ(field(ctrl, 9, 8), 0u) << "16-bit pixels (RGB565)";
    EXPECT_EQ(field(ctrl, 11, 10), 0u) << "16-bit data bus (the FPC's D0..D15)";
    EXPECT_EQ(field(model.last(lcdif::kCtrl1), 19, 16), 0xFu);
    const uint32_t tc = model.last(lcdif::kTransferCount);
    EXPECT_EQ(field(tc, 15, 0), 480u);
    EXPECT_EQ(field(tc, 31, 16), 272u);
    const uint32_t v0 = model.last(lcdif::kVdctrl0);
    EXPECT_EQ(field(v0, 17, 0), s.vsw);
    EXPECT_TRUE(v0 & (1u << 20)) << "VSYNC pulse width in lines";
    EXPECT_TRUE(v0 & (1u << 21)) << "VSYNC period in lines";
    EXPECT_TRUE(v0 & (1u << 28)) << "DE present";
    EXPECT_TRUE(v0 & (1u << 24)) << "DE active high";
    EXPECT_TRUE(v0 & (1u << 25)) << "data driven on the rising edge";
    EXPECT_FALSE(v0 & (1u << 26)) << "HSYNC active low";
    EXPECT_FALSE(v0 & (1u << 27)) << "VSYNC active low";
    EXPECT_EQ(model.last(lcdif::kVdctrl1), s.vsw + s.vbp + 272 + s.vfp);
    const uint32_t v2 = model.last(lcdif::kVdctrl2);
    EXPECT_EQ(field(v2, 31, 18), s.hsw);
    EXPECT_EQ(field(v2, 17, 0), s.hsw + s.hbp + 480 + s.hfp);
    const uint32_t v3 = model.last(lcdif::kVdctrl3);
    EXPECT_EQ(field(v3, 27, 16), s.hsw + s.hbp);
    EXPECT_EQ(field(v3, 15, 0), s.vsw + s.vbp);
    const uint32_t v4 = model.last(lcdif::kVdctrl4);
    EXPECT_EQ(field(v4, 17, 0), 480u);
    EXPECT_TRUE(v4 & (1u << 18)) << "sync signals on";
    // The frame rate at the 9.3 MHz pixel clock: about 60 Hz.
    const double hz = 9.3e6 / ((s.hsw + s.hbp + 480 + s.hfp) * double(s.vsw + s.vbp + 272 + s.vfp));
    EXPECT_GT(hz, 55.0);
    EXPECT_LT(hz, 65.0);
    const uint32_t first = uint32_t(reinterpret_cast<uintptr_t>(frames[0]));
    EXPECT_EQ(model.last(lcdif::kCurBuf), first);
    EXPECT_EQ(model.last(lcdif::kNextBuf), first);

    // The flip: the next frame's address, taken at the end of the frame being sent.
    model.regs[lcdif::kCtrl1] |= lcdif::kCurFrameDone; // a frame ended long ago
    EXPECT_EQ(lcd.show(frames[1]), Status::Ok);
    EXPECT_EQ(model.last(lcdif::kNextBuf), uint32_t(reinterpret_cast<uintptr_t>(frames[1])));
    EXPECT_TRUE(lcd.busy()) << "until the controller finishes the frame on the glass";
    model.regs[lcdif::kCtrl1] |= lcdif::kCurFrameDone;
    EXPECT_FALSE(lcd.busy());
}

INSTANTIATE_TEST_SUITE_P(Rk043, Panels,
                         ::testing::Values(PanelSheet{&kRk043fn66hs, 4, 8, 43, 4, 8, 12},
                                           PanelSheet{&kRk043fn02h, 41, 4, 8, 10, 4, 2}),
                         [](const ::testing::TestParamInfo<PanelSheet>& i) {
                             return i.param.driver == &kRk043fn66hs ? std::string("RK043FN66HS") : std::string("RK043FN02H");
                         });

// --- LPI2C and the touch controllers ---------------------------------------------------------------

// An I2C device behind the simulated bus: register reads and writes with an address pointer.
struct Device {
    uint8_t address = 0;
    uint32_t address_bytes = 1;                 // 2: the GT911's 16-bit registers
    std::map<uint32_t, uint8_t> mem;
    std::vector<std::vector<uint8_t>> writes;   // every write (the register pointer included)
    uint32_t pointer = 0;
};

// The LPI2C master's commands (MTDR) carried out at once against `devices`: START+address ACKs
// or sets NDF; transmitted bytes go to the selected device; RECEIVE queues bytes; STOP sets SDF.
struct Bus {
    std::vector<Device*> devices;
    Device* selected = nullptr;
    bool reading = false;
    std::vector<uint8_t> pending;
    std::deque<uint8_t> rx;
    std::vector<uint32_t> commands;
    uint32_t msr = 0;

    void attach() {
        const uint32_t base = lpi2c::kLpi2c1;
        model.write_hook = [this, base](uint32_t a, uint32_t v) {
            if (a == base + lpi2c::kMtdr) return command(v), true;
            if (a == base + lpi2c::kMcr && (v & lpi2c::kRrf)) rx.clear();
            if (a == base + lpi2c::kMsr) return msr &= ~(v & 0x3F00), true;
            return false;
        };
        model.read_hook = [this, base](uint32_t a, uint32_t& v) {
            if (a == base + lpi2c::kMsr) return v = msr | lpi2c::kTdf, true;
            if (a == base + lpi2c::kMfsr) return v = uint32_t(rx.size()) << 16, true;
            if (a == base + lpi2c::kMrdr) {
                if (rx.empty()) return v = lpi2c::kRxEmpty, true;
                v = rx.front();
                rx.pop_front();
                return true;
            }
            return false;
        };
    }
    void end_write() {
        if (selected && !reading && !pending.empty()) {
            selected->writes.push_back(pending);
            uint32_t p = 0;
            for (uint32_t i = 0; i < selected->address_bytes && i < pending.size(); ++i) p = p << 8 | pending[i];
            selected->pointer = p;
            for (size_t i = selected->address_bytes; i < pending.size(); ++i) selected->mem[p + uint32_t(i - selected->address_bytes)] = pending[i];
        }
        pending.clear();
    }
    void command(uint32_t v) {
        commands.push_back(v);
        const uint32_t cmd = v & 0x700, data = v & 0xFF;
        if (cmd == lpi2c::kCmdStart) {
            end_write();
            selected = nullptr;
            for (Device* d : devices)
                if (d->address == (data >> 1)) selected = d;
            reading = data & 1;
            if (!selected) msr |= lpi2c::kNdf;
        } else if (cmd == lpi2c::kCmdTransmit) {
            if (selected) pending.push_back(uint8_t(data));
        } else if (cmd == lpi2c::kCmdReceive) {
            if (!selected) return; // nobody acknowledged: nothing comes
            for (uint32_t i = 0; i <= data; ++i) rx.push_back(selected ? selected->mem[selected->pointer++] : 0xFF);
        } else if (cmd == lpi2c::kCmdStop) {
            end_write();
            selected = nullptr;
            msr |= lpi2c::kSdf;
        }
    }
};

TEST(Lpi2c, StandardModeTimingWithinTheI2cSpecification) {
    reset_model();
    Lpi2c i2c(lpi2c::kLpi2c1);
    i2c.init(kI2c100kHzAt10MHz);
    const uint32_t m = model.last(lpi2c::kLpi2c1 + lpi2c::kMccr0);
    const uint32_t clklo = field(m, 5, 0), clkhi = field(m, 13, 8), sethold = field(m, 21, 16), datavd = field(m, 29, 24);
    const double tick = 1.0 / 10e6; // LPI2C root: 10 MHz (clocks.h); PRESCALE 0
    EXPECT_EQ(field(model.last(lpi2c::kLpi2c1 + lpi2c::kMcfgr1), 2, 0), 0u);
    const double period = (clkhi + clklo + 2 + 1) * tick; // SCL_LATENCY 1 with no filter
    EXPECT_LE(1.0 / period, 100e3 * 1.0001) << "at most 100 kHz";
    EXPECT_GE(1.0 / period, 90e3);
    EXPECT_GE((clklo + 1) * tick, 4.7e-6) << "tLOW";
    EXPECT_GE((clkhi + 1 + 1) * tick, 4.0e-6) << "tHIGH";
    EXPECT_GE((sethold + 1) * tick, 4.7e-6) << "tSU;STA and tHD;STA";
    EXPECT_LE((datavd + 1) * tick, 3.45e-6) << "tVD;DAT";
    EXPECT_TRUE(model.last(lpi2c::kLpi2c1 + lpi2c::kMcr) & lpi2c::kMen);
}

Device gt911(uint8_t address, uint16_t res_x, uint16_t res_y) {
    Device d;
    d.address = address;
    d.address_bytes = 2;
    const char id[] = "911";
    for (int i = 0; i < 4; ++i) d.mem[0x8140 + i] = uint8_t(id[i]);
    d.mem[0x8048] = uint8_t(res_x), d.mem[0x8049] = uint8_t(res_x >> 8);
    d.mem[0x804A] = uint8_t(res_y), d.mem[0x804B] = uint8_t(res_y >> 8);
    return d;
}

void gt911_point(Device& d, int slot, uint8_t id, uint16_t x, uint16_t y) {
    const uint32_t p = 0x814F + 8 * slot;
    d.mem[p] = id, d.mem[p + 1] = uint8_t(x), d.mem[p + 2] = uint8_t(x >> 8), d.mem[p + 3] = uint8_t(y),
    d.mem[p + 4] = uint8_t(y >> 8);
}

TEST(Touch, Gt911FoundAt0x5DReadWithTheDocumentedRegisterSequence) {
    reset_model();
    Bus bus;
    Device d = gt911(0x5D, 800, 480); // a GT911 configured for another resolution: scaled
    bus.devices = {&d};
    bus.attach();
    Lpi2c i2c(lpi2c::kLpi2c1);
    Touch touch;
    ASSERT_TRUE(touch.probe(i2c, 480, 272).ok());
    EXPECT_EQ(touch.chip(), Touch::Chip::Gt911);
    // The product ID read: START+W (0xBA), register 0x8140 high byte first, repeated START+R
    // (0xBB), receive 4 bytes, STOP.
    const std::vector<uint32_t> id_read = {lpi2c::kCmdStart | 0xBA, 0x81, 0x40, lpi2c::kCmdStart | 0xBB,
                                           lpi2c::kCmdReceive | 3, lpi2c::kCmdStop};
    ASSERT_GE(bus.commands.size(), id_read.size());
    EXPECT_EQ(std::vector<uint32_t>(bus.commands.begin(), bus.commands.begin() + 6), id_read);

    TouchFrame f;
    bool changed = true;
    d.mem[0x814E] = 0x00; // nothing new
    ASSERT_TRUE(touch.read(f, changed).ok());
    EXPECT_FALSE(changed);
    d.mem[0x814E] = 0x82; // buffer ready, two points
    gt911_point(d, 0, 7, 400, 240);
    gt911_point(d, 1, 9, 799, 0);
    ASSERT_TRUE(touch.read(f, changed).ok());
    ASSERT_TRUE(changed);
    ASSERT_EQ(f.count, 2u);
    EXPECT_EQ(f.points[0].id, 7);
    EXPECT_EQ(f.points[0].x, 240);
    EXPECT_EQ(f.points[0].y, 136);
    EXPECT_EQ(f.points[1].x, 479);
    EXPECT_EQ(f.points[1].y, 0);
    EXPECT_EQ(d.mem[0x814E], 0) << "the status register cleared after the read";
    EXPECT_EQ(d.writes.back(), (std::vector<uint8_t>{0x81, 0x4E, 0x00}));
}

TEST(Touch, Gt911AtItsOtherAddressFt5406OrNothing) {
    {
        reset_model();
        Bus bus;
        Device d = gt911(0x14, 480, 272);
        bus.devices = {&d};
        bus.attach();
        Lpi2c i2c(lpi2c::kLpi2c1);
        Touch touch;
        ASSERT_TRUE(touch.probe(i2c, 480, 272).ok());
        EXPECT_EQ(touch.chip(), Touch::Chip::Gt911);
    }
    {
        reset_model();
        Bus bus;
        Device ft;
        ft.address = 0x38;
        bus.devices = {&ft};
        bus.attach();
        Lpi2c i2c(lpi2c::kLpi2c1);
        Touch touch;
        ASSERT_TRUE(touch.probe(i2c, 480, 272).ok());
        EXPECT_EQ(touch.chip(), Touch::Chip::Ft5406);
        EXPECT_EQ(ft.writes.front(), (std::vector<uint8_t>{0x00, 0x00})) << "DEVICE_MODE 0: normal operation";
        // One finger in contact (event 2, ID 1) at the controller's x = 100, y = 200: the
        // panel's (200, 100) — the FT5406's axes are the panel's y and x.
        ft.mem[0x02] = 1;
        ft.mem[0x03] = 0x80 | 0x00, ft.mem[0x04] = 100, ft.mem[0x05] = 0x10, ft.mem[0x06] = 200;
        TouchFrame f;
        bool changed = false;
        ASSERT_TRUE(touch.read(f, changed).ok());
        ASSERT_EQ(f.count, 1u);
        EXPECT_EQ(f.points[0].x, 200);
        EXPECT_EQ(f.points[0].y, 100);
        EXPECT_EQ(f.points[0].id, 1);
        ft.mem[0x03] = 0x40; // lift-up event: no finger
        ASSERT_TRUE(touch.read(f, changed).ok());
        EXPECT_EQ(f.count, 0u);
    }
    {
        reset_model();
        Bus bus; // nobody on the bus: every address NACKs
        bus.attach();
        Lpi2c i2c(lpi2c::kLpi2c1);
        Touch touch;
        const Result r = touch.probe(i2c, 480, 272);
        EXPECT_EQ(r.status, Status::NotFound);
        EXPECT_EQ(touch.chip(), Touch::Chip::None);
        uint8_t b;
        const uint8_t reg = 0;
        EXPECT_EQ(i2c.transfer(0x38, &reg, 1, &b, 1).status, Status::NotFound);
    }
}

// --- The MPU plan -----------------------------------------------------------------------------

// The region that decides an address: the highest-numbered enabled region covering it.
int decider(const cortex_m::MpuRegion* r, uint32_t n, uint32_t address) {
    for (int i = int(n) - 1; i >= 0; --i)
        if (cortex_m::covers(r[i], address)) return i;
    return -1;
}
uint32_t ap(const cortex_m::MpuRegion& r) { return field(r.rasr, 26, 24); }
bool xn(const cortex_m::MpuRegion& r) { return r.rasr & (1u << 28); }
uint32_t tex_c_b(const cortex_m::MpuRegion& r) { return field(r.rasr, 21, 19) << 2 | field(r.rasr, 17, 16); }

struct Layout {
    const char* name;
    uint32_t flash, flash_bytes, sdram, sdram_bytes;
};

class Mpu : public ::testing::TestWithParam<Layout> {};

TEST_P(Mpu, EveryMemoryWithItsAttributesAndNothingBeyond) {
    using cortex_m::Memory;
    const Layout& l = GetParam();
    const cortex_m::Range ranges[] = {
        {0x40000000, 0x20000000, Memory::Device}, {0x00000000, 128 << 10, Memory::Tcm},
        {0x20000000, 128 << 10, Memory::Data},    {0x20200000, 768 << 10, Memory::Data},
        {l.flash, l.flash_bytes, Memory::Code},   {l.sdram, l.sdram_bytes, Memory::Data},
        {l.sdram, 522240, Memory::Scanout},       {0x00000000, 32, Memory::NoAccess},
    };
    cortex_m::MpuRegion r[8];
    const uint32_t n = cortex_m::plan(ranges, 8, r, 8);
    ASSERT_EQ(n, 8u);
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t size = cortex_m::region_size(r[i]);
        EXPECT_EQ((r[i].rbar & ~0x1Fu) & (size - 1), 0u) << "region " << i << " aligned to its size";
        EXPECT_EQ(r[i].rbar & 0xF, i);
        EXPECT_TRUE(r[i].rbar & 0x10) << "VALID";
    }
    auto at = [&](uint32_t a) { return decider(r, n, a); };
    // Past the SDRAM, past the OCRAM, between memories: no region, a fault.
    EXPECT_EQ(at(l.sdram + l.sdram_bytes), -1);
    EXPECT_EQ(at(0x202C0000), -1);
    EXPECT_EQ(at(0x20020000), -1);
    EXPECT_EQ(at(0x00020000), -1);
    if (l.flash + l.flash_bytes != l.sdram) {
        EXPECT_EQ(at(l.flash + l.flash_bytes), -1);
    }
    EXPECT_EQ(at(0xA0000000), -1);
    // The last byte of each memory is still in.
    EXPECT_EQ(at(l.sdram + l.sdram_bytes - 1), 5);
    EXPECT_EQ(at(0x202BFFFF), 3);
    // Null pointer: no access; the ITCM above it: read-write, executable, not cached.
    EXPECT_EQ(at(0), 7);
    EXPECT_EQ(ap(r[7]), 0u);
    EXPECT_EQ(at(32), 1);
    EXPECT_EQ(ap(r[1]), 3u);
    EXPECT_FALSE(xn(r[1]));
    // Flash (code and the pack): read-only, executable, write-through.
    EXPECT_EQ(at(l.flash + 0x2000), 4);
    EXPECT_EQ(at(0x60100000), 4);
    EXPECT_EQ(ap(r[4]), 6u);
    EXPECT_FALSE(xn(r[4]));
    EXPECT_EQ(tex_c_b(r[4]), 0b000'10u);
    // RAM: read-write, never executed, write-back write-allocate (TEX 1, C 1, B 1).
    for (uint32_t a : {0x20000000u, 0x20200000u, l.sdram + 0x100000}) {
        const int i = at(a);
        ASSERT_GE(i, 0);
        EXPECT_EQ(ap(r[i]), 3u);
        EXPECT_TRUE(xn(r[i]));
        EXPECT_EQ(tex_c_b(r[i]), 0b001'11u);
    }
    // The frames: write-through (TEX 0, C 1, B 0), so the LCD controller reads what was drawn.
    EXPECT_EQ(at(l.sdram), 6);
    EXPECT_EQ(at(l.sdram + 522239), 6);
    EXPECT_EQ(tex_c_b(r[6]), 0b000'10u);
    // Peripherals: device memory, never executed.
    EXPECT_EQ(at(0x402B8000), 0);
    EXPECT_EQ(tex_c_b(r[0]), 0b010'00u);
    EXPECT_TRUE(xn(r[0]));
}

INSTANTIATE_TEST_SUITE_P(EvkbAndStandIn, Mpu,
                         ::testing::Values(Layout{"EVKB", 0x60000000, 8u << 20, 0x80000000, 32u << 20},
                                           Layout{"StandIn", 0x60000000, 4u << 20, 0x60400000, 12u << 20}),
                         [](const ::testing::TestParamInfo<Layout>& i) { return std::string(i.param.name); });

TEST(Mpu, AnEmptyRangeOrTooManyIsRefused) {
    cortex_m::MpuRegion r[2];
    const cortex_m::Range empty[] = {{0x20000000, 0, cortex_m::Memory::Data}};
    EXPECT_EQ(cortex_m::plan(empty, 1, r, 2), 0u);
    const cortex_m::Range three[] = {{0, 32, cortex_m::Memory::Data}, {64, 32, cortex_m::Memory::Data}, {128, 32, cortex_m::Memory::Data}};
    EXPECT_EQ(cortex_m::plan(three, 3, r, 2), 0u);
}

} // namespace
