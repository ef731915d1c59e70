#include "cdt/check.h"

#include "cdt/predicates.h"
#include "core/format.h"

#include <algorithm>

namespace facet::cdt {
namespace {

// A broken property of the triangulation (Corrupt), or of the checker's own scratch (Full).
constexpr Result fail(const char* what, Place where = {}, Place at = {}) {
    return Result::fail(Status::Corrupt, what, where, at);
}

int64_t orient_pts(Point a, Point b, Point c) { return orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

// Winding number of c (coordinates scaled by 3) about the directed segments (also scaled).
int winding_step(Point a, Point b, int64_t cx, int64_t cy) {
    const int64_t ax = 3 * int64_t(a.x), ay = 3 * int64_t(a.y);
    const int64_t bx = 3 * int64_t(b.x), by = 3 * int64_t(b.y);
    const int64_t o = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (ay <= cy && cy < by && o > 0) return 1;
    if (by <= cy && cy < ay && o < 0) return -1;
    return 0;
}

constexpr uint32_t kSlabs = 1024;

struct Slabs {
    int64_t ymin = INT64_MAX, ymax = INT64_MIN;
    explicit Slabs(std::span<const Segment> cons) {
        for (const Segment& sg : cons) {
            ymin = std::min<int64_t>(ymin, std::min(sg.a.y, sg.b.y));
            ymax = std::max<int64_t>(ymax, std::max(sg.a.y, sg.b.y));
        }
    }
    uint32_t of(int64_t y3) const { // y scaled by 3
        const int64_t span = ymax >= ymin ? (ymax - ymin + 1) : 1;
        const int64_t s = ((y3 - 3 * ymin) * kSlabs) / (3 * span);
        return uint32_t(s < 0 ? 0 : (s >= kSlabs ? kSlabs - 1 : s));
    }
    // Entries of the slab index: each non-horizontal segment once per slab it spans.
    size_t entries(std::span<const Segment> cons) const {
        size_t n = 0;
        for (const Segment& sg : cons) {
            if (sg.a.y == sg.b.y) continue;
            n += of(3 * int64_t(std::max(sg.a.y, sg.b.y))) - of(3 * int64_t(std::min(sg.a.y, sg.b.y))) + 1;
        }
        return n;
    }
};

} // namespace

size_t check_scratch_words(size_t vertices, size_t triangles, std::span<const Segment> segments) {
    // vertices by position; Along edges: at most 3T/2 + 4, two words each, plus one mark each
    return vertices + 3 * (3 * triangles / 2 + 4) + (kSlabs + 1) + Slabs(segments).entries(segments) + 16;
}

template <typename Index>
Result check(const Cdt<Index>& cdt, std::span<const Segment> cons, bool check_inner,
                  std::span<uint32_t> scratch) {
    const uint32_t nv = cdt.vertex_count(), nt = cdt.triangle_count();
    if (scratch.size() < check_scratch_words(nv, nt, cons)) {
        return Result::fail(Status::Full, "the checker's scratch is too small", {"words", uint32_t(scratch.size())});
    }
    if (nv < 4) return fail("fewer than the 4 box vertices", {"vertices", nv});
    if (nt != 2 * nv - 6) return fail("Euler: not 2V - 6 triangles", {"triangles", nt}, {"vertices", nv});

    // Topology and orientation.
    uint32_t hull = 0;
    for (uint32_t t = 0; t < nt; ++t) {
        const Triangle<Index>& T = cdt.triangle(Index(t));
        for (int i = 0; i < 3; ++i) {
            if (T.v[i] >= nv) return fail("a vertex index out of range", {"triangle", t}, {"vertex", uint32_t(T.v[i])});
        }
        if (T.v[0] == T.v[1] || T.v[1] == T.v[2] || T.v[0] == T.v[2]) return fail("a vertex repeats", {"triangle", t});
        const int64_t o = orient_pts(cdt.vertex(T.v[0]).p, cdt.vertex(T.v[1]).p, cdt.vertex(T.v[2]).p);
        if (o <= 0) return fail(o == 0 ? "degenerate" : "clockwise", {"triangle", t});
        for (int i = 0; i < 3; ++i) {
            const Index u = T.n[i];
            const Index a = T.v[next3(i)], b = T.v[prev3(i)];
            if (u == kNone<Index>) {
                ++hull;
                if (a >= kBoxVertices || b >= kBoxVertices) return fail("no neighbour, but not a box edge", {"triangle", t}, {"edge", uint32_t(i)});
                if (T.flag(i) != Flag::None) return fail("a box edge is flagged", {"triangle", t});
                continue;
            }
            if (u >= nt) return fail("a neighbour index out of range", {"triangle", t}, {"neighbour", uint32_t(u)});
            const Triangle<Index>& U = cdt.triangle(u);
            const int j = U.edge_to(Index(t));
            if (j < 0) return fail("neighbours not symmetric (no link back)", {"triangle", t}, {"neighbour", uint32_t(u)});
            if (T.back_edge(i) != j) return fail("a back-edge index does not name the neighbour's shared edge", {"triangle", t}, {"edge", uint32_t(i)});
            if (U.v[next3(j)] != b || U.v[prev3(j)] != a) return fail("neighbours disagree on their shared edge", {"triangle", t}, {"neighbour", uint32_t(u)});
            const Flag f = T.flag(i), g = U.flag(j);
            if (f != reverse(g)) return fail("the two sides' constraint flags are not consistent", {"edge from vertex", uint32_t(a)}, {"to vertex", uint32_t(b)});
            if (f == Flag::None) {
                const Point pa = cdt.vertex(T.v[i]).p, pb = cdt.vertex(a).p, pc = cdt.vertex(b).p;
                const Point q = cdt.vertex(U.v[j]).p;
                if (incircle_exact(pa.x, pa.y, pb.x, pb.y, pc.x, pc.y, q.x, q.y) > 0) {
                    return fail("an edge is not locally Delaunay", {"triangle", t}, {"neighbour", uint32_t(u)});
                }
            }
        }
    }
    if (hull != 4) return fail("the hull is not the 4 box edges", {"hull edges", hull});
    for (uint32_t v = 0; v < nv; ++v) {
        const Index t = cdt.vertex(Index(v)).tri;
        if (t >= nt || cdt.triangle(t).index_of(Index(v)) < 0) return fail("its incident triangle does not hold it", {"vertex", v}, {"triangle", uint32_t(t)});
    }

    // Constraints. Vertices sorted by position, for looking up segment end points.
    uint32_t* byxy = scratch.data();
    for (uint32_t v = 0; v < nv; ++v) byxy[v] = v;
    auto less_xy = [&](uint32_t a, uint32_t b) {
        const Point pa = cdt.vertex(Index(a)).p, pb = cdt.vertex(Index(b)).p;
        return pa.x != pb.x ? pa.x < pb.x : pa.y < pb.y;
    };
    std::sort(byxy, byxy + nv, less_xy);
    for (uint32_t i = 1; i < nv; ++i) {
        if (cdt.vertex(Index(byxy[i])).p == cdt.vertex(Index(byxy[i - 1])).p) return fail("two vertices coincide", {"vertex", byxy[i - 1]}, {"vertex", byxy[i]});
    }
    auto find = [&](Point p) -> int64_t {
        uint32_t lo = 0, hi = nv;
        while (lo < hi) {
            const uint32_t mid = (lo + hi) / 2;
            const Point q = cdt.vertex(Index(byxy[mid])).p;
            if (q.x < p.x || (q.x == p.x && q.y < p.y)) lo = mid + 1;
            else hi = mid;
        }
        return lo < nv && cdt.vertex(Index(byxy[lo])).p == p ? int64_t(byxy[lo]) : -1;
    };
    // Directed Along edges (u -> v with the triangle on its left), as pairs, sorted by u.
    uint32_t* edges = byxy + nv;
    uint32_t ne = 0;
    for (uint32_t t = 0; t < nt; ++t) {
        const Triangle<Index>& T = cdt.triangle(Index(t));
        for (int i = 0; i < 3; ++i) {
            const Flag f = T.flag(i);
            if (f == Flag::Along || f == Flag::Both) {
                edges[2 * ne] = T.v[next3(i)];
                edges[2 * ne + 1] = T.v[prev3(i)];
                ++ne;
            }
        }
    }
    struct Pair {
        uint32_t u, v;
    };
    Pair* pairs = reinterpret_cast<Pair*>(edges);
    std::sort(pairs, pairs + ne, [](const Pair& x, const Pair& y) { return x.u != y.u ? x.u < y.u : x.v < y.v; });
    uint32_t* used = edges + 2 * ne; // one mark per Along edge
    for (uint32_t e = 0; e < ne; ++e) used[e] = 0;
    for (size_t s = 0; s < cons.size(); ++s) {
        const Segment& sg = cons[s];
        if (sg.a == sg.b) continue;
        const int64_t a = find(sg.a), b = find(sg.b);
        if (a < 0 || b < 0) return fail("an end point is not a vertex", {"constraint", uint32_t(s)});
        uint32_t cur = uint32_t(a);
        while (cur != uint32_t(b)) {
            // The outgoing Along edge of cur that runs along a->b toward b.
            uint32_t lo = 0, hi = ne;
            while (lo < hi) {
                const uint32_t mid = (lo + hi) / 2;
                if (edges[2 * mid] < cur) lo = mid + 1;
                else hi = mid;
            }
            int64_t next = -1;
            const Point pc = cdt.vertex(Index(cur)).p;
            for (uint32_t e = lo; e < ne && edges[2 * e] == cur; ++e) {
                const Point px = cdt.vertex(Index(edges[2 * e + 1])).p;
                if (orient_pts(sg.a, sg.b, px) != 0) continue;
                if (dot2d(pc, px, sg.b) <= 0) continue; // must head toward b
                if (dot2d(sg.a, px, sg.b) < 0 || dot2d(sg.b, px, sg.a) < 0) continue; // within a-b
                next = edges[2 * e + 1];
                used[e] = 1;
                break;
            }
            if (next < 0) return fail("missing from the triangulation", {"constraint", uint32_t(s)}, {"after vertex", uint32_t(cur)});
            cur = uint32_t(next);
        }
    }
    for (uint32_t e = 0; e < ne; ++e) {
        if (!used[e]) return fail("a flagged edge that no input constraint covers", {"edge from vertex", edges[2 * e]}, {"to vertex", edges[2 * e + 1]});
    }

    if (!check_inner) return {};
    // Inner set by winding number of each centroid, with the segments bucketed into
    // horizontal slabs so each query sees only segments that span its height.
    uint32_t* slab_start = used + ne; // kSlabs + 1 entries
    uint32_t* slab_items = slab_start + kSlabs + 1;
    const size_t room = scratch.size() - size_t(slab_items - scratch.data());
    const Slabs slabs(cons);
    const int64_t ymin = slabs.ymin, ymax = slabs.ymax;
    auto slab_of = [&](int64_t y3) { return slabs.of(y3); };
    for (uint32_t i = 0; i <= kSlabs; ++i) slab_start[i] = 0;
    for (int pass = 0; pass < 2; ++pass) {
        for (uint32_t s = 0; s < cons.size(); ++s) {
            const Segment& sg = cons[s];
            if (sg.a.y == sg.b.y) continue; // horizontal segments never count
            const uint32_t s0 = slab_of(3 * int64_t(std::min(sg.a.y, sg.b.y)));
            const uint32_t s1 = slab_of(3 * int64_t(std::max(sg.a.y, sg.b.y)));
            for (uint32_t k = s0; k <= s1; ++k) {
                if (pass == 0) ++slab_start[k + 1];
                else slab_items[slab_start[k]++] = s;
            }
        }
        if (pass == 0) {
            for (uint32_t k = 0; k < kSlabs; ++k) slab_start[k + 1] += slab_start[k];
            if (slab_start[kSlabs] > room) return Result::fail(Status::Full, "the checker's scratch is too small for the slab index");
        } else {
            for (uint32_t k = kSlabs; k > 0; --k) slab_start[k] = slab_start[k - 1];
            slab_start[0] = 0;
        }
    }
    for (uint32_t t = 0; t < nt; ++t) {
        const Triangle<Index>& T = cdt.triangle(Index(t));
        const Point a = cdt.vertex(T.v[0]).p, b = cdt.vertex(T.v[1]).p, c = cdt.vertex(T.v[2]).p;
        const int64_t cx = int64_t(a.x) + b.x + c.x, cy = int64_t(a.y) + b.y + c.y;
        int wind = 0;
        if (cy >= 3 * ymin && cy <= 3 * ymax) {
            const uint32_t k = slab_of(cy);
            for (uint32_t i = slab_start[k]; i < slab_start[k + 1]; ++i) {
                wind += winding_step(cons[slab_items[i]].a, cons[slab_items[i]].b, cx, cy);
            }
        }
        const bool expect = wind > 0;
        if (expect != T.inner()) {
            return fail(T.inner() ? "marked inner, but its winding number says outside" : "not marked inner, but its winding number says inside", {"triangle", t});
        }
    }
    return {};
}

template Result check(const Cdt<uint16_t>&, std::span<const Segment>, bool, std::span<uint32_t>);
template Result check(const Cdt<uint32_t>&, std::span<const Segment>, bool, std::span<uint32_t>);

} // namespace facet::cdt
