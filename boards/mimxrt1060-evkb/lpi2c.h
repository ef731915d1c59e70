#pragma once
// LPI2C1 as a polled I2C master (the touch controller's bus), and the small bus interface the
// touch drivers use (so they are tested on the host with a simulated device).
#include "core/status.h"

#include <cstdint>

namespace facet::evkb {

class I2cBus {
public:
    // A write of `wn` bytes to 7-bit `address`, then (if rn) a repeated start and a read of `rn`
    // bytes. NotFound: nobody acknowledged the address; Io: a bus error; Busy: a time-out.
    virtual Result transfer(uint8_t address, const uint8_t* w, uint32_t wn, uint8_t* r, uint32_t rn) = 0;

protected:
    ~I2cBus() = default;
};

// SCL timing (RM, LPI2C "Master Clock Configuration Register 0"): with PRESCALE 0 and no
// glitch filter, SCL period = (CLKHI + CLKLO + 2 + 1) functional clocks; the low time is
// CLKLO + 1 clocks, the high time CLKHI + 1 + 1; START hold and STOP setup SETHOLD + 1 clocks;
// data valid DATAVD + 1 clocks. For a 10 MHz functional clock:
struct I2cTiming {
    uint32_t clklo, clkhi, sethold, datavd;
};
// 100 kHz (standard mode: tLOW >= 4.7 us, tHIGH >= 4.0 us, tHD;STA >= 4.0 us, tSU;STA >= 4.7 us,
// tVD;DAT <= 3.45 us): low 5.1 us, high 4.9 us, start/stop 4.8 us, data valid 1.0 us.
constexpr I2cTiming kI2c100kHzAt10MHz{50, 47, 47, 9};

class Lpi2c final : public I2cBus {
public:
    explicit Lpi2c(uint32_t base) : base_(base) {}
    void init(const I2cTiming& timing);
    Result transfer(uint8_t address, const uint8_t* w, uint32_t wn, uint8_t* r, uint32_t rn) override;

private:
    Result finish(Result r);
    bool push(uint32_t word);
    uint32_t base_;
};

} // namespace facet::evkb
