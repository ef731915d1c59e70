#include "cdt/predicates.h"

namespace facet::cdt {
namespace {

// Unsigned 64 x 64 -> 128 from four 32 x 32 -> 64 products (what a 32-bit core has).
void mul_u64(uint64_t a, uint64_t b, uint64_t& lo, uint64_t& hi) {
    const uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    const uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    lo = (p00 & 0xFFFFFFFFu) | (mid << 32);
    hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

uint64_t magnitude(int64_t v) { return v < 0 ? ~static_cast<uint64_t>(v) + 1 : uint64_t(v); }

// Bit length: 0 for 0, else floor(log2 v) + 1 (two 32-bit CLZs: cheap on ARMv5TE and later).
int bits(uint64_t v) {
    const uint32_t hi = uint32_t(v >> 32), lo = uint32_t(v);
    return hi ? 64 - __builtin_clz(hi) : (lo ? 32 - __builtin_clz(lo) : 0);
}

} // namespace

Int128 Int128::mul(int64_t a, int64_t b) {
#if defined(__SIZEOF_INT128__)
    // 64-bit hosts multiply 64 x 64 -> 128 in one instruction. The 32-bit targets have no
    // __int128 and use mul_portable, which the host tests check against GMP as well.
    const __int128 p = static_cast<__int128>(a) * b;
    return {static_cast<uint64_t>(p), static_cast<int64_t>(p >> 64)};
#else
    return mul_portable(a, b);
#endif
}

Int128 Int128::mul_portable(int64_t a, int64_t b) {
    uint64_t lo, hi;
    mul_u64(magnitude(a), magnitude(b), lo, hi);
    Int128 r{lo, static_cast<int64_t>(hi)};
    if ((a < 0) != (b < 0)) { // two's-complement negate
        r.lo = ~lo + 1;
        r.hi = static_cast<int64_t>(~hi + (r.lo == 0 ? 1 : 0));
    }
    return r;
}

Int128 Int128::operator+(const Int128& o) const {
    const uint64_t l = lo + o.lo;
    return {l, static_cast<int64_t>(uint64_t(hi) + uint64_t(o.hi) + (l < lo ? 1 : 0))};
}

Int128 Int128::operator-(const Int128& o) const {
    const uint64_t l = lo - o.lo;
    return {l, static_cast<int64_t>(uint64_t(hi) - uint64_t(o.hi) - (lo < o.lo ? 1 : 0))};
}

namespace {

// The lifted terms (squared distances to d) and 2x2 minors of the incircle determinant:
// exact in int64 over the whole range (< 2^54). det = alift*bc + blift*ca + clift*ab.
struct IncircleTerms {
    int64_t alift, blift, clift, bc, ca, ab;

    IncircleTerms(int64_t adx, int64_t ady, int64_t bdx, int64_t bdy, int64_t cdx, int64_t cdy)
        : alift(adx * adx + ady * ady), blift(bdx * bdx + bdy * bdy), clift(cdx * cdx + cdy * cdy)
        , bc(bdx * cdy - cdx * bdy), ca(cdx * ady - adx * cdy), ab(adx * bdy - bdx * ady) {}

