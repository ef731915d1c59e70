// uSDHC1 and the microSD card behind it (usdhc.h). Register fields from the RT1060 reference
// manual's uSDHC chapter; the commands and the CSD from the SD Physical Layer Simplified
// Specification; pins and pad settings as NXP's SDK and the EVK's device tree set them.
#include "usdhc.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {

using namespace usdhc;
constexpr uint32_t kBase = kUsdhc1;
constexpr Place kCard{"card"};
constexpr uint32_t kPolls = 2'000'000;
// CMD_XFR_TYP: the response's CRC and index checked (CCCEN, CICEN), data with it (DPSEL).
constexpr uint32_t kCccen = 1u << 19, kCicen = 1u << 20, kDpsel = 1u << 21;
constexpr uint32_t kBcen = 1u << 1, kAc12en = 1u << 2, kDtdsel = 1u << 4, kMsbsel = 1u << 5;
constexpr uint32_t kCihb = 1u << 0, kCdihb = 1u << 1, kSdstb = 1u << 3;
constexpr uint32_t kRsta = 1u << 24, kRstc = 1u << 25, kRstd = 1u << 26, kInita = 1u << 27;
constexpr uint32_t kCdGpio = gpio::kGpio2, kCdPin = 28, kPowerGpio = gpio::kGpio1, kPowerPin = 5;

uint32_t reg(uint32_t offset) { return mmio::read(kBase + offset); }
void set(uint32_t offset, uint32_t value) { mmio::write(kBase + offset, value); }
Result io(const char* what) { return Result::fail(Status::Io, what, kCard); }

} // namespace

SdClock sd_clock(uint32_t base_hz, uint32_t most) {
    // SD clock = base / (prescaler x divisor): prescaler 1 (SDCLKFS 0) or 2, 4, ... 256
    // (SDCLKFS 0x01 ... 0x80), divisor 1 to 16 (DVS 0 to 15).
    SdClock best{0x80, 15, base_hz / (256 * 16)}; // (the slowest, when even it is too fast)
    for (uint32_t k = 0; k <= 8; ++k) {
        const uint32_t prescaler = 1u << k;
        for (uint32_t dvs = 0; dvs < 16; ++dvs) {
            const uint32_t hz = base_hz / (prescaler * (dvs + 1));
            if (hz <= most && hz > best.hz) best = {prescaler >> 1, dvs, hz};
        }
    }
    return best;
}

uint32_t UsdhcCard::base_hz() const {
    const uint32_t frac = (mmio::read(analog::kPfd528) >> 16) & 0x3F;
    const uint32_t podf = (mmio::read(ccm::kCscdr1) >> 11) & 0x7;
    return frac >= 12 ? uint32_t(528'000'000ull * 18 / frac / (podf + 1)) : 0;
}

void UsdhcCard::init() {
    using namespace iomuxc;
    // CMD, CLK, DATA0-3: ALT0, 47K pull-up, speed 100 MHz, DSE 4, hysteresis (= 0x17061).
    constexpr uint32_t kSdPad = pad(1, 4, 1, 0, 1, 1, 1, 1);
    static_assert(kSdPad == 0x17061, "the EVK's device tree's uSDHC pad value");
    for (uint32_t n = 0; n < 6; ++n) {
        mmio::write(kMuxSdB0 + 4 * n, 0);
        mmio::write(kPadSdB0 + 4 * n, kSdPad);
    }
    // Card detect GPIO_B1_12 as GPIO2_IO28 (ALT5), an input with a 100K pull-up (= 0x1B000).
    mmio::write(kMuxB1 + 4 * 12, 5);
    mmio::write(kPadB1 + 4 * 12, pad(0, 0, 0, 0, 1, 1, 2, 1));
    mmio::modify(kCdGpio + gpio::kGdir, 1u << kCdPin, 0);
    // The slot's power GPIO_AD_B0_05 as GPIO1_IO05 (ALT5), an output driven high.
    mmio::write(kMuxAdB0 + 4 * 5, 5);
    mmio::modify(kPowerGpio + gpio::kDr, 1u << kPowerPin, 1u << kPowerPin);
    mmio::modify(kPowerGpio + gpio::kGdir, 1u << kPowerPin, 1u << kPowerPin);
    // The clock root: PLL2 PFD2 (396 MHz as the boot ROM leaves it) / 2.
    mmio::modify(ccm::kCscmr1, 1u << 16, 0);
    mmio::modify(ccm::kCscdr1, 0x7u << 11, 1u << 11);
}

