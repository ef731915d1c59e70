#include "lpi2c.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {
using namespace lpi2c;
constexpr uint32_t kErrorFlags = kNdf | kAlf | kFef | kPltf;
constexpr uint32_t kAllW1c = 0x3F00; // EPF SDF NDF ALF FEF PLTF: write 1 to clear
constexpr uint32_t kPoll = 200000;   // reads before a time-out (a byte at 100 kHz is 90 us)
constexpr uint32_t kTxFifo = 4;      // the transmit FIFO's depth (PARAM.MTXFIFO = 2^2)
} // namespace

void Lpi2c::init(const I2cTiming& t) {
    mmio::write(base_ + kMcr, kRst);
    mmio::write(base_ + kMcr, 0);
    mmio::write(base_ + kMcfgr1, 0);  // PRESCALE /1, two-pin open drain, no auto-stop
    mmio::write(base_ + kMcfgr2, 0);  // no glitch filters, no bus idle time-out
    mmio::write(base_ + kMccr0, (t.datavd << 24) | (t.sethold << 16) | (t.clkhi << 8) | t.clklo);
    mmio::write(base_ + kMcr, kMen);
}

bool Lpi2c::push(uint32_t word) {
    for (uint32_t i = 0; i < kPoll; ++i) {
        if ((mmio::read(base_ + kMfsr) & 7) < kTxFifo) {
            mmio::write(base_ + kMtdr, word);
            return true;
        }
        if (mmio::read(base_ + kMsr) & kErrorFlags) return false;
    }
    return false;
}

// A stop on the bus (queued after what is in the FIFO), then the verdict: a NACK or a bus error
// seen on the way beats `r`; the FIFOs are emptied and the flags cleared either way.
Result Lpi2c::finish(Result r) {
    if (mmio::read(base_ + kMsr) & kErrorFlags) mmio::write(base_ + kMcr, kMen | kRtf | kRrf); // drop what is queued
    mmio::write(base_ + kMtdr, kCmdStop);
    mmio::wait(base_ + kMsr, kSdf, kSdf, kPoll);
    const uint32_t msr = mmio::read(base_ + kMsr);
    if (msr & kNdf) r = Result::fail(Status::NotFound, "no acknowledge from the I2C device");
    else if (msr & (kAlf | kFef | kPltf)) r = Result::fail(Status::Io, "I2C bus error");
    mmio::write(base_ + kMcr, kMen | kRtf | kRrf);
    mmio::write(base_ + kMsr, kAllW1c);
    return r;
}

Result Lpi2c::transfer(uint8_t address, const uint8_t* w, uint32_t wn, uint8_t* r, uint32_t rn) {
    if (rn > 256) return Result::fail(Status::OutOfRange, "an I2C read of more than 256 bytes");
    if (!mmio::wait(base_ + kMsr, kMbf, 0, kPoll)) return Result::fail(Status::Busy, "the I2C master stays busy");
    mmio::write(base_ + kMsr, kAllW1c);
    const Result timeout = Result::fail(Status::Busy, "I2C time-out");
    if (wn) {
        if (!push(kCmdStart | (uint32_t(address) << 1))) return finish(timeout);
        for (uint32_t i = 0; i < wn; ++i)
            if (!push(kCmdTransmit | w[i])) return finish(timeout);
    }
    if (rn) {
        if (!push(kCmdStart | (uint32_t(address) << 1) | 1)) return finish(timeout);
        if (!push(kCmdReceive | (rn - 1))) return finish(timeout);
        for (uint32_t i = 0; i < rn; ++i) {
            uint32_t v = kRxEmpty, n = 0;
            while ((v = mmio::read(base_ + kMrdr)) & kRxEmpty) {
                if (++n == kPoll || (mmio::read(base_ + kMsr) & kErrorFlags)) return finish(timeout);
            }
            r[i] = uint8_t(v);
        }
    }
    // Wait for the address and data to leave (or a NACK), then stop.
    for (uint32_t n = 0; (mmio::read(base_ + kMfsr) & 7) != 0; ++n) {
        if (n == kPoll || (mmio::read(base_ + kMsr) & kErrorFlags)) break;
    }
    return finish({});
}

} // namespace facet::evkb
