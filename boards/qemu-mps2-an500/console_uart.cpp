#include "console_uart.h"

#include "memory_map.h"

namespace facet::mps2 {
namespace {
constexpr uintptr_t kData = kUart0 + 0x00, kState = kUart0 + 0x04, kCtrl = kUart0 + 0x08,
                    kBaudDiv = kUart0 + 0x10;
constexpr uint32_t kTxFull = 1u << 0, kRxFull = 1u << 1;
} // namespace

void CmsdkUart::init() {
    reg(kBaudDiv) = kSysClockHz / 115200;
    reg(kCtrl) = 0x3; // TX and RX enabled, no interrupts
}

void CmsdkUart::write(const char* data, size_t size) {
    for (size_t i = 0; i < size; ++i) {
        while (reg(kState) & kTxFull) {
        }
        reg(kData) = static_cast<uint8_t>(data[i]);
    }
}

int CmsdkUart::read_byte() {
    if (!(reg(kState) & kRxFull)) return -1;
    return static_cast<int>(reg(kData) & 0xFF);
}

} // namespace facet::mps2
