#pragma once
// Stack painting: fill the unused stack with a pattern at boot, find the high-water mark later.
#include <cstdint>

namespace facet::stack {

constexpr uint32_t kPaint = 0xF0CAC1A5;

// Paints from the stack's lowest address up to (not including) the current stack pointer
// minus a small margin. Call early, from the reset path.
void paint();
// Bytes at the bottom of the stack still holding the paint.
uint32_t unused();
uint32_t size();

} // namespace facet::stack
