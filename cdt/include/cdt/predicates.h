#pragma once
// Exact geometric predicates on the integer grid. No floating point, no __int128.
//
// Range: every coordinate |x|, |y| <= kPredicateRange (2^25), so differences fit 27 bits.
//   orient2d: products of differences <= 2^52, the determinant <= 2^53: exact in int64.
//   incircle: lifted terms <= 2^53 times 2x2 minors <= 2^53, three of them: < 2^108.
//             Four exact tiers: differences < 2^14 (32-bit terms); every lift * minor under
//             2^61 (int64); lifts and minors under 2^40 (split products, int64); otherwise two
//             limbs (128-bit) from 32x32 products on 32-bit cores, the native multiply on
//             64-bit hosts.
// The CDT keeps its input within kMaxCoord = 2^24 and puts its box corners at 2^25.
#include <cstdint>

namespace facet::cdt {

constexpr int32_t kPredicateRange = 1 << 25;

// > 0 if a, b, c turn counter-clockwise (c left of a->b), < 0 clockwise, 0 collinear.
int64_t orient2d(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy);

// > 0 if d is strictly inside the circle through a, b, c (a, b, c counter-clockwise),
// < 0 outside, 0 on it. Returns the sign only (-1, 0, 1).
int incircle(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy, int32_t dx,
             int32_t dy);

// A signed 128-bit integer in two limbs: just what incircle needs. Exposed for tests.
struct Int128 {
    uint64_t lo;
    int64_t hi;

    static Int128 mul(int64_t a, int64_t b);          // exact product
    static Int128 mul_portable(int64_t a, int64_t b); // the same from 32 x 32 -> 64 products
    Int128 operator+(const Int128& o) const;
    Int128 operator-(const Int128& o) const;
    int sign() const { return hi < 0 ? -1 : ((hi | static_cast<int64_t>(lo)) ? 1 : 0); }
    bool operator==(const Int128& o) const { return lo == o.lo && hi == o.hi; }
};

// The same incircle determinant, always through the exact 128-bit path (for tests/benches).
int incircle_exact(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy,
                   int32_t dx, int32_t dy);

} // namespace facet::cdt
