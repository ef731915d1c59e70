// Constraint insertion (§3.2 after Anglada 1997): if a-b is not an edge, remove the triangles
// the segment crosses and re-triangulate the two pseudo-polygons on either side of it, each
// by recursively choosing the vertex whose circle through the base holds no other vertex.
//
// A cavity need not be simple: the segment can cross every triangle around a vertex without
// passing through it (two near-180-degree slivers make this possible even in a CDT). That
// vertex then appears in a chain between two copies of one neighbour (x, v, x), and the edge
// v-x lies inside the cavity, a slit. Its two records are linked to each other, not outside.
//
// Two phases keep the triangulation valid on failure: a read-only trace of the whole segment
// (split at vertices lying on it) checks for crossed constraints and sizes the largest cavity;
// only then is anything changed.
#include "cdt/cdt.h"
#include "cdt/predicates.h"

namespace facet::cdt {
namespace {

Flag merge(Flag old, Flag add) {
    if (old == Flag::None || old == add) return add == Flag::None ? old : add;
    return old == Flag::Both ? Flag::Both : (add == reverse(old) ? Flag::Both : old);
}


} // namespace

// Follows the segment a->b from a, through the triangles it crosses, to b or to the first
// vertex lying exactly on it (`reached`). The visitor sees:
//   edge(t, e)         a->reached is already edge e of t, t on its left
//   first(t, k)        t = (a, x, y), a = v[k]: the segment leaves t through edge k
//   step(u, j, side)   entered u across its edge j; u.v[j] is left (+1) or right (-1) of the
//                      segment, or the end of this piece (0)
// Returns Crossing, before calling anything else, if a crossed edge is a constraint.
template <typename Index>
template <typename Visitor>
Status Cdt<Index>::trace(Index a, Index b, Index& reached, Visitor& visit) {
    const Point pa = P(a), pb = P(b);
    Index t;
    int k;
    int64_t oa;
    wedge(a, pb, t, k, oa);
    const Triangle<Index>& T = a_.triangles[t];
    if (oa == 0) { // the segment runs along edge a-x
        const Index x = T.v[next3(k)];
        FACET_ASSERT("cdt.trace", dot2d(pa, P(x), pb) <= dot2d(pa, pb, pb)); // x is not past b
        reached = x;
        visit.edge(t, prev3(k));
        return Status::Ok;
    }
    if (T.constrained(k)) return Status::Crossing;
    // Check the whole path before the visitor sees any of it.
    Index u = T.n[k];
    int j = T.back_edge(k);
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            visit.first(t, k);
            u = T.n[k];
            j = T.back_edge(k);
        }
        for (;;) {
            FACET_ASSERT("cdt.trace", u != kNone<Index>);
            const Triangle<Index>& U = a_.triangles[u];
            const Index w = U.v[j];
            const int64_t ow = orient2d(pa.x, pa.y, pb.x, pb.y, P(w).x, P(w).y);
            if (ow == 0) {
                if (pass == 1) visit.step(u, j, 0);
                reached = w;
                break;
            }
            const int exit = ow > 0 ? next3(j) : prev3(j);
            if (pass == 0 && U.constrained(exit)) return Status::Crossing;
            if (pass == 1) visit.step(u, j, ow > 0 ? 1 : -1);
            u = U.n[exit];
            j = U.back_edge(exit);
        }
    }
    return Status::Ok;
}

namespace {

// Counts the triangles a piece crosses (phase 1).
template <typename Index>
struct CountCrossed {
    uint32_t crossed = 0;
    void edge(Index, int) {}
    void first(Index, int) { ++crossed; }
    void step(Index, int, int) { ++crossed; }
};

} // namespace

