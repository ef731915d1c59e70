#pragma once
// What a board gives the portable code. Each board implements board() and the free functions.
#include "hal/capture.h"
#include "hal/card.h"
#include "hal/clock.h"
#include "hal/console.h"
#include "hal/display.h"
#include "hal/input.h"

namespace facet::hal {

struct Board {
    const char* name;
    Console& console;
    Clock& clock;
    Display& display;
    Input& input;
    Capture* capture = nullptr; // screenshots for a watching host (QEMU); null: none
    Card* card = nullptr;       // a memory card slot (hal/card.h); null: none
};

// The board's singletons, ready to use (startup has initialised them).
Board& board();

// Ends the program with an exit code: on QEMU it reaches the host shell (semihosting); a real
// board halts or resets.
[[noreturn]] void exit(int code);

// One named span of RAM, reported by report_memory().
struct MemoryRegion {
    const char* name;
    uintptr_t start;
    uint32_t bytes;
};
// Fills up to `max` entries describing how the board's RAM is used; returns the count.
uint32_t memory_map(MemoryRegion* out, uint32_t max);
// The RAM nothing else uses (after the linker's .arena contents, to the end of its memory):
// what the firmware hands the module as its workspace. A pack QEMU loads into RAM lies inside.
struct FreeRam {
    uint8_t* start;
    size_t bytes;
};
FreeRam free_ram();
// Bytes of stack never touched since boot (the painted stack's high-water mark), and its size.
uint32_t stack_unused();
uint32_t stack_size();

} // namespace facet::hal

// The firmware's entry point, called by the board's startup once drivers are up.
int facet_main(facet::hal::Board& board);
