// Inner triangle selection (§3.4): flood fill from every triangle that sees a constraint
// running along its loop (flag Along or Both), never crossing a constraint.
#include "cdt/cdt.h"

namespace facet::cdt {

template <typename Index>
Status Cdt<Index>::mark_inner() {
    using T = Triangle<Index>;
    Index* stack = a_.work.data();
    uint32_t top = 0;
    for (Index t = 0; t < nt_; ++t) a_.triangles[t].flags &= T::kEdgeFlagMask;
    for (Index t = 0; t < nt_; ++t) {
        T& tri = a_.triangles[t];
        for (int i = 0; i < 3; ++i) {
            const Flag f = tri.flag(i);
            if ((f == Flag::Along || f == Flag::Both) && !tri.inner()) {
                tri.flags |= T::kInnerBit;
                stack[top++] = t; // each triangle at most once: top <= nt_ <= work size
            }
        }
    }
    if (top > stats_.work_peak) stats_.work_peak = top;
    bool leaked = false;
    while (top) {
        const T& tri = a_.triangles[stack[--top]];
        for (int j = 0; j < 3; ++j) {
            if (tri.constrained(j)) continue;
            const Index u = tri.n[j];
            if (u == kNone<Index>) {
                leaked = true; // reached the box: a loop is open or runs the wrong way
                continue;
            }
            if (!a_.triangles[u].inner()) {
                a_.triangles[u].flags |= T::kInnerBit;
                stack[top++] = u;
            }
        }
    }
    if (leaked) {
        for (Index t = 0; t < nt_; ++t) a_.triangles[t].flags &= T::kEdgeFlagMask;
        return Status::Degenerate;
    }
    return Status::Ok;
}

} // namespace facet::cdt
