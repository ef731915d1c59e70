#include "hal/display.h"

#include <cstddef>

namespace facet::hal {

Status copy_area(Rgb565* frame, uint16_t width, uint16_t height, const Area& a, const Rgb565* pixels) {
    if (!frame) return Status::NotFound;
    if (!pixels || a.width == 0 || a.height == 0 || uint32_t(a.x) + a.width > width || uint32_t(a.y) + a.height > height) {
        return Status::OutOfRange;
    }
    // Whole rows at once when the area spans the screen's width (bands).
    Rgb565* to = frame + size_t(a.y) * width + a.x;
    if (a.x == 0 && a.width == width) {
        const uint32_t n = uint32_t(a.width) * a.height;
        for (uint32_t i = 0; i < n; ++i) to[i] = pixels[i];
        return Status::Ok;
    }
    for (uint16_t y = 0; y < a.height; ++y, to += width, pixels += a.width)
        for (uint16_t x = 0; x < a.width; ++x) to[x] = pixels[x];
    return Status::Ok;
}

} // namespace facet::hal