bool UsdhcCard::present() {
    const bool in = !(mmio::read(kCdGpio + gpio::kPsr) & (1u << kCdPin));
    if (!in) started_ = false; // (one put back is started again)
    return in;
}

void UsdhcCard::set_clock(uint32_t most) {
    const SdClock c = sd_clock(base_hz(), most);
    set(kSysCtrl, (reg(kSysCtrl) & ~0x000FFFF0u) | (c.sdclkfs << 8) | (c.dvs << 4) | (0xEu << 16));
    (void)mmio::wait(kBase + kPresState, kSdstb, kSdstb, kPolls);
    clock_hz_ = c.hz;
}

Result UsdhcCard::command(uint32_t index, uint32_t argument, uint32_t response, bool data) {
    const uint32_t busy = data ? kCihb | kCdihb : kCihb;
    if (!mmio::wait(kBase + kPresState, busy, 0, kPolls)) return io("the controller stayed busy");
    set(kIntStatus, 0xFFFFFFFFu);
    set(kCmdArg, argument);
    // A 48-bit response has its CRC and index checked, a 136-bit one its CRC; R3 (ACMD41) neither.
    uint32_t checks = response == kRsp48 || response == kRsp48Busy ? kCccen | kCicen : response == kRsp136 ? kCccen : 0;
    if (index == 41) checks = 0;
    set(kCmdXfrTyp, (index << 24) | (response << 16) | checks | (data ? kDpsel : 0));
    for (uint32_t k = 0; k < kPolls; ++k) {
        const uint32_t s = reg(kIntStatus);
        if (s & kCmdErrors) {
            set(kSysCtrl, reg(kSysCtrl) | kRstc); // (the command line reset)
            (void)mmio::wait(kBase + kSysCtrl, kRstc, 0, kPolls);
            return io(s & (1u << 16) ? "the card did not answer a command" : "a command's answer failed its checks");
        }
        if (s & kCc) {
            set(kIntStatus, kCc);
            for (int i = 0; i < 4; ++i) resp_[i] = reg(kCmdRsp0 + 4 * i);
            return {};
        }
    }
    return io("the controller never ended a command");
}

