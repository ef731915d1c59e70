#pragma once
// Pack files on the host: compressing a finished pack for storage, and reading a file of any
// kind (geom/pack_file.h) into an aligned buffer ready for Pack::open. Host only (allocates).
#include "geom/pack.h"
#include "geom/pack_file.h"

#include <cstdint>
#include <string>
#include <vector>

namespace facet::geom {

// The pack deflated (a DeflatedHead and a raw DEFLATE stream, zlib at its best compression).
std::vector<uint8_t> deflate_pack(const std::vector<uint8_t>& pack);

// The pack as an LZMA file (an LzmaHead and a raw LZMA1 stream, xz's best preset, lc 0, lp 2,
// pb 2): facet-pack's default, about two thirds of the deflated size on B-spline-heavy packs.
std::vector<uint8_t> lzma_pack(const std::vector<uint8_t>& pack);

// A pack file (any kind) read and, if compressed, decoded with the device's code; a blocked
// one joined into a whole pack (pack_blocks.h).
struct LoadedPack {
    std::vector<uint32_t> words; // the pack, 4-byte aligned
    uint32_t bytes = 0;          // the pack's size
    uint32_t file_bytes = 0;     // the file's size
    PackFileKind kind = PackFileKind::Pack;
    // The model's box as the viewer takes it (Scene::open): a blocked file's, its index's parts'
    // boxes joined (the packer's exact boxes); empty (min > max) for the others, whose pack
    // header's box it is. The default level of detail comes from it (model_tolerance()).
    float box_min[3] = {1, 1, 1}, box_max[3] = {0, 0, 0};
    const void* data() const { return words.data(); }
};

// The viewer's default tolerance for the model the file holds (its pack opened as `pack`).
float model_tolerance(const LoadedPack& file, const Pack& pack);
bool load_pack_file(const std::string& path, LoadedPack& out, std::string& error);
// The same from bytes already in memory.
bool load_pack_bytes(const std::vector<uint8_t>& file, LoadedPack& out, std::string& error);

// A library (pack_format.h's LibraryHeader) of model files: each read back with the device's
// code first (a file that is no sound pack is refused), named after its model, laid out
// 8-byte aligned after the table. False with the reason in `error`.
bool make_library(const std::vector<std::vector<uint8_t>>& files, std::vector<uint8_t>& out, std::string& error);

} // namespace facet::geom
