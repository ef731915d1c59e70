#include "display_ram.h"

#include "facet_board_config.h"

namespace facet::mps2 {
namespace {
constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
alignas(64) __attribute__((section(".framebuffers"))) hal::Rgb565 buffers[2][kW * kH];
} // namespace

void RamDisplay::init() { fb_.init(buffers[0], buffers[1], kW, kH); }

hal::DisplayInfo RamDisplay::info() const { return {kW, kH, hal::PixelFormat::Rgb565, 2}; }

Status RamDisplay::push_span(uint16_t x, uint16_t y, const hal::Rgb565* pixels, uint16_t count) {
    return fb_.push_span(x, y, pixels, count);
}

Status RamDisplay::fill_span(uint16_t x, uint16_t y, uint16_t count, hal::Rgb565 colour) {
    return fb_.fill_span(x, y, count, colour);
}

Status RamDisplay::flip() {
    fb_.swap();
    return Status::Ok;
}

} // namespace facet::mps2
