// LZMA decoding (the raw LZMA1 stream), written from the format's description: a binary range
// decoder, bit trees of adaptive 11-bit probabilities, a 12-state machine choosing between
// literals, matches and repeated distances, lengths and distances coded by their own trees.
#include "geom/unlzma.h"

namespace facet::geom {
namespace {

constexpr uint32_t kProbBits = 11;
constexpr uint16_t kProbInit = 1u << (kProbBits - 1);
constexpr uint32_t kMoveBits = 5;
constexpr uint32_t kTop = 1u << 24;
constexpr uint32_t kStates = 12;
constexpr uint32_t kEndPosModel = 14;   // distance slots below this code their low bits by trees
constexpr uint32_t kFullDistances = 128; // 1 << (kEndPosModel / 2)
constexpr uint32_t kAlignBits = 4;

// Offsets of each model in LzmaProbs::p.
constexpr uint32_t kIsMatch = 0;                        // [state << 4 | posState]
constexpr uint32_t kIsRep = kIsMatch + (kStates << 4); // [state]
constexpr uint32_t kIsRepG0 = kIsRep + kStates;
constexpr uint32_t kIsRepG1 = kIsRepG0 + kStates;
constexpr uint32_t kIsRepG2 = kIsRepG1 + kStates;
constexpr uint32_t kIsRep0Long = kIsRepG2 + kStates; // [state << 4 | posState]
constexpr uint32_t kPosSlot = kIsRep0Long + (kStates << 4); // 4 trees of 6 bits
constexpr uint32_t kPosSpecial = kPosSlot + 4 * 64;       // reverse trees of slots 4..13
constexpr uint32_t kAlign = kPosSpecial + 1 + kFullDistances - kEndPosModel;
constexpr uint32_t kLenCoder = kAlign + (1u << kAlignBits);
constexpr uint32_t kRepLenCoder = kLenCoder + 514;
constexpr uint32_t kLiteral = kRepLenCoder + 514;
static_assert(kLiteral + LzmaProbs::kLiterals == LzmaProbs::kCount, "the model offsets add up to the table");
// Inside a length coder: choice, choice2, low[16][8], mid[16][8], high[256].
constexpr uint32_t kLenChoice = 0, kLenChoice2 = 1, kLenLow = 2, kLenMid = kLenLow + 128, kLenHigh = kLenMid + 128;

// The range decoder's state lives in LzmaDecoder between pieces; run() copies it into this
// class's registers and back.
class RangeDecoder {
public:
    RangeDecoder(const uint8_t* p, const uint8_t* end, uint32_t range, uint32_t code, bool overrun)
        : p_(p), end_(end), range_(range), code_(code), overrun_(overrun) {}

    bool init() {
        if (next() != 0) return false; // the encoder's first byte is always 0
        for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next();
        return code_ != range_;
    }
    bool overrun() const { return overrun_; }
    bool finished_cleanly() const { return code_ == 0; }
    uint32_t left() const { return uint32_t(end_ - p_); }
    void save(const uint8_t*& p, uint32_t& range, uint32_t& code, bool& overrun) const {
        p = p_, range = range_, code = code_, overrun = overrun_;
    }

    [[gnu::always_inline]] uint32_t bit(uint16_t* prob) {
        const uint32_t bound = (range_ >> kProbBits) * *prob;
        uint32_t b;
        if (code_ < bound) {
            *prob = uint16_t(*prob + (((1u << kProbBits) - *prob) >> kMoveBits));
            range_ = bound;
            b = 0;
        } else {
            *prob = uint16_t(*prob - (*prob >> kMoveBits));
            code_ -= bound;
            range_ -= bound;
            b = 1;
        }
        normalize();
        return b;
    }

    // numBits bits, most significant first, through the tree at probs[1..2^numBits).
    [[gnu::always_inline]] uint32_t tree(uint16_t* probs, uint32_t num_bits) {
        uint32_t m = 1;
        for (uint32_t i = 0; i < num_bits; ++i) m = (m << 1) | bit(probs + m);
        return m - (1u << num_bits);
    }

    // The same, least significant bit first.
    [[gnu::always_inline]] uint32_t reverse_tree(uint16_t* probs, uint32_t num_bits) {
        uint32_t m = 1, symbol = 0;
        for (uint32_t i = 0; i < num_bits; ++i) {
            const uint32_t b = bit(probs + m);
            m = (m << 1) | b;
            symbol |= b << i;
        }
        return symbol;
    }

