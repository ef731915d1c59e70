#pragma once
// The microSD slot: uSDHC1 (RM chapter "Ultra Secured Digital Host Controller (uSDHC)") with
// the card behind it, polled (no DMA, no interrupts: a read ends inside the call). The card is
// brought up at under 400 kHz (CMD0, CMD8, ACMD41, CMD2, CMD3, CMD9 for its size, CMD7, CMD16
// for a standard-capacity card, ACMD6 for the 4-bit bus) and read at 25 MHz, a sector (CMD17)
// or many (CMD18 with the controller's automatic CMD12), its data taken from the buffer port
// as the read watermark fills. Pins (the EVKB's schematic; NXP's SDK board files): CMD, CLK,
// DATA0-3 on GPIO_SD_B0_00-05 (ALT0), card detect GPIO_B1_12 as GPIO2_IO28 (low: a card in),
// the slot's power GPIO_AD_B0_05 as GPIO1_IO05 (high: on).
#include "hal/card.h"

#include <cstdint>

namespace facet::evkb {

namespace usdhc {
constexpr uint32_t kUsdhc1 = 0x402C0000;
constexpr uint32_t kBlkAtt = 0x04;     // BLKSIZE 12:0, BLKCNT 31:16
constexpr uint32_t kCmdArg = 0x08;
constexpr uint32_t kCmdXfrTyp = 0x0C;  // RSPTYP 17:16, CCCEN 19, CICEN 20, DPSEL 21, CMDTYP 23:22, CMDINX 29:24
constexpr uint32_t kCmdRsp0 = 0x10;    // CMD_RSP0..3 at 0x10..0x1C
constexpr uint32_t kDataPort = 0x20;   // DATA_BUFF_ACC_PORT
constexpr uint32_t kPresState = 0x24;  // CIHB 0, CDIHB 1, SDSTB 3, BREN 11, CINST 16
constexpr uint32_t kProtCtrl = 0x28;   // DTW 2:1 (0: 1-bit, 1: 4-bit), EMODE 5:4 (2: little endian)
constexpr uint32_t kSysCtrl = 0x2C;    // DVS 7:4, SDCLKFS 15:8, DTOCV 19:16, RSTA 24, RSTC 25, RSTD 26, INITA 27
constexpr uint32_t kIntStatus = 0x30;  // CC 0, TC 1, BRR 5, CTOE 16, CCE 17, CEBE 18, CIE 19, DTOE 20, DCE 21, DEBE 22, AC12E 24
constexpr uint32_t kIntStatusEn = 0x34;
constexpr uint32_t kWtmkLvl = 0x44;    // RD_WML 7:0 (words)
constexpr uint32_t kMixCtrl = 0x48;    // BCEN 1, AC12EN 2, DTDSEL 4 (read), MSBSEL 5
// Response types (CMD_XFR_TYP.RSPTYP): none, 136 bits, 48 bits, 48 bits with busy.
constexpr uint32_t kRspNone = 0, kRsp136 = 1, kRsp48 = 2, kRsp48Busy = 3;
constexpr uint32_t kCc = 1u << 0, kTc = 1u << 1, kBrr = 1u << 5;
constexpr uint32_t kCmdErrors = 0xFu << 16, kDataErrors = 0x7u << 20, kAc12e = 1u << 24;
constexpr uint32_t kCclkMax = 400'000, kTransferMax = 25'000'000; // identification and default-speed clocks
} // namespace usdhc

// The SD clock for a base clock: SDCLKFS (prescaler 2^k as the bit 2^(k-1); 0: 1) and DVS
// (divisor DVS + 1) giving the fastest clock at or under `most`.
struct SdClock {
    uint32_t sdclkfs, dvs, hz;
};
SdClock sd_clock(uint32_t base_hz, uint32_t most);

class UsdhcCard final : public hal::Card {
public:
    void init();            // pins, the slot's power and the controller's clock root
    bool present() override; // the card-detect switch
    Result start() override;
    uint32_t sectors() const override { return sectors_; }
    Result read(uint32_t sector, uint32_t count, void* into) override;
    uint32_t clock_hz() const { return clock_hz_; } // the SD clock now
    uint32_t base_hz() const;                       // the controller's clock root (from the PLL's PFD)

private:
    Result command(uint32_t index, uint32_t argument, uint32_t response, bool data = false);
    void set_clock(uint32_t most);
    uint32_t resp_[4] = {};
    uint32_t sectors_ = 0, rca_ = 0, clock_hz_ = 0;
    bool block_addressed_ = false, started_ = false;
};

} // namespace facet::evkb
