#include "console_pl011.h"

#include "memory_map.h"

namespace facet::versatilepb {
namespace {
constexpr uintptr_t kDr = kPl011 + 0x00, kFr = kPl011 + 0x18, kCr = kPl011 + 0x30;
constexpr uint32_t kFrRxEmpty = 1u << 4, kFrTxFull = 1u << 5;
} // namespace

void Pl011Console::init() { reg(kCr) = 0x301; } // UARTEN | TXE | RXE

void Pl011Console::write(const char* data, size_t size) {
    for (size_t i = 0; i < size; ++i) {
        while (reg(kFr) & kFrTxFull) {
        }
        reg(kDr) = static_cast<uint8_t>(data[i]);
    }
}

int Pl011Console::read_hardware() {
    if (reg(kFr) & kFrRxEmpty) return -1;
    return static_cast<int>(reg(kDr) & 0xFF);
}

void Pl011Console::keep(uint8_t byte) {
    if (head_ - tail_ < kRing) ring_[head_++ % kRing] = byte; // full: drop the newest
}

int Pl011Console::read_byte() {
    if (head_ != tail_) return ring_[tail_++ % kRing];
    return read_hardware();
}

} // namespace facet::versatilepb
