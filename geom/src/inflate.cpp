// DEFLATE decoding (RFC 1951): stored, fixed-Huffman and dynamic-Huffman blocks.
//
// Canonical Huffman codes of up to 9 bits (nearly every symbol of a pack) are decoded by one
// look-up in a 512-entry table built per block; longer ones one bit at a time against the
// count of codes of each length (codes of one length are consecutive integers, in symbol
// order). The bit-by-bit decoder alone took about a hundred instructions per symbol: 5 to 26%
// of a model's load on the ARM926 (tail_section_asm: 75 M instructions). Away from the ends of
// the input and the output, literals (most of a pack's symbols: its floats) decode two a turn
// without a check of either end: the 10 k-face assembly's 6 MB inflate in 127 M instructions
// on the ARM926, 145 M before.
#include "geom/inflate.h"

namespace facet::geom {
namespace {

constexpr int kMaxBits = 15;              // longest code
constexpr int kLiteralLengthCodes = 288;  // 286 used, 2 reserved
constexpr int kDistanceCodes = 30;
constexpr int kCodeLengthCodes = 19;
constexpr int kFastBits = 9;              // codes this short decode by table
constexpr uint32_t kFastMask = (1u << kFastBits) - 1;

// LSB-first bits from the stream; past its end every read gives zeros and sets `truncated`.
struct Bits {
    const uint8_t* p;
    const uint8_t* end;
    uint32_t buffer = 0;
    int count = 0; // bits in buffer (under 8 between reads)
    bool truncated = false;

