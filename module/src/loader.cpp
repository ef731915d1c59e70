#include "loader.h"

#include "geom/pack_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

namespace facet::module {
namespace {

constexpr Place kFile{"pack file"};

constexpr uint32_t align4(uint64_t n) { return uint32_t((n + 3) & ~uint64_t(3)); }
constexpr uint32_t align8(uint64_t n) { return uint32_t((n + 7) & ~uint64_t(7)); }
constexpr uint32_t table_bytes(uint32_t blocks) { return align4(uint64_t(blocks) * sizeof(Block)); }

// A plain block is read in place (blocks lie 4-byte aligned in the file) when the file is in memory.
bool in_place(const geom::PackIndex& index, uint32_t b) {
    if (!index.mapped()) return false;
    const auto file = index.block_file(b);
    return geom::pack_file_kind(file.data(), uint32_t(file.size())) == geom::PackFileKind::Pack;
}

// A block on storage whose stored bytes are not its pack (compressed) is staged before it is decoded.
uint32_t staging(const geom::PackIndex& index, uint32_t b) {
    const pack::Block& k = index.blocks()[b];
    return !index.mapped() && k.stored_bytes != k.pack_bytes ? align8(k.stored_bytes) : 0;
}

// Where block b's stored bytes are staged before they are decoded: just below `end` (the room's
// end: where the index lies). And a block read to its place: a plain pack, or the file lies.
uint8_t* staged_at(const Unpacked& u, uint32_t b, uint32_t end) { return u.memory + ((end - staging(u.index, b)) & ~7u); }
Result plain_block(const uint8_t* at, uint32_t b, uint32_t bytes) {
    if (geom::pack_file_kind(at, bytes) == geom::PackFileKind::Pack) return {};
    return Result::fail(Status::Corrupt, "a block of its pack's size is no plain pack", {"block", b});
}

// What a blocked pack needs: its table of blocks, each block decoded (4-byte aligned), and an
// LZMA decoder's state (with its alignment). 0 when the index does not read. On storage, also
// its index and the room to stage the largest block kept.
uint32_t blocked_need(const geom::PackIndex& index, const BlockCut& cut) {
    uint64_t n = table_bytes(uint32_t(index.blocks().size())) + geom::kLzmaStateBytes + 8;
    uint32_t stage = 0;
    for (uint32_t b = 0; b < index.blocks().size(); ++b) {
        if (kept(index, b, cut) && !in_place(index, b)) n += align4(index.blocks()[b].pack_bytes);
        stage = std::max(stage, staging(index, b)); // (any block may come in later)
    }
    if (!index.mapped()) n += align8(index.header().index_bytes) + stage;
    return n > UINT32_MAX ? UINT32_MAX : uint32_t(n);
}

// Block b, kept, brought into the pack memory at `at` (room up to `end`, its staging included)
// at load: read (from storage) and decoded.
Result load_block(Unpacked& u, uint32_t b, uint32_t at, uint32_t end) {
    const pack::Block& entry = u.index.blocks()[b];
    const Place here{"block", b};
    const uint32_t stage = staging(u.index, b);
    if (uint64_t(at) + entry.pack_bytes + stage > end) return Result::fail(Status::Full, "the decoded blocks do not fit the pack memory", here);
    std::span<const uint8_t> file;
    if (u.reader) {
        uint8_t* into = stage ? staged_at(u, b, end) : u.memory + at;
        if (Result r = u.reader->read(entry.offset, into, entry.stored_bytes); !r.ok()) return r.within(here);
        file = {into, entry.stored_bytes};
        if (!stage) {
            if (Result r = plain_block(into, b, entry.stored_bytes); !r.ok()) return r;
            u.blocks[b].data = into;
            return {};
        }
    } else {
        file = u.index.block_file(b);
    }
    geom::PackDecoder decoder;
    Result r = decoder.start(file, {u.memory + at, entry.pack_bytes}, *u.probs);
    while (r.status == Status::Busy) r = decoder.run(1u << 30);
    if (!r.ok()) return r.within(here);
    if (decoder.pack_bytes() != entry.pack_bytes) return Result::fail(Status::Corrupt, "the block's size is not the index's", here);
    u.blocks[b].data = u.memory + at;
    return {};
}

Result unpack_blocked(const uint8_t* in, uint32_t file_bytes, uint8_t* mem, uint32_t memory_bytes, bool inside, const BlockCut& cut,
                      Unpacked& out) {
    const uint32_t whole = out.reader ? out.reader->bytes() : file_bytes; // (on storage: `in` is its index)
    // The index first, where it lies: a file that lies is Corrupt, whatever memory came with it.
    if (!inside) {
        if (reinterpret_cast<uintptr_t>(in) & 3) return Result::fail(Status::OutOfRange, "a blocked pack must lie 4-byte aligned", kFile);
        geom::PackIndex index;
        if (Result r = index.open(in, file_bytes, whole); !r.ok()) return r;
    }
    if (!mem || (reinterpret_cast<uintptr_t>(mem) & 7)) {
        return Result::fail(Status::Full, "a blocked pack needs 8-byte aligned pack memory", kFile);
    }
    // The decoder's state at the memory's end; a file loaded into the memory just before it.
    if (memory_bytes < geom::kLzmaStateBytes + 64) {
        return Result::fail(Status::Full, "the decoded blocks do not fit the pack memory (it holds not even the decoder's state)", kFile);
    }
    const uint32_t state_at = (memory_bytes - geom::kLzmaStateBytes) & ~7u;
    uint32_t end = state_at;
    if (inside) {
        if (file_bytes > end) return Result::fail(Status::Full, "the blocked pack leaves no pack memory to decode into", kFile);
        end = (end - file_bytes) & ~7u;
        std::memmove(mem + end, in, file_bytes);
        in = mem + end;
    }
    if (reinterpret_cast<uintptr_t>(in) & 3) return Result::fail(Status::OutOfRange, "a blocked pack must lie 4-byte aligned", kFile);
    geom::PackIndex& index = out.index;
    if (Result r = index.open(in, file_bytes, whole); !r.ok()) return r;
    const uint32_t count = uint32_t(index.blocks().size());
    const uint32_t need = blocked_need(index, cut);
    const uint64_t have = uint64_t(end) + (memory_bytes - state_at) + (inside && !index.mapped() ? align8(file_bytes) : 0);
    if (need > have) {
        return Result::fail(Status::Full, "the decoded blocks do not fit the pack memory", {"bytes needed", need});
    }
    auto* table = reinterpret_cast<Block*>(mem);
    for (uint32_t b = 0; b < count; ++b) new (&table[b]) Block{};
    out.blocks = {table, count};
    out.memory = mem, out.limit = end, out.probs = reinterpret_cast<geom::LzmaProbs*>(mem + state_at);
    uint32_t at = table_bytes(count);
    for (uint32_t b = 0; b < count; ++b) {
        if (!kept(index, b, cut)) {
            table[b].left_out = true;
            continue;
        }
        if (in_place(index, b)) { // checked when it is opened
            table[b].data = index.block_file(b).data();
            continue;
        }
        if (Result r = load_block(out, b, at, end); !r.ok()) return r;
        at += align4(index.blocks()[b].pack_bytes);
    }
    out.pack = mem;
    out.bytes = at;
    return {};
}
} // namespace

float block_size(const pack::Block& b) {
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        const float e = b.box_max[k] - b.box_min[k];
        if (!(e >= 0)) return 0; // empty
        r2 += e * e;
    }
    return std::sqrt(r2);
}

