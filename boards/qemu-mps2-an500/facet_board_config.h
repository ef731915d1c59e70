#pragma once
// Capacities the portable firmware sizes its static buffers from. Only boards/ knows them.
// The mps2-an500 has no LCD: the display is a RAM framebuffer with the geometry of the
// MIMXRT1060-EVKB's panel (480x272 RGB565), whose Cortex-M7 this board stands in for.
#include <cstdint>

namespace facet::board_config {
constexpr const char* kName = "qemu-mps2-an500";
constexpr uint16_t kDisplayWidth = 480;
constexpr uint16_t kDisplayHeight = 272;
constexpr uint32_t kRamBytes = 24u << 20; // SSRAM1 4 MiB + SSRAM2/3 4 MiB + PSRAM 16 MiB
// Where QEMU's loader puts the pack (tools/qemu/run.py --load FILE@ADDR), and its room.
constexpr uintptr_t kPackAddress = 0x60C00000;
constexpr uint32_t kPackBytes = 4u << 20;
} // namespace facet::board_config
