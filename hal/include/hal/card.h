#pragma once
// A memory card (or any block device): 512-byte sectors read by number. A board with a card slot
// gives one (QEMU versatilepb's PL181, the EVKB's uSDHC); hal/fat.h reads its filesystem.
#include "core/status.h"

#include <cstdint>

namespace facet::hal {

class Card {
public:
    static constexpr uint32_t kSectorBytes = 512;

    // Whether a card is in the slot (its card-detect line). No card: every read is Io.
    virtual bool present() = 0;
    // The card brought up (after it was put in): its size known. Io: no card, or it does not answer.
    [[nodiscard]] virtual Result start() = 0;
    virtual uint32_t sectors() const = 0; // the card's size (0 before start())
    // `count` sectors from `sector` on into `into` (4-byte aligned). Io: the card failed or was
    // pulled; OutOfRange: past its end.
    [[nodiscard]] virtual Result read(uint32_t sector, uint32_t count, void* into) = 0;

protected:
    ~Card() = default;
};

} // namespace facet::hal
