#pragma once
// Input events: keys (UART bytes, board buttons) and a pointer (mouse, touch).
#include <cstdint>

namespace facet::hal {

struct InputEvent {
    enum class Kind : uint8_t { Key, PointerMove, PointerDown, PointerUp };
    Kind kind;
    uint8_t key;      // Kind::Key: the character
    int16_t dx, dy;   // PointerMove: relative motion in pixels
    uint8_t buttons;  // bit 0 left, bit 1 right, bit 2 middle
};

class Input {
public:
    // True and fills `event` if one is waiting; false at once otherwise.
    virtual bool poll(InputEvent& event) = 0;

protected:
    ~Input() = default;
};

} // namespace facet::hal
