// Topology helpers of Cdt: every change of the triangle array goes through these, and each
// moves a triangle's vertices, neighbours and flags together so they cannot drift apart.
#include "cdt/cdt.h"
#include "cdt/predicates.h"

#include <algorithm>

namespace facet::cdt {

template <typename Index>
int64_t Cdt<Index>::orient(Index a, Index b, Point c) const {
    const Point& pa = P(a);
    const Point& pb = P(b);
    return orient2d(pa.x, pa.y, pb.x, pb.y, c.x, c.y);
}

template <typename Index>
void Cdt<Index>::rotate(Index t, int k) {
    if (k == 0) return;
    Triangle<Index>& T = a_.triangles[t];
    const Triangle<Index> o = copy_of(T);
    for (int i = 0; i < 3; ++i) {
        const int s = (i + k) % 3;
        T.v[i] = o.v[s];
        T.n[i] = o.n[s];
        T.set_flag(i, o.flag(s));
        T.set_back(i, o.back_edge(s));
        if (T.n[i] != kNone<Index>) a_.triangles[T.n[i]].set_back(T.back_edge(i), i);
    }
}

template <typename Index>
void Cdt<Index>::link(Index t, int i, Index u, int j) {
    Triangle<Index>& T = a_.triangles[t];
    T.n[i] = u;
    T.set_back(i, j);
    if (u != kNone<Index>) {
        Triangle<Index>& U = a_.triangles[u];
        U.n[j] = t;
        U.set_back(j, i);
    }
}

template <typename Index>
Index Cdt<Index>::new_triangle(Index v0, Index v1, Index v2) {
    FACET_ASSERT("cdt", nt_ < a_.triangles.size()); // 2V-6 bound: callers checked vertices
    const Index t = nt_++;
    a_.triangles[t] = {{v0, v1, v2}, {kNone<Index>, kNone<Index>, kNone<Index>}, 0, 0};
    return t;
}

template <typename Index>
void Cdt<Index>::set_vertex_tri(Index t) {
    const Triangle<Index>& T = a_.triangles[t];
    for (int i = 0; i < 3; ++i) a_.vertices[T.v[i]].tri = t;
}

// Flips edge 0 of t = (p, a, b), shared with neighbour u (its edge j, opposite q):
//
//        b                     b
//       / \                   /|\ .
//      / t \                 / | \ .
//     p-----q     ==>       p t|u q      t' = (p, a, q), u' = (p, q, b)
//      \ u /                 \ | /
//       \ /                   \|/
//        a                     a
// p stays vertex 0 of both (Lawson's stack relies on it). The outer four edges keep their
// neighbours and flags; the new edge p-q is unconstrained. t keeps its edge 2 (p-a) as it is,
// and u's edge 1 (b-p) is t's old edge 1, so of the four outer neighbours only a-q and q-b
// change their back-edge index and only a-q and b-p their neighbour.
template <typename Index>
[[gnu::always_inline]] inline void Cdt<Index>::flip(Index t) {
    Triangle<Index>* const tri = a_.triangles.data();
    Triangle<Index>& T = tri[t];
    const Index u = T.n[0];
    Triangle<Index>& U = tri[u];
    const int j = T.back_edge(0), j1 = next3(j), j2 = prev3(j);
    const Index p = T.v[0], a = T.v[1], b = T.v[2], q = U.v[j];
    const Index n_bp = T.n[1], n_aq = U.n[j1], n_qb = U.n[j2];
    const unsigned uf = U.flags, ub = U.back, tf = T.flags, tb = T.back;
    const unsigned f_aq = (uf >> (2 * j1)) & 3, f_qb = (uf >> (2 * j2)) & 3;
    const unsigned b_aq = (ub >> (2 * j1)) & 3, b_qb = (ub >> (2 * j2)) & 3;

    // Field by field: aggregate assignment of the 14-byte record costs a memcpy on ARMv5.
    T.v[2] = q;
    T.n[0] = n_aq, T.n[1] = u;
    T.flags = uint8_t(f_aq | (tf & 0x30));
    T.back = uint8_t(b_aq | 2 << 2 | (tb & 0x30));
    U.v[0] = p, U.v[1] = q, U.v[2] = b;
    U.n[0] = n_qb, U.n[1] = n_bp, U.n[2] = t;
    U.flags = uint8_t(f_qb | (tf & 0x0C));
    U.back = uint8_t(b_qb | (tb & 0x0C) | 1 << 4);
    if (n_aq != kNone<Index>) {
        Triangle<Index>& N = tri[n_aq];
        N.n[b_aq] = t;
        N.back = uint8_t(N.back & ~(3u << (2 * b_aq))); // edge 0 of t
    }
    if (n_qb != kNone<Index>) {
        Triangle<Index>& N = tri[n_qb];
        N.back = uint8_t(N.back & ~(3u << (2 * b_qb))); // edge 0 of u
    }
    if (n_bp != kNone<Index>) tri[n_bp].n[(tb >> 2) & 3] = u;
    a_.vertices[a].tri = t;
    a_.vertices[b].tri = u;
    ++stats_.flips;
}

template <typename Index>
Status Cdt<Index>::reset() {
    return reset({-kMaxCoord, -kMaxCoord}, {kMaxCoord, kMaxCoord});
}

template <typename Index>
Status Cdt<Index>::reset(Point lo, Point hi) {
    if (lo.x > hi.x || lo.y > hi.y || lo.x < -kMaxCoord || lo.y < -kMaxCoord ||
        hi.x > kMaxCoord || hi.y > kMaxCoord) {
        return Status::OutOfRange;
    }
    if (a_.vertices.size() < 8 || a_.triangles.size() < triangles_for(a_.vertices.size()) ||
        a_.work.size() < work_for(a_.vertices.size()) ||
        triangles_for(a_.vertices.size()) >= size_t(kNone<Index>) - 1) {
        return Status::OutOfRange;
    }
    // Corners one extent (at least 16 units) beyond the bounds: inside +-kBoxCoord, since
    // the bounds are inside +-kMaxCoord and the extent is at most 2 * kMaxCoord... halved.
    const int32_t extent = std::max(hi.x - lo.x, hi.y - lo.y);
    const int32_t m = extent / 2 + 16;
    box_lo_ = {lo.x - m, lo.y - m};
    box_hi_ = {hi.x + m, hi.y + m};
    const Point corners[4] = {box_lo_, {box_hi_.x, box_lo_.y}, box_hi_, {box_lo_.x, box_hi_.y}};
    for (Index i = 0; i < 4; ++i) a_.vertices[i] = {corners[i], kNone<Index>};
    nv_ = 4;
    nt_ = 0;
    const Index t0 = new_triangle(0, 1, 2), t1 = new_triangle(0, 2, 3);
    link(t0, 1, t1, 2); // edge (2, 0)
    set_vertex_tri(t0);
    set_vertex_tri(t1);
    a_.vertices[0].tri = t0;
    last_ = kNone<Index>;
    stats_ = {};
    return Status::Ok;
}

} // namespace facet::cdt
