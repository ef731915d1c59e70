// The EVKB's eLCDIF driver against the register model: the timings and polarities it sends each
// panel, as the panels' data sheets give them.
#include "register_model.h"

#include "imxrt1062.h"
#include "lcdif.h"

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


} // namespace
