#pragma once
// Capture: pictures for a host that watches the board (QEMU's runner, tools/qemu/run.py), each
// under a name (letters, digits, - and _). A board without such a host has none
// (Board::capture is null; its board.json says "screenshots": false).
#include "core/pixel.h"
#include "core/status.h"

#include <cstdint>

namespace facet::hal {

class Capture {
public:
    // The frame on the screen. Io when the host did not take it (no runner).
    virtual Status shot(const char* name) = 0;
    // Any picture in memory (width x height RGB565, row after row).
    virtual Status dump(const char* name, const Rgb565* pixels, uint16_t width, uint16_t height) = 0;

protected:
    ~Capture() = default;
};

} // namespace facet::hal
