#pragma once
// Input events: keys (UART bytes, board buttons), a relative pointer (mouse) and touch points.
#include <cstdint>

namespace facet::hal {

struct InputEvent {
    enum class Kind : uint8_t { Key, PointerMove, PointerDown, PointerUp, Touch };
    Kind kind;
    uint8_t key;      // Kind::Key: the character
    int16_t dx, dy;   // PointerMove: relative motion in pixels
    uint8_t buttons;  // bit 0 left, bit 1 right, bit 2 middle
    // Kind::Touch: finger `finger` (0, 1) at (x, y) screen pixels, down or lifted.
    uint8_t finger;
    bool down;
    int16_t x, y;
};

class Input {
public:
    // True and fills `event` if one is waiting; false at once otherwise.
    virtual bool poll(InputEvent& event) = 0;

protected:
    ~Input() = default;
};

} // namespace facet::hal
