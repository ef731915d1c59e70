#include "lcdif.h"

#include "cortex_m.h"
#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {
using namespace lcdif;
uint32_t address(const void* p) { return uint32_t(reinterpret_cast<uintptr_t>(p)); }
} // namespace

void Lcdif::init(const PanelTiming& p) {
    panel_ = &p;
    running_ = false;
    // Reset (RM, eLCDIF "Software reset"): ungate, assert SFTRST, wait for the block to gate its
    // clock (CLKGATE reads 1), ungate, release.
    mmio::write(kCtrlClr, kClkgate);
    if (!(mmio::read(kCtrl) & kSftrst)) {
        mmio::write(kCtrlSet, kSftrst);
        mmio::wait(kCtrl, kClkgate, kClkgate, 100000);
        mmio::write(kCtrlClr, kClkgate);
    }
    mmio::write(kCtrlClr, kSftrst);

    // DOTCLK mode, master (it fetches the frame itself), 16-bit pixels on a 16-bit bus
    // (WORD_LENGTH 0, LCD_DATABUS_WIDTH 0), BYPASS_COUNT: it keeps running frame after frame.
    mmio::write(kCtrl, kDotclkMode | kBypassCount | kMaster);
    mmio::write(kCtrl1, 0xFu << 16);          // BYTE_PACKING_FORMAT 0xF: all four bytes valid
    mmio::modify(kCtrl2, 7u << 21, 2u << 21); // OUTSTANDING_REQS 2: four AXI requests in flight
    mmio::write(kTransferCount, (uint32_t(p.height) << 16) | p.width);
    // VSYNC pulse and period counted in lines (the two _UNIT bits), DE present.
    uint32_t v0 = (1u << 28) | (1u << 21) | (1u << 20) | p.vsync;
    if (p.enable_high) v0 |= 1u << 24;
    if (p.data_on_rising_edge) v0 |= 1u << 25;
    if (p.hsync_high) v0 |= 1u << 26;
    if (p.vsync_high) v0 |= 1u << 27;
    mmio::write(kVdctrl0, v0);
    mmio::write(kVdctrl1, uint32_t(p.vsync) + p.vback + p.height + p.vfront);                  // VSYNC_PERIOD
    mmio::write(kVdctrl2, (uint32_t(p.hsync) << 18) | (uint32_t(p.hsync) + p.hback + p.width + p.hfront));
    mmio::write(kVdctrl3, ((uint32_t(p.hsync) + p.hback) << 16) | (uint32_t(p.vsync) + p.vback)); // wait counts
    mmio::write(kVdctrl4, (1u << 18) | p.width); // SYNC_SIGNALS_ON, valid pixels per line
}

hal::DisplayInfo Lcdif::info() const {
    return {panel_ ? panel_->width : uint16_t(0), panel_ ? panel_->height : uint16_t(0), PixelFormat::Rgb565, true};
}

Status Lcdif::show(Rgb565* frame) {
    if (!frame || !panel_) return Status::OutOfRange;
    // The frames sit in a write-through MPU region: memory already holds every pixel; the
    // barrier makes sure the last stores have left the core before the controller reads.
    cortex_m::dsb();
    if (!running_) {
        mmio::write(kCurBuf, address(frame));
        mmio::write(kNextBuf, address(frame));
        mmio::write(kCtrlSet, kRun);
        running_ = true;
    } else {
        mmio::write(kCtrl1Clr, kCurFrameDone);
        mmio::write(kNextBuf, address(frame));
    }
    shown_ = frame;
    return Status::Ok;
}

bool Lcdif::busy() const {
    if (!running_) return false;
    // CUR_FRAME_DONE: a frame ended since show() cleared it, so NEXT_BUF has become CUR_BUF.
    return !(mmio::read(kCtrl1) & kCurFrameDone);
}

Status Lcdif::write(const Area& area, const Rgb565* pixels) {
    if (!panel_) return Status::NotFound;
    return hal::copy_area(shown_, panel_->width, panel_->height, area, pixels);
}

} // namespace facet::evkb
