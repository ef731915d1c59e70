#pragma once
// The eLCDIF driving the EVKB's 4.3" 480x272 RGB565 panel in DOTCLK (RGB) mode, 16-bit bus,
// scanning a frame out of RAM. Double buffering: show() writes the next frame's address to
// NEXT_BUF, which the controller takes at the end of the frame it is sending (vertical blank);
// busy() stays true until then (CTRL1.CUR_FRAME_DONE_IRQ), so the caller does not draw into
// the frame still on the glass.
#include "hal/display.h"

#include <cstdint>

namespace facet::evkb {

struct PanelTiming {
    const char* name;
    uint16_t width, height;
    uint16_t hsync, hfront, hback; // pixel clocks
    uint16_t vsync, vfront, vback; // lines
    bool hsync_high, vsync_high, enable_high, data_on_rising_edge;
};

// The two panels NXP sells for this connector (timings as NXP's SDK and Zephyr's shields
// rk043fn66hs_ctg / rk043fn02h_ct give them; sync pulses active low, DE active high, data
// driven on the rising edge of the pixel clock):
//   RK043FN66HS-CTG, the EVKB's current panel, with a Goodix GT911 touch controller
constexpr PanelTiming kRk043fn66hs{"RK043FN66HS-CTG", 480, 272, 4, 8, 43, 4, 8, 12, false, false, true, true};
//   RK043FN02H-CT, the earlier panel, with a FocalTech FT5406 touch controller
constexpr PanelTiming kRk043fn02h{"RK043FN02H-CT", 480, 272, 41, 4, 8, 10, 4, 2, false, false, true, true};

constexpr uint32_t frame_clocks(const PanelTiming& p) {
    return uint32_t(p.hsync + p.hback + p.width + p.hfront) * (p.vsync + p.vback + p.height + p.vfront);
}

class Lcdif final : public hal::Display {
public:
    // Programs the controller for `panel` (it starts scanning at the first show()).
    void init(const PanelTiming& panel);
    hal::DisplayInfo info() const override;
    Status show(Rgb565* frame) override;
    Status write(const Area& area, const Rgb565* pixels) override;
    const Rgb565* frame() const override { return shown_; }
    bool busy() const override;
    const PanelTiming* panel() const { return panel_; }

private:
    const PanelTiming* panel_ = nullptr;
    Rgb565* shown_ = nullptr;
    bool running_ = false;
};

} // namespace facet::evkb
