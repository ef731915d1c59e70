#pragma once
// PS/2 mouse on the PL050 KMI (ARM DDI 0143; versatilepb: KMI1 at 0x10007000), polled.
// QEMU feeds it from the display window's pointer or from QMP input-send-event.
#include "hal/input.h"

#include <cstdint>

namespace facet::versatilepb {

class Pl050Mouse {
public:
    // Enables the KMI and asks the mouse to stream (PS/2 0xF4). False if no mouse answered.
    bool init();
    // True and fills a PointerMove event (with the buttons held) per complete 3-byte packet;
    // a change of buttons also yields PointerDown / PointerUp first.
    bool poll(hal::InputEvent& event);

private:
    bool read_byte(uint8_t& b);
    uint8_t packet_[3] = {};
    uint8_t have_ = 0;
    uint8_t buttons_ = 0;
    bool pending_move_ = false;
    int16_t dx_ = 0, dy_ = 0;
};

} // namespace facet::versatilepb
