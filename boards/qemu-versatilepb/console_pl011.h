#pragma once
// PL011 UART0 console. Polled (no interrupts), with a small receive ring so bytes that arrive
// while the firmware waits for a capture acknowledgement are not lost.
#include "hal/console.h"

#include <cstdint>

namespace facet::versatilepb {

class Pl011Console final : public hal::Console {
public:
    void init();
    void write(const char* data, size_t size) override;
    int read_byte() override;
    // Reads one byte from the hardware only (bypassing the ring); -1 if none.
    int read_hardware();
    // Puts a byte into the receive ring (used while waiting for a specific byte).
    void keep(uint8_t byte);

private:
    static constexpr uint32_t kRing = 64;
    uint8_t ring_[kRing];
    uint32_t head_ = 0, tail_ = 0;
};

} // namespace facet::versatilepb
