#pragma once
// PL110 colour LCD at 640x480 RGB565, double-buffered by swapping the upper-panel base.
#include "framebuffer.h"
#include "hal/display.h"

namespace facet::versatilepb {

class Pl110Display final : public hal::Display {
public:
    void init();
    hal::DisplayInfo info() const override;
    Status push_span(uint16_t x, uint16_t y, const hal::Rgb565* pixels, uint16_t count) override;
    Status fill_span(uint16_t x, uint16_t y, uint16_t count, hal::Rgb565 colour) override;
    Status flip() override;
    hal::Rgb565* draw_buffer() override { return fb_.draw(); }

private:
    boards::Framebuffers fb_;
};

} // namespace facet::versatilepb