bool kept(const geom::PackIndex& index, uint32_t b, const BlockCut& cut) {
    if (cut.above <= 0) return true;
    const float size = block_size(index.blocks()[b]);
    return size >= cut.above || (size >= cut.from && b <= cut.through);
}

void kept_counts(const geom::PackIndex& index, const BlockCut& cut, uint32_t& faces, uint32_t& edges) {
    faces = edges = 0;
    for (uint32_t k = 0; k < index.blocks().size(); ++k) {
        if (!kept(index, k, cut)) continue;
        const pack::Block& b = index.blocks()[k];
        for (uint32_t p = b.first_part; p < b.first_part + b.part_count; ++p) {
            faces += index.parts()[p].face_count, edges += index.parts()[p].edge_count;
        }
    }
}

uint32_t pack_memory_need(const geom::PackIndex& index, const BlockCut& cut) { return blocked_need(index, cut); }

uint32_t pack_memory_need(const void* file, uint32_t file_bytes, const BlockCut& cut, const Reader* reader) {
    switch (geom::pack_file_kind(file, file_bytes)) {
    case geom::PackFileKind::Unknown: return 0;
    case geom::PackFileKind::Blocked: {
        geom::PackIndex index;
        if ((reinterpret_cast<uintptr_t>(file) & 3) || !index.open(file, file_bytes, reader ? reader->bytes() : file_bytes).ok()) return 0;
        return blocked_need(index, cut);
    }
    case geom::PackFileKind::Pack: return (reinterpret_cast<uintptr_t>(file) & 3) ? file_bytes : 0;
    case geom::PackFileKind::Deflated:
    case geom::PackFileKind::Lzma: return geom::decoded_memory_bytes(file, file_bytes);
    }
    return 0;
}

