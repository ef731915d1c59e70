#pragma once
// Sequential constrained Delaunay triangulation in a fixed-capacity CET arena
// (Yang, Choi & Lee 2009, §3; constraint insertion after Anglada 1997).
//
//   Cdt<uint16_t> cdt(arena.view());
//   cdt.reset();                              // 4 box corners, 2 triangles
//   Index a, b;
//   cdt.insert_point({0, 0}, a, kNone);       // hint: walk from this vertex
//   cdt.insert_point({100, 0}, b, a);
//   cdt.insert_constraint(a, b);              // a->b runs along its loop
//   cdt.mark_inner();                         // flood fill from the flags (§3.4)
//
// Every call returns a Status; on any status other than Ok the triangulation is unchanged
// and valid (Full, OutOfRange, Crossing never leave it half-modified).
#include "cdt/arena.h"
#include "core/status.h"

namespace facet::cdt {

// Where a point lies in the current triangulation.
template <typename Index>
struct Location {
    enum class Kind : uint8_t { Inside, OnEdge, OnVertex } kind;
    Index tri;    // Inside/OnEdge: the triangle; OnVertex: an incident triangle
    uint8_t edge; // OnEdge: the edge index in tri
    Index vertex; // OnVertex: the vertex
};

struct CdtStats {
    uint64_t walk_steps = 0;   // triangles crossed by Locate walks
    uint64_t flips = 0;        // Lawson flips
    uint64_t cavities = 0;     // constraints that needed re-triangulation
    uint64_t cavity_triangles = 0;
    uint32_t work_peak = 0;    // most `work` entries in use at once
    uint32_t splits = 0;       // constraints split at a vertex lying exactly on them
};

template <typename Index>
class Cdt {
public:
    explicit Cdt(ArenaView<Index> arena) : a_(arena) {}

    // Starts a new face: the box corners (vertices 0..3) and two triangles. By default the box
    // is +-kBoxCoord, around the whole input range; given the bounds of the points to come,
    // it sits just around them (fewer flips against far-away corners, smaller predicates).
    // OutOfRange if the arena is too small or its work buffer is short of work_for(), or the
    // bounds leave +-kMaxCoord.
    Status reset();
    Status reset(Point lo, Point hi);

    // Inserts p, walking from vertex `hint` (kNone: from the last inserted vertex). `out` is the
    // new vertex, or the existing one if p is a duplicate. OutOfRange outside +-kMaxCoord; Full
    // if no vertex slot is left.
    Status insert_point(Point p, Index& out, Index hint);

    // Makes the segment a-b a constraint running from a to b along its loop. Vertices lying
    // exactly on the segment split it; an existing edge is flagged (merging with a flag already
    // there). Crossing if it would cross an existing constraint; Full if the cavity does not
    // fit the work buffer. a == b is a zero-length segment: Ok, nothing to do.
    Status insert_constraint(Index a, Index b);

    // Finds p by the straight walk from vertex `from` (an inserted, non-box vertex).
    Status locate(Point p, Index from, Location<Index>& out);

    // Marks the triangles inside the loops: those whose winding number is 1 or more (§3.4's
    // flood fill, from the box, counting the loops crossed by their flags). Degenerate if a
    // loop runs the wrong way (a winding number below 0) or the flags disagree.
    Status mark_inner();

    // The vertex next to `from` on the way to `to` along a constraint's segment: `to` itself
    // when they share an edge, else the vertex the segment was split at; kNone if neither.
    Index step_along(Index from, Index to) const;

