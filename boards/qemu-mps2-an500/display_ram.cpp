#include "display_ram.h"

#include "facet_board_config.h"

namespace facet::mps2 {
namespace {
constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
} // namespace

hal::DisplayInfo RamDisplay::info() const { return {kW, kH, PixelFormat::Rgb565, true}; }

Status RamDisplay::show(Rgb565* frame) {
    if (!frame) return Status::OutOfRange;
    shown_ = frame;
    return Status::Ok;
}

Status RamDisplay::write(const Area& area, const Rgb565* pixels) {
    return hal::copy_area(shown_, kW, kH, area, pixels);
}

} // namespace facet::mps2
