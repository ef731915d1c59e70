// Locate (§3.2): the straight walk from a vertex toward a point.
//
// From vertex s, turn around s to the triangle whose wedge holds the direction s->p, then
// cross triangles along the segment s->p until the one containing p. If the segment runs
// exactly through a vertex, the walk restarts from that vertex. Every predicate is exact, so
// the walk cannot cycle; each step moves strictly forward along the segment.
#include "cdt/cdt.h"
#include "cdt/predicates.h"

namespace facet::cdt {

template <typename Index>
Index Cdt<Index>::start_vertex(Point, Index hint) const {
    if (hint != kNone<Index> && hint >= kBoxVertices && hint < nv_) return hint;
    return last_;
}

// Turns counter-clockwise around vertex s (not a box corner) to the triangle t = (s, a, b),
// s = t.v[k], whose half-open wedge [s->a, s->b) holds the direction s->p (p != s).
// oa = orient(s, a, p) >= 0; oa == 0 means p lies on the ray s->a.
template <typename Index>
void Cdt<Index>::wedge(Index s, Point p, Index& t, int& k, int64_t& oa) const {
    t = a_.vertices[s].tri;
    k = a_.triangles[t].index_of(s);
    FACET_ASSERT("cdt.wedge", k >= 0);
    oa = orient(s, a_.triangles[t].v[next3(k)], p);
    for (uint32_t turns = 0;; ++turns) {
        FACET_ASSERT("cdt.wedge", turns <= nt_);
        const Triangle<Index>& T = a_.triangles[t];
        const int64_t ob = orient(s, T.v[prev3(k)], p);
        if (oa >= 0 && ob < 0) return;
        // Across edge (s, b), which runs s -> b there: s is the vertex after that edge's own,
        // b the new a, so ob is the new oa.
        const int e = next3(k);
        t = T.n[e];
        FACET_ASSERT("cdt.wedge", t != kNone<Index>);
        k = next3(T.back_edge(e));
        oa = ob;
    }
}

template <typename Index>
Status Cdt<Index>::walk(Index s, Point p, Location<Index>& out) {
    using Kind = typename Location<Index>::Kind;
    if (s == kNone<Index>) {
        // No input vertex yet: test the few triangles there are.
        for (Index t = 0; t < nt_; ++t) {
            const Triangle<Index>& T = a_.triangles[t];
            int64_t o[3];
            for (int i = 0; i < 3; ++i) o[i] = orient(T.v[next3(i)], T.v[prev3(i)], p);
            if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
            for (int i = 0; i < 3; ++i) {
                if (P(T.v[i]) == p) {
                    out = {Kind::OnVertex, t, 0, T.v[i]};
                    return Status::Ok;
                }
            }
            for (int i = 0; i < 3; ++i) {
                if (o[i] == 0) {
                    out = {Kind::OnEdge, t, uint8_t(i), kNone<Index>};
                    return Status::Ok;
                }
            }
            out = {Kind::Inside, t, 0, kNone<Index>};
            return Status::Ok;
        }
        return Status::OutOfRange;
    }

    uint32_t guard = 0;
    const uint32_t limit = 4u * nt_ + 16;
    for (;;) { // one iteration per vertex the segment passes through
        const Point ps = P(s);
        if (ps == p) {
            out = {Kind::OnVertex, a_.vertices[s].tri, 0, s};
            return Status::Ok;
        }
        Index t;
        int k;
        int64_t oa;
        wedge(s, p, t, k, oa);
        const Triangle<Index>& T = a_.triangles[t];
        const Index a = T.v[next3(k)], b = T.v[prev3(k)];
        if (oa == 0) { // p on the ray s->a
            const int64_t d = dot2d(ps, p, P(a)), len = dot2d(ps, P(a), P(a));
            if (d < len) {
                out = {Kind::OnEdge, t, uint8_t(prev3(k)), kNone<Index>};
                return Status::Ok;
            }
            s = a; // p is a, or beyond it
            continue;
        }
        const int64_t o = orient(a, b, p);
        if (o > 0) {
            out = {Kind::Inside, t, 0, kNone<Index>};
            return Status::Ok;
        }
        if (o == 0) {
            out = {Kind::OnEdge, t, uint8_t(k), kNone<Index>};
            return Status::Ok;
        }
        // Cross triangles along s->p. Entering u across its edge j: v[j+1] lies left of the
        // segment, v[j+2] right, both strictly.
        Index u = T.n[k];
        int j = T.back_edge(k);
        bool restarted = false;
        for (;;) {
            FACET_ASSERT("cdt.locate", u != kNone<Index> && ++guard < limit);
            ++stats_.walk_steps;
            const Triangle<Index>& U = a_.triangles[u];
            const Index w = U.v[j];
            const int64_t ow = orient2d(ps.x, ps.y, p.x, p.y, P(w).x, P(w).y);
            int exit;
            if (ow > 0) {
                exit = next3(j); // edge (v[j+2], w)
            } else if (ow < 0) {
                exit = prev3(j); // edge (w, v[j+1])
            } else { // w on the line, ahead
                const int64_t d = dot2d(ps, p, P(w)), len = dot2d(ps, P(w), P(w));
                if (d < len) {
                    out = {Kind::Inside, u, 0, kNone<Index>};
                    return Status::Ok;
                }
                s = w;
                restarted = true;
                break;
            }
            const int64_t oe = orient(U.v[next3(exit)], U.v[prev3(exit)], p);
            if (oe > 0) {
                out = {Kind::Inside, u, 0, kNone<Index>};
                return Status::Ok;
            }
            if (oe == 0) {
                out = {Kind::OnEdge, u, uint8_t(exit), kNone<Index>};
                return Status::Ok;
            }
            u = U.n[exit];
            j = U.back_edge(exit);
        }
        if (!restarted) break;
    }
    return Status::Corrupt; // not reached
}

template <typename Index>
Status Cdt<Index>::locate(Point p, Index from, Location<Index>& out) {
    if (p.x < -kMaxCoord || p.x > kMaxCoord || p.y < -kMaxCoord || p.y > kMaxCoord ||
        p.x <= box_lo_.x || p.x >= box_hi_.x || p.y <= box_lo_.y || p.y >= box_hi_.y) {
        return Status::OutOfRange;
    }
    if (from != kNone<Index> && (from < kBoxVertices || from >= nv_)) return Status::OutOfRange;
    return walk(from, p, out);
}

} // namespace facet::cdt
