#include "mouse_pl050.h"

namespace facet::versatilepb {
namespace {

constexpr uintptr_t kBase = 0x10007000; // KMI1: the mouse
volatile uint32_t& reg(uint32_t off) { return *reinterpret_cast<volatile uint32_t*>(kBase + off); }
constexpr uint32_t kCr = 0x00, kStat = 0x04, kData = 0x08, kClkDiv = 0x0C;
constexpr uint32_t kCrEnable = 1u << 2;
constexpr uint32_t kStatRxFull = 1u << 4, kStatTxEmpty = 1u << 6;

} // namespace

bool Pl050Mouse::read_byte(uint8_t& b) {
    if (!(reg(kStat) & kStatRxFull)) return false;
    b = static_cast<uint8_t>(reg(kData));
    return true;
}

bool Pl050Mouse::init() {
    reg(kClkDiv) = 2; // 24 MHz reference / 8 MHz KMI clock - 1
    reg(kCr) = kCrEnable;
    for (int i = 0; i < 100000 && !(reg(kStat) & kStatTxEmpty); ++i) {
    }
    reg(kData) = 0xF4; // enable data reporting
    uint8_t b = 0;
    for (int i = 0; i < 100000; ++i) {
        if (read_byte(b)) return b == 0xFA; // acknowledge
    }
    return false;
}

bool Pl050Mouse::poll(hal::InputEvent& event) {
    if (!pending_move_) {
        uint8_t b;
        while (!pending_move_ && read_byte(b)) {
            // Byte 0 always has bit 3 set: resynchronise on it if a byte was lost.
            if (have_ == 0 && !(b & 0x08)) continue;
            packet_[have_++] = b;
            if (have_ < 3) continue;
            have_ = 0;
            const uint8_t head = packet_[0];
            if (head & 0xC0) continue; // overflow: the motion is unknown, drop the packet
            dx_ = static_cast<int16_t>(head & 0x10 ? int(packet_[1]) - 256 : int(packet_[1]));
            dy_ = static_cast<int16_t>(-(head & 0x20 ? int(packet_[2]) - 256 : int(packet_[2]))); // PS/2 y is up
            pending_move_ = true;
            const uint8_t now = head & 0x07;
            if (now != buttons_) {
                event = {};
                event.kind = (now & ~buttons_) ? hal::InputEvent::Kind::PointerDown : hal::InputEvent::Kind::PointerUp;
                event.buttons = now;
                buttons_ = now;
                if (dx_ == 0 && dy_ == 0) pending_move_ = false;
                return true;
            }
        }
        if (!pending_move_) return false;
    }
    pending_move_ = false;
    if (dx_ == 0 && dy_ == 0) return poll(event);
    event = {};
    event.kind = hal::InputEvent::Kind::PointerMove;
    event.dx = dx_;
    event.dy = dy_;
    event.buttons = buttons_;
    return true;
}

} // namespace facet::versatilepb
