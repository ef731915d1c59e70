#pragma once
// What the viewer draws over the model: today the progress bar along the bottom while the
// faces fill in. Drawn into the target's rows only (a band gets its part).
#include "render/raster.h"

#include <cstdint>

namespace facet::module {

// n pixels of one colour from p (word stores).
void fill(hal::Rgb565* p, uint32_t n, hal::Rgb565 colour);

class Overlay {
public:
    static constexpr uint16_t kBarRows = 4;
    static constexpr hal::Rgb565 kDone = hal::rgb565(40, 110, 220), kLeft = hal::rgb565(70, 74, 84);

    // The bottom kBarRows rows: `finished` of `total` faces in blue, the rest grey; nothing
    // once every face is in.
    void progress(const render::Target& target, uint32_t finished, uint32_t total) const;
};

} // namespace facet::module
