#pragma once
// The EVKB's input: keys from the console (the probe's virtual COM port), the user button SW8
// (a press is the fit key, 'f') and the touch panel (fingers as Touch events; the module
// decides the gestures). Polled: the touch controller at most every 16 ms (its report rate; an
// I2C read costs about half a millisecond at 100 kHz), the button through GPIO5_IO00.
#include "gpt.h"
#include "hal/input.h"
#include "lpuart.h"
#include "touch.h"

namespace facet::evkb {

class BoardInput final : public hal::Input {
public:
    BoardInput(Lpuart& console, Touch& touch, GptClock& clock) : console_(console), touch_(touch), clock_(clock) {}
    bool poll(hal::InputEvent& event) override;
    uint32_t touch_errors() const { return touch_errors_; }

private:
    void push(const hal::InputEvent& e);
    void poll_touch();
    void poll_button();
    Lpuart& console_;
    Touch& touch_;
    GptClock& clock_;
    hal::InputEvent queue_[8] = {};
    uint32_t head_ = 0, count_ = 0;
    bool slot_used_[TouchFrame::kMax] = {};
    uint8_t slot_id_[TouchFrame::kMax] = {};
    int16_t slot_x_[TouchFrame::kMax] = {}, slot_y_[TouchFrame::kMax] = {};
    uint64_t next_touch_us_ = 0, button_since_us_ = 0;
    bool button_down_ = false, button_reported_ = false;
    uint32_t touch_errors_ = 0;
};

} // namespace facet::evkb
