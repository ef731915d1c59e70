#pragma once
// DEFLATE (RFC 1951) decoding for the device: packs travel deflated (a third to a quarter of
// their size) and are inflated once, into the memory they are then read from in place.
//
//   uint32_t written;
//   if (Result r = inflate(stream, out, written); !r.ok()) print(con, "pack: {}\n", r);
//
// No heap and no window of its own (the output is the history); about 2 KB of stack.
// Every read, length and distance is checked: a corrupt or truncated stream, or one that
// does not fit the output, gets Status::Corrupt (or Full) and a reason, never a write outside
// `out`. On Full, `written` says how much of `out` the stream's start filled (a pack's head is
// read so: geom::stored_pack_counts()); on Corrupt, 0.
#include "core/status.h"

#include <cstdint>
#include <span>

namespace facet::geom {

Result inflate(std::span<const uint8_t> in, std::span<uint8_t> out, uint32_t& written);

} // namespace facet::geom
