// The overlay on its own: the progress bar, whole or in bands.
#include "overlay.h"
#include "render/text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace facet;
using namespace facet::module;

TEST(Overlay, TheProgressBarShowsTheFacesDoneAndGoesWhenAllAreIn) {
    constexpr uint16_t W = 101, H = 30;
    std::vector<Rgb565> px(W * H, 7);
    std::vector<uint16_t> depth(W * H);
    const render::Target t{px.data(), depth.data(), W, H, 0, H};
    Overlay o;
    o.progress(t, 1, 4);
    for (uint16_t y = 0; y < H; ++y) {
        for (uint16_t x = 0; x < W; ++x) {
            const Rgb565 want = y < H - Overlay::kBarRows ? 7 : (x < W / 4 ? Overlay::kDone : Overlay::kLeft);
            ASSERT_EQ(px[y * W + x], want) << x << "," << y;
        }
    }
    std::vector<Rgb565> before = px;
    o.progress(t, 4, 4);
    EXPECT_EQ(px, before) << "nothing drawn once every face is in";
}

TEST(Overlay, BandsGetTheirRowsOfTheBar) {
    constexpr uint16_t W = 64, H = 20;
    std::vector<Rgb565> whole(W * H, 1), depth(W * H);
    Overlay o;
    o.progress({whole.data(), depth.data(), W, H, 0, H}, 3, 8);
    // The whole screen as the bar should be (not only as the same code draws it): 3/8 done.
    for (uint16_t y = 0; y < H; ++y) {
        for (uint16_t x = 0; x < W; ++x) {
            const Rgb565 want = y < H - Overlay::kBarRows ? 1 : (x < W * 3 / 8 ? Overlay::kDone : Overlay::kLeft);
            ASSERT_EQ(whole[y * W + x], want) << x << "," << y;
        }
    }
    for (uint16_t band : {1, 3, 7}) {
        std::vector<Rgb565> screen(W * H, 1);
        for (uint16_t y0 = 0; y0 < H; y0 += band) {
            const uint16_t rows = uint16_t(std::min<int>(band, H - y0));
            std::vector<Rgb565> px(W * rows, 1);
            std::vector<uint16_t> z(W * rows);
            o.progress({px.data(), z.data(), W, H, y0, rows}, 3, 8);
            std::copy(px.begin(), px.end(), screen.begin() + W * y0);
        }
        EXPECT_EQ(screen, whole) << "bands of " << band;
    }
}

namespace {

// The whole overlay into a screen, whole or band by band.
std::vector<Rgb565> draw(const Overlay& o, uint16_t w, uint16_t h, uint16_t band, const StatusInfo& s) {
    std::vector<Rgb565> screen(size_t(w) * h, 0x1234);
    for (uint16_t y0 = 0; y0 < h; y0 += band) {
        const uint16_t rows = uint16_t(std::min<int>(band, h - y0));
        std::vector<Rgb565> px(size_t(w) * rows, 0x1234);
        std::vector<uint16_t> z(size_t(w) * rows);
        o.draw({px.data(), z.data(), w, h, y0, rows}, s);
        std::copy(px.begin(), px.end(), screen.begin() + ptrdiff_t(w) * y0);
    }
    return screen;
}

} // namespace

// The toolbar on the two shipped screens: every button a finger's size, inside the screen,
// below the status bar, none overlapping; a tap finds its button; the model is framed in the rest.
TEST(Overlay, TheToolbarFitsBothScreensAndATapFindsItsButton) {
    for (const auto& [w, h] : {std::pair<uint16_t, uint16_t>{480, 272}, {640, 480}}) {
        Overlay o;
        o.layout(w, h);
        const FreeArea a = o.taken();
        EXPECT_GE(a.top, 10) << "a status bar";
        EXPECT_GE(a.right, 40) << "a toolbar";
        EXPECT_EQ(a.left, 0);
        EXPECT_EQ(a.bottom, 0) << "no measurement yet";
        const Action all[] = {Action::Fit,     Action::NextView, Action::NextDisplayMode, Action::Projection, Action::Section,
                              Action::Measure, Action::Parts,    Action::NextDetail,      Action::Help};
        int y = a.top;
        for (Action act : all) {
            // Walk down the toolbar's middle column: each button in turn, at least 28 pixels tall.
            const int x = w - a.right / 2;
            ASSERT_EQ(o.button_at(int16_t(x), int16_t(y + 1)), act) << w << "x" << h << " at " << y;
            int end = y + 1;
            while (end < h && o.button_at(int16_t(x), int16_t(end)) == act) ++end;
            EXPECT_GE(end - y, 28) << "a finger's height";
            y = end;
        }
        EXPECT_EQ(o.button_at(int16_t(w / 2), int16_t(h / 2)), Action::None) << "the model's area";
        EXPECT_EQ(o.button_at(int16_t(w - a.right - 1), int16_t(h / 2)), Action::None);
        // A measurement panel takes rows at the bottom.
        const char* lines[2] = {"#3 plane", "#4 cylinder hole  D 6.350 mm"};
        o.set_lines(lines, 2);
        EXPECT_GE(o.taken().bottom, 2 * render::kLineHeight);
    }
    Overlay tiny;
    tiny.layout(120, 80);
    EXPECT_EQ(tiny.taken().right, 0) << "no toolbar on a screen too small for one";
    EXPECT_EQ(tiny.button_at(110, 40), Action::None);
}