// Flags an existing edge, or collects and re-triangulates the cavity of one piece (phase 2).
template <typename Index>
void Cdt<Index>::apply_piece(Index a, Index b, uint32_t K, Index& reached) {
    // The cavity's parts in the work buffer (CavityLayout: checked in phase 1).
    static_assert(sizeof(Index) != 2 || (CavityLayout::of(1).entries == 13 + 18 && sizeof(CavityEdge) == 3 * sizeof(Index)),
                  "the device's cavity: 13 K + 18 entries, an edge record in three");
    Index* const w = a_.work.data();
    const CavityLayout at = CavityLayout::of(K);
    struct Collect {
        Cdt& c;
        Index* slots;
        Index* lpoly;
        CavityEdge* ledge;
        Index* rpoly;
        CavityEdge* redge;
        uint32_t ns = 0, nl = 0, nr = 0;
        bool existing = false;

        void record(CavityEdge& out, Index t, int e) {
            const Triangle<Index>& T = c.a_.triangles[t];
            out.outside = T.n[e];
            out.outside_edge = uint8_t(T.back_edge(e));
            out.flag = T.flag(e);
            out.slit = out.slit_built = false;
        }
        void edge(Index t, int e) {
            existing = true;
            Triangle<Index>& T = c.a_.triangles[t];
            T.set_flag(e, merge(T.flag(e), Flag::Along));
            const Index u = T.n[e];
            FACET_ASSERT("cdt.constraint", u != kNone<Index>);
            Triangle<Index>& U = c.a_.triangles[u];
            const int j = T.back_edge(e);
            U.set_flag(j, merge(U.flag(j), Flag::Against));
        }
        void first(Index t, int k) {
            const Triangle<Index>& T = c.a_.triangles[t];
            slots[ns++] = t;
            lpoly[++nl] = T.v[prev3(k)];
            record(ledge[0], t, next3(k)); // (a, y)
            rpoly[++nr] = T.v[next3(k)];
            record(redge[0], t, prev3(k)); // (a, x)
        }
        void step(Index u, int j, int side) {
            const Triangle<Index>& U = c.a_.triangles[u];
            slots[ns++] = u;
            if (side >= 0) { // left boundary edge (v[j+1], w) is edge j+2
                record(ledge[nl], u, prev3(j));
                if (side > 0) lpoly[++nl] = U.v[j];
            }
            if (side <= 0) { // right boundary edge (v[j+2], w) is edge j+1
                record(redge[nr], u, next3(j));
                if (side < 0) rpoly[++nr] = U.v[j];
            }
        }
    } col{*this,
          w + at.slots,
          w + at.left_poly,
          reinterpret_cast<CavityEdge*>(w + at.left_edges),
          w + at.right_poly,
          reinterpret_cast<CavityEdge*>(w + at.right_edges)};
    Index* const stack = w + at.stack;

    (void)trace(a, b, reached, col);
    if (col.existing) return;

    // Records whose "outside" is a crossed triangle are slit edges inside the cavity.
    for (uint32_t i = 0; i < col.ns; ++i) a_.triangles[col.slots[i]].flags |= Triangle<Index>::kMarkBit;
    for (CavityEdge* edges : {col.ledge, col.redge}) {
        const uint32_t n = edges == col.ledge ? col.nl + 1 : col.nr + 1;
        for (uint32_t i = 0; i < n; ++i) {
            CavityEdge& rec = edges[i];
            if (rec.outside != kNone<Index> && (a_.triangles[rec.outside].flags & Triangle<Index>::kMarkBit)) rec.slit = true;
        }
    }

    const Index end = reached;
    col.lpoly[0] = a;
    col.lpoly[++col.nl] = end;
    col.rpoly[0] = a;
    col.rpoly[++col.nr] = end;
    // The right polygon is built from end to a so its chain lies left of its base.
    const uint32_t rn = col.nr + 1;
    for (uint32_t i = 0, j = rn - 1; i < j; ++i, --j) {
        const Index t = col.rpoly[i];
        col.rpoly[i] = col.rpoly[j];
        col.rpoly[j] = t;
    }
    for (uint32_t i = 0, j = rn - 2; i < j; ++i, --j) {
        const CavityEdge t = col.redge[i];
        col.redge[i] = col.redge[j];
        col.redge[j] = t;
    }
    uint32_t cursor = 0;
    const Index tl = build_polygon(col.lpoly, col.ledge, col.nl + 1, stack, col.slots, cursor);
    const Index tr = build_polygon(col.rpoly, col.redge, rn, stack, col.slots, cursor);
    FACET_ASSERT("cdt.constraint", cursor == col.ns);
    link(tl, 2, tr, 2);
    a_.triangles[tl].set_flag(2, Flag::Along);
    a_.triangles[tr].set_flag(2, Flag::Against);
    ++stats_.cavities;
    stats_.cavity_triangles += col.ns;
}

