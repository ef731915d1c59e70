#include "input.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {
constexpr uint64_t kTouchPeriodUs = 16'000, kDebounceUs = 20'000;
} // namespace

void BoardInput::push(const hal::InputEvent& e) {
    if (count_ == sizeof queue_ / sizeof queue_[0]) return; // full: the oldest stay, this one is dropped
    queue_[(head_ + count_++) % (sizeof queue_ / sizeof queue_[0])] = e;
}

void BoardInput::poll_touch() {
    if (touch_.chip() == Touch::Chip::None) return;
    const uint64_t now = clock_.ticks();
    if (now < next_touch_us_) return;
    next_touch_us_ = now + kTouchPeriodUs;
    TouchFrame now_fingers;
    bool changed = false;
    if (!touch_.read(now_fingers, changed).ok()) {
        ++touch_errors_;
        return;
    }
    if (!changed) return;
    hal::InputEvent e{};
    e.kind = hal::InputEvent::Kind::Touch;
    // Each finger keeps its slot (the module's finger 0 or 1) while it stays down, whatever
    // order the controller reports it in. Lifted fingers first, then every finger down.
    for (uint32_t s = 0; s < TouchFrame::kMax; ++s) {
        if (!slot_used_[s]) continue;
        bool still = false;
        for (uint32_t j = 0; j < now_fingers.count; ++j) still |= now_fingers.points[j].id == slot_id_[s];
        if (still) continue;
        slot_used_[s] = false;
        e.finger = uint8_t(s), e.down = false, e.x = slot_x_[s], e.y = slot_y_[s];
        push(e);
    }
    for (uint32_t j = 0; j < now_fingers.count; ++j) {
        const TouchPoint& p = now_fingers.points[j];
        uint32_t s = 0;
        while (s < TouchFrame::kMax && !(slot_used_[s] && slot_id_[s] == p.id)) ++s;
        if (s == TouchFrame::kMax) { // a new finger: the first free slot
            s = 0;
            while (s < TouchFrame::kMax && slot_used_[s]) ++s;
            if (s == TouchFrame::kMax) continue;
            slot_used_[s] = true, slot_id_[s] = p.id;
        }
        slot_x_[s] = p.x, slot_y_[s] = p.y;
        e.finger = uint8_t(s), e.down = true, e.x = p.x, e.y = p.y;
        push(e);
    }
}

void BoardInput::poll_button() {
    const bool down = !(mmio::read(gpio::kGpio5 + gpio::kPsr) & 1u); // SW8 pulls WAKEUP low
    const uint64_t now = clock_.ticks();
    if (down != button_down_) button_down_ = down, button_since_us_ = now, button_reported_ = false;
    if (down && !button_reported_ && now - button_since_us_ >= kDebounceUs) {
        button_reported_ = true;
        hal::InputEvent e{};
        e.kind = hal::InputEvent::Kind::Key;
        e.key = 'f';
        push(e);
    }
}

bool BoardInput::poll(hal::InputEvent& event) {
    if (count_ == 0) {
        const int c = console_.read_byte();
        if (c >= 0) {
            event = {};
            event.kind = hal::InputEvent::Kind::Key;
            event.key = uint8_t(c);
            return true;
        }
        poll_button();
        poll_touch();
    }
    if (count_ == 0) return false;
    event = queue_[head_];
    head_ = (head_ + 1) % (sizeof queue_ / sizeof queue_[0]);
    --count_;
    return true;
}

} // namespace facet::evkb
