#include "input_uart.h"

namespace facet::boards {

bool UartInput::poll(hal::InputEvent& event) {
    const int c = console_.read_byte();
    if (c < 0) return false;
    event = {};
    event.kind = hal::InputEvent::Kind::Key;
    event.key = static_cast<uint8_t>(c);
    return true;
}

} // namespace facet::boards
