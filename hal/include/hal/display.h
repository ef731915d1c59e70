#pragma once
// Display: the smallest contract a span renderer needs (cf. LVGL flush_cb, Zephyr display_write).
// The geometry comes from the driver; nothing outside boards/ may assume a resolution.
#include "hal/status.h"

#include <cstdint>

namespace facet::hal {

enum class PixelFormat : uint8_t { Rgb565 };

struct DisplayInfo {
    uint16_t width;
    uint16_t height;
    PixelFormat format;
    uint8_t buffers; // 2: draws go to a back buffer shown by flip(); 1: draws are visible at once
};

using Rgb565 = uint16_t;

constexpr Rgb565 rgb565(uint8_t r, uint8_t g, uint8_t b) {
    return static_cast<Rgb565>(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

class Display {
public:
    virtual DisplayInfo info() const = 0;
    // Copies `count` pixels to row y starting at column x of the draw buffer.
    // OutOfRange (and nothing drawn) if the span leaves the screen.
    virtual Status push_span(uint16_t x, uint16_t y, const Rgb565* pixels, uint16_t count) = 0;
    // Fills `count` pixels of row y from column x with one colour.
    virtual Status fill_span(uint16_t x, uint16_t y, uint16_t count, Rgb565 colour) = 0;
    // Shows the draw buffer; the other buffer becomes the draw buffer. Content of the new draw
    // buffer is undefined (callers redraw every pixel).
    virtual Status flip() = 0;
    // The draw buffer itself (width * height pixels, row after row) when it is plain memory, so
    // a renderer can write pixels in place; null when pixels must go through the spans (a
    // controller behind a bus). Valid until the next flip().
    virtual Rgb565* draw_buffer() { return nullptr; }

protected:
    ~Display() = default;
};

} // namespace facet::hal
