// The section plane as a tool (section.h).
#include "section.h"

#include <cmath>

namespace facet::module {

void Sectioning::reset() {
    camera_.set_section({});
    kind_ = Kind::Off;
    presenter_.overlay().set_slider(false, 0.5f);
}

// The range a section plane moves in: the placed model's sphere along its normal.
void Sectioning::range(const Section& s, float& lo, float& hi) const {
    const float* c = scene_.centre();
    const float at = s.n[0] * c[0] + s.n[1] * c[1] + s.n[2] * c[2];
    lo = at - scene_.radius(), hi = at + scene_.radius();
}

void Sectioning::changed() {
    const Section& s = camera_.section();
    float lo, hi;
    range(s, lo, hi);
    presenter_.overlay().set_slider(s.on && slider_, hi > lo ? (s.offset - lo) / (hi - lo) : 0.5f);
    presenter_.invalidate();
}

void Sectioning::set(const Section& s, Kind kind) {
    camera_.set_section(s);
    kind_ = s.on ? kind : Kind::Off;
    changed();
}

Result Sectioning::across(uint8_t axis) {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    if (axis > 2) return Result::fail(Status::OutOfRange, "the axis is 0 (x), 1 (y) or 2 (z)", {"axis", axis});
    Section s;
    s.on = true;
    s.n[0] = axis == 0, s.n[1] = axis == 1, s.n[2] = axis == 2;
    s.offset = scene_.centre()[axis]; // through the model's middle
    set(s, Kind(uint8_t(Kind::X) + axis));
    return {};
}

Result Sectioning::move(float by_mm) {
    const Section& s = camera_.section();
    if (!scene_.loaded() || !s.on) return Result::fail(Status::NotFound, "no section is on");
    if (!std::isfinite(by_mm)) return Result::fail(Status::OutOfRange, "the distance must be finite");
    float lo, hi;
    range(s, lo, hi);
    at(hi > lo ? by_mm / (hi - lo) : 0, true);
    return {};
}

void Sectioning::at(float at, bool relative) {
    Section s = camera_.section();
    if (!s.on) return;
    float lo, hi;
    range(s, lo, hi);
    if (relative && hi > lo) at += (s.offset - lo) / (hi - lo);
    s.offset = lo + (at < 0 ? 0 : at > 1 ? 1 : at) * (hi - lo);
    camera_.set_section(s);
    changed();
}

} // namespace facet::module
