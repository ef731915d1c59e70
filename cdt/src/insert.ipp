// Point insertion (§3.2, Update): split the triangle (or the edge) that holds the point, then
// restore the empty-circle property with Lawson flips that never flip a constraint.
#include "cdt/cdt.h"
#include "cdt/predicates.h"

namespace facet::cdt {

// t = (a, b, c) and new vertex v inside it become (v, a, b), (v, b, c) [reusing t], (v, c, a).
template <typename Index>
Status Cdt<Index>::split_triangle(Index t, Index v) {
    const Triangle<Index> o = copy_of(a_.triangles[t]);
    const Index a = o.v[0], b = o.v[1], c = o.v[2];
    const Index t1 = new_triangle(v, a, b), t3 = new_triangle(v, c, a);
    Triangle<Index>& T2 = a_.triangles[t];
    T2 = {{v, b, c}, {o.n[0], kNone<Index>, kNone<Index>}, 0, uint8_t(o.back & 3)};
    T2.set_flag(0, o.flag(0));
    link(t1, 0, o.n[2], o.back_edge(2));
    a_.triangles[t1].set_flag(0, o.flag(2));
    link(t3, 0, o.n[1], o.back_edge(1));
    a_.triangles[t3].set_flag(0, o.flag(1));
    link(t1, 1, t, 2);  // (b, v)
    link(t, 1, t3, 2);  // (c, v)
    link(t3, 1, t1, 2); // (a, v)
    a_.vertices[v].tri = t1;
    a_.vertices[a].tri = t1;
    a_.vertices[b].tri = t;
    a_.vertices[c].tri = t;
    return Status::Ok;
}

// v on edge i of t, shared with u. With t = (a, b, c) (edge 0 = b-c) and u = (d, c, b):
// (v, c, a) [t], (v, a, b), (v, b, d) [u], (v, d, c). A constraint on b-c is split in two,
// both halves keeping its flags.
template <typename Index>
Status Cdt<Index>::split_edge(Index t, int i, Index v) {
    rotate(t, i);
    const Index u = a_.triangles[t].n[0];
    FACET_ASSERT("cdt.split_edge", u != kNone<Index>);
    rotate(u, a_.triangles[t].back_edge(0));
    const Triangle<Index> ot = copy_of(a_.triangles[t]), ou = copy_of(a_.triangles[u]);
    const Index a = ot.v[0], b = ot.v[1], c = ot.v[2], d = ou.v[0];
    const Flag ft = ot.flag(0), fu = ou.flag(0);
    const Index t2 = new_triangle(v, a, b), u2 = new_triangle(v, d, c);

    Triangle<Index>& T1 = a_.triangles[t];
    T1 = {{v, c, a}, {kNone<Index>, kNone<Index>, kNone<Index>}, 0, 0};
    link(t, 0, ot.n[1], ot.back_edge(1));
    T1.set_flag(0, ot.flag(1));
    Triangle<Index>& U1 = a_.triangles[u];
    U1 = {{v, b, d}, {kNone<Index>, kNone<Index>, kNone<Index>}, 0, 0};
    link(u, 0, ou.n[1], ou.back_edge(1));
    U1.set_flag(0, ou.flag(1));
    link(t2, 0, ot.n[2], ot.back_edge(2));
    a_.triangles[t2].set_flag(0, ot.flag(2));
    link(u2, 0, ou.n[2], ou.back_edge(2));
    a_.triangles[u2].set_flag(0, ou.flag(2));

    link(t, 1, t2, 2);  // (a, v)
    link(t2, 1, u, 2);  // (b, v) - half of the split edge
    link(u, 1, u2, 2);  // (d, v)
    link(u2, 1, t, 2);  // (c, v) - the other half
    a_.triangles[t2].set_flag(1, ft);
    a_.triangles[t].set_flag(2, ft);
    a_.triangles[u].set_flag(2, fu);
    a_.triangles[u2].set_flag(1, fu);
    a_.vertices[v].tri = t;
    a_.vertices[a].tri = t;
    a_.vertices[c].tri = t;
    a_.vertices[b].tri = t2;
    a_.vertices[d].tri = u;
    return Status::Ok;
}

// Lawson: every triangle on the stack has v as its vertex 0 (the splits make it so and flip()
// keeps it); test edge 0, the edge opposite v. The stack holds at most twice v's degree.
template <typename Index>
Status Cdt<Index>::legalize(Index v, uint32_t top) {
    Index* const stack = a_.work.data();
    const uint32_t capacity = uint32_t(a_.work.size());
    const Triangle<Index>* const tri = a_.triangles.data();
    const Vertex<Index>* const V = a_.vertices.data();
    const int32_t vx = V[v].p.x, vy = V[v].p.y;
    uint32_t peak = top;
    while (top > 0) {
        const Index t = stack[--top];
        const Triangle<Index>& T = tri[t];
        const Index u = T.n[0];
        if (T.constrained(0) || u == kNone<Index>) continue; // a constraint, or the box
        const Point& a = V[T.v[1]].p;
        const Point& b = V[T.v[2]].p;
        const Point& q = V[tri[u].v[T.back_edge(0)]].p;
        if (incircle(vx, vy, a.x, a.y, b.x, b.y, q.x, q.y) <= 0) continue;
        flip(t);
        if (top + 2 > capacity) return Status::Full; // cannot happen: see work_for()
        stack[top++] = t;
        stack[top++] = u;
        if (top > peak) peak = top;
    }
    if (peak > stats_.work_peak) stats_.work_peak = peak;
    return Status::Ok;
}

template <typename Index>
Status Cdt<Index>::insert_point(Point p, Index& out, Index hint) {
    if (nt_ == 0) return Status::OutOfRange; // reset() not called
    if (p.x < -kMaxCoord || p.x > kMaxCoord || p.y < -kMaxCoord || p.y > kMaxCoord ||
        p.x <= box_lo_.x || p.x >= box_hi_.x || p.y <= box_lo_.y || p.y >= box_hi_.y) {
        return Status::OutOfRange;
    }
    Location<Index> loc;
    if (Status s = walk(start_vertex(p, hint), p, loc); !ok(s)) return s;
    using Kind = typename Location<Index>::Kind;
    if (loc.kind == Kind::OnVertex) {
        out = loc.vertex;
        last_ = out;
        return Status::Ok;
    }
    if (nv_ >= a_.vertices.size()) return Status::Full;
    const Index v = nv_++;
    a_.vertices[v] = {p, kNone<Index>};
    uint32_t top = 0;
    Index* stack = a_.work.data();
    if (loc.kind == Kind::Inside) {
        const Index t = loc.tri;
        (void)split_triangle(t, v);
        stack[top++] = t;
        stack[top++] = nt_ - 1;
        stack[top++] = nt_ - 2;
    } else {
        const Index t = loc.tri, u = a_.triangles[t].n[loc.edge];
        (void)split_edge(t, loc.edge, v);
        stack[top++] = t;
        stack[top++] = u;
        stack[top++] = nt_ - 1;
        stack[top++] = nt_ - 2;
    }
    out = v;
    last_ = v;
    return legalize(v, top);
}

} // namespace facet::cdt
