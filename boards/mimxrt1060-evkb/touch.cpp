#include "touch.h"

#include <initializer_list>

namespace facet::evkb {
namespace {
constexpr uint8_t kGt911Address = 0x5D, kGt911AltAddress = 0x14, kFt5406Address = 0x38;
constexpr uint16_t kGt911ProductId = 0x8140, kGt911Config = 0x8048, kGt911Status = 0x814E, kGt911Points = 0x814F;

Result gt911_read(I2cBus& bus, uint8_t address, uint16_t reg, uint8_t* out, uint32_t n) {
    const uint8_t a[2] = {uint8_t(reg >> 8), uint8_t(reg)};
    return bus.transfer(address, a, 2, out, n);
}

int16_t scale(uint32_t v, uint32_t from, uint32_t to) {
    if (from == 0 || from == to) return int16_t(v < to ? v : to - 1);
    const uint32_t s = v * to / from;
    return int16_t(s < to ? s : to - 1);
}
} // namespace

const char* Touch::name() const {
    switch (chip_) {
    case Chip::Gt911: return "GT911";
    case Chip::Ft5406: return "FT5406";
    case Chip::None: break;
    }
    return "none";
}

Result Touch::probe(I2cBus& bus, uint16_t width, uint16_t height) {
    bus_ = &bus;
    width_ = width, height_ = height;
    chip_ = Chip::None;
    for (uint8_t address : {kGt911Address, kGt911AltAddress}) {
        uint8_t id[4] = {};
        if (!gt911_read(bus, address, kGt911ProductId, id, 4).ok()) continue;
        if (id[0] != '9' || id[1] != '1' || id[2] != '1') continue;
        uint8_t res[4] = {};
        if (Result r = gt911_read(bus, address, kGt911Config, res, 4); !r.ok()) return r;
        chip_ = Chip::Gt911, address_ = address;
        res_x_ = uint16_t(res[0] | (res[1] << 8)), res_y_ = uint16_t(res[2] | (res[3] << 8));
        if (res_x_ == 0 || res_y_ == 0) res_x_ = width, res_y_ = height;
        return {};
    }
    const uint8_t normal[2] = {0x00, 0x00}; // DEVICE_MODE = 0: normal operation
    if (bus.transfer(kFt5406Address, normal, 2, nullptr, 0).ok()) {
        chip_ = Chip::Ft5406, address_ = kFt5406Address;
        return {};
    }
    return Result::fail(Status::NotFound, "no touch controller answers (GT911 at 0x5D/0x14, FT5406 at 0x38)");
}

Result Touch::read(TouchFrame& frame, bool& changed) {
    changed = false;
    switch (chip_) {
    case Chip::Gt911: return read_gt911(frame, changed);
    case Chip::Ft5406: return read_ft5406(frame, changed);
    case Chip::None: break;
    }
    return Result::fail(Status::NotFound, "no touch controller");
}

Result Touch::read_gt911(TouchFrame& frame, bool& changed) {
    uint8_t status = 0;
    if (Result r = gt911_read(*bus_, address_, kGt911Status, &status, 1); !r.ok()) return r;
    if (!(status & 0x80)) return {}; // no new report
    const uint32_t n = status & 0x0F;
    uint8_t data[8 * TouchFrame::kMax] = {};
    const uint32_t take = n < TouchFrame::kMax ? n : TouchFrame::kMax;
    if (take) {
        if (Result r = gt911_read(*bus_, address_, kGt911Points, data, 8 * take); !r.ok()) return r;
    }
    const uint8_t clear[3] = {uint8_t(kGt911Status >> 8), uint8_t(kGt911Status), 0};
    if (Result r = bus_->transfer(address_, clear, 3, nullptr, 0); !r.ok()) return r;
    frame.count = take;
    for (uint32_t i = 0; i < take; ++i) {
        const uint8_t* p = data + 8 * i;
        frame.points[i] = {p[0], scale(uint32_t(p[1] | (p[2] << 8)), res_x_, width_),
                           scale(uint32_t(p[3] | (p[4] << 8)), res_y_, height_)};
    }
    changed = true;
    return {};
}

Result Touch::read_ft5406(TouchFrame& frame, bool& changed) {
    const uint8_t reg = 0x02; // TD_STATUS, then the points
    uint8_t data[1 + 6 * TouchFrame::kMax] = {};
    if (Result r = bus_->transfer(address_, &reg, 1, data, sizeof data); !r.ok()) return r;
    uint32_t n = data[0] & 0x0F;
    if (n > 5) n = 0; // not a count the FT5406 gives: ignore the report
    frame.count = 0;
    for (uint32_t i = 0; i < n && i < TouchFrame::kMax; ++i) {
        const uint8_t* p = data + 1 + 6 * i;
        const uint32_t event = p[0] >> 6; // 0 press down, 1 lift up, 2 contact, 3 none
        if (event == 1 || event == 3) continue;
        const uint32_t x = uint32_t((p[0] & 0x0F) << 8) | p[1], y = uint32_t((p[2] & 0x0F) << 8) | p[3];
        frame.points[frame.count++] = {uint8_t(p[2] >> 4), scale(y, width_, width_), scale(x, height_, height_)};
    }
    changed = true;
    return {};
}

} // namespace facet::evkb
