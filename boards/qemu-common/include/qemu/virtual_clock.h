#pragma once
// Time on the QEMU boards. tools/qemu/run.py runs them with the board description's
// `-icount shift=0,sleep=off`: the guest's clock advances 1 ns per executed instruction, so
// every run's timing is the same. The boards stand in for a 600 MHz core that executes one
// instruction a cycle, so 1,000 instructions (1 us of QEMU's virtual clock) are 1.67 us of
// the target's time: a timer of `virtual_hz` in the virtual clock ticks virtual_hz x 0.6 times
// in a second of the target's time, and that is what the boards' clocks report.
#include <cstdint>

namespace facet::qemu {

constexpr uint32_t kTargetHz = 600'000'000;  // the handheld's core: 600 MHz, one instruction a cycle
constexpr uint32_t kVirtualHz = 1'000'000'000; // -icount shift=0: 2^0 ns per instruction

constexpr uint32_t target_ticks_per_second(uint32_t virtual_hz) {
    return uint32_t(uint64_t(virtual_hz) * kTargetHz / kVirtualHz);
}

} // namespace facet::qemu
