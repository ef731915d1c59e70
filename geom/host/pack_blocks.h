#pragma once
// Blocked packs on the host (pack_format.h: an index, then blocks each a pack of some shells):
// made from a whole pack by facet-pack, and joined back into a whole one for the host tools
// (the mesher, facet-measure), which read every kind of pack file through load_pack_file().
// Host only (allocates).
#include "geom/pack.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace facet::geom {

// A shell's box in its own coordinates (mm).
struct PartBox {
    float min[3], max[3];
};

// [lo, hi] grown by box b placed by the instance (its eight corners placed: mm, the model's
// coordinates), as a blocked pack's block and group boxes are made.
void grow_by_placed(const pack::Instance& inst, const PartBox& b, float lo[3], float hi[3]);

enum class BlockStore : uint8_t { Lzma, Deflated, Plain };

struct Proxy; // (proxies.h)
struct BlockOptions {
    uint32_t block_bytes = 64 * 1024; // a block's decoded size to aim at: shells are grouped until
                                      // the next would pass it (a larger shell is a block alone)
    BlockStore store = BlockStore::Lzma;
    const std::vector<Proxy>* proxies = nullptr; // each shell's (proxies.h), into the index; none: no proxies
    // With the proxies, the most triangles a group's proxy has at each level (groups.h), the
    // coarsest first; empty: no groups.
    std::span<const uint32_t> group_caps = {};
};

// The blocked pack of `whole` (validated): its shells, in order, grouped into blocks; its
// instances and names in the index. `boxes`: one per shell (the packer's exact boxes); empty:
// each shell's box from its vertices' and curves' control points is used.
bool make_blocked(const Pack& whole, const std::vector<PartBox>& boxes, const BlockOptions& options,
                  std::vector<uint8_t>& out, std::string& error);

// The whole pack a blocked file holds (each block decoded and validated with the device's code):
// the parts' shells in part order, then the index's instances and names.
bool join_blocked(std::span<const uint8_t> file, std::vector<uint8_t>& whole, std::string& error);

// One whole pack of several packs' shells (each pack's shells in order, then the next's), each
// shell placed once, the k-th of all moved `spacing_mm` along x from the one before: an
// assembly of shapes built in code, for tests.
std::vector<uint8_t> combine_packs(std::span<const Pack> packs, float spacing_mm);

} // namespace facet::geom
