#include "framebuffer.h"

#include <cstdint>

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
    // Two pixels per word store, eight words per round (a full-screen fill is every frame's
    // background): the odd pixel at each end on its own.
    using Pair = uint32_t __attribute__((may_alias, aligned(4)));
    if ((reinterpret_cast<uintptr_t>(dst) & 2) && count) *dst++ = colour, --count;
    Pair* w = reinterpret_cast<Pair*>(dst);
    const uint32_t pair = uint32_t(colour) * 0x00010001u;
    uint32_t words = count / 2;
    for (; words >= 8; words -= 8, w += 8) w[0] = w[1] = w[2] = w[3] = w[4] = w[5] = w[6] = w[7] = pair;
    while (words--) *w++ = pair;
    if (count & 1) *reinterpret_cast<hal::Rgb565*>(w) = colour;
    return Status::Ok;
}

void Framebuffers::swap() {
    hal::Rgb565* t = shown_;
    shown_ = draw_;
    draw_ = t;
}

} // namespace facet::boards
