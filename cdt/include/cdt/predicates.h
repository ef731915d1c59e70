#pragma once
// Exact geometric predicates on the integer grid. No floating point, no __int128.
//
// Range: every coordinate |x|, |y| <= kPredicateRange (2^25), so differences fit 27 bits.
//   orient2d: products of differences <= 2^52, the determinant <= 2^53: exact in int64.
//   incircle: lifted terms <= 2^53 times 2x2 minors <= 2^53, three of them: < 2^108.
//             Four exact tiers: differences in [-2^15, 2^15) (32-bit terms, inline); every lift * minor under
//             2^61 (int64); lifts and minors under 2^40 (split products, int64); otherwise two
//             limbs (128-bit) from 32x32 products on 32-bit cores, the native multiply on
//             64-bit hosts.
// The CDT keeps its input within kMaxCoord = 2^24 and puts its box corners at 2^25.
#include <cstdint>

namespace facet::cdt {

constexpr int32_t kPredicateRange = 1 << 25;

// > 0 if a, b, c turn counter-clockwise (c left of a->b), < 0 clockwise, 0 collinear.
inline int64_t orient2d(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy) {
    return int64_t(bx - ax) * (cy - ay) - int64_t(by - ay) * (cx - ax);
}

// incircle beyond its first tier, from the differences a - d, b - d, c - d (each below 2^26
// in magnitude); the sign as incircle's.
int incircle_wide(int32_t sx, int32_t sy, int32_t tx, int32_t ty, int32_t ux, int32_t uy);

// > 0 if d is strictly inside the circle through a, b, c (a, b, c counter-clockwise),
// < 0 outside, 0 on it. Returns the sign only (-1, 0, 1).
//
// The first tier is inline: with every difference in [-2^15, 2^15) (a face on the device's
// +-2^14 grid), the lifts are at most 2^31 (uint32), the minors below 2^31 in magnitude (int32)
// and each of the three products below 2^62. The first two then add without overflow; the
// third either has the sign of their sum (no need to add it) or the opposite (the sum cannot
// overflow).
inline int incircle(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy, int32_t dx,
                    int32_t dy) {
    const int32_t sx = ax - dx, sy = ay - dy, tx = bx - dx, ty = by - dy, ux = cx - dx, uy = cy - dy;
    constexpr uint32_t kHalf = 1u << 15;
    if (((uint32_t(sx) + kHalf) | (uint32_t(sy) + kHalf) | (uint32_t(tx) + kHalf) | (uint32_t(ty) + kHalf) |
         (uint32_t(ux) + kHalf) | (uint32_t(uy) + kHalf)) >= 2 * kHalf) {
        return incircle_wide(sx, sy, tx, ty, ux, uy);
    }
    const uint32_t alift = uint32_t(sx * sx) + uint32_t(sy * sy), blift = uint32_t(tx * tx) + uint32_t(ty * ty),
                   clift = uint32_t(ux * ux) + uint32_t(uy * uy);
    const int32_t bc = tx * uy - ux * ty, ca = ux * sy - sx * uy, ab = sx * ty - tx * sy;
    const int64_t s = int64_t(alift) * bc + int64_t(blift) * ca, c = int64_t(clift) * ab;
    if ((s ^ c) >= 0) return s < 0 ? -1 : int((s | c) != 0); // one sign (or zeros): no cancellation
    const int64_t det = s + c;
    return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

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
