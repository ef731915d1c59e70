#include "framebuffer.h"

namespace facet::boards {

void Framebuffers::init(hal::Rgb565* first, hal::Rgb565* second, uint16_t width, uint16_t height) {
    shown_ = first;
    draw_ = second;
    w_ = width;
    h_ = height;
    for (uint32_t i = 0; i < uint32_t(width) * height; ++i) first[i] = 0;
}

Status Framebuffers::push_span(uint16_t x, uint16_t y, const hal::Rgb565* pixels, uint16_t count) {
    if (!pixels || !in_range(x, y, count)) return Status::OutOfRange;
    hal::Rgb565* dst = draw_ + uint32_t(y) * w_ + x;
    for (uint16_t i = 0; i < count; ++i) dst[i] = pixels[i];
    return Status::Ok;
}

Status Framebuffers::fill_span(uint16_t x, uint16_t y, uint16_t count, hal::Rgb565 colour) {
    if (!in_range(x, y, count)) return Status::OutOfRange;
    hal::Rgb565* dst = draw_ + uint32_t(y) * w_ + x;
    for (uint16_t i = 0; i < count; ++i) dst[i] = colour;
    return Status::Ok;
}

void Framebuffers::swap() {
    hal::Rgb565* t = shown_;
    shown_ = draw_;
    draw_ = t;
}

} // namespace facet::boards