Result UsdhcCard::start() {
    started_ = false, sectors_ = 0;
    if (!present()) return io("no card in the slot");
    set(kSysCtrl, reg(kSysCtrl) | kRsta);
    if (!mmio::wait(kBase + kSysCtrl, kRsta, 0, kPolls)) return io("the controller did not reset");
    set(kProtCtrl, 2u << 4); // little endian, 1-bit bus
    set(kIntStatusEn, 0xFFFFFFFFu);
    set_clock(kCclkMax);
    set(kSysCtrl, reg(kSysCtrl) | kInita); // 80 clocks for the card to start
    (void)mmio::wait(kBase + kSysCtrl, kInita, 0, kPolls);
    if (Result r = command(0, 0, kRspNone); !r.ok()) return r;
    const bool v2 = command(8, 0x1AA, kRsp48).ok() && (resp_[0] & 0xFFF) == 0x1AA;
    bool ready = false;
    for (uint32_t k = 0; k < 2000 && !ready; ++k) { // (about a second at most: a card takes up to one)
        if (Result r = command(55, 0, kRsp48); !r.ok()) return r;
        if (Result r = command(41, v2 ? 0x40FF8000u : 0x00FF8000u, kRsp48); !r.ok()) return r;
        ready = resp_[0] & 0x80000000u;
        if (!ready) mmio::delay_us(500);
    }
    if (!ready) return io("the card never left its power-up");
    block_addressed_ = v2 && (resp_[0] & 0x40000000u);
    if (Result r = command(2, 0, kRsp136); !r.ok()) return r;
    if (Result r = command(3, 0, kRsp48); !r.ok()) return r;
    rca_ = resp_[0] & 0xFFFF0000u;
    if (Result r = command(9, rca_, kRsp136); !r.ok()) return r;
    // The 136-bit response holds the CSD's bits 127-8 (its CRC left out) as bits 119-0 of RSP3:RSP0.
    auto csd = [&](uint32_t hi, uint32_t lo) {
        uint32_t v = 0;
        for (uint32_t b = hi + 1; b-- > lo;) v = (v << 1) | ((resp_[(b - 8) / 32] >> ((b - 8) % 32)) & 1u);
        return v;
    };
    if (csd(127, 126) == 1) {
        sectors_ = (csd(69, 48) + 1) * 1024; // (C_SIZE + 1) x 512 KiB
    } else {
        const uint64_t bytes = uint64_t(csd(73, 62) + 1) << (csd(49, 47) + 2 + csd(83, 80));
        sectors_ = uint32_t(bytes / kSectorBytes);
    }
    if (sectors_ == 0) return io("the card states no size");
    if (Result r = command(7, rca_, kRsp48Busy); !r.ok()) return r;
    if (!block_addressed_) {
        if (Result r = command(16, kSectorBytes, kRsp48); !r.ok()) return r;
    }
    // The 4-bit bus (ACMD6), then the default-speed clock.
    if (Result r = command(55, rca_, kRsp48); !r.ok()) return r;
    if (Result r = command(6, 2, kRsp48); !r.ok()) return r;
    set(kProtCtrl, (reg(kProtCtrl) & ~(3u << 1)) | (1u << 1));
    set_clock(kTransferMax);
    started_ = true;
    return {};
}

Result UsdhcCard::read(uint32_t sector, uint32_t count, void* into) {
    if (!started_ || !present()) return io("no card (pulled, or not started)");
    if (uint64_t(sector) + count > sectors_) return Result::fail(Status::OutOfRange, "a read past the card's end", kCard);
    auto* out = static_cast<uint32_t*>(into);
    constexpr uint32_t kWords = kSectorBytes / 4;
    while (count > 0) {
        const uint32_t n = count < 0xFFFF ? count : 0xFFFF;
        set(kBlkAtt, kSectorBytes | (n << 16));
        set(kWtmkLvl, (reg(kWtmkLvl) & ~0xFFu) | kWords);
        set(kMixCtrl, kDtdsel | (n > 1 ? kMsbsel | kBcen | kAc12en : 0));
        const uint32_t address = block_addressed_ ? sector : sector * kSectorBytes;
        if (Result r = command(n > 1 ? 18 : 17, address, kRsp48, true); !r.ok()) return r;
        Result r;
        for (uint32_t b = 0; b < n && r.ok(); ++b) {
            uint32_t s = 0;
            for (uint32_t k = 0; k < kPolls && !((s = reg(kIntStatus)) & (kBrr | kDataErrors)); ++k) {
            }
            if (s & kDataErrors) {
                r = io(s & (1u << 20) ? "the card stopped sending data" : "a block from the card failed its CRC");
            } else if (!(s & kBrr)) {
                r = io("the card never sent a block");
            } else {
                set(kIntStatus, kBrr);
                for (uint32_t w = 0; w < kWords; ++w) *out++ = reg(kDataPort);
            }
        }
        if (r.ok()) {
            uint32_t s = 0;
            for (uint32_t k = 0; k < kPolls && !((s = reg(kIntStatus)) & (kTc | kDataErrors | kAc12e)); ++k) {
            }
            if (!(s & kTc) || (s & (kDataErrors | kAc12e))) r = io("the transfer did not end cleanly");
        }
        if (!r.ok()) {
            set(kSysCtrl, reg(kSysCtrl) | kRstc | kRstd); // (the command and data lines reset)
            (void)mmio::wait(kBase + kSysCtrl, kRstc | kRstd, 0, kPolls);
            return r;
        }
        sector += n, count -= n;
    }
    return {};
}

} // namespace facet::evkb
