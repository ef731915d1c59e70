// The MPU plan of the EVKB and its stand-in: every memory with its attributes, nothing beyond.
#include "register_model.h"

#include "imxrt1062.h"
#include "mpu.h"

#include <gtest/gtest.h>

#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace facet;
using namespace facet::evkb;
using namespace facet::evkb::test;

// --- The MPU plan -----------------------------------------------------------------------------

// The region that decides an address: the highest-numbered enabled region covering it.
int decider(const cortex_m::MpuRegion* r, uint32_t n, uint32_t address) {
    for (int i = int(n) - 1; i >= 0; --i)
        if (cortex_m::covers(r[i], address)) return i;
    return -1;
}
uint32_t ap(const cortex_m::MpuRegion& r) { return field(r.rasr, 26, 24); }
bool xn(const cortex_m::MpuRegion& r) { return r.rasr & (1u << 28); }
uint32_t tex_c_b(const cortex_m::MpuRegion& r) { return field(r.rasr, 21, 19) << 2 | field(r.rasr, 17, 16); }

struct Layout {
    const char* name;
    uint32_t flash, flash_bytes, sdram, sdram_bytes;
};

class Mpu : public ::testing::TestWithParam<Layout> {};

TEST_P(Mpu, EveryMemoryWithItsAttributesAndNothingBeyond) {
    using cortex_m::Memory;
    const Layout& l = GetParam();
    const cortex_m::Range ranges[] = {
        {0x40000000, 0x20000000, Memory::Device}, {0x00000000, 128 << 10, Memory::Tcm},
        {0x20000000, 128 << 10, Memory::Data},    {0x20200000, 768 << 10, Memory::Data},
        {l.flash, l.flash_bytes, Memory::Code},   {l.sdram, l.sdram_bytes, Memory::Data},
        {l.sdram, 522240, Memory::Scanout},       {0x00000000, 32, Memory::NoAccess},
    };
    cortex_m::MpuRegion r[8];
    const uint32_t n = cortex_m::plan(ranges, 8, r, 8);
    ASSERT_EQ(n, 8u);
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t size = cortex_m::region_size(r[i]);
        EXPECT_EQ((r[i].rbar & ~0x1Fu) & (size - 1), 0u) << "region " << i << " aligned to its size";
        EXPECT_EQ(r[i].rbar & 0xF, i);
        EXPECT_TRUE(r[i].rbar & 0x10) << "VALID";
    }
    auto at = [&](uint32_t a) { return decider(r, n, a); };
    // Past the SDRAM, past the OCRAM, between memories: no region, a fault.
    EXPECT_EQ(at(l.sdram + l.sdram_bytes), -1);
    EXPECT_EQ(at(0x202C0000), -1);
    EXPECT_EQ(at(0x20020000), -1);
    EXPECT_EQ(at(0x00020000), -1);
    if (l.flash + l.flash_bytes != l.sdram) {
        EXPECT_EQ(at(l.flash + l.flash_bytes), -1);
    }
    EXPECT_EQ(at(0xA0000000), -1);
    // The last byte of each memory is still in.
    EXPECT_EQ(at(l.sdram + l.sdram_bytes - 1), 5);
    EXPECT_EQ(at(0x202BFFFF), 3);
    // Null pointer: no access; the ITCM above it: read-write, executable, not cached.
    EXPECT_EQ(at(0), 7);
    EXPECT_EQ(ap(r[7]), 0u);
    EXPECT_EQ(at(32), 1);
    EXPECT_EQ(ap(r[1]), 3u);
    EXPECT_FALSE(xn(r[1]));
    // Flash (code and the pack): read-only, executable, write-through.
    EXPECT_EQ(at(l.flash + 0x2000), 4);
    EXPECT_EQ(at(0x60100000), 4);
    EXPECT_EQ(ap(r[4]), 6u);
    EXPECT_FALSE(xn(r[4]));
    EXPECT_EQ(tex_c_b(r[4]), 0b000'10u);
    // RAM: read-write, never executed, write-back write-allocate (TEX 1, C 1, B 1).
    for (uint32_t a : {0x20000000u, 0x20200000u, l.sdram + 0x100000}) {
        const int i = at(a);
        ASSERT_GE(i, 0);
        EXPECT_EQ(ap(r[i]), 3u);
        EXPECT_TRUE(xn(r[i]));
        EXPECT_EQ(tex_c_b(r[i]), 0b001'11u);
    }
    // The frames: write-through (TEX 0, C 1, B 0), so the LCD controller reads what was drawn.
    EXPECT_EQ(at(l.sdram), 6);
    EXPECT_EQ(at(l.sdram + 522239), 6);
    EXPECT_EQ(tex_c_b(r[6]), 0b000'10u);
    // Peripherals: device memory, never executed.
    EXPECT_EQ(at(0x402B8000), 0);
    EXPECT_EQ(tex_c_b(r[0]), 0b010'00u);
    EXPECT_TRUE(xn(r[0]));
}

INSTANTIATE_TEST_SUITE_P(EvkbAndStandIn, Mpu,
                         ::testing::Values(Layout{"EVKB", 0x60000000, 8u << 20, 0x80000000, 32u << 20},
                                           Layout{"StandIn", 0x60000000, 4u << 20, 0x60400000, 12u << 20}),
                         [](const ::testing::TestParamInfo<Layout>& i) { return std::string(i.param.name); });

TEST(Mpu, AnEmptyRangeOrTooManyIsRefused) {
    cortex_m::MpuRegion r[2];
    const cortex_m::Range empty[] = {{0x20000000, 0, cortex_m::Memory::Data}};
    EXPECT_EQ(cortex_m::plan(empty, 1, r, 2), 0u);
    const cortex_m::Range three[] = {{0, 32, cortex_m::Memory::Data}, {64, 32, cortex_m::Memory::Data}, {128, 32, cortex_m::Memory::Data}};
    EXPECT_EQ(cortex_m::plan(three, 3, r, 2), 0u);
}


} // namespace
