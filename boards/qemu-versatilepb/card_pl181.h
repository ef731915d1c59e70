#pragma once
// The SD card behind the Versatile/PB's PL181 MultiMedia Card Interface (MMCI0; QEMU's
// `-drive if=sd`): brought up with the SD protocol's commands (CMD0, CMD8, ACMD41, CMD2, CMD3,
// CMD9, CMD7, CMD16), read a sector at a time (CMD17) or many (CMD18, then CMD12), its data
// polled out of the controller's FIFO. The card-detect line is the system controller's SYS_MCI
// (QEMU does not drive it: there, a card is present when it answers).
#include "hal/card.h"

#include <cstdint>

namespace facet::versatilepb {

class Pl181Card final : public hal::Card {
public:
    bool present() override;
    Result start() override;
    uint32_t sectors() const override { return sectors_; }
    Result read(uint32_t sector, uint32_t count, void* into) override;

private:
    // A command: its response (short or long) in resp_ (Io on a timeout or a CRC failure,
    // except where `crc_ok` says the response has none, as ACMD41's).
    Result command(uint32_t index, uint32_t argument, uint32_t response, bool crc_ok = false);
    Result read_data(uint32_t* out, uint32_t words);
    uint32_t resp_[4] = {};
    uint32_t sectors_ = 0, rca_ = 0;
    bool block_addressed_ = false; // SDHC: sector numbers; SDSC: byte addresses
    bool started_ = false;
};

} // namespace facet::versatilepb
