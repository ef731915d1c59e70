// The overlay on its own: the progress bar, whole or in bands.
#include "overlay.h"

#include <gtest/gtest.h>

#include <vector>

using namespace facet;
using namespace facet::module;

TEST(Overlay, TheProgressBarShowsTheFacesDoneAndGoesWhenAllAreIn) {
    constexpr uint16_t W = 101, H = 30;
    std::vector<hal::Rgb565> px(W * H, 7);
    std::vector<uint16_t> depth(W * H);
    const render::Target t{px.data(), depth.data(), W, H, 0, H};
    Overlay o;
    o.progress(t, 1, 4);
    for (uint16_t y = 0; y < H; ++y) {
        for (uint16_t x = 0; x < W; ++x) {
            const hal::Rgb565 want = y < H - Overlay::kBarRows ? 7 : (x < W / 4 ? Overlay::kDone : Overlay::kLeft);
            ASSERT_EQ(px[y * W + x], want) << x << "," << y;
        }
    }
    std::vector<hal::Rgb565> before = px;
    o.progress(t, 4, 4);
    EXPECT_EQ(px, before) << "nothing drawn once every face is in";
}

TEST(Overlay, BandsGetTheirRowsOfTheBar) {
    constexpr uint16_t W = 64, H = 20;
    std::vector<hal::Rgb565> whole(W * H, 1), depth(W * H);
    Overlay o;
    o.progress({whole.data(), depth.data(), W, H, 0, H}, 3, 8);
    for (uint16_t band : {1, 3, 7}) {
        std::vector<hal::Rgb565> screen(W * H, 1);
        for (uint16_t y0 = 0; y0 < H; y0 += band) {
            const uint16_t rows = uint16_t(std::min<int>(band, H - y0));
            std::vector<hal::Rgb565> px(W * rows, 1);
            std::vector<uint16_t> z(W * rows);
            o.progress({px.data(), z.data(), W, H, y0, rows}, 3, 8);
            std::copy(px.begin(), px.end(), screen.begin() + W * y0);
        }
        EXPECT_EQ(screen, whole) << "bands of " << band;
    }
}
