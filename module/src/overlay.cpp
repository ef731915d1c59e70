#include "overlay.h"

namespace facet::module {

void fill(hal::Rgb565* p, uint32_t n, hal::Rgb565 c) {
    // Two pixels per word store, eight words per round: the odd pixel at each end on its own.
    using Pair = uint32_t __attribute__((may_alias, aligned(4)));
    if ((reinterpret_cast<uintptr_t>(p) & 2) && n) *p++ = c, --n;
    Pair* w = reinterpret_cast<Pair*>(p);
    const uint32_t pair = uint32_t(c) * 0x00010001u;
    uint32_t words = n / 2;
    for (; words >= 8; words -= 8, w += 8) w[0] = w[1] = w[2] = w[3] = w[4] = w[5] = w[6] = w[7] = pair;
    while (words--) *w++ = pair;
    if (n & 1) *reinterpret_cast<hal::Rgb565*>(w) = c;
}

void Overlay::progress(const render::Target& t, uint32_t finished, uint32_t total) const {
    if (finished >= total) return;
    const uint32_t w = t.width * finished / total;
    for (int32_t y = t.height - kBarRows; y < t.height; ++y) {
        if (y < t.y0 || y >= t.y0 + t.rows) continue;
        fill(t.row(y), w, kDone);
        fill(t.row(y) + w, t.width - w, kLeft);
    }
}

} // namespace facet::module
