// Inner triangle selection (§3.4), by winding numbers: a flood fill from the box (winding
// number 0) over every triangle, crossing a constraint counted by its flag: from the side a loop
// runs along (its inner, left side) to the other the number drops by one, the other way it
// rises by one, and an edge two loops share in opposite directions (flag Both) changes nothing.
// A triangle is inner when its number is 1 or more. (Flooding from the Along flags alone, as the
// paper does, fills both holes when two holes' sides meet on one edge: a wall thinner than the
// grid.)
#include "cdt/cdt.h"

namespace facet::cdt {

template <typename Index>
Status Cdt<Index>::mark_inner() {
    using T = Triangle<Index>;
    // The work buffer: the stack, then each triangle's winding number (offset by kZero).
    if (a_.work.size() < 2 * size_t(nt_)) return Status::Full;
    Index* stack = a_.work.data();
    Index* winding = stack + nt_;
    constexpr Index kZero = Index(Index(1) << (8 * sizeof(Index) - 2));
    uint32_t top = 0;
    for (Index t = 0; t < nt_; ++t) {
        T& tri = a_.triangles[t];
        tri.flags &= T::kEdgeFlagMask;
        if (tri.n[0] == kNone<Index> || tri.n[1] == kNone<Index> || tri.n[2] == kNone<Index>) {
            tri.flags |= T::kMarkBit; // on the box: outside every loop
            winding[t] = kZero;
            stack[top++] = t;
        }
    }
    bool consistent = true;
    uint32_t peak = top;
    while (top) {
        const Index t = stack[--top];
        const T& tri = a_.triangles[t];
        for (int j = 0; j < 3; ++j) {
            const Index u = tri.n[j];
            if (u == kNone<Index>) continue;
            const Flag f = tri.flag(j);
            const Index w = Index(winding[t] - (f == Flag::Along) + (f == Flag::Against));
            T& next = a_.triangles[u];
            if (next.flags & T::kMarkBit) {
                consistent = consistent && winding[u] == w;
            } else {
                next.flags |= T::kMarkBit;
                winding[u] = w;
                stack[top++] = u; // each triangle at most once: top <= nt_
                if (top > peak) peak = top;
            }
        }
    }
    if (nt_ + peak > stats_.work_peak) stats_.work_peak = nt_ + peak;
    bool negative = false;
    for (Index t = 0; t < nt_; ++t) {
        T& tri = a_.triangles[t];
        tri.flags &= T::kEdgeFlagMask;
        if (winding[t] > kZero) tri.flags |= T::kInnerBit;
        negative = negative || winding[t] < kZero;
    }
    if (!consistent || negative) {
        for (Index t = 0; t < nt_; ++t) a_.triangles[t].flags &= T::kEdgeFlagMask;
        return Status::Degenerate;
    }
    return Status::Ok;
}

} // namespace facet::cdt
