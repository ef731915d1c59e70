#include "geom/library.h"

#include <cstring>

namespace facet::geom {

bool is_library(const void* data, uint32_t available) {
    return data && available >= 4 && std::memcmp(data, pack::kLibraryMagic, 4) == 0;
}

Result check_library_head(const pack::LibraryHeader& h, uint32_t available) {
    if (std::memcmp(h.magic, pack::kLibraryMagic, 4) != 0) return Result::fail(Status::Corrupt, "no library here");
    if (h.version != pack::kLibraryVersion) return Result::fail(Status::Unsupported, "a library of another version", {"version", h.version});
    if (h.count == 0 || h.count > pack::kMaxLibraryEntries) return Result::fail(Status::Corrupt, "a library's count is out of range", {"count", h.count});
    if (h.total_bytes > available) {
        return Result::fail(Status::Corrupt, "the library is larger than the bytes given", {"bytes needed", h.total_bytes});
    }
    if (library_table_end(h) > h.total_bytes) { // (a total too small for its own table of entries)
        return Result::fail(Status::Corrupt, "the library's total is smaller than its table of entries", {"bytes", h.total_bytes});
    }
    return {};
}

bool library_entry_sound(const pack::LibraryEntry& e, const pack::LibraryHeader& h) {
    const bool inside = e.offset >= library_table_end(h) && e.offset <= h.total_bytes && e.bytes <= h.total_bytes - e.offset;
    return inside && !(e.offset & 7) && e.bytes != 0 && std::memchr(e.name, 0, sizeof e.name) != nullptr;
}

Result Library::open(const void* data, uint32_t available) {
    using pack::LibraryEntry;
    using pack::LibraryHeader;
    *this = {};
    if (!is_library(data, available) || available < sizeof(LibraryHeader)) return Result::fail(Status::Corrupt, "no library here");
    if ((reinterpret_cast<uintptr_t>(data) & 7) != 0) return Result::fail(Status::OutOfRange, "a library must be 8-byte aligned");
    LibraryHeader h;
    std::memcpy(&h, data, sizeof h);
    if (Result r = check_library_head(h, available); !r.ok()) return r;
    const uint32_t table_end = library_table_end(h);
    const auto* bytes = static_cast<const uint8_t*>(data);
    if (pack::crc32(bytes + sizeof h, table_end - uint32_t(sizeof h)) != h.crc32) return Result::fail(Status::Corrupt, "the library's table fails its CRC");
    for (uint32_t i = 0; i < h.count; ++i) {
        LibraryEntry e;
        std::memcpy(&e, bytes + sizeof h + i * sizeof e, sizeof e);
        if (!library_entry_sound(e, h)) return Result::fail(Status::Corrupt, "a library entry lies outside it or is unterminated", {"entry", i});
    }
    data_ = bytes, count_ = h.count, bytes_ = h.total_bytes;
    return {};
}

Library::Entry Library::entry(uint32_t i) const {
    if (i >= count_) return {nullptr, 0, ""};
    const auto* e = reinterpret_cast<const pack::LibraryEntry*>(data_ + sizeof(pack::LibraryHeader)) + i;
    return {data_ + e->offset, e->bytes, e->name};
}

} // namespace facet::geom
