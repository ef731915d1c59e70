#pragma once
// Pixels and areas of a screen: RGB565, the format of the boards' panels and of every buffer
// facet draws into, and one rectangle type for the whole project (the display drivers, the
// renderer, the module's public API; facet_area is its C spelling).
#include <cstdint>

namespace facet {

enum class PixelFormat : uint8_t { Rgb565 };

using Rgb565 = uint16_t; // red in bits 15:11, green 10:5, blue 4:0

constexpr Rgb565 rgb565(uint8_t r, uint8_t g, uint8_t b) {
    return static_cast<Rgb565>(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

// A rectangle of pixels: columns [x, x + width), rows [y, y + height).
struct Area {
    uint16_t x, y, width, height;

    constexpr bool contains(int32_t px, int32_t py) const {
        return px >= x && px < int32_t(x) + width && py >= y && py < int32_t(y) + height;
    }
};

} // namespace facet
