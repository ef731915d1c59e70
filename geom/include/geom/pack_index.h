#pragma once
// Reading a blocked pack's index in place (pack_format.h: IndexHeader, Blocks, Parts, and the
// instances and names), after validating all of it; the blocks themselves are read when needed
// (block_file(), then geom/pack_file.h and geom/pack.h).
//
//   geom::PackIndex index;
//   if (Result r = index.open(file, bytes); !r.ok()) print(con, "pack: {}\n", r);
//       -> "pack: index section Parts record 3: block index out of range"
//
// open() checks the header, the index's CRC, every section's bounds and record size, that the
// blocks lie in the file after the index, in order, and hold every part once, and every index,
// box and placement. Nothing is read before it is checked.
#include "geom/pack_format.h"
#include "core/status.h"

#include <cstdint>
#include <span>

namespace facet::geom {

class PackIndex {
public:
    // Corrupt, with the bad record as the place, unless every check passes. `size`: the bytes
    // available at `data` (the file's own size is in its header: it may be shorter).
    Result open(const void* data, uint32_t size) { return open(data, size, size); }
    // The index alone at `data` (`size` bytes, at least the index's), of a file of `file_bytes`
    // read from storage: its blocks are not in memory (mapped() is false).
    Result open(const void* data, uint32_t size, uint32_t file_bytes);
    // The whole file lies in memory with the index: block_file() reads a block in place.
    bool mapped() const { return mapped_; }

    const pack::IndexHeader& header() const { return *header_; }
    std::span<const pack::Block> blocks() const { return blocks_; }
    std::span<const pack::Part> parts() const { return parts_; }
    std::span<const pack::Instance> instances() const { return instances_; }
    // Each part's proxies (pack_format.h: ProxyParts), proxy_levels() of them: empty when the
    // index has none.
    std::span<const pack::ProxyPart> proxy_parts() const { return proxy_parts_; }
    uint32_t proxy_levels() const { return parts_.empty() ? 0 : uint32_t(proxy_parts_.size() / parts_.size()); }
    const pack::ProxyPart& proxy(uint32_t part, uint32_t level) const { return proxy_parts_[part * proxy_levels() + level]; }
    std::span<const pack::ProxyVertex> proxy_vertices() const { return proxy_vertices_; }
    std::span<const pack::ProxyTriangle> proxy_triangles() const { return proxy_triangles_; }
    // Groups of instances (pack_format.h: Groups), each member of one; empty when the index has
    // none. Group g's level l (group_levels() of them, the coarsest first) is its pieces
    // group_piece(g, l, c) for each of its colours c, corners over its box.
    std::span<const pack::Group> groups() const { return groups_; }
    std::span<const uint32_t> group_members() const { return group_members_; }
    uint32_t group_of(uint32_t instance) const { return instance_groups_[instance]; }
    uint32_t group_levels() const { return group_levels_; }
    const pack::ProxyPart& group_piece(uint32_t g, uint32_t level, uint32_t colour) const {
        return group_pieces_[group_piece_at(g, level, colour)];
    }
    // What the whole model takes on a device (pack::Needs); null when the index says nothing.
    const pack::Needs* needs() const { return needs_.empty() ? nullptr : needs_.data(); }
    // Block b as stored: an LZMA file or a plain pack (geom/pack_file.h reads either). mapped() only.
    std::span<const uint8_t> block_file(uint32_t b) const {
        return {base_ + blocks_[b].offset, blocks_[b].stored_bytes};
    }
    // The parts' boxes joined, each in its shell's coordinates (mm; all zeros when there are
    // none): the box the viewer takes the model's default tolerance from.
    void parts_box(float lo[3], float hi[3]) const;
    // Names from the STEP file: "" when the file has none.
    const char* model_name() const { return names_.empty() ? "" : names_.data(); }
    std::span<const char> names() const { return names_; } // the pool
    const char* part_name(uint32_t p) const { return name_at(part_names_, p); }
    const char* instance_name(uint32_t i) const { return name_at(instance_names_, i); }

private:
    Result fail(const char* what, uint32_t section, uint32_t index);
    Result check_records();
    const char* name_at(std::span<const uint32_t> table, uint32_t i) const {
        return i < table.size() && table[i] != pack::kNoIndex ? names_.data() + table[i] : "";
    }

    const uint8_t* base_ = nullptr;
    bool mapped_ = false;
    const pack::IndexHeader* header_ = nullptr;
    std::span<const pack::Block> blocks_;
    std::span<const pack::Part> parts_;
    std::span<const pack::Instance> instances_;
    std::span<const char> names_;
    std::span<const uint32_t> part_names_, instance_names_;
    std::span<const pack::Needs> needs_;
    std::span<const pack::ProxyPart> proxy_parts_;
    std::span<const pack::ProxyVertex> proxy_vertices_;
    std::span<const pack::ProxyTriangle> proxy_triangles_;
    Result check_proxies();
    Result check_proxy(const pack::ProxyPart& x, uint32_t section, uint32_t record);
    Result check_groups();
    uint32_t group_piece_at(uint32_t g, uint32_t level, uint32_t colour) const {
        return groups_[g].first_piece + level * groups_[g].colours + colour;
    }
    std::span<const pack::Group> groups_;
    std::span<const uint32_t> group_members_, instance_groups_;
    std::span<const pack::ProxyPart> group_pieces_;
    uint32_t group_levels_ = 0;
};

// The place of record `index` of index section `id` ("index section Parts record" 3).
Place index_place(uint32_t id, uint32_t index);

// The first entry of a name table that is neither kNoIndex nor the start of a string of `pool`
// (0-terminated strings), or kNoIndex when every one is. Shared by the pack's and the index's checks.
uint32_t first_bad_name(std::span<const char> pool, std::span<const uint32_t> table);

} // namespace facet::geom
