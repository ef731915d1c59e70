#pragma once
// Display: a board's panel, in the two ways pixels reach one (LVGL's flush_cb, Zephyr's
// display_write): an LCD controller that scans a frame out of RAM is shown a frame the caller
// owns; any panel takes areas copied into the frame it shows (or into its own memory, behind a
// bus). The geometry comes from the driver; nothing outside boards/ may assume a resolution.
#include "core/pixel.h"
#include "core/status.h"

#include <cstdint>

namespace facet::hal {

struct DisplayInfo {
    uint16_t width;
    uint16_t height;
    PixelFormat format;
    bool scanout; // show() works: the controller reads frames from RAM
};

class Display {
public:
    virtual DisplayInfo info() const = 0;
    // Shows `frame` (width * height pixels, row after row, in the caller's memory, which must
    // stay valid while it is shown) from the next refresh on. Unsupported without scan-out.
    virtual Status show(Rgb565* frame) = 0;
    // Copies `pixels` (area.width * area.height, row after row) into the frame on the panel.
    // OutOfRange (nothing written) if the area leaves the screen; NotFound on a scan-out panel
    // that was shown no frame yet.
    virtual Status write(const Area& area, const Rgb565* pixels) = 0;
    // The frame on the screen (for captures); null when there is none in RAM.
    virtual const Rgb565* frame() const = 0;
    // True while the frame last passed to show() is not on the screen yet: a controller that
    // switches frames at vertical blank still scans the previous one out, which must not be
    // drawn into until then. Displays that switch at once never are.
    virtual bool busy() const { return false; }

protected:
    ~Display() = default;
};

// The copy every RAM-frame driver needs: `area` of `pixels` into `frame` (width x height),
// bounds-checked.
Status copy_area(Rgb565* frame, uint16_t width, uint16_t height, const Area& area, const Rgb565* pixels);

} // namespace facet::hal
