#include "display_ram.h"

#include "facet_board_config.h"

namespace facet::mps2 {
namespace {
constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
alignas(64) __attribute__((section(".framebuffers"))) hal::Rgb565 buffers[2][kW * kH];
} // namespace

void RamDisplay::init() {
    for (hal::Rgb565& p : buffers[0]) p = 0;
    shown_ = buffers[0];
    draw_ = buffers[1];
}

hal::DisplayInfo RamDisplay::info() const { return {kW, kH, hal::PixelFormat::Rgb565, 2}; }

Status RamDisplay::push_span(uint16_t x, uint16_t y, const hal::Rgb565* pixels, uint16_t count) {
    if (!pixels || count == 0 || y >= kH || x >= kW || uint32_t(x) + count > kW) {
        return Status::OutOfRange;
    }
    hal::Rgb565* dst = draw_ + uint32_t(y) * kW + x;
    for (uint16_t i = 0; i < count; ++i) dst[i] = pixels[i];
    return Status::Ok;
}

Status RamDisplay::fill_span(uint16_t x, uint16_t y, uint16_t count, hal::Rgb565 colour) {
    if (count == 0 || y >= kH || x >= kW || uint32_t(x) + count > kW) return Status::OutOfRange;
    hal::Rgb565* dst = draw_ + uint32_t(y) * kW + x;
    for (uint16_t i = 0; i < count; ++i) dst[i] = colour;
    return Status::Ok;
}

Status RamDisplay::flip() {
    hal::Rgb565* t = shown_;
    shown_ = draw_;
    draw_ = t;
    return Status::Ok;
}

} // namespace facet::mps2
