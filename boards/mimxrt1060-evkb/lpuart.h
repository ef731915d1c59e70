#pragma once
// LPUART1, polled: the console on the debug probe's virtual COM port, 115200 8N1.
#include "hal/console.h"

#include <cstdint>

namespace facet::evkb {

// BAUD register dividers: baud = clock / ((OSR + 1) x SBR), OSR + 1 from 4 to 32, SBR from 1
// to 8191 (RM, LPUART: "Baud rate generation"). The pair with the smallest error, the largest
// oversampling among equals.
struct BaudDivisors {
    uint32_t osr; // the OSR field: oversampling - 1
    uint32_t sbr;
};
constexpr BaudDivisors baud_divisors(uint32_t clock_hz, uint32_t baud) {
    BaudDivisors best{15, 1};
    uint64_t best_error = ~uint64_t(0);
    for (uint32_t over = 4; over <= 32; ++over) {
        uint32_t sbr = uint32_t((uint64_t(clock_hz) + uint64_t(baud) * over / 2) / (uint64_t(baud) * over));
        if (sbr < 1) sbr = 1;
        if (sbr > 8191) continue;
        const uint64_t got = clock_hz / (uint64_t(over) * sbr);
        const uint64_t error = got > baud ? got - baud : baud - got;
        if (error <= best_error) best = {over - 1, sbr}, best_error = error;
    }
    return best;
}

class Lpuart final : public hal::Console {
public:
    explicit Lpuart(uint32_t base) : base_(base) {}
    void init(uint32_t clock_hz, uint32_t baud);
    void write(const char* data, size_t size) override;
    // A received byte, or -1. Bytes with a framing, noise or parity error are dropped (counted).
    int read_byte() override;
    uint32_t dropped() const { return dropped_; }

private:
    uint32_t base_;
    uint32_t dropped_ = 0;
};

} // namespace facet::evkb