    // Read access.
    Index vertex_count() const { return nv_; }
    Index triangle_count() const { return nt_; }
    Index inner_count() const { // triangles inside the loops (after mark_inner)
        Index n = 0;
        for (Index t = 0; t < nt_; ++t) n = Index(n + a_.triangles[t].inner());
        return n;
    }
    const Vertex<Index>& vertex(Index i) const { return a_.vertices[i]; }
    const Triangle<Index>& triangle(Index i) const { return a_.triangles[i]; }
    Index vertex_capacity() const { return Index(a_.vertices.size()); }
    Index last_vertex() const { return last_; }
    const CdtStats& stats() const { return stats_; }
    ArenaView<Index> arena() const { return a_; }

private:
    // topology (mesh.ipp)
    void rotate(Index t, int k);                 // make v[k] the new v[0], permuting n and flags
    void link(Index t, int i, Index u, int j);   // t's edge i and u's edge j are the same edge
    void flip(Index t);                          // flip edge 0 of t; t.v[0] stays v[0] of both
    Index new_triangle(Index v0, Index v1, Index v2);
    void set_vertex_tri(Index t);

    // walks (locate.ipp)
    Status walk(Index from, Point p, Location<Index>& out);
    void wedge(Index s, Point p, Index& t, int& k, int64_t& oa) const;
    Index start_vertex(Point p, Index hint) const;

    // insertion (insert.ipp)
    Status split_triangle(Index t, Index v);
    Status split_edge(Index t, int i, Index v);
    Status legalize(Index v, uint32_t stack_base);

    // constraints (constraint.ipp)
    //
    // A boundary edge of a constraint's cavity, recorded before the cavity's triangles are
    // taken apart: the triangle a new one will meet across it, and its flag. A slit (an edge
    // with the cavity on both sides) is linked to its twin instead, once both sides are built.
    struct CavityEdge {
        Index outside;       // the triangle across the edge, outside the cavity (kNone: the box)
        uint8_t outside_edge; // which of its edges (0..2)
        Flag flag;           // the edge's constraint flag, seen from inside
        bool slit;           // both sides inside the cavity
        bool slit_built;     // a slit whose first side is built: outside/outside_edge name it
    };
    // Where each part of the cavity of a piece crossing at most K triangles lies in the work
    // buffer (in Index entries): the crossed triangles' slots (K), each side's polygon (K + 2
    // vertices) and boundary edges (K + 1 records), and the polygon stack (4 entries per
    // pending sub-polygon, at most K + 2).
    struct CavityLayout {
        uint32_t slots, left_poly, left_edges, right_poly, right_edges, stack, entries;

        static constexpr uint32_t kEdgeEntries = uint32_t((sizeof(CavityEdge) + sizeof(Index) - 1) / sizeof(Index));
        static constexpr CavityLayout of(uint32_t K) {
            CavityLayout c{};
            c.slots = 0;
            c.left_poly = c.slots + K;
            c.left_edges = c.left_poly + (K + 2);
            c.right_poly = c.left_edges + (K + 1) * kEdgeEntries;
            c.right_edges = c.right_poly + (K + 2);
            c.stack = c.right_edges + (K + 1) * kEdgeEntries;
            c.entries = c.stack + 4 * (K + 2);
            return c;
        }
    };
    template <typename Visitor>
    Status trace(Index a, Index b, Index& reached, Visitor& visit);
    void apply_piece(Index a, Index b, uint32_t max_crossed, Index& reached);
    Index build_polygon(const Index* poly, CavityEdge* edges, uint32_t count, Index* stack, const Index* slots,
                        uint32_t& cursor);
    void set_boundary(Index t, int e, const Index* poly, CavityEdge* edges, uint32_t count, uint32_t i);

    bool work_fits(uint32_t need) {
        if (need > a_.work.size()) return false;
        if (need > stats_.work_peak) stats_.work_peak = need;
        return true;
    }
    const Point& P(Index v) const { return a_.vertices[v].p; }
    int64_t orient(Index a, Index b, Point c) const;
    int64_t orient(Index a, Index b, Index c) const { return orient(a, b, P(c)); }

    ArenaView<Index> a_;
    Index nv_ = 0, nt_ = 0;
    Index last_ = kNone<Index>;
    Point box_lo_{-kBoxCoord, -kBoxCoord}, box_hi_{kBoxCoord, kBoxCoord};
    CdtStats stats_;
};

extern template class Cdt<uint16_t>;
extern template class Cdt<uint32_t>;

} // namespace facet::cdt
