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
uint32_t abs32(int32_t v) { return v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v); }

} // namespace

Int128 Int128::mul(int64_t a, int64_t b) {
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

int64_t orient2d(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy) {
    return int64_t(bx - ax) * (cy - ay) - int64_t(by - ay) * (cx - ax);
}

int incircle_exact(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy,
                   int32_t dx, int32_t dy) {
    const int64_t adx = int64_t(ax) - dx, ady = int64_t(ay) - dy;
    const int64_t bdx = int64_t(bx) - dx, bdy = int64_t(by) - dy;
    const int64_t cdx = int64_t(cx) - dx, cdy = int64_t(cy) - dy;
    const int64_t alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy;
    const int64_t clift = cdx * cdx + cdy * cdy;
    const int64_t bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy;
    const int64_t ab = adx * bdy - bdx * ady;
    const Int128 det = Int128::mul(alift, bc) + Int128::mul(blift, ca) + Int128::mul(clift, ab);
    return det.sign();
}

int incircle(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy, int32_t dx,
             int32_t dy) {
    const int32_t adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy;
    const int32_t cdx = cx - dx, cdy = cy - dy;
    constexpr uint32_t kFast = 28000; // 12 * 28000^4 < 2^63
    if ((abs32(adx) | abs32(ady) | abs32(bdx) | abs32(bdy) | abs32(cdx) | abs32(cdy)) < 16384 ||
        (abs32(adx) <= kFast && abs32(ady) <= kFast && abs32(bdx) <= kFast &&
         abs32(bdy) <= kFast && abs32(cdx) <= kFast && abs32(cdy) <= kFast)) {
        const int64_t alift = int64_t(adx) * adx + int64_t(ady) * ady;
        const int64_t blift = int64_t(bdx) * bdx + int64_t(bdy) * bdy;
        const int64_t clift = int64_t(cdx) * cdx + int64_t(cdy) * cdy;
        const int64_t det = alift * (int64_t(bdx) * cdy - int64_t(cdx) * bdy) +
                            blift * (int64_t(cdx) * ady - int64_t(adx) * cdy) +
                            clift * (int64_t(adx) * bdy - int64_t(bdx) * ady);
        return det > 0 ? 1 : (det < 0 ? -1 : 0);
    }
    return incircle_exact(ax, ay, bx, by, cx, cy, dx, dy);
}

} // namespace facet::cdt
