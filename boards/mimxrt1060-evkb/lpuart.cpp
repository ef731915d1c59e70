#include "lpuart.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {

void Lpuart::init(uint32_t clock_hz, uint32_t baud) {
    using namespace lpuart;
    mmio::write(base_ + kGlobal, 1u << 1); // software reset
    mmio::write(base_ + kGlobal, 0);
    const BaudDivisors d = baud_divisors(clock_hz, baud);
    // BOTHEDGE is required when the oversampling ratio is 4 to 7 (RM, LPUART_BAUD OSR).
    const uint32_t both = d.osr + 1 < 8 ? kBothEdge : 0;
    mmio::write(base_ + kBaud, (d.osr << 24) | both | d.sbr); // SBNS 0: one stop bit
    mmio::write(base_ + kCtrl, kTe | kRe);                   // M 0, PE 0: 8 data bits, no parity
}

void Lpuart::write(const char* data, size_t size) {
    for (size_t i = 0; i < size; ++i) {
        while (!(mmio::read(base_ + lpuart::kStat) & lpuart::kTdre)) {
        }
        mmio::write(base_ + lpuart::kData, uint8_t(data[i]));
    }
}

int Lpuart::read_byte() {
    const uint32_t stat = mmio::read(base_ + lpuart::kStat);
    if (stat & lpuart::kErrors) {
        mmio::write(base_ + lpuart::kStat, stat & lpuart::kErrors); // write 1 to clear
        if (stat & lpuart::kRdrf) (void)mmio::read(base_ + lpuart::kData);
        ++dropped_;
        return -1;
    }
    if (!(stat & lpuart::kRdrf)) return -1;
    return int(mmio::read(base_ + lpuart::kData) & 0xFF);
}

} // namespace facet::evkb
