#pragma once
// Pack files on the host: deflating a finished pack for storage, and reading a file of either
// kind (geom/pack_file.h) into an aligned buffer ready for Pack::open. Host only (allocates).
#include <cstdint>
#include <string>
#include <vector>

namespace facet::geom {

// The pack deflated (a DeflatedHead and a raw DEFLATE stream, zlib at its best compression).
std::vector<uint8_t> deflate_pack(const std::vector<uint8_t>& pack);

// A pack file (plain or deflated) read and, if deflated, inflated with the device's code.
struct LoadedPack {
    std::vector<uint32_t> words; // the pack, 4-byte aligned
    uint32_t bytes = 0;          // the pack's size
    uint32_t file_bytes = 0;     // the file's size
    bool deflated = false;
    const void* data() const { return words.data(); }
};
bool load_pack_file(const std::string& path, LoadedPack& out, std::string& error);
// The same from bytes already in memory.
bool load_pack_bytes(const std::vector<uint8_t>& file, LoadedPack& out, std::string& error);

} // namespace facet::geom
