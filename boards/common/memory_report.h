#pragma once
// Builds the hal::memory_map() answer from linker-script symbol pairs.
#include "hal/board.h"

namespace facet::boards {

struct LinkerSpan {
    const char* name;
    uint8_t* start;
    uint8_t* end;
};

inline uint32_t fill_memory_map(const LinkerSpan* spans, uint32_t count, hal::MemoryRegion* out,
                                uint32_t max) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < count && n < max; ++i) {
        out[n++] = {spans[i].name, reinterpret_cast<uintptr_t>(spans[i].start),
                    uint32_t(spans[i].end - spans[i].start)};
    }
    return n;
}

} // namespace facet::boards