// Gives new triangle t's edge e (poly edge i: poly[i] -> poly[i+1]) its recorded neighbour
// and flag. A slit edge waits for its twin (the same edge, reversed, elsewhere in the chain)
// and is linked to it once both sides exist.
template <typename Index>
void Cdt<Index>::set_boundary(Index t, int e, const Index* poly, CavityEdge* edges, uint32_t count, uint32_t i) {
    CavityEdge& rec = edges[i];
    Triangle<Index>& T = a_.triangles[t];
    T.set_flag(e, rec.flag);
    if (!rec.slit) {
        link(t, e, rec.outside, rec.outside_edge);
        return;
    }
    for (uint32_t k = 0; k + 1 < count; ++k) {
        const CavityEdge& twin = edges[k];
        if (k == i || poly[k] != poly[i + 1] || poly[k + 1] != poly[i] || !twin.slit) continue;
        if (twin.slit_built) {
            link(t, e, twin.outside, twin.outside_edge);
        } else {
            rec.outside = t;
            rec.outside_edge = uint8_t(e);
            rec.slit_built = true;
            T.n[e] = kNone<Index>; // until the twin is built
        }
        return;
    }
    FACET_ASSERT("cdt.constraint", false); // a slit edge always has its twin in the chain
}

// Triangulates poly[0..count-1]: base poly[0] -> poly[count-1], the chain between them on the
// base's left. Reuses slots[cursor...]; returns the triangle on the base (its edge 2).
template <typename Index>
Index Cdt<Index>::build_polygon(const Index* poly, CavityEdge* edges, uint32_t count, Index* stack, const Index* slots,
                                uint32_t& cursor) {
    uint32_t top = 0;
    Index root = kNone<Index>;
    auto push = [&](uint32_t lo, uint32_t hi, Index parent, int pedge) {
        stack[top++] = Index(lo);
        stack[top++] = Index(hi);
        stack[top++] = parent;
        stack[top++] = Index(pedge);
    };
    push(0, count - 1, kNone<Index>, 0);
    while (top) {
        top -= 4;
        const uint32_t lo = stack[top], hi = stack[top + 1];
        const Index parent = stack[top + 2];
        const int pedge = stack[top + 3];
        const Point pu = P(poly[lo]), pv = P(poly[hi]);
        uint32_t c = lo + 1;
        for (uint32_t m = lo + 2; m < hi; ++m) {
            const Point pc = P(poly[c]), pm = P(poly[m]);
            if (incircle(pu.x, pu.y, pv.x, pv.y, pc.x, pc.y, pm.x, pm.y) > 0) c = m;
        }
        const Index t = slots[cursor++];
        a_.triangles[t] = {{poly[lo], poly[hi], poly[c]}, {kNone<Index>, kNone<Index>, kNone<Index>}, 0, 0};
        set_vertex_tri(t);
        if (parent == kNone<Index>) root = t;
        else link(t, 2, parent, pedge);
        if (c - lo == 1) set_boundary(t, 1, poly, edges, count, lo); // (c, u)
        else push(lo, c, t, 1);
        if (hi - c == 1) set_boundary(t, 0, poly, edges, count, c); // (v, c)
        else push(c, hi, t, 0);
    }
    return root;
}

template <typename Index>
Status Cdt<Index>::insert_constraint(Index a, Index b) {
    if (a == b) return Status::Ok;
    if (a < kBoxVertices || b < kBoxVertices || a >= nv_ || b >= nv_) return Status::OutOfRange;
    uint32_t max_crossed = 0;
    for (Index cur = a, reached; cur != b; cur = reached) {
        CountCrossed<Index> count;
        if (Status s = trace(cur, b, reached, count); !ok(s)) return s;
        if (count.crossed > max_crossed) max_crossed = count.crossed;
    }
    if (!work_fits(CavityLayout::of(max_crossed).entries)) return Status::Full;
    for (Index cur = a, reached; cur != b; cur = reached) {
        apply_piece(cur, b, max_crossed, reached);
        stats_.splits += reached != b;
    }
    return Status::Ok;
}

template <typename Index>
Index Cdt<Index>::step_along(Index from, Index to) const {
    if (from == to || from < kBoxVertices || to < kBoxVertices || from >= nv_ || to >= nv_) return kNone<Index>;
    const Point pa = P(from), pb = P(to);
    // Around `from`, counter-clockwise: each triangle's next vertex after it.
    const Index first = a_.vertices[from].tri;
    Index t = first;
    for (uint32_t guard = 0; guard < nt_; ++guard) {
        const Triangle<Index>& T = a_.triangles[t];
        const int k = T.index_of(from);
        if (k < 0) return kNone<Index>;
        const Index x = T.v[next3(k)];
        if (x == to) return x;
        const Point px = P(x);
        if (x >= kBoxVertices && orient2d(pa.x, pa.y, pb.x, pb.y, px.x, px.y) == 0 && dot2d(pa, px, pb) > 0) return x;
        t = T.n[prev3(k)]; // across the edge from-x... the edge opposite v[prev3(k)] joins from and x
        if (t == kNone<Index> || t == first) break;
    }
    return kNone<Index>;
}

} // namespace facet::cdt
