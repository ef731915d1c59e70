#include "display_ram.h"

#include "facet_board_config.h"

namespace facet::mps2 {
namespace {
constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
} // namespace

hal::DisplayInfo RamDisplay::info() const { return {kW, kH, hal::PixelFormat::Rgb565, true}; }

Status RamDisplay::show(hal::Rgb565* frame) {
    if (!frame) return Status::OutOfRange;
    shown_ = frame;
    return Status::Ok;
}

Status RamDisplay::write(const hal::Rect& area, const hal::Rgb565* pixels) {
    return hal::copy_area(shown_, kW, kH, area, pixels);
}

} // namespace facet::mps2