Result unpack(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes, const BlockCut& cut, Unpacked& out,
              Reader* reader) {
    out = {};
    out.reader = reader;
    auto* mem = static_cast<uint8_t*>(memory);
    const auto* in = static_cast<const uint8_t*>(file);
    if (!mem) memory_bytes = 0;
    const bool inside = mem && in >= mem && in < mem + memory_bytes;
    if (!file) return Result::fail(Status::OutOfRange, "no pack file");
    // (on storage, a blocked pack's index: its size is the index's)
    const uint32_t stored = !reader ? geom::pack_file_bytes(file, file_bytes)
                            : file_bytes >= sizeof(pack::IndexHeader) ? std::min(file_bytes, static_cast<const pack::IndexHeader*>(file)->index_bytes)
                                                                      : 0;
    const uint8_t* pack = in;
    uint32_t bytes = 0;
    switch (geom::pack_file_kind(file, file_bytes)) {
    case geom::PackFileKind::Unknown: return Result::fail(Status::Corrupt, "no pack here (neither FPK1, FPX1, FPZ1 nor FPB1)", kFile);
    case geom::PackFileKind::Blocked:
        if (stored == 0 || stored > file_bytes) return Result::fail(Status::Corrupt, "the blocked pack is longer than the bytes given, or truncated", kFile);
        return unpack_blocked(in, stored, mem, memory_bytes, inside, cut, out);
    case geom::PackFileKind::Pack:
        bytes = stored;
        if (bytes == 0) return Result::fail(Status::Corrupt, "the pack is longer than the bytes given, or truncated", kFile);
        if (reinterpret_cast<uintptr_t>(in) & 3) { // copied where it can be read in place
            if (memory_bytes < bytes || (reinterpret_cast<uintptr_t>(mem) & 3)) {
                return Result::fail(Status::Full, "an unaligned pack needs 4-byte aligned pack memory of its size", kFile);
            }
            std::memmove(mem, in, bytes);
            pack = mem;
        }
        break;
    case geom::PackFileKind::Deflated:
    case geom::PackFileKind::Lzma: {
        Result r;
        if (!mem || (reinterpret_cast<uintptr_t>(mem) & 3)) {
            r = Result::fail(Status::Full, "a compressed pack needs 4-byte aligned pack memory", kFile);
        } else if (inside) { // the file was loaded into the pack memory: inflated in place
            const uint32_t offset = uint32_t(in - mem);
            if (offset) std::memmove(mem, in, memory_bytes - offset < file_bytes ? memory_bytes - offset : file_bytes);
            r = geom::unpack_in_place(mem, memory_bytes, memory_bytes - offset, bytes);
        } else {
            r = geom::decode_pack_file({in, file_bytes}, {mem, memory_bytes}, bytes);
        }
        if (!r.ok()) return r;
        pack = mem;
        break;
    }
    }
    out.pack = pack, out.bytes = bytes;
    return {};
}

Result open_unpacked(Unpacked& u, Scene& scene) {
    if (u.blocks.empty()) {
        geom::Pack p;
        if (Result r = p.open(u.pack, u.bytes); !r.ok()) return r;
        return scene.open(p);
    }
    for (uint32_t b = 0; b < u.blocks.size(); ++b) {
        if (u.blocks[b].left_out) continue;
        const uint32_t bytes = u.index.blocks()[b].pack_bytes;
        if (in_place(u.index, b) && u.index.block_file(b).size() < bytes) {
            return Result::fail(Status::Corrupt, "a plain block is shorter than the index says", {"block", b});
        }
        if (Result r = u.blocks[b].pack.open(u.blocks[b].data, bytes); !r.ok()) return r.within({"block", b});
    }
    return scene.open(u.index, u.blocks);
}