// Everything the overlay draws, band by band, is the same as drawn whole; and what it draws is
// there: the status text in the top rows, the panel's text at the bottom, the help panel.
TEST(Overlay, StatusToolbarPanelAndHelpDrawTheSameInBands) {
    constexpr uint16_t W = 480, H = 272;
    Overlay o;
    o.layout(W, H);
    const char* lines[3] = {"#60 cylinder hole  D 15.360 mm  axis (0.000, 0.000, 1.000)", "#2 plane", "axis at 90.000 deg to the plane"};
    o.set_lines(lines, 3);
    o.set_help(true);
    o.set_measuring(true);
    StatusInfo s;
    s.finished = 40, s.total = 87, s.triangles = 1594, s.frame_us = 13100, s.tolerance_mm = 0.504f;
    const std::vector<Rgb565> whole = draw(o, W, H, H, s);
    for (uint16_t band : {1, 16, 100}) EXPECT_EQ(draw(o, W, H, band, s), whole) << "bands of " << band;
    auto touched = [&](int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) n += whole[size_t(y) * W + x] != 0x1234;
        return n;
    };
    EXPECT_EQ(touched(0, 0, W, 12), W * 12) << "the status bar is opaque";
    EXPECT_EQ(touched(436, 12, W, H), (W - 436) * (H - 12)) << "the toolbar is opaque";
    EXPECT_GT(touched(0, H - 34, 200, H), 200 * 30) << "the measurement panel";
    EXPECT_EQ(touched(40, 40, 300, 50), 260 * 10) << "the help panel covers the upper middle";
}

// The font: a glyph drawn is its pixel art (tools/font/make_font.py), scaled.
TEST(Overlay, TextIsTheFontsPixelArt) {
    constexpr uint16_t W = 40, H = 20;
    std::vector<Rgb565> px(W * H, 0);
    std::vector<uint16_t> z(W * H);
    const render::Target t{px.data(), z.data(), W, H, 0, H};
    EXPECT_EQ(render::draw_text(t, 1, 1, "T", 0xFFFF), 1 + render::kCellWidth);
    // 'T': "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ....."
    for (int x = 0; x < 5; ++x) EXPECT_EQ(px[1 * W + 1 + x], 0xFFFF) << x;
    for (int y = 2; y < 8; ++y) {
        for (int x = 0; x < 5; ++x) EXPECT_EQ(px[size_t(1 + y - 1) * W + 1 + x], x == 2 ? 0xFFFF : 0) << x << "," << y;
    }
    EXPECT_EQ(render::text_width("T"), 5);
    EXPECT_EQ(render::text_width("TT", 2), 22);
}

