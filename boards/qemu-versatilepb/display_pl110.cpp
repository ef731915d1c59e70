// PL110 driver for QEMU's versatilepb.
//
// QEMU models the Versatile's modified PL110: the control register is at +0x18 and the
// interrupt mask at +0x1C (swapped against a stock PL110). Settings, verified in QEMU 7.2
// (tests/qemu checks the colours of the reference screenshots):
//   TIM0 0x3F1F3F9C  pixels per line = 16 * (PPL + 1) = 640 (PPL in bits [7:2])
//   TIM1 0x090B05DF  lines per panel = LPP + 1 = 480 (LPP in bits [9:0])
//   TIM2 0x067F0020
//   CTRL 0x829       enable | 16 bpp (BPP=4) | TFT | power; BGR (bit 8) clear (set when the
//                    first frame is shown)
//   SYS_CLCD (0x10000050) bits[1:0] = 3: the board's pixel mux set to 5:6:5, which with the
//   control above gives standard RGB565 (red in bits 15:11, blue in bits 4:0).
#include "display_pl110.h"

#include "facet_board_config.h"
#include "memory_map.h"

namespace facet::versatilepb {
namespace {

constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
static_assert(kW % 16 == 0 && kW <= 1024 && kH <= 1024, "PL110 geometry limits");

constexpr uintptr_t kTim0 = kPl110 + 0x00, kTim1 = kPl110 + 0x04, kTim2 = kPl110 + 0x08;
constexpr uintptr_t kUpBase = kPl110 + 0x10, kControl = kPl110 + 0x18;
constexpr uint32_t kControlOn = 0x829;

} // namespace

void Pl110Display::init() {
    reg(kSysClcd) = (reg(kSysClcd) & ~3u) | 3u;
    reg(kTim0) = 0x3F1F3F00 | ((kW / 16 - 1) << 2);
    reg(kTim1) = 0x090B0400 | (kH - 1);
    reg(kTim2) = 0x067F0020;
}

hal::DisplayInfo Pl110Display::info() const { return {kW, kH, PixelFormat::Rgb565, true}; }

Status Pl110Display::show(Rgb565* frame) {
    // The upper panel base must be 8-byte aligned (the controller fetches doublewords).
    if (!frame || (reinterpret_cast<uintptr_t>(frame) & 7)) return Status::OutOfRange;
    reg(kUpBase) = reinterpret_cast<uintptr_t>(frame);
    if (!shown_) reg(kControl) = kControlOn;
    shown_ = frame;
    return Status::Ok;
}

Status Pl110Display::write(const Area& area, const Rgb565* pixels) {
    return hal::copy_area(shown_, kW, kH, area, pixels);
}

} // namespace facet::versatilepb
