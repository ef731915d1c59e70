#pragma once
// Register access for the EVKB's drivers. On the target a plain volatile load or store; on the
// host the drivers are compiled against a register model (tests/boards/evkb_regs_test.cpp)
// that records every write and answers the reads a driver polls — so the set-up sequences are
// checked against the reference manual's formulas and the panel's and touch controller's
// documented values without the board.
#include <cstdint>

namespace facet::evkb::mmio {

#if FACET_TARGET
inline uint32_t read(uint32_t address) { return *reinterpret_cast<volatile uint32_t*>(uintptr_t(address)); }
inline void write(uint32_t address, uint32_t value) { *reinterpret_cast<volatile uint32_t*>(uintptr_t(address)) = value; }
inline uint16_t read16(uint32_t address) { return *reinterpret_cast<volatile uint16_t*>(uintptr_t(address)); }
inline void write16(uint32_t address, uint16_t value) { *reinterpret_cast<volatile uint16_t*>(uintptr_t(address)) = value; }
#else
uint32_t read(uint32_t address);
void write(uint32_t address, uint32_t value);
uint16_t read16(uint32_t address);
void write16(uint32_t address, uint16_t value);
#endif

inline void modify(uint32_t address, uint32_t mask, uint32_t value) { write(address, (read(address) & ~mask) | value); }

// Busy-waits at least `us` microseconds (the GPT's 1 MHz count once it runs).
void delay_us(uint32_t us);

// Polls until (read(address) & mask) == want, at most `limit` reads. False on time-out.
inline bool wait(uint32_t address, uint32_t mask, uint32_t want, uint32_t limit = 10'000'000) {
    for (uint32_t i = 0; i < limit; ++i)
        if ((read(address) & mask) == want) return true;
    return false;
}

} // namespace facet::evkb::mmio
