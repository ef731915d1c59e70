#pragma once
// A library of model files (pack_format.h's LibraryHeader): its table checked once, then each
// entry's bytes where they lie. Read in place (flash or RAM); nothing is copied.
//
//   Library lib;
//   if (lib.open(flash, flash_bytes).ok())
//       for (uint32_t i = 0; i < lib.count(); ++i) lib.entry(i) ...
#include "geom/pack_format.h"
#include "core/status.h"

#include <cstdint>

namespace facet::geom {

// Whether the bytes start a library (its magic; open() checks the rest).
bool is_library(const void* data, uint32_t available);

// A library's head checked against the bytes it has (its magic, version, count, total and the
// table inside it), and one entry of its table against the head (inside the library, after the
// table, aligned, not empty, its name terminated): Library::open's checks, and a reader's that
// reads the table from storage a piece at a time. The table's CRC is the caller's.
Result check_library_head(const pack::LibraryHeader& h, uint32_t available);
bool library_entry_sound(const pack::LibraryEntry& e, const pack::LibraryHeader& h);
constexpr uint32_t library_table_end(const pack::LibraryHeader& h) {
    return uint32_t(sizeof h + h.count * sizeof(pack::LibraryEntry));
}

class Library {
public:
    struct Entry {
        const uint8_t* file; // the model file (any kind pack_file_kind() names)
        uint32_t bytes;
        const char* name;    // UTF-8
    };
    // Corrupt (naming the entry) when the head or the table is not sound: the magic and
    // version, the count, the table's CRC, each entry aligned, after the table and inside the
    // library, and its name terminated.
    Result open(const void* data, uint32_t available);
    uint32_t count() const { return count_; }
    Entry entry(uint32_t i) const; // i < count()
    uint32_t bytes() const { return bytes_; }

private:
    const uint8_t* data_ = nullptr;
    uint32_t count_ = 0, bytes_ = 0;
};

} // namespace facet::geom
