#include "hal/fake.h"

#include <gtest/gtest.h>

using namespace facet;

TEST(FakeDisplay, RejectsSpansOffScreenAndDrawsNothing) {
    hal::fake::Display d(32, 8);
    const hal::Rgb565 px[4] = {1, 2, 3, 4};
    EXPECT_EQ(d.push_span(30, 0, px, 4), Status::OutOfRange); // runs off the right edge
    EXPECT_EQ(d.push_span(0, 8, px, 1), Status::OutOfRange);  // below the last row
    EXPECT_EQ(d.fill_span(0, 0, 0, 7), Status::OutOfRange);   // empty span
    EXPECT_EQ(d.push_span(0, 0, nullptr, 1), Status::OutOfRange);
    EXPECT_EQ(d.rejected, 4u);
    EXPECT_EQ(d.pixels, 0u);
    for (hal::Rgb565 p : d.drawn()) EXPECT_EQ(p, 0);
}

TEST(FakeDisplay, DoubleBufferingShowsOnlyAfterFlip) {
    hal::fake::Display d(16, 4);
    ASSERT_EQ(d.fill_span(0, 1, 16, 0xF800), Status::Ok);
    EXPECT_EQ(d.pixel(3, 1), 0);
    ASSERT_EQ(d.flip(), Status::Ok);
    EXPECT_EQ(d.pixel(3, 1), 0xF800);
    EXPECT_EQ(d.pixel(3, 0), 0);
    EXPECT_EQ(d.info().buffers, 2);
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
    in.queue.push_back({hal::InputEvent::Kind::Key, 'r', 0, 0, 0});
    ASSERT_TRUE(in.poll(e));
    EXPECT_EQ(e.key, 'r');
}

TEST(Rgb565, PacksChannels) {
    EXPECT_EQ(hal::rgb565(255, 0, 0), 0xF800);
    EXPECT_EQ(hal::rgb565(0, 255, 0), 0x07E0);
    EXPECT_EQ(hal::rgb565(0, 0, 255), 0x001F);
}
