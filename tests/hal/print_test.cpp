#include "hal/fake.h"
#include "hal/print.h"

#include <gtest/gtest.h>

#include <climits>
#include <string>

using facet::fixed;
using facet::format;
using facet::hex;

namespace {
std::string fmt(const char* f, auto... args) {
    char buf[128];
    format(buf, sizeof buf, f, args...);
    return buf;
}
} // namespace

TEST(Print, IntegersOfEveryWidthAndSign) {
    EXPECT_EQ(fmt("{} {} {} {}", 0, -1, 42u, int8_t(-128)), "0 -1 42 -128");
    EXPECT_EQ(fmt("{}", INT64_MIN), "-9223372036854775808");
    EXPECT_EQ(fmt("{}", UINT64_MAX), "18446744073709551615");
    EXPECT_EQ(fmt("{}", INT32_MIN), "-2147483648");
}

TEST(Print, HexFixedStringsBools) {
    EXPECT_EQ(fmt("{}", hex(0x2000000)), "0x02000000");
    EXPECT_EQ(fmt("{}", hex(0xAB, 2)), "0xab");
    EXPECT_EQ(fmt("{}", fixed(12345, 3)), "12.345");
    EXPECT_EQ(fmt("{}", fixed(-5, 2)), "-0.05");
    EXPECT_EQ(fmt("{} {}", "abc", true), "abc true");
    EXPECT_EQ(fmt("{}", static_cast<const char*>(nullptr)), "(null)");
}

TEST(Print, BracesAndMissingArguments) {
    EXPECT_EQ(fmt("{{}} {}", 1), "{} 1");
    EXPECT_EQ(fmt("{} {}", 1), "1 {?}");
    EXPECT_EQ(fmt("{", 1), "{");
}

TEST(Print, TruncatesButReportsFullLength) {
    char buf[6];
    EXPECT_EQ(format(buf, sizeof buf, "{}-{}", 12345, 678), 9u);
    EXPECT_STREQ(buf, "12345");
    EXPECT_EQ(format(buf, 0, "x"), 1u);
}

TEST(Print, LongOutputToConsoleIsComplete) {
    facet::hal::fake::Console con;
    std::string expect;
    for (int i = 0; i < 60; ++i) expect += std::to_string(i) + ",";
    facet::print(con, "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},"
                      "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},"
                      "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},",
                 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22,
                 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43,
                 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59);
    EXPECT_EQ(con.output, expect);
}