    // Bits at probability one half.
    uint32_t direct(uint32_t num_bits, bool& corrupt) {
        uint32_t r = 0;
        for (uint32_t i = 0; i < num_bits; ++i) {
            range_ >>= 1;
            code_ -= range_;
            const uint32_t t = 0u - (code_ >> 31); // all ones if code went below zero
            code_ += range_ & t;
            if (code_ == range_) corrupt = true;
            normalize();
            r = (r << 1) + (t + 1);
        }
        return r;
    }

private:
    [[gnu::always_inline]] uint8_t next() {
        if (p_ < end_) return *p_++;
        overrun_ = true; // reads past the end see zeros; the caller reports the stream truncated
        return 0;
    }
    [[gnu::always_inline]] void normalize() {
        if (range_ < kTop) {
            range_ <<= 8;
            code_ = (code_ << 8) | next();
        }
    }

    const uint8_t* p_;
    const uint8_t* end_;
    uint32_t range_;
    uint32_t code_;
    bool overrun_;
};

[[gnu::always_inline]] inline uint32_t decode_length(RangeDecoder& rc, uint16_t* coder, uint32_t pos_state) {
    if (rc.bit(coder + kLenChoice) == 0) return rc.tree(coder + kLenLow + (pos_state << 3), 3);
    if (rc.bit(coder + kLenChoice2) == 0) return 8 + rc.tree(coder + kLenMid + (pos_state << 3), 3);
    return 16 + rc.tree(coder + kLenHigh, 8);
}

} // namespace

Result LzmaDecoder::start(std::span<const uint8_t> in, uint8_t props, std::span<uint8_t> out, LzmaProbs& probs) {
    *this = LzmaDecoder{};
    if (props >= 9 * 5 * 5) return fail(Result::fail(Status::Corrupt, "bad properties byte"));
    lc_ = props % 9;
    const uint32_t lp = (props / 9) % 5, pb = props / 45;
    if (lc_ + lp > kLzmaMaxLcLp) {
        return fail(Result::fail(Status::Unsupported, "literal context bits (lc + lp) beyond what the decoder holds", {"lc + lp", lc_ + lp}));
    }
    pb_mask_ = (1u << pb) - 1, lp_mask_ = (1u << lp) - 1;
    probs_ = probs.p;
    for (uint32_t i = 0; i < LzmaProbs::kCount; ++i) probs_[i] = kProbInit;
    out_ = out.data(), size_ = uint32_t(out.size());
    end_ = in.data() + in.size();
    RangeDecoder rc(in.data(), end_, 0xFFFFFFFFu, 0, false);
    if (!rc.init()) return fail(Result::fail(Status::Corrupt, "the stream does not start as a range coder's does"));
    rc.save(in_, range_, code_, overrun_);
    status_ = Status::Busy;
    return Result::fail(Status::Busy, "decoding");
}

Result LzmaDecoder::fail(const Result& r) {
    status_ = r.status;
    failure_ = r;
    return r;
}

Result LzmaDecoder::run(uint32_t bytes) {
    if (status_ != Status::Busy) return status_ == Status::Ok ? Result{} : failure_;
    RangeDecoder rc(in_, end_, range_, code_, overrun_);
    uint16_t* const P = probs_;
    uint8_t* const o = out_;
    const uint32_t size = size_, lc = lc_, pb_mask = pb_mask_, lp_mask = lp_mask_;
    const uint32_t stop = bytes < size - pos_ ? pos_ + bytes : size; // a match may run past it
    uint32_t pos = pos_, state = state_, rep0 = rep_[0], rep1 = rep_[1], rep2 = rep_[2], rep3 = rep_[3];
    bool corrupt = false;
    Result r = Result::fail(Status::Busy, "decoding");
    while (pos < stop) {
        if (rc.overrun()) {
            r = Result::fail(Status::Corrupt, "the stream ends early (truncated)", {"byte", pos});
            break;
        }
        const uint32_t pos_state = pos & pb_mask;
        if (rc.bit(P + kIsMatch + (state << 4) + pos_state) == 0) {
            // A literal, coded in the context of the previous byte's high bits and the position.
            const uint32_t prev = pos > 0 ? o[pos - 1] : 0;
            uint16_t* lit = P + kLiteral + 0x300 * (((pos & lp_mask) << lc) + (prev >> (8 - lc)));
            uint32_t symbol = 1;
            if (state >= 7) { // after a match: the byte at rep0 guides the first bits
                if (rep0 >= pos) {
                    r = Result::fail(Status::Corrupt, "a distance reaches before the start", {"byte", pos});
                    break;
                }
                uint32_t match = o[pos - rep0 - 1];
                do {
                    const uint32_t match_bit = (match >> 7) & 1;
                    match <<= 1;
                    const uint32_t b = rc.bit(lit + ((1 + match_bit) << 8) + symbol);
                    symbol = (symbol << 1) | b;
                    if (match_bit != b) break;
                } while (symbol < 0x100);
            }
            while (symbol < 0x100) symbol = (symbol << 1) | rc.bit(lit + symbol);
            o[pos++] = uint8_t(symbol);
            state = state < 4 ? 0 : (state < 10 ? state - 3 : state - 6);
            continue;
        }
        uint32_t len;
        if (rc.bit(P + kIsRep + state) != 0) {
            if (pos == 0) {
                r = Result::fail(Status::Corrupt, "a repeated match before any output");
                break;
            }
            if (rc.bit(P + kIsRepG0 + state) == 0) {
                if (rc.bit(P + kIsRep0Long + (state << 4) + pos_state) == 0) { // one byte at rep0
                    if (rep0 >= pos) {
                        r = Result::fail(Status::Corrupt, "a distance reaches before the start", {"byte", pos});
                        break;
                    }
                    state = state < 7 ? 9 : 11;
                    o[pos] = o[pos - rep0 - 1];
                    ++pos;
                    continue;
                }
            } else {
                uint32_t dist;
                if (rc.bit(P + kIsRepG1 + state) == 0) {
                    dist = rep1;
                } else {
                    if (rc.bit(P + kIsRepG2 + state) == 0) {
                        dist = rep2;
                    } else {
                        dist = rep3;
                        rep3 = rep2;
                    }
                    rep2 = rep1;
                }
                rep1 = rep0;
                rep0 = dist;
            }
            len = decode_length(rc, P + kRepLenCoder, pos_state);
            state = state < 7 ? 8 : 11;
        } else {
            rep3 = rep2;
            rep2 = rep1;
            rep1 = rep0;
            len = decode_length(rc, P + kLenCoder, pos_state);
            state = state < 7 ? 7 : 10;
            // The distance: a 6-bit slot per length class, then its low bits.
            const uint32_t slot = rc.tree(P + kPosSlot + 64 * (len < 3 ? len : 3), 6);
            if (slot < 4) {
                rep0 = slot;
            } else {
                const uint32_t direct_bits = (slot >> 1) - 1;
                uint32_t dist = (2 | (slot & 1)) << direct_bits;
                if (slot < kEndPosModel) {
                    dist += rc.reverse_tree(P + kPosSpecial + dist - slot, direct_bits);
                } else {
                    dist += rc.direct(direct_bits - kAlignBits, corrupt) << kAlignBits;
                    dist += rc.reverse_tree(P + kAlign, kAlignBits);
                }
                rep0 = dist;
            }
            if (rep0 == 0xFFFFFFFFu) { // the end marker
                r = Result::fail(Status::Corrupt, "the stream ends before the output is complete", {"byte", pos});
                break;
            }
        }
        len += 2;
        if (corrupt) {
            r = Result::fail(Status::Corrupt, "the range coder's state is invalid", {"byte", pos});
            break;
        }
        if (rep0 >= pos) {
            r = Result::fail(Status::Corrupt, "a distance reaches before the start", {"byte", pos});
            break;
        }
        if (len > size - pos) {
            r = Result::fail(Status::Corrupt, "a match runs past the end of the output", {"byte", pos});
            break;
        }
        const uint8_t* from = o + pos - rep0 - 1;
        uint8_t* to = o + pos;
        for (uint32_t i = 0; i < len; ++i) to[i] = from[i]; // may overlap forward: byte by byte
        pos += len;
    }
    pos_ = pos, state_ = state, rep_[0] = rep0, rep_[1] = rep1, rep_[2] = rep2, rep_[3] = rep3;
    if (r.status != Status::Busy) return fail(r);
    if (pos < size) {
        rc.save(in_, range_, code_, overrun_);
        return r; // Busy: more next time
    }
    if (rc.overrun()) return fail(Result::fail(Status::Corrupt, "the stream ends early (truncated)", {"byte", pos}));
    // The encoder's flush leaves the decoder with a zero code and every byte read.
    if (!rc.finished_cleanly()) return fail(Result::fail(Status::Corrupt, "the stream does not end where the output does"));
    if (rc.left() != 0) return fail(Result::fail(Status::Corrupt, "bytes follow the end of the LZMA stream", {"bytes", rc.left()}));
    status_ = Status::Ok;
    return {};
}

Result unlzma(std::span<const uint8_t> in, uint8_t props, std::span<uint8_t> out, LzmaProbs& probs,
              uint32_t& written) {
    written = 0;
    LzmaDecoder d;
    Result r = d.start(in, props, out, probs);
    if (r.status == Status::Busy) r = d.run(uint32_t(out.size()));
    if (r.ok()) written = d.written();
    return r;
}

} // namespace facet::geom
