#pragma once
// A pack's, or a blocked pack's index's, table of sections as its open() checked it: where the
// readers of optional sections (geom/pmi.h, geom/tree.h) find theirs and check their bounds.
#include "geom/pack_format.h"

#include <cstdint>
#include <span>

namespace facet::geom {

class Pack;
class PackIndex;

struct SectionTable {
    const uint8_t* base = nullptr; // the pack's (the index's) first byte; null: none open
    uint32_t bytes = 0;            // its bytes (an index's: up to its first block)
    std::span<const pack::SectionEntry> entries;

    static SectionTable of(const Pack& pack);       // (none when no pack is open)
    static SectionTable of(const PackIndex& index); // (likewise)
    // Null when entry s holds records of `record_bytes`, 4-byte aligned, inside the bytes after
    // the table; else why not.
    const char* problem(const pack::SectionEntry& s, uint32_t record_bytes) const;
    template <typename T>
    std::span<const T> records(const pack::SectionEntry& s) const { // (once problem() said none)
        return {reinterpret_cast<const T*>(base + s.offset), s.count};
    }
};

} // namespace facet::geom
