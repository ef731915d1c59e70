#include "hal/fake.h"

#include <gtest/gtest.h>

using namespace facet;

TEST(FakeDisplay, RejectsAreasOffScreenAndDrawsNothing) {
    hal::fake::Display d(32, 8, false);
    const Rgb565 px[4] = {1, 2, 3, 4};
    EXPECT_EQ(d.write({30, 0, 4, 1}, px), Status::OutOfRange); // runs off the right edge
    EXPECT_EQ(d.write({0, 8, 1, 1}, px), Status::OutOfRange);  // below the last row
    EXPECT_EQ(d.write({0, 0, 0, 1}, px), Status::OutOfRange);  // empty
    EXPECT_EQ(d.write({0, 0, 1, 1}, nullptr), Status::OutOfRange);
    EXPECT_EQ(d.show(nullptr), Status::Unsupported) << "no scan-out on this panel";
    EXPECT_EQ(d.rejected, 5u);
    EXPECT_EQ(d.pixels, 0u);
    for (Rgb565 p : d.front()) EXPECT_EQ(p, 0);
}

TEST(FakeDisplay, ShowsFramesInPlaceAndWritesAreasIntoThem) {
    hal::fake::Display d(16, 4);
    std::vector<Rgb565> a(16 * 4, 0x1111), b(16 * 4, 0x2222);
    ASSERT_EQ(d.show(a.data()), Status::Ok);
    EXPECT_EQ(d.pixel(3, 1), 0x1111);
    ASSERT_EQ(d.show(b.data()), Status::Ok);
    EXPECT_EQ(d.pixel(3, 1), 0x2222);
    const Rgb565 band[16 * 2] = {};
    ASSERT_EQ(d.write({0, 2, 16, 2}, band), Status::Ok);
    EXPECT_EQ(b[16 * 2 + 5], 0) << "an area goes into the frame shown";
    EXPECT_EQ(d.pixel(5, 1), 0x2222);
    EXPECT_TRUE(d.info().scanout);
}

TEST(FakeConsoleInput, RecordsAndReplays) {
    hal::fake::Console c;
    c.write("ab", 2);
    EXPECT_EQ(c.output, "ab");
    c.type("x");
    EXPECT_EQ(c.read_byte(), 'x');
    EXPECT_EQ(c.read_byte(), -1);
    hal::fake::Input in;
    hal::InputEvent e{};
    EXPECT_FALSE(in.poll(e));
    hal::InputEvent key{};
    key.kind = hal::InputEvent::Kind::Key;
    key.key = 'r';
    in.queue.push_back(key);
    ASSERT_TRUE(in.poll(e));
    EXPECT_EQ(e.key, 'r');
}

TEST(Rgb565, PacksChannels) {
    EXPECT_EQ(rgb565(255, 0, 0), 0xF800);
    EXPECT_EQ(rgb565(0, 255, 0), 0x07E0);
    EXPECT_EQ(rgb565(0, 0, 255), 0x001F);
}
