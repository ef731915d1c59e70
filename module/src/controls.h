#pragma once
// Input to commands: one table from keys to actions, and the gestures of a mouse and of
// fingers decided here, so every application gets the same handling:
//   left drag / one finger: orbit     right drag / two fingers moving together: pan
//   middle drag, wheel / pinch: dolly click / tap (no motion between down and up): pick
//   a drag that starts on the section slider: slide (the plane follows the finger)
#include "facet/viewer.h"
#include "overlay.h"

#include <cstdint>

namespace facet::module {

struct Command {
    enum class Kind : uint8_t { None, Act, Orbit, Pan, Dolly, Pick, Slide } kind = Kind::None;
    Action action = Action::None; // Act
    float yaw = 0, pitch = 0;     // Orbit: rad
    int16_t dx = 0, dy = 0;       // Pan: screen pixels
    float factor = 1;             // Dolly: < 1 closer
    int16_t x = 0, y = 0;         // Pick: the screen pixel; Slide: the row
};

class Controls {
public:
    static constexpr float kRadPerPixel = 0.00872665f; // orbit: half a degree per pixel
    static constexpr int32_t kTapSlop = 6;             // pixels a tap may wander

    void set_screen(uint16_t width, uint16_t height);
    void set_overlay(const Overlay* overlay) { overlay_ = overlay; } // where the slider is
    Command key(uint32_t key) const;
    Command pointer(int16_t dx, int16_t dy, uint8_t buttons);
    Command wheel(int16_t clicks) const;
    // A finger went down, moved or was lifted; up to two commands (a pinch pans and dollies).
    uint32_t touch(uint8_t id, int16_t x, int16_t y, bool down, Command out[2]);
    // A drag under way: a mouse button held, or a finger down, past a tap's slop.
    bool dragging() const { return (buttons_ && travel_ > kTapSlop) || (fingers_[0].down && fingers_[0].moved) || fingers_[1].down; }
    bool finger_down(uint8_t id) const { return id < 2 && fingers_[id].down; }

private:
    struct Finger {
        bool down = false;
        int16_t x = 0, y = 0;         // where it is
        int16_t x0 = 0, y0 = 0;       // where it went down
        bool moved = false;           // beyond the tap slop
    };
    uint16_t width_ = 0, height_ = 0;
    int32_t cursor_x_ = 0, cursor_y_ = 0; // the mouse's position, for a click's pick
    uint8_t buttons_ = 0;
    int32_t travel_ = 0;                  // pixels moved since a button went down
    Finger fingers_[2];
    bool pinched_ = false;                // two fingers were down in this touch (no tap then)
    const Overlay* overlay_ = nullptr;
    bool sliding_ = false;                // the left button or finger 0 went down on the slider
    bool on_slider(int32_t x, int32_t y) const { return overlay_ && overlay_->slider().contains(x, y); }
};

} // namespace facet::module
