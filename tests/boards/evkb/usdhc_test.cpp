// The EVKB's microSD slot (boards/mimxrt1060-evkb/usdhc.cpp) against a register model of uSDHC1
// with a simulated SD card behind it: the pins and clock root as NXP's SDK sets them, the SD
// start-up's commands in order at under 400 kHz, the card's size from its CSD (versions 1 and
// 2), the 4-bit bus at 25 MHz, reads of one and many sectors with the bytes of the card's image,
// and what fails: no card, a card that does not answer, a block with a bad CRC.
#include "register_model.h"

#include "imxrt1062.h"
#include "usdhc.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <vector>

namespace {

using namespace facet;
using namespace facet::evkb;
using namespace facet::evkb::test;
using namespace facet::evkb::usdhc;

constexpr uint32_t kB = kUsdhc1;

// An SD card as the controller sees it: commands in, responses and data out.
struct Card {
    std::vector<uint8_t> image;
    bool high_capacity = true, answers = true, bad_crc_on_data = false;
    bool present = true;
    std::vector<uint32_t> commands;   // indices, in order
    std::vector<uint32_t> arguments;
    std::vector<uint32_t> clocks_hz;  // the SD clock at each command
    uint32_t ocr_polls = 0;
    std::deque<uint32_t> data;        // words of the sectors asked for
    uint32_t words_in_block = 0;
    bool multi = false;

    uint32_t sectors() const { return uint32_t(image.size() / 512); }

    // The CSD: version 2 (C_SIZE in 512 KiB units) or version 1 (a 512 MiB-or-less card).
    void csd(uint32_t rsp[4]) const {
        uint32_t c[4] = {}; // c[0]: bits 31-0 ... c[3]: bits 127-96
        auto put = [&](uint32_t hi, uint32_t lo, uint32_t v) {
            for (uint32_t b = lo; b <= hi; ++b) c[b / 32] |= ((v >> (b - lo)) & 1u) << (b % 32);
        };
        if (high_capacity) {
            put(127, 126, 1);
            put(69, 48, sectors() / 1024 - 1);
        } else { // READ_BL_LEN 9 (512), C_SIZE_MULT 7 (x512): (C_SIZE + 1) x 512 x 512 bytes
            put(83, 80, 9);
            put(49, 47, 7);
            put(73, 62, sectors() / 512 - 1);
        }
        // The controller keeps bits 127-8 as bits 119-0 of RSP3:RSP0.
        for (int i = 0; i < 4; ++i) rsp[i] = (c[i] >> 8) | (i < 3 ? c[i + 1] << 24 : 0);
    }

    uint32_t clock_hz() const {
        const uint32_t sys = model.regs[kB + kSysCtrl];
        const uint32_t sdclkfs = field(sys, 15, 8), dvs = field(sys, 7, 4);
        const uint32_t base = uint32_t(528'000'000ull * 18 / field(model.regs[analog::kPfd528], 21, 16) /
                                       (field(model.regs[ccm::kCscdr1], 13, 11) + 1));
        return base / ((sdclkfs ? sdclkfs * 2 : 1) * (dvs + 1));
    }

    void command(uint32_t xfr) {
        const uint32_t index = field(xfr, 29, 24), arg = model.regs[kB + kCmdArg];
        commands.push_back(index), arguments.push_back(arg), clocks_hz.push_back(clock_hz());
        uint32_t& status = model.regs[kB + kIntStatus];
        if (!answers && index != 0) {
            status |= 1u << 16; // CTOE
            return;
        }
        uint32_t r[4] = {};
        switch (index) {
        case 0: break;
        case 8: r[0] = arg & 0xFFF; break;
        case 55: r[0] = 0x120; break;
        case 41: r[0] = (++ocr_polls >= 3 ? 0x80000000u : 0) | (high_capacity ? 0x40000000u : 0) | 0xFF8000; break;
        case 2: r[0] = 0x12345678; break;
        case 3: r[0] = 0xAAAA0000u; break;
        case 9: csd(r); break;
        case 7: case 16: case 6: r[0] = 0x900; break;
        case 17: case 18: {
            const uint32_t sector = high_capacity ? arg : arg / 512;
            const uint32_t blocks = field(model.regs[kB + kBlkAtt], 31, 16);
            multi = index == 18;
            for (uint32_t b = 0; b < (multi ? blocks : 1); ++b) {
                for (uint32_t w = 0; w < 128; ++w) {
                    uint32_t v;
                    std::memcpy(&v, &image[size_t(sector + b) * 512 + 4 * w], 4);
                    data.push_back(v);
                }
            }
            words_in_block = 0;
            status |= bad_crc_on_data ? 1u << 21 : kBrr;
            break;
        }
        default: break;
        }
        for (uint32_t i = 0; i < 4; ++i) model.regs[kB + kCmdRsp0 + 4 * i] = r[i]; // (a map: one by one)
        status |= kCc;
    }

