#pragma once
// A pack as stored or sent: the pack itself (magic FPK1), or deflated (FPZ1: a DeflatedHead and
// a raw DEFLATE stream, a third to a quarter of the size). Either way it ends up as a pack in
// memory, read in place from there (geom/pack.h).
//
// On the device the file is loaded at the start of the pack region; unpack_in_place() inflates
// a deflated one there:
//
//   uint32_t bytes;
//   if (unpack_in_place(region, capacity, loaded, bytes).ok()) r = pack.open(region, bytes);
#include "geom/pack_format.h"
#include "hal/status.h"

#include <cstdint>
#include <span>

namespace facet::geom {

// What the bytes at `data` hold, from their first bytes alone.
enum class PackFileKind : uint8_t { Unknown, Pack, Deflated };
PackFileKind pack_file_kind(const void* data, uint32_t available);

// The size of the file at `data` (either kind) as its head states it; 0 when unknown or
// larger than `available`.
uint32_t pack_file_bytes(const void* data, uint32_t available);

// Makes the file loaded at region[0, loaded) a pack at region[0, bytes). A deflated file is
// moved to the region's end and inflated to its start: it needs the pack's size plus its own
// within `capacity`. A plain pack is left as it is. The region must be 4-byte aligned.
Result unpack_in_place(uint8_t* region, uint32_t capacity, uint32_t loaded, uint32_t& bytes);

// Inflates a deflated file into out (at least its head's pack_bytes long; the host sizes it).
Result inflate_pack_file(std::span<const uint8_t> file, std::span<uint8_t> out, uint32_t& bytes);

} // namespace facet::geom
