#pragma once
// Pixels: RGB565, the format of the boards' panels (and of every buffer facet draws into).
#include <cstdint>

namespace facet::hal {

enum class PixelFormat : uint8_t { Rgb565 };

using Rgb565 = uint16_t; // red in bits 15:11, green 10:5, blue 4:0

constexpr Rgb565 rgb565(uint8_t r, uint8_t g, uint8_t b) {
    return static_cast<Rgb565>(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

} // namespace facet::hal
