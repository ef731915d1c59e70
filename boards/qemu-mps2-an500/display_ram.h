#pragma once
// A double-buffered RAM framebuffer (the board has no LCD). Captures are written to the host
// through semihosting as F565 files (tools/img.py).
#include "framebuffer.h"
#include "hal/display.h"

namespace facet::mps2 {

class RamDisplay final : public hal::Display {
public:
    void init();
    hal::DisplayInfo info() const override;
    Status push_span(uint16_t x, uint16_t y, const hal::Rgb565* pixels, uint16_t count) override;
    Status fill_span(uint16_t x, uint16_t y, uint16_t count, hal::Rgb565 colour) override;
    Status flip() override;
    hal::Rgb565* draw_buffer() override { return fb_.draw(); }
    const hal::Rgb565* shown() const { return fb_.shown(); }

private:
    boards::Framebuffers fb_;
};

} // namespace facet::mps2
