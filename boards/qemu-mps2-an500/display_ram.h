#pragma once
// The mps2 has no LCD: a "panel" that shows a frame in RAM (the firmware's), with the geometry
// of the MIMXRT1060-EVKB's panel (board.json), whose Cortex-M7 this board stands in for.
// Captures are written to the host through semihosting as F565 files (tools/img.py).
#include "hal/display.h"

namespace facet::mps2 {

class RamDisplay final : public hal::Display {
public:
    hal::DisplayInfo info() const override;
    Status show(Rgb565* frame) override;
    Status write(const Area& area, const Rgb565* pixels) override;
    const Rgb565* frame() const override { return shown_; }

private:
    Rgb565* shown_ = nullptr;
};

} // namespace facet::mps2