    void attach() {
        model.regs[analog::kPfd528] = 24u << 16;   // PFD2 at the boot ROM's 396 MHz
        model.regs[gpio::kGpio2 + gpio::kPsr] = present ? 0 : 1u << 28;
        model.write_hook = [this](uint32_t a, uint32_t v) {
            if (a == kB + kCmdXfrTyp) return command(v), true;
            if (a == kB + kIntStatus) return model.regs[a] &= ~v, true;
            if (a == kB + kSysCtrl) { // (resets and INITA end at once; the data line's reset empties the buffer)
                if (v & (1u << 26)) data.clear(), words_in_block = 0;
                return model.regs[a] = v & ~(0xFu << 24), true;
            }
            return false;
        };
        model.read_hook = [this](uint32_t a, uint32_t& v) {
            if (a == kB + kPresState) return v = 1u << 3, true; // SDSTB, never busy
            if (a == kB + kDataPort) {
                v = data.empty() ? 0 : data.front();
                if (!data.empty()) data.pop_front();
                if (++words_in_block == 128) {
                    words_in_block = 0;
                    model.regs[kB + kIntStatus] |= data.empty() ? kTc : kBrr;
                }
                return true;
            }
            return false;
        };
    }
};

std::vector<uint8_t> image(uint32_t mib) {
    std::vector<uint8_t> v(size_t(mib) << 20);
    for (size_t i = 0; i < v.size(); ++i) v[i] = uint8_t(i * 7 + (i >> 9));
    return v;
}

TEST(Usdhc, PinsPowerAndClockRootAsTheSdkSetsThem) {
    reset_model();
    UsdhcCard card;
    card.init();
    for (uint32_t n = 0; n < 6; ++n) {
        EXPECT_EQ(model.last(iomuxc::kMuxSdB0 + 4 * n), 0u) << "GPIO_SD_B0_0" << n << " ALT0";
        EXPECT_EQ(model.last(iomuxc::kPadSdB0 + 4 * n), 0x17061u);
    }
    EXPECT_EQ(model.last(iomuxc::kMuxB1 + 4 * 12), 5u) << "card detect: GPIO2_IO28";
    EXPECT_EQ(model.last(iomuxc::kPadB1 + 4 * 12), 0x1B000u);
    EXPECT_EQ(field(model.regs[gpio::kGpio2 + gpio::kGdir], 28, 28), 0u);
    EXPECT_EQ(model.last(iomuxc::kMuxAdB0 + 4 * 5), 5u) << "the slot's power: GPIO1_IO05";
    EXPECT_EQ(field(model.regs[gpio::kGpio1 + gpio::kDr], 5, 5), 1u);
    EXPECT_EQ(field(model.regs[gpio::kGpio1 + gpio::kGdir], 5, 5), 1u);
    EXPECT_EQ(field(model.regs[ccm::kCscmr1], 16, 16), 0u) << "PLL2 PFD2";
    EXPECT_EQ(field(model.regs[ccm::kCscdr1], 13, 11), 1u) << "/ 2";
    model.regs[analog::kPfd528] = 24u << 16;
    EXPECT_EQ(card.base_hz(), 198'000'000u);
}

TEST(Usdhc, TheClockDividersGiveTheFastestClockUnderEachLimit) {
    for (const uint32_t base : {198'000'000u, 176'000'000u, 132'000'000u}) {
        for (const uint32_t most : {400'000u, 25'000'000u}) {
            const SdClock c = sd_clock(base, most);
            const uint32_t hz = base / ((c.sdclkfs ? c.sdclkfs * 2 : 1) * (c.dvs + 1));
            EXPECT_EQ(hz, c.hz);
            EXPECT_LE(hz, most);
            EXPECT_GE(hz, most * 3 / 4) << base << " " << most;
        }
    }
}

TEST(Usdhc, AHighCapacityCardStartsAndReadsItsSectors) {
    reset_model();
    Card sim;
    sim.image = image(2);
    sim.attach();
    UsdhcCard card;
    card.init();
    ASSERT_TRUE(card.present());
    const Result r = card.start();
    ASSERT_TRUE(r.ok()) << r.what;
    EXPECT_EQ(card.sectors(), sim.sectors());
    // The start-up in order: CMD0, CMD8, ACMD41 until ready, CMD2, CMD3, CMD9, CMD7, ACMD6.
    const std::vector<uint32_t> want = {0, 8, 55, 41, 55, 41, 55, 41, 2, 3, 9, 7, 55, 6};
    EXPECT_EQ(sim.commands, want);
    for (size_t i = 0; i < sim.commands.size(); ++i) EXPECT_LE(sim.clocks_hz[i], 400'000u) << "command " << sim.commands[i];
    EXPECT_EQ(sim.arguments[1], 0x1AAu);
    EXPECT_EQ(sim.arguments[3], 0x40FF8000u) << "ACMD41 asks for high capacity at 3.3 V";
    EXPECT_EQ(sim.arguments[10], 0xAAAA0000u) << "CMD9 to the card's address";
    EXPECT_EQ(sim.arguments.back(), 2u) << "ACMD6: the 4-bit bus";
    EXPECT_EQ(field(model.regs[kB + kProtCtrl], 2, 1), 1u) << "4-bit";
    EXPECT_EQ(field(model.regs[kB + kProtCtrl], 5, 4), 2u) << "little endian";
    EXPECT_LE(card.clock_hz(), 25'000'000u);
    EXPECT_GE(card.clock_hz(), 20'000'000u);
    // One sector, then 37 at once (CMD18, automatic CMD12), at sector numbers.
    std::vector<uint8_t> got(37 * 512);
    ASSERT_TRUE(card.read(5, 1, got.data()).ok());
    EXPECT_EQ(std::memcmp(got.data(), &sim.image[5 * 512], 512), 0);
    EXPECT_EQ(sim.commands.back(), 17u);
    EXPECT_EQ(sim.arguments.back(), 5u);
    ASSERT_TRUE(card.read(100, 37, got.data()).ok());
    EXPECT_EQ(std::memcmp(got.data(), &sim.image[100 * 512], got.size()), 0);
    EXPECT_EQ(sim.commands.back(), 18u);
    const uint32_t mix = model.last(kB + kMixCtrl);
    EXPECT_TRUE((mix & (1u << 4)) && (mix & (1u << 5)) && (mix & (1u << 2)) && (mix & (1u << 1))) << "read, multi-block, auto CMD12, count";
    EXPECT_EQ(model.last(kB + kBlkAtt), 512u | (37u << 16));
    EXPECT_EQ(card.read(sim.sectors() - 1, 2, got.data()).status, Status::OutOfRange);
}

TEST(Usdhc, AStandardCapacityCardIsAddressedInBytes) {
    reset_model();
    Card sim;
    sim.high_capacity = false;
    sim.image = image(4);
    sim.attach();
    UsdhcCard card;
    card.init();
    ASSERT_TRUE(card.start().ok());
    EXPECT_EQ(card.sectors(), sim.sectors()) << "from CSD version 1";
    EXPECT_NE(std::find(sim.commands.begin(), sim.commands.end(), 16u), sim.commands.end()) << "SET_BLOCKLEN 512";
    std::vector<uint8_t> got(512);
    ASSERT_TRUE(card.read(9, 1, got.data()).ok());
    EXPECT_EQ(sim.arguments.back(), 9u * 512);
    EXPECT_EQ(std::memcmp(got.data(), &sim.image[9 * 512], 512), 0);
}

TEST(Usdhc, NoCardACardThatDoesNotAnswerAndABadBlockAreIo) {
    reset_model();
    Card sim;
    sim.present = false;
    sim.image = image(1);
    sim.attach();
    UsdhcCard card;
    card.init();
    EXPECT_FALSE(card.present());
    EXPECT_EQ(card.start().status, Status::Io);
    std::vector<uint8_t> got(512);
    EXPECT_EQ(card.read(0, 1, got.data()).status, Status::Io);

    reset_model();
    Card mute;
    mute.answers = false;
    mute.image = image(1);
    mute.attach();
    card.init();
    EXPECT_EQ(card.start().status, Status::Io);

    reset_model();
    Card bad;
    bad.image = image(1);
    bad.attach();
    card.init();
    ASSERT_TRUE(card.start().ok());
    bad.bad_crc_on_data = true;
    const Result r = card.read(3, 1, got.data());
    EXPECT_EQ(r.status, Status::Io);
    EXPECT_TRUE(model.last(kB + kSysCtrl) & (1u << 26)) << "the data line reset after the error";
    // Pulled: the card-detect switch opens; reads say so until it is started again.
    bad.bad_crc_on_data = false;
    model.regs[gpio::kGpio2 + gpio::kPsr] = 1u << 28;
    EXPECT_EQ(card.read(3, 1, got.data()).status, Status::Io);
    model.regs[gpio::kGpio2 + gpio::kPsr] = 0;
    EXPECT_EQ(card.read(3, 1, got.data()).status, Status::Io) << "a card put back is started first";
    ASSERT_TRUE(card.start().ok());
    EXPECT_TRUE(card.read(3, 1, got.data()).ok());
}

} // namespace
