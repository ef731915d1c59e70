#pragma once
// The overlay's colours and the lists' measures, for its files (overlay.cpp, overlay_pmi.cpp).
#include "core/pixel.h"

#include <cstdint>

namespace facet::module::overlay_style {

constexpr Rgb565 kBar = rgb565(36, 40, 48), kText = rgb565(236, 238, 242), kDim = rgb565(150, 156, 168);
constexpr Rgb565 kButton = rgb565(58, 64, 76), kButtonOn = rgb565(40, 110, 220), kEdge = rgb565(20, 22, 28);
constexpr int32_t kScrollW = 28; // a list's scroll buttons
constexpr int32_t kTabW = 40;    // a list header's tab to the other list

// A list's first row moved by `rows`, within what keeps its `shown` rows full of its `count`.
constexpr uint32_t scrolled(uint32_t first, int32_t rows, uint32_t count, uint32_t shown) {
    const int64_t last = count > shown ? int64_t(count - shown) : 0, at = int64_t(first) + rows;
    return uint32_t(at < 0 ? 0 : at > last ? last : at);
}

} // namespace facet::module::overlay_style
