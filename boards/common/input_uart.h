#pragma once
// Input events from the console: each received byte is a key. (The PL050 mouse joins later.)
#include "hal/console.h"
#include "hal/input.h"

namespace facet::boards {

class UartInput final : public hal::Input {
public:
    explicit UartInput(hal::Console& console) : console_(console) {}
    bool poll(hal::InputEvent& event) override;

private:
    hal::Console& console_;
};

} // namespace facet::boards
