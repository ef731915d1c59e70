#pragma once
// A memory card image on the host, read through semihosting: the card of a QEMU board without an
// SD slot (mps2). `facet-card.img` in QEMU's working directory (tools/qemu/run.py --card puts the
// image there); its 512-byte blocks are the card's sectors. Looked for once, at the first
// present(): a card in from the start or never, and never pulled.
#include "hal/card.h"

namespace facet::qemu {

class SemihostedCard final : public hal::Card {
public:
    static constexpr const char* kPath = "facet-card.img";
    bool present() override;
    [[nodiscard]] Result start() override;
    uint32_t sectors() const override { return sectors_; }
    [[nodiscard]] Result read(uint32_t sector, uint32_t count, void* into) override;

private:
    bool looked_ = false;
    int handle_ = -1;
    uint32_t sectors_ = 0;
};

} // namespace facet::qemu
