#pragma once
// The CET (Constraints Embedded Triangle) record of Yang, Choi & Lee (2009), §3.1.
#include <cstdint>
#include <limits>

namespace facet::cdt {

// Input coordinates must satisfy |x|, |y| <= kMaxCoord; the four box corners sit at
// +-kBoxCoord, strictly outside, so every input point is interior to the triangulation.
constexpr int32_t kMaxCoord = 1 << 24;
constexpr int32_t kBoxCoord = 1 << 25;
constexpr uint32_t kBoxVertices = 4; // vertices 0..3 are the box corners

struct Point {
    int32_t x, y;
    bool operator==(const Point&) const = default;
};

// Constraint flag of one edge, 2 bits (§3.1): how the loop that owns the edge runs relative to
// the triangle's counter-clockwise order of that edge.
enum class Flag : uint8_t {
    None = 0,    // not a constraint
    Along = 1,   // the loop runs this way: the triangle is on the loop's inner (left) side
    Against = 2, // the loop runs the other way
    Both = 3,    // two loops share the edge in opposite directions (merged)
};

constexpr Flag reverse(Flag f) {
    return f == Flag::Along ? Flag::Against : (f == Flag::Against ? Flag::Along : f);
}

// One triangle.
//
//                v[2]
//                /  \ .
//      edge 1   /    \   edge 0          vertices counter-clockwise;
//   (n[1], f1) /      \ (n[0], f0)       edge i is the edge opposite v[i],
//             /        \                 n[i] the neighbour across it (kNone at the box),
//          v[0] ------ v[1]              fi its 2-bit constraint flag (bits 2i, 2i+1 of flags).
//               edge 2
//             (n[2], f2)
//
// Bits 6 and 7 of `flags` hold the inner mark (set by mark_inner) and a scratch mark.
// `back` (the record's otherwise spare byte) keeps, for each edge i, which edge of n[i] it is
// (bits 2i, 2i+1), so crossing an edge never searches the neighbour's three indices.
template <typename Index>
struct Triangle {
    Index v[3];
    Index n[3];
    uint8_t flags;
    uint8_t back;

    Flag flag(int i) const { return static_cast<Flag>((flags >> (2 * i)) & 3); }
    void set_flag(int i, Flag f) {
        flags = static_cast<uint8_t>((flags & ~(3 << (2 * i))) | (uint8_t(f) << (2 * i)));
    }
    bool inner() const { return flags & kInnerBit; }
    bool constrained(int i) const { return flag(i) != Flag::None; }
    int index_of(Index vertex) const { return v[0] == vertex ? 0 : (v[1] == vertex ? 1 : (v[2] == vertex ? 2 : -1)); }
    int edge_to(Index neighbour) const { return n[0] == neighbour ? 0 : (n[1] == neighbour ? 1 : (n[2] == neighbour ? 2 : -1)); }
    int back_edge(int i) const { return (back >> (2 * i)) & 3; }
    void set_back(int i, int j) { back = static_cast<uint8_t>((back & ~(3 << (2 * i))) | (j << (2 * i))); }

    static constexpr uint8_t kEdgeFlagMask = 0x3F;
    static constexpr uint8_t kInnerBit = 0x40;
    static constexpr uint8_t kMarkBit = 0x80;
};

// A copy of a record, field by field (copying the 14-byte record whole is a memcpy call on
// ARMv5).
template <typename Index>
inline Triangle<Index> copy_of(const Triangle<Index>& t) {
    return {{t.v[0], t.v[1], t.v[2]}, {t.n[0], t.n[1], t.n[2]}, t.flags, t.back};
}

template <typename Index>
struct Vertex {
    Point p;
    Index tri; // one incident triangle (the paper's L); kNone until inserted
};

// "No triangle" / "no vertex": the largest index, never a valid slot.
template <typename Index>
constexpr Index kNone = std::numeric_limits<Index>::max();

static_assert(sizeof(Triangle<uint16_t>) <= 16, "device CET record must fit 16 bytes");
static_assert(sizeof(Triangle<uint16_t>) == 14, "device CET: 3+3 16-bit indices, flag and back-edge bytes");
static_assert(sizeof(Vertex<uint16_t>) == 12, "device vertex: two int32 coordinates and L");

// (a - o) . (b - o), exact in int64 within the predicate range.
inline int64_t dot2d(Point o, Point a, Point b) {
    return int64_t(a.x - o.x) * (b.x - o.x) + int64_t(a.y - o.y) * (b.y - o.y);
}

inline constexpr int next3(int i) { return i == 2 ? 0 : i + 1; }
inline constexpr int prev3(int i) { return i == 0 ? 2 : i - 1; }

} // namespace facet::cdt
