#include "stack.h"

#include "hal/board.h"

// From the board's linker script: the main stack occupies [__stack_start, __stack_end).
extern "C" uint32_t __stack_start[], __stack_end[];

namespace facet::stack {

__attribute__((noinline)) void paint() {
    // Stop 64 bytes below the current stack pointer: this frame and its callers stay intact.
    const uintptr_t sp = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
    uint32_t* limit = reinterpret_cast<uint32_t*>((sp - 64) & ~uintptr_t(3));
    for (uint32_t* p = __stack_start; p < limit; ++p) *p = kPaint;
}

uint32_t unused() {
    const uint32_t* p = __stack_start;
    while (p < __stack_end && *p == kPaint) ++p;
    return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(p) -
                                 reinterpret_cast<uintptr_t>(__stack_start));
}

uint32_t size() {
    return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(__stack_end) -
                                 reinterpret_cast<uintptr_t>(__stack_start));
}

} // namespace facet::stack

namespace facet::hal {
uint32_t stack_unused() { return stack::unused(); }
uint32_t stack_size() { return stack::size(); }
} // namespace facet::hal
