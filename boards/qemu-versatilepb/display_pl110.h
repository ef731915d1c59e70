#pragma once
// PL110 colour LCD at the board's resolution (board.json), RGB565, scanning out whichever frame
// it was shown last (the firmware owns the frames; switching the base is the double buffering).
#include "hal/display.h"

namespace facet::versatilepb {

class Pl110Display final : public hal::Display {
public:
    void init(); // timings; the controller is enabled with the first frame shown
    hal::DisplayInfo info() const override;
    Status show(Rgb565* frame) override;
    Status write(const Area& area, const Rgb565* pixels) override;
    const Rgb565* frame() const override { return shown_; }

private:
    Rgb565* shown_ = nullptr;
};

} // namespace facet::versatilepb
