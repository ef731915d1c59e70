#pragma once
// The mps2's UART and timer, started (boards/qemu-mps2-an500/peripherals.cpp).
namespace facet::mps2 {
void start_peripherals();
} // namespace facet::mps2
