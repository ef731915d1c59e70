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
    const Triangle<Index> o = T;
    for (int i = 0; i < 3; ++i) {
        const int s = (i + k) % 3;
        T.v[i] = o.v[s];
        T.n[i] = o.n[s];
        T.set_flag(i, o.flag(s));
    }
}

template <typename Index>
void Cdt<Index>::link(Index t, int i, Index u, int j) {
    a_.triangles[t].n[i] = u;
    if (u != kNone<Index>) a_.triangles[u].n[j] = t;
}

template <typename Index>
Index Cdt<Index>::new_triangle(Index v0, Index v1, Index v2) {
    FACET_ASSERT("cdt", nt_ < a_.triangles.size()); // 2V-6 bound: callers checked vertices
    const Index t = nt_++;
    a_.triangles[t] = {{v0, v1, v2}, {kNone<Index>, kNone<Index>, kNone<Index>}, 0};
    return t;
}

template <typename Index>
void Cdt<Index>::set_vertex_tri(Index t) {
    const Triangle<Index>& T = a_.triangles[t];
    for (int i = 0; i < 3; ++i) a_.vertices[T.v[i]].tri = t;
}

// Flips the edge opposite v[i] of t, shared with neighbour u:
//
//        b                     b
//       / \                   /|\ .
//      / t \                 / | \ .
//     p-----q     ==>       p t|u q      t' = (p, a, q), u' = (q, b, p)
//      \ u /                 \ | /
//       \ /                   \|/
//        a                     a
// (t = (p, a, b) with p = t.v[i], u = (q, b, a) read from its shared edge.) The outer four
// edges keep their neighbours and flags; the new edge p-q is unconstrained.
template <typename Index>
void Cdt<Index>::flip(Index t, int i) {
    Triangle<Index>& T = a_.triangles[t];
    const Index u = T.n[i];
    Triangle<Index>& U = a_.triangles[u];
    const int j = U.edge_to(t);
    const int i1 = next3(i), i2 = prev3(i), j1 = next3(j), j2 = prev3(j);
    const Index p = T.v[i], a = T.v[i1], b = T.v[i2], q = U.v[j];
    const Index n_bp = T.n[i1], n_pa = T.n[i2], n_aq = U.n[j1], n_qb = U.n[j2];
    const Flag f_bp = T.flag(i1), f_pa = T.flag(i2), f_aq = U.flag(j1), f_qb = U.flag(j2);

    // Field by field: aggregate assignment of the 14-byte record costs a memcpy on ARMv5.
    T.v[0] = p, T.v[1] = a, T.v[2] = q;
    T.n[0] = n_aq, T.n[1] = u, T.n[2] = n_pa;
    T.flags = uint8_t(uint8_t(f_aq) | uint8_t(f_pa) << 4);
    U.v[0] = q, U.v[1] = b, U.v[2] = p;
    U.n[0] = n_bp, U.n[1] = t, U.n[2] = n_qb;
    U.flags = uint8_t(uint8_t(f_bp) | uint8_t(f_qb) << 4);
    if (n_aq != kNone<Index>) {
        Triangle<Index>& N = a_.triangles[n_aq];
        N.n[N.edge_to(u)] = t;
    }
    if (n_bp != kNone<Index>) {
        Triangle<Index>& N = a_.triangles[n_bp];
        N.n[N.edge_to(t)] = u;
    }
    a_.vertices[p].tri = t;
    a_.vertices[a].tri = t;
    a_.vertices[q].tri = u;
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
