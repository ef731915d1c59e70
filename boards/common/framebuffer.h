#pragma once
// Two RGB565 buffers in RAM, one drawn into and one shown, with the bounds-checked span
// primitives every framebuffer display driver needs. A board's display driver owns one and adds
// what its hardware needs (the PL110 points its base register at shown() on each swap).
#include "hal/display.h"

namespace facet::boards {

class Framebuffers {
public:
    void init(hal::Rgb565* first, hal::Rgb565* second, uint16_t width, uint16_t height);
    Status push_span(uint16_t x, uint16_t y, const hal::Rgb565* pixels, uint16_t count);
    Status fill_span(uint16_t x, uint16_t y, uint16_t count, hal::Rgb565 colour);
    void swap();
    const hal::Rgb565* shown() const { return shown_; }
    hal::Rgb565* draw() { return draw_; }
    uint16_t width() const { return w_; }
    uint16_t height() const { return h_; }

private:
    bool in_range(uint16_t x, uint16_t y, uint16_t count) const {
        return count > 0 && y < h_ && x < w_ && uint32_t(x) + count <= w_;
    }

    hal::Rgb565* draw_ = nullptr;
    hal::Rgb565* shown_ = nullptr;
    uint16_t w_ = 0, h_ = 0;
};

} // namespace facet::boards