    int exact_sign() const {
        return (Int128::mul(alift, bc) + Int128::mul(blift, ca) + Int128::mul(clift, ab)).sign();
    }
};

} // namespace

int incircle_exact(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy,
                   int32_t dx, int32_t dy) {
    return IncircleTerms(int64_t(ax) - dx, int64_t(ay) - dy, int64_t(bx) - dx, int64_t(by) - dy,
                         int64_t(cx) - dx, int64_t(cy) - dy)
        .exact_sign();
}

namespace {

// Tier 3 when every difference is under 2^19 in magnitude (neighbours of a dense input on a
// wide grid, and a face's points against the CDT box's corners: the commonest cases past tier
// 1): the lifts and minors are then under 2^39, each a sum of two 32 x 32 -> 64 products, and
// each lift is split at bit 20 into two parts that fit 32 bits, so that no product is wider
// than 32 x 64 bits and no bit lengths are needed. The sign as incircle's.
int incircle_near(int32_t sx, int32_t sy, int32_t tx, int32_t ty, int32_t ux, int32_t uy) {
    const int64_t alift = int64_t(sx) * sx + int64_t(sy) * sy, blift = int64_t(tx) * tx + int64_t(ty) * ty,
                  clift = int64_t(ux) * ux + int64_t(uy) * uy;
    const int64_t bc = int64_t(tx) * uy - int64_t(ux) * ty, ca = int64_t(ux) * sy - int64_t(sx) * uy,
                  ab = int64_t(sx) * ty - int64_t(tx) * sy;
    // lift = h 2^20 + l (h < 2^19, l < 2^20): det = A 2^20 + B, |A| < 3 2^58, |B| < 3 2^59, and with
    // B = q 2^20 + r (0 <= r < 2^20) the sign of det is that of A + q, or of r when A + q is 0.
    constexpr int64_t kLow = (int64_t(1) << 20) - 1;
    const int64_t A = int64_t(int32_t(alift >> 20)) * bc + int64_t(int32_t(blift >> 20)) * ca + int64_t(int32_t(clift >> 20)) * ab;
    const int64_t B = int64_t(int32_t(alift & kLow)) * bc + int64_t(int32_t(blift & kLow)) * ca + int64_t(int32_t(clift & kLow)) * ab;
    const int64_t hi = A + (B >> 20); // arithmetic shift: floor division
    if (hi != 0) return hi > 0 ? 1 : -1;
    return (B & kLow) != 0 ? 1 : 0;
}

} // namespace

int incircle_wide(int32_t sx, int32_t sy, int32_t tx, int32_t ty, int32_t ux, int32_t uy) {
    constexpr uint32_t kNear = 1u << 19;
    if (((uint32_t(sx) + kNear) | (uint32_t(sy) + kNear) | (uint32_t(tx) + kNear) | (uint32_t(ty) + kNear) |
         (uint32_t(ux) + kNear) | (uint32_t(uy) + kNear)) < 2 * kNear) {
        return incircle_near(sx, sy, tx, ty, ux, uy);
    }
    // Tiers 2 to 4 (tier 1 is incircle's own, inline). The lifted terms (squared distances to
    // d) and the 2x2 minors are exact in int64 over the whole range (< 2^54); what varies is
    // how their products are summed.
    const IncircleTerms t(sx, sy, tx, ty, ux, uy);
    const int64_t alift = t.alift, blift = t.blift, clift = t.clift, bc = t.bc, ca = t.ca, ab = t.ab;
    const int la = bits(uint64_t(alift)), lb = bits(uint64_t(blift)), lc = bits(uint64_t(clift));
    const int ma = bits(magnitude(bc)), mb = bits(magnitude(ca)), mc = bits(magnitude(ab));
    if (la + ma <= 61 && lb + mb <= 61 && lc + mc <= 61) {
        // 2. Each product below 2^61, so their sum below 2^63.
        const int64_t det = alift * bc + blift * ca + clift * ab;
        return det > 0 ? 1 : (det < 0 ? -1 : 0);
    }
    if (la <= 40 && lb <= 40 && lc <= 40 && ma <= 40 && mb <= 40 && mc <= 40) {
        // 3. Split each lift as h * 2^20 + l (h, l < 2^20): every partial product is below 2^60,
        //    det = A * 2^20 + B with |A|, |B| < 3 * 2^60, and with B = q * 2^20 + r (0 <= r < 2^20)
        //    the sign of det is the sign of A + q, or of r when A + q is 0.
        constexpr int64_t kLow = (int64_t(1) << 20) - 1;
        const int64_t A = (alift >> 20) * bc + (blift >> 20) * ca + (clift >> 20) * ab;
        const int64_t B = (alift & kLow) * bc + (blift & kLow) * ca + (clift & kLow) * ab;
        const int64_t hi = A + (B >> 20); // arithmetic shift: floor division
        if (hi != 0) return hi > 0 ? 1 : -1;
        return (B & kLow) != 0 ? 1 : 0;
    }
    return t.exact_sign(); // 4. The full range: exact 128-bit sums.
}

} // namespace facet::cdt