// Text is UTF-8: Latin-1, Latin Extended-A, Greek and Cyrillic are the font's (Debian's
// misc-fixed 5x8); a character the font lacks, and each run of bytes that is no UTF-8, is one
// replacement mark (issue 27: names as the CAD system wrote them, not "?" a byte).
TEST(Overlay, TextIsUtf8AndACharacterTheFontLacksIsOneMark) {
    constexpr uint16_t W = 40, H = 10;
    std::vector<uint16_t> z(W * H);
    auto drawn = [&](const char* text, int32_t* end = nullptr) {
        std::vector<Rgb565> px(W * H, 0);
        const int32_t x = render::draw_text({px.data(), z.data(), W, H, 0, H}, 0, 0, text, 1);
        if (end) *end = x;
        return px;
    };
    auto code = [](const char* text) { return render::next_code_point(text); };
    EXPECT_EQ(code("A"), 0x41u);
    EXPECT_EQ(code("\xC3\xA9"), 0xE9u);             // e acute
    EXPECT_EQ(code("\xCE\xA9"), 0x3A9u);            // Omega
    EXPECT_EQ(code("\xD0\x96"), 0x416u);            // Zhe
    EXPECT_EQ(code("\xE3\x83\x96"), 0x30D6u);       // katakana bu (io1_cm_214's part name)
    EXPECT_EQ(code("\xF0\x9F\x98\x80"), 0x1F600u);   // four bytes
    for (const char* bad : {"\x80", "\xC3", "\xE3\x83", "\xC0\xAF", "\xED\xA0\x80", "\xFF"}) {
        const char* at = bad;
        EXPECT_EQ(render::next_code_point(at), render::kReplacement) << bad;
        EXPECT_GT(at, bad);
    }
    const char* cut = "\xE3\x83" "A"; // a sequence cut short: its bytes one mark, then the A
    EXPECT_EQ(render::next_code_point(cut), render::kReplacement);
    EXPECT_EQ(*cut, 'A');
    EXPECT_EQ(render::text_length("\xD0\x96\xD1\x83\xD0\xBA"), 3); // three Cyrillic letters
    EXPECT_EQ(render::text_width("\xD0\x96\xD1\x83\xD0\xBA"), 3 * render::kCellWidth - 1);
    char name[] = "\xD0\x96\xD1\x83\xD0\xBA" "1";
    render::cut_text(name, 2);
    EXPECT_STREQ(name, "\xD0\x96\xD1\x83") << "cut after whole characters";

    // The mark: for a control character, a character the font lacks, bad bytes; one cell each.
    const std::vector<Rgb565> mark = drawn("\xEF\xBF\xBD");
    int32_t end = 0;
    EXPECT_EQ(drawn("\x01"), mark);
    EXPECT_EQ(drawn("\xE3\x83\x96", &end), mark);
    EXPECT_EQ(end, render::kCellWidth) << "one cell for the three bytes";
    EXPECT_EQ(drawn("\xE3\x83", &end), mark);
    EXPECT_EQ(end, render::kCellWidth);
    EXPECT_NE(mark, drawn("?")) << "the mark reads apart from a question mark";
    EXPECT_NE(mark, drawn(" "));
    // Zhe, from the font: its middle column from row 1 to 6, mirror-symmetric, not the mark.
    const std::vector<Rgb565> zhe = drawn("\xD0\x96");
    EXPECT_NE(zhe, mark);
    for (int y = 1; y < 7; ++y) {
        EXPECT_NE(zhe[size_t(y) * W + 2], 0) << y;
        for (int x = 0; x < 2; ++x) EXPECT_EQ(zhe[size_t(y) * W + x], zhe[size_t(y) * W + 4 - x]) << x << "," << y;
    }
    for (const char* letter : {"\xC3\xA9", "\xC5\xA0", "\xCE\xB1", "\xD0\xB1", "\xD1\x8F"}) { // e acute, S caron, alpha, be, ya
        EXPECT_NE(drawn(letter), mark) << letter;
        EXPECT_NE(drawn(letter), drawn(" ")) << letter;
    }
}

// A Cyrillic model name in the status bar: the font's letters, not "?" a byte.
TEST(Overlay, TheStatusBarShowsANameInCyrillic) {
    constexpr uint16_t W = 480, H = 272;
    Overlay o;
    o.layout(W, H);
    StatusInfo s;
    const char* name = "\xD0\x94\xD0\xB5\xD1\x82\xD0\xB0\xD0\xBB\xD1\x8C" "1"; // "Detal'1" in Russian
    s.name = name, s.finished = 87, s.total = 87;
    const std::vector<Rgb565> screen = draw(o, W, H, H, s);
    std::vector<Rgb565> text(size_t(W) * H, 0);
    std::vector<uint16_t> z(size_t(W) * H);
    render::draw_text({text.data(), z.data(), W, H, 0, H}, 3, 2, name, 0xFFFF);
    const Rgb565 bar = screen[0];
    const int32_t width = render::text_width(name);
    EXPECT_EQ(width, 7 * render::kCellWidth - 1);
    int32_t set = 0;
    for (int y = 2; y < 2 + render::kGlyphHeight; ++y) {
        for (int x = 3; x < 3 + width; ++x) {
            const size_t at = size_t(y) * W + size_t(x);
            EXPECT_EQ(screen[at] != bar, text[at] != 0) << x << "," << y;
            set += text[at] != 0;
        }
    }
    EXPECT_GT(set, 7 * 8);
}

// The frame-time field is where tools/img.py's frame_time_field() says (the screenshot
// comparisons between a board and the host leave it out: each shows its own clock).
TEST(Overlay, TheFrameTimeFieldIsWhereImgPySaysItIs) {
    struct Case {
        uint16_t w, h;
        int16_t x0, x1;
    };
    // frame_time_field(480, 272) = (380, 0, 433, 12); (640, 480) = (528, 0, 581, 12)
    for (const Case c : {Case{480, 272, 380, 433}, Case{640, 480, 528, 581}}) {
        Overlay o;
        o.layout(c.w, c.h);
        const Overlay::TimeField f = o.time_field();
        EXPECT_EQ(f.x0, c.x0) << c.w;
        EXPECT_EQ(f.x1, c.x1) << c.w;
        EXPECT_EQ(f.rows, 12);
        // The time is drawn inside it only.
        StatusInfo s;
        s.finished = s.total = 5, s.frame_us = 1234567;
        const std::vector<Rgb565> with = draw(o, c.w, c.h, c.h, s);
        s.frame_us = 0;
        const std::vector<Rgb565> without = draw(o, c.w, c.h, c.h, s);
        for (int y = 0; y < c.h; ++y)
            for (int x = 0; x < c.w; ++x)
                if (with[size_t(y) * c.w + x] != without[size_t(y) * c.w + x]) {
                    ASSERT_TRUE(x >= f.x0 && x < f.x1 && y < f.rows) << x << "," << y;
                }
    }
}
