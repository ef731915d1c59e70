#pragma once
// A pack file opened into the scene, whatever its form: a plain pack read in place (or copied
// where it can be, when unaligned), a compressed one decoded into the pack memory, a blocked
// one's blocks decoded there one after the other behind a table of them (the index and plain
// blocks read in place). When the file itself lies inside the pack memory, it is first moved to the memory's
// end and decoded from there.
#include "scene.h"

#include <cstdint>

namespace facet::module {

// The pack memory a file needs (facet::pack_memory_bytes()); 0 for one read in place, or unreadable.
uint32_t pack_memory_need(const void* file, uint32_t file_bytes);

// A pack file made readable: a whole pack's bytes, or a blocked pack's index and its blocks
// decoded behind their table (each block's pack not yet opened).
struct Unpacked {
    const uint8_t* pack = nullptr; // a whole pack
    uint32_t bytes = 0;            // its size, or the pack memory the blocks and their table take
    geom::PackIndex index;         // a blocked pack's (read in place)
    std::span<Block> blocks;       // a blocked pack's, in the pack memory: each compressed block decoded
                                   // after the table and the blocks before it (4-byte aligned); a plain
                                   // block read in place
};

// Decodes `file` into the pack memory as its form asks (the work a profile calls unpacking).
Result unpack(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes, Unpacked& out);
// Validates what unpack() made and opens it into the scene.
Result open_unpacked(Unpacked& u, Scene& scene);

} // namespace facet::module
