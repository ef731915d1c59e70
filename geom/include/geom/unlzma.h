#pragma once
// LZMA decoding for the device: packs travel as LZMA streams (FPX1, geom/pack_file.h), about two
// thirds of their DEFLATE size on B-spline-heavy models, and are decoded once, into the memory
// they are then read from in place.
//
//   static LzmaProbs probs;                   // ~10 KB: the caller's memory, not the stack
//   uint32_t written;
//   if (Result r = unlzma(stream, props, out, probs, written); !r.ok()) print(con, "pack: {}\n", r);
//
// The raw LZMA stream of xz's LZMA1 filter and 7-Zip (no .lzma or .xz container): a range coder
// over adaptive bit probabilities, literals and matches into the output itself (no window of
// its own: the output is the history). `props` is the usual byte (pb * 5 + lp) * 9 + lc; the
// probability table here holds lc + lp <= 2 (facet-pack writes lc 0, lp 2, pb 2: literals
// coded by their place in a 4-byte float). The stream has no end marker (liblzma's LZMA1EXT
// without ALLOW_EOPM): it ends when `out` is full, with the range coder's code at zero and every
// input byte read. An end marker, a truncated or corrupt stream, bytes after its end, or a
// distance reaching before the output's start gets Status::Corrupt and a reason, never a read
// or write outside `in` and `out`.
#include "core/status.h"

#include <cstdint>
#include <span>

namespace facet::geom {

constexpr uint32_t kLzmaMaxLcLp = 2; // lc + lp the probability table holds

// Every adaptive probability of the decoder, 11-bit, reset by unlzma().
struct LzmaProbs {
    static constexpr uint32_t kLiterals = 0x300u << kLzmaMaxLcLp;
    static constexpr uint32_t kCount = 192 + 4 * 12 + 192 + 4 * 64 + 115 + 16 + 2 * 514 + kLiterals;
    uint16_t p[kCount];
};

// The same a piece at a time: start(), then run() until it is no longer Busy. The decoder keeps
// where it stands (about 60 bytes); `in`, `out` and `probs` must stay put meanwhile.
//
//   LzmaDecoder d;
//   Result r = d.start(stream, props, out, probs);
//   while (r.status == Status::Busy) r = d.run(64 * 1024); // about 64 KB of output a piece
class LzmaDecoder {
public:
    Result start(std::span<const uint8_t> in, uint8_t props, std::span<uint8_t> out, LzmaProbs& probs);
    // About `bytes` more output (a match under way is finished): Busy while some is left, then
    // Ok once all of `out` is written and the stream checked to its end, or the failure (which
    // every later call returns again).
    Result run(uint32_t bytes);
    uint32_t written() const { return pos_; }

private:
    Result fail(const Result& r);

    const uint8_t* in_ = nullptr;
    const uint8_t* end_ = nullptr;
    uint32_t range_ = 0, code_ = 0;
    bool overrun_ = false;
    uint16_t* probs_ = nullptr;
    uint8_t* out_ = nullptr;
    uint32_t size_ = 0, pos_ = 0, state_ = 0, rep_[4] = {};
    uint32_t lc_ = 0, pb_mask_ = 0, lp_mask_ = 0;
    Status status_ = Status::OutOfRange;
    Result failure_ = Result::fail(Status::OutOfRange, "run() before start()");
};

Result unlzma(std::span<const uint8_t> in, uint8_t props, std::span<uint8_t> out, LzmaProbs& probs,
              uint32_t& written);

} // namespace facet::geom
