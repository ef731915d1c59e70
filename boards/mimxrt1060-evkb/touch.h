#pragma once
// The panel's capacitive touch controller, polled over I2C. Which one answers tells which panel
// is on the connector (NXP sells two for it, both 480x272):
//   Goodix GT911 at 0x5D (or 0x14): the RK043FN66HS-CTG, the EVKB's current panel. 16-bit
//     register addresses, big-endian: product ID "911" at 0x8140, the configured resolution at
//     0x8048/0x804A (little-endian), the status at 0x814E (bit 7: new data, bits 3:0: points),
//     points from 0x814F, 8 bytes each (track ID, x, y little-endian, size); the host clears the
//     status after reading (Goodix GT911 programming guide; NXP's fsl_gt911.c does the same).
//   FocalTech FT5406 at 0x38: the RK043FN02H-CT. 8-bit registers: DEVICE_MODE 0x00 (0: normal),
//     TD_STATUS 0x02 (points, 3:0), points from 0x03, 6 bytes each (XH: event 7:6, x 11:8; XL;
//     YH: ID 7:4, y 11:8; YL). Its x and y axes are the panel's y and x: NXP's SDK swaps them.
#include "lpi2c.h"

#include <cstdint>

namespace facet::evkb {

struct TouchPoint {
    uint8_t id;
    int16_t x, y; // screen pixels
};

struct TouchFrame {
    static constexpr uint32_t kMax = 2; // the module's gestures use two fingers
    uint32_t count = 0;
    TouchPoint points[kMax];
};

class Touch {
public:
    enum class Chip : uint8_t { None, Gt911, Ft5406 };

    // Finds the controller on `bus` (GT911 at 0x5D, then 0x14; FT5406 at 0x38) and reads what it
    // needs (the GT911's resolution). NotFound when nothing answers.
    Result probe(I2cBus& bus, uint16_t width, uint16_t height);
    Chip chip() const { return chip_; }
    const char* name() const;

    // The fingers on the panel now. `changed` is false when the controller has nothing new
    // (the GT911 between its reports): `frame` is then left as it was.
    Result read(TouchFrame& frame, bool& changed);

private:
    Result read_gt911(TouchFrame& frame, bool& changed);
    Result read_ft5406(TouchFrame& frame, bool& changed);
    I2cBus* bus_ = nullptr;
    Chip chip_ = Chip::None;
    uint8_t address_ = 0;
    uint16_t width_ = 0, height_ = 0, res_x_ = 0, res_y_ = 0;
};

} // namespace facet::evkb