    uint32_t take(int n) { // n <= 16
        while (count < n) {
            if (p == end) {
                truncated = true;
                return 0;
            }
            buffer |= uint32_t(*p++) << count;
            count += 8;
        }
        const uint32_t v = buffer & ((1u << n) - 1);
        buffer >>= n;
        count -= n;
        return v;
    }
    // The next kFastBits bits without taking them (zeros past the end; `count` says how many
    // are real). The buffer may then hold whole bytes not yet taken.
    uint32_t peek() {
        while (count < kFastBits && p != end) {
            buffer |= uint32_t(*p++) << count;
            count += 8;
        }
        return buffer & kFastMask;
    }
    void drop(int n) { buffer >>= n, count -= n; } // n <= count
    // The rest of the current byte is padding; whole bytes read ahead go back to the stream.
    void to_byte() {
        p -= count >> 3;
        buffer = 0, count = 0;
    }
    // Whether bytes are left that no read has taken.
    bool more() const { return p != end || count >= 8; }
};

struct Huffman {
    uint16_t count[kMaxBits + 1];
    uint16_t symbol[kLiteralLengthCodes]; // by code: shortest codes first, then by symbol
    uint16_t fast[1 << kFastBits];        // by the next kFastBits bits: symbol << 4 | length (kLonger: longer)
};
constexpr uint16_t kLonger = 0xFFF0;               // a fast entry of no short code (length 0)
constexpr uint32_t kLiteralEntries = 256u << 4;     // a literal's fast entry is under this

// The code for symbols 0..n-1 of the given lengths (0: unused). Returns 0 for a complete code,
// the number of missing codes (> 0) for an incomplete one, < 0 for an over-subscribed one.
int build(Huffman& h, const uint8_t* length, int n) {
    for (uint16_t& c : h.count) c = 0;
    for (int s = 0; s < n; ++s) ++h.count[length[s]];
    if (h.count[0] == n) return 0; // no codes at all: complete, and never decodes
    int left = 1;
    for (int len = 1; len <= kMaxBits; ++len) {
        left = 2 * left - h.count[len];
        if (left < 0) return left;
    }
    uint16_t offset[kMaxBits + 2];
    offset[1] = 0;
    for (int len = 1; len <= kMaxBits; ++len) offset[len + 1] = uint16_t(offset[len] + h.count[len]);
    for (int s = 0; s < n; ++s)
        if (length[s]) h.symbol[offset[length[s]]++] = uint16_t(s);
    // The table: each short code, bit-reversed (the stream sends codes from their top bit),
    // at every index whose low bits it is.
    for (uint16_t& f : h.fast) f = kLonger;
    int code = 0, index = 0;
    for (int len = 1; len <= kFastBits; ++len) {
        for (int i = 0; i < h.count[len]; ++i, ++code) {
            int reversed = 0;
            for (int b = 0; b < len; ++b) reversed |= ((code >> b) & 1) << (len - 1 - b);
            const uint16_t entry = uint16_t(h.symbol[index + i] << 4 | len);
            for (int fill = reversed; fill < (1 << kFastBits); fill += 1 << len) h.fast[fill] = entry;
        }
        index += h.count[len];
        code <<= 1;
    }
    return left;
}

// The next symbol, or -1 (no such code, or the stream ended).
int decode(Bits& in, const Huffman& h) {
    const uint32_t entry = h.fast[in.peek()];
    const int len = int(entry & 15);
    if (len && len <= in.count) {
        in.drop(len);
        return int(entry >> 4);
    }
    int code = 0, first = 0, index = 0;
    for (int len = 1; len <= kMaxBits; ++len) {
        code |= int(in.take(1));
        if (in.truncated) return -1;
        const int count = h.count[len];
        if (code - first < count) return h.symbol[index + (code - first)];
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    return -1;
}

constexpr uint16_t kLengthBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr uint8_t kLengthExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr uint16_t kDistanceBase[kDistanceCodes] = {1,    2,    3,    4,    5,    7,     9,     13,    17,  25,
                                                    33,   49,   65,   97,   129,  193,   257,   385,   513, 769,
                                                    1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr uint8_t kDistanceExtra[kDistanceCodes] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

struct Output {
    uint8_t* data;
    uint32_t size;
    uint32_t at = 0;
};

// One block's literals and copies, up to its end-of-block symbol. The stream's bits are kept
// in locals here, 25 or more in hand before each code (a byte store to the output may alias
// any memory: kept in the Bits they would be reloaded after every byte written).
Result codes(Bits& in, Output& out, const Huffman& literal, const Huffman& distance) {
    const uint8_t* p = in.p;
    const uint8_t* const end = in.end;
    uint32_t buffer = in.buffer;
    int count = in.count;
    uint8_t* const data = out.data;
    const uint32_t size = out.size;
    uint32_t at = out.at;
    const auto give_back = [&] { in.p = p, in.buffer = buffer, in.count = count, out.at = at; };
    const auto fail = [&](Status s, const char* why) {
        give_back();
        return Result::fail(s, why);
    };
    const auto refill = [&] { // to over 24 bits, while bytes are left
        for (; count <= 24 && p != end; count += 8) buffer |= uint32_t(*p++) << count;
    };
    // The next symbol of h from the bits in hand (a code is 15 bits at most): -1 when no code
    // matches, -2 when the stream ends inside one.
    const auto next = [&](const Huffman& h) -> int {
        const uint32_t entry = h.fast[buffer & kFastMask];
        const int len = int(entry & 15);
        if (len && len <= count) {
            buffer >>= len, count -= len;
            return int(entry >> 4);
        }
        int code = 0, first = 0, index = 0;
        uint32_t bits = buffer;
        for (int n = 1; n <= kMaxBits; ++n, bits >>= 1) {
            if (n > count) return -2;
            code |= int(bits & 1);
            const int c = h.count[n];
            if (code - first < c) {
                buffer >>= n, count -= n;
                return h.symbol[index + (code - first)];
            }
            index += c;
            first = (first + c) << 1;
            code <<= 1;
        }
        return -1;
    };
    const auto take = [&](int n) -> int { // n extra bits (-1: the stream ends first)
        if (n > count) return -1;
        const uint32_t v = buffer & ((1u << n) - 1);
        buffer >>= n, count -= n;
        return int(v);
    };
    constexpr const char* kEarly = "the DEFLATE stream ends early";
    constexpr const char* kLarger = "the inflated data is larger than its space";
    for (;;) {
        // Literals, two a turn, while the input holds the 4 bytes a refill may read and the
        // output has room for both: no check of either per symbol (most of a pack's symbols
        // are literals: its floats). The rest, and everything near either end, below.
        if (end - p >= 4 && size - at >= 2) {
            if (count <= 24) { // to 25..31 bits: the next 4 bytes, and past those taken whole
                const uint32_t word = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
                buffer |= word << count; // (bits past `count` are the stream's next: or-ing them again changes none)
                p += (31 - count) >> 3;
                count |= 24;
            }
            uint32_t e = literal.fast[buffer & kFastMask];
            if (e < kLiteralEntries) {
                buffer >>= e & 15, count -= int(e & 15);
                data[at++] = uint8_t(e >> 4);
                e = literal.fast[buffer & kFastMask]; // (16 bits or more still in hand)
                if (e < kLiteralEntries) {
                    buffer >>= e & 15, count -= int(e & 15);
                    data[at++] = uint8_t(e >> 4);
                    continue;
                }
            }
        }
        refill();
        const int sym = next(literal);
        if (sym < 0) return fail(Status::Corrupt, sym == -2 ? kEarly : "an invalid literal/length code");
        if (sym < 256) {
            if (at == size) return fail(Status::Full, kLarger);
            data[at++] = uint8_t(sym);
            continue;
        }
        if (sym == 256) {
            give_back();
            return {};
        }
        const int ls = sym - 257;
        if (ls >= 29) return fail(Status::Corrupt, "an invalid length symbol");
        const int lx = take(kLengthExtra[ls]); // (the code and its extra bits: 20 at most, in hand)
        if (lx < 0) return fail(Status::Corrupt, kEarly);
        const uint32_t length = kLengthBase[ls] + uint32_t(lx);
        refill();
        const int dsym = next(distance);
        if (dsym == -2) return fail(Status::Corrupt, kEarly);
        if (dsym < 0 || dsym >= kDistanceCodes) return fail(Status::Corrupt, "an invalid distance code");
        refill();
        const int dx = take(kDistanceExtra[dsym]);
        if (dx < 0) return fail(Status::Corrupt, kEarly);
        const uint32_t dist = kDistanceBase[dsym] + uint32_t(dx);
        if (dist > at) return fail(Status::Corrupt, "a copy reaches back before the start");
        if (length > size - at) return fail(Status::Full, kLarger);
        // Byte by byte: a copy may overlap what it writes (a run); four at a time when each
        // reads only bytes written before them.
        uint8_t* to = data + at;
        const uint8_t* from = to - dist;
        uint32_t k = 0;
        if (dist >= 4) {
            for (; k + 4 <= length; k += 4) to[k] = from[k], to[k + 1] = from[k + 1], to[k + 2] = from[k + 2], to[k + 3] = from[k + 3];
        }
        for (; k < length; ++k) to[k] = from[k];
        at += length;
    }
}

Result stored(Bits& in, Output& out) {
    in.to_byte();
    if (in.end - in.p < 4) {
        return Result::fail(Status::Corrupt, "the DEFLATE stream ends early");
    }
    const uint32_t len = uint32_t(in.p[0]) | uint32_t(in.p[1]) << 8, nlen = uint32_t(in.p[2]) | uint32_t(in.p[3]) << 8;
    in.p += 4;
    if (len != (~nlen & 0xFFFFu)) {
        return Result::fail(Status::Corrupt, "a stored block's length check fails");
    }
    if (uint32_t(in.end - in.p) < len) {
        return Result::fail(Status::Corrupt, "the DEFLATE stream ends early");
    }
    if (len > out.size - out.at) {
        for (uint32_t k = 0; k < out.size - out.at; ++k) out.data[out.at + k] = in.p[k];
        out.at = out.size;
        return Result::fail(Status::Full, "the inflated data is larger than its space");
    }
    for (uint32_t k = 0; k < len; ++k) out.data[out.at + k] = in.p[k];
    in.p += len;
    out.at += len;
    return {};
}

Result fixed(Bits& in, Output& out) {
    uint8_t length[kLiteralLengthCodes];
    Huffman literal, distance;
    for (int s = 0; s < kLiteralLengthCodes; ++s) length[s] = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
    build(literal, length, kLiteralLengthCodes);
    for (int s = 0; s < kDistanceCodes; ++s) length[s] = 5;
    build(distance, length, kDistanceCodes);
    return codes(in, out, literal, distance);
}

Result dynamic(Bits& in, Output& out) {
    static constexpr uint8_t kOrder[kCodeLengthCodes] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    const int nlen = int(in.take(5)) + 257, ndist = int(in.take(5)) + 1, ncode = int(in.take(4)) + 4;
    if (nlen > 286 || ndist > kDistanceCodes) {
        return Result::fail(Status::Corrupt, "a block header has too many codes");
    }
    uint8_t length[286 + kDistanceCodes];
    for (int k = 0; k < kCodeLengthCodes; ++k) length[kOrder[k]] = k < ncode ? uint8_t(in.take(3)) : 0;
    Huffman lencode, distance;
    if (in.truncated || build(lencode, length, kCodeLengthCodes) != 0) {
        return Result::fail(Status::Corrupt, in.truncated ? "the DEFLATE stream ends early" : "an incomplete code-length code");
    }
    for (int k = 0; k < nlen + ndist;) {
        const int sym = decode(in, lencode);
        if (sym < 0) {
            return Result::fail(Status::Corrupt, in.truncated ? "the DEFLATE stream ends early" : "an invalid code-length code");
        }
        if (sym < 16) {
            length[k++] = uint8_t(sym);
            continue;
        }
        uint8_t value = 0;
        int repeat;
        if (sym == 16) {
            if (k == 0) {
                return Result::fail(Status::Corrupt, "a repeated code length with none before it");
            }
            value = length[k - 1];
            repeat = 3 + int(in.take(2));
        } else if (sym == 17) {
            repeat = 3 + int(in.take(3));
        } else {
            repeat = 11 + int(in.take(7));
        }
        if (k + repeat > nlen + ndist) {
            return Result::fail(Status::Corrupt, "code lengths run past their count");
        }
        while (repeat--) length[k++] = value;
    }
    if (length[256] == 0) {
        return Result::fail(Status::Corrupt, "a block without an end-of-block code");
    }
    // An incomplete code is allowed only when it has a single symbol (RFC 1951, 3.2.7).
    Huffman literal;
    int err = build(literal, length, nlen);
    if (err < 0 || (err > 0 && nlen - literal.count[0] != 1)) {
        return Result::fail(Status::Corrupt, "an over-subscribed or incomplete literal/length code");
    }
    err = build(distance, length + nlen, ndist);
    if (err < 0 || (err > 0 && ndist - distance.count[0] != 1)) {
        return Result::fail(Status::Corrupt, "an over-subscribed or incomplete distance code");
    }
    return codes(in, out, literal, distance);
}

} // namespace

Result inflate(std::span<const uint8_t> in, std::span<uint8_t> out, uint32_t& written) {
    Bits bits{in.data(), in.data() + in.size()};
    Output o{out.data(), uint32_t(out.size())};
    written = 0;
    bool last = false;
    while (!last) {
        last = bits.take(1) != 0;
        const uint32_t type = bits.take(2);
        if (bits.truncated) {
            return Result::fail(Status::Corrupt, "the DEFLATE stream ends early");
        }
        Result st;
        switch (type) {
        case 0: st = stored(bits, o); break;
        case 1: st = fixed(bits, o); break;
        case 2: st = dynamic(bits, o); break;
        default: return Result::fail(Status::Corrupt, "an invalid block type");
        }
        if (!st.ok()) {
            written = st.status == Status::Full ? o.at : 0; // (the stream's start, up to where it no longer fit)
            return st;
        }
    }
    if (bits.more()) {
        // The last block ended inside the stream: what follows is not DEFLATE (appended bytes).
        return Result::fail(Status::Corrupt, "bytes follow the DEFLATE stream's last block");
    }
    written = o.at;
    return {};
}

} // namespace facet::geom