uint32_t block_memory(const Unpacked& u, uint32_t b) {
    return in_place(u.index, b) ? 0 : align4(u.index.blocks()[b].pack_bytes);
}

uint32_t free_block_memory(const Unpacked& u) {
    uint64_t used = table_bytes(uint32_t(u.blocks.size())); // (the room up to u.limit, where the index or file lies)
    for (uint32_t b = 0; b < u.blocks.size(); ++b) used += u.blocks[b].left_out ? 0 : block_memory(u, b);
    return used < u.limit ? uint32_t(u.limit - used) : 0;
}

void compact_blocks(Unpacked& u) {
    const uint32_t count = uint32_t(u.blocks.size());
    uint32_t top = table_bytes(count);
    const uint8_t* last = nullptr; // the last block moved (by where it lay)
    for (;;) {
        uint32_t next = count; // the decoded block lying lowest past `last`
        for (uint32_t b = 0; b < count; ++b) {
            const Block& block = u.blocks[b];
            if (block.left_out || block_memory(u, b) == 0 || block.data <= last) continue;
            if (next == count || block.data < u.blocks[next].data) next = b;
        }
        if (next == count) break;
        Block& block = u.blocks[next];
        last = block.data;
        const uint32_t bytes = u.index.blocks()[next].pack_bytes;
        if (block.data != u.memory + top) {
            std::memmove(u.memory + top, block.data, bytes);
            block.data = u.memory + top;
            block.pack.moved(block.data); // (the same bytes: checked when they were decoded)
            last = block.data + bytes - 1; // (past it, as the blocks lying higher were)
        }
        top += align4(bytes);
    }
    u.bytes = top;
}

uint32_t block_staging(const Unpacked& u, uint32_t b) { return staging(u.index, b); }

Result start_block(Unpacked& u, uint32_t b, geom::PackDecoder& decoder) {
    const pack::Block& entry = u.index.blocks()[b];
    const uint32_t room = block_memory(u, b), stage = staging(u.index, b);
    if (room == 0) return {};
    if (uint64_t(u.bytes) + room + stage > u.limit) return Result::fail(Status::Full, "no room in the pack memory for the block", {"block", b});
    if (!u.reader) return decoder.start(u.index.block_file(b), {u.memory + u.bytes, entry.pack_bytes}, *u.probs).within({"block", b});
    uint8_t* into = stage ? staged_at(u, b, u.limit) : u.memory + u.bytes;
    const Result r = u.reader->start(entry.offset, into, entry.stored_bytes);
    if (r.ok()) return decode_block(u, b, decoder);
    return r.status == Status::Busy ? r : r.within({"block", b});
}

Result decode_block(Unpacked& u, uint32_t b, geom::PackDecoder& decoder) {
    const pack::Block& entry = u.index.blocks()[b];
    if (!staging(u.index, b)) return plain_block(u.memory + u.bytes, b, entry.stored_bytes); // (read to its place)
    const uint8_t* file = staged_at(u, b, u.limit);
    return decoder.start({file, entry.stored_bytes}, {u.memory + u.bytes, entry.pack_bytes}, *u.probs).within({"block", b});
}

Result finish_block(Unpacked& u, uint32_t b, const geom::PackDecoder* decoder, Scene& scene) {
    const uint32_t bytes = u.index.blocks()[b].pack_bytes;
    Block& block = u.blocks[b];
    const Place here{"block", b};
    if (block_memory(u, b) == 0) {
        if (u.index.block_file(b).size() < bytes) return Result::fail(Status::Corrupt, "a plain block is shorter than the index says", here);
        block.data = u.index.block_file(b).data();
    } else if (!decoder) { // a plain block read from storage to its place
        if (u.index.blocks()[b].stored_bytes != bytes) return Result::fail(Status::Corrupt, "the block's size is not the index's", here);
        block.data = u.memory + u.bytes;
    } else {
        if (decoder->pack_bytes() != bytes) return Result::fail(Status::Corrupt, "the block's size is not the index's", here);
        block.data = u.memory + u.bytes;
    }
    if (Result r = block.pack.open(block.data, bytes); !r.ok()) {
        block.pack = {}, block.data = nullptr;
        return r.within(here);
    }
    if (Result r = scene.take_block(b); !r.ok()) {
        block.data = nullptr;
        return r;
    }
    u.bytes += block_memory(u, b);
    return {};
}

} // namespace facet::module
