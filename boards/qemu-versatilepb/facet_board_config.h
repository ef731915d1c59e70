#pragma once
// Capacities the portable firmware sizes its static buffers from. Only boards/ knows them.
#include <cstdint>

namespace facet::board_config {
constexpr const char* kName = "qemu-versatilepb";
constexpr uint16_t kDisplayWidth = 640;   // PL110 at VGA, the paper's PDA resolution
constexpr uint16_t kDisplayHeight = 480;
constexpr uint32_t kRamBytes = 32u << 20; // the budget: one 32 MiB region at 0
// Where QEMU's loader puts the pack (tools/qemu/run.py --load FILE@ADDR), and its room.
constexpr uintptr_t kPackAddress = 0x01C00000;
constexpr uint32_t kPackBytes = 4u << 20;
} // namespace facet::board_config
