#pragma once
// A pack as stored or sent: the pack itself (magic FPK1), LZMA-compressed (FPX1: an LzmaHead
// and a raw LZMA stream, the default of facet-pack) or deflated (FPZ1: a DeflatedHead and a raw
// DEFLATE stream). Either way it ends up as a pack in memory, read in place from there
// (geom/pack.h).
//
// On the device the file is loaded at the start of the pack region; unpack_in_place() decodes
// a compressed one there:
//
//   uint32_t bytes;
//   if (unpack_in_place(region, capacity, loaded, bytes).ok()) r = pack.open(region, bytes);
#include "geom/pack_format.h"
#include "geom/unlzma.h"
#include "core/status.h"

#include <cstdint>
#include <span>

namespace facet::geom {

// What the bytes at `data` hold, from their first bytes alone.
// Blocked: an index and blocks (pack_format.h, geom/pack_index.h), each block itself one of
// the other kinds.
enum class PackFileKind : uint8_t { Unknown, Pack, Deflated, Lzma, Blocked };
PackFileKind pack_file_kind(const void* data, uint32_t available);
constexpr bool compressed(PackFileKind k) { return k == PackFileKind::Deflated || k == PackFileKind::Lzma; }

// The size of the file at `data` (any kind) as its head states it; 0 when unknown or larger
// than `available`.
uint32_t pack_file_bytes(const void* data, uint32_t available);

// The decoder's state an LZMA file needs next to its output (4-byte aligned), 0 for the others.
constexpr uint32_t kLzmaStateBytes = (sizeof(LzmaProbs) + 3) & ~3u;

// The memory decode_pack_file() needs for a compressed file: its pack, and after it the LZMA
// decoder's state; 0 when the head is unreadable.
uint32_t decoded_memory_bytes(const void* data, uint32_t available);

// A stored pack (a whole one, or one block of a blocked pack) decoded into caller memory a
// piece at a time: an LZMA file in pieces of about the bytes run() is given, a deflated one in
// one piece, a plain one copied. `out` must hold pack_bytes (stored_pack_bytes()), 4-byte
// aligned; `probs` is an LZMA file's decoder state (caller memory, kLzmaStateBytes).
//
//   PackDecoder d;
//   Result r = d.start(file, out, probs);
//   while (r.status == Status::Busy) r = d.run(64 * 1024);
//   if (r.ok()) r = pack.open(out.data(), d.pack_bytes());
class PackDecoder {
public:
    Result start(std::span<const uint8_t> file, std::span<uint8_t> out, LzmaProbs& probs);
    Result run(uint32_t bytes);
    uint32_t pack_bytes() const { return pack_bytes_; }

private:
    Result finish(const Result& r, uint32_t written);
    PackFileKind kind_ = PackFileKind::Unknown;
    std::span<const uint8_t> stream_;
    std::span<uint8_t> out_;
    uint32_t pack_bytes_ = 0;
    LzmaDecoder lzma_;
    Result result_ = Result::fail(Status::OutOfRange, "run() before start()");
};

// The decoded size of a stored pack as its head says (plain: its total), 0 when unreadable.
uint32_t stored_pack_bytes(const void* data, uint32_t available);

// The counts of a whole pack's records and its Needs, from its head and section table alone (a
// compressed file's first few hundred bytes decoded, an LZMA one's with `probs`).
// Not validated: the pack's own open() checks them when it is read. head_only: `data` is the
// file's first bytes only (enough for the head: a file listed on storage).
struct PackCounts {
    uint32_t faces = 0, edges = 0, shells = 0;
    bool has_needs = false; // the pack's Needs record (written in its head by the packer)
    pack::Needs needs{};
};
Result stored_pack_counts(const void* data, uint32_t available, PackCounts& out, LzmaProbs& probs, bool head_only = false);

// Makes the file loaded at region[0, loaded) a pack at region[0, bytes). A compressed file is
// moved to the region's end and decoded to its start: it needs the pack's size plus its own
// within `capacity` (an LZMA file kLzmaStateBytes more, for its state at the very end). A plain
// pack is left as it is. The region must be 4-byte aligned.
Result unpack_in_place(uint8_t* region, uint32_t capacity, uint32_t loaded, uint32_t& bytes);

// Decodes a compressed file into out (at least decoded_memory_bytes() long, 4-byte aligned;
// an LZMA file's decoder state goes after the pack).
Result decode_pack_file(std::span<const uint8_t> file, std::span<uint8_t> out, uint32_t& bytes);

} // namespace facet::geom
