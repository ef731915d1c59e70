// Loops the CDT's grid cannot keep apart (tessellate_face step 4).
//
// A valid B-rep's loops never cross or touch in (u,v), but files do not always hold one, and
// the grid is finite:
//
// * Crossing loops (untangle): a curve that overshoots its vertex and hooks back across its
//   neighbour (a translator's artefact a few microns long: usb4110_spatial_ap242.stp's face
//   188). The CDT refuses the segment; the smaller of the two pieces the crossing cuts off goes,
//   its points kept as a fan of slivers from the point before it, and the loops are
//   triangulated anew.
// * Touching loops (stitch): a wall thinner than a grid unit (two holes a micron apart on a
//   plate of 160 mm, whose grid unit is 5 microns) puts loop points of different 3D positions
//   on one grid point, or one loop's point on another's segment. The CDT makes them one vertex,
//   or splits the segment there, so the face's triangles meet that segment's neighbour along
//   other points than its own. A fan of slivers closes each such gap.
//
// Either way every edge sample the neighbours use is still used, each segment by exactly two
// triangles: the mesh stays watertight, and strays from the face's true boundary by no more
// than the piece that went or the grid's unit.
#include "face_internal.h"

#include "cdt/predicates.h"

#include <cmath>
#include <utility>

namespace facet::geom::detail {

namespace {

int sign(int64_t v) { return (v > 0) - (v < 0); }

// Whether segments ab and cd cross at a point inside both (what the CDT refuses; segments that
// touch or overlap it splits or merges).
bool cross(cdt::Point a, cdt::Point b, cdt::Point c, cdt::Point d) {
    const int o1 = sign(cdt::orient2d(a.x, a.y, b.x, b.y, c.x, c.y));
    const int o2 = sign(cdt::orient2d(a.x, a.y, b.x, b.y, d.x, d.y));
    const int o3 = sign(cdt::orient2d(c.x, c.y, d.x, d.y, a.x, a.y));
    const int o4 = sign(cdt::orient2d(c.x, c.y, d.x, d.y, b.x, b.y));
    return o1 * o2 < 0 && o3 * o4 < 0;
}

// A loop's place in the face's points.
struct LoopSpan {
    uint32_t index = 0, start = 0, size = 0;
    uint32_t at(uint32_t k) const { return start + k % size; } // the point k steps on from the first
    uint32_t next(uint32_t i) const { return i + 1 == start + size ? start : i + 1; }
};

LoopSpan loop_of(const FaceScratch& sc, uint32_t nl, uint32_t point) {
    LoopSpan L;
    for (; L.index < nl; ++L.index) {
        L.size = sc.loop_sizes[L.index];
        if (point < L.start + L.size) return L;
        L.start += L.size;
    }
    return {nl, 0, 0};
}

// The 3D length of the loop's chain from point `from`, `steps` segments on.
float chain_length(const FaceScratch& sc, const LoopSpan& L, uint32_t from, uint32_t steps) {
    float sum = 0;
    for (uint32_t k = 0, i = L.start + from; k < steps; ++k) {
        const uint32_t j = L.next(i);
        sum += length(sc.xyz[j] - sc.xyz[i]);
        i = j;
    }
    return sum;
}

// A run of a loop's points to drop: `count` points from position `first` (cyclic), between the
// kept points before and after it.
struct Run {
    LoopSpan loop;
    uint32_t first = 0, count = 0;
    float length = 0; // how large the piece is (3D)
};

// Drops the run: its points become a fan of slivers from the point before it, the loop closes
// over the chord, and a loop left without area goes (its slivers carry its edges).
Result drop(FaceScratch& sc, uint32_t& np, uint32_t& nl, uint32_t& slivers, const Run& r) {
    const LoopSpan& L = r.loop;
    const uint32_t before = L.at(r.first + L.size - 1);
    for (uint32_t k = 0; k < r.count; ++k) {
        if (slivers >= sc.slivers.size()) return Result::fail(Status::Full, "more collapsed loop points than the face scratch holds");
        const uint32_t b = L.at(r.first + k), c = L.at(r.first + k + 1);
        sc.slivers[slivers++] = {{sc.xyz[before], sc.xyz[b], sc.xyz[c]}, {sc.uv[before], sc.uv[b], sc.uv[c]}};
    }
    // Keep the loop's other points in loop order from the one after the run (a loop's first
    // point is no different from the others).
    const uint32_t kept = L.size - r.count;
    const uint32_t keep_from = r.first + r.count;
    // Rotate the loop in place so that the kept points come first: three reversals.
    auto swap_points = [&](uint32_t i, uint32_t j) {
        std::swap(sc.loop_points[i], sc.loop_points[j]);
        std::swap(sc.uv[i], sc.uv[j]);
        std::swap(sc.xyz[i], sc.xyz[j]);
        std::swap(sc.pinned[i], sc.pinned[j]);
    };
    auto reverse = [&](uint32_t from, uint32_t to) { // [from, to) of the loop's slots
        for (uint32_t i = L.start + from, j = L.start + to; i + 1 < j; ++i, --j) swap_points(i, j - 1);
    };
    const uint32_t shift = keep_from % L.size;
    reverse(0, shift), reverse(shift, L.size), reverse(0, L.size);
    // The loop now starts with its kept points; the run's points sit at its end and go.
    const uint32_t gone = kept >= 3 ? r.count : L.size;
    for (uint32_t i = L.start + L.size; i < np; ++i) {
        sc.loop_points[i - gone] = sc.loop_points[i];
        sc.uv[i - gone] = sc.uv[i];
        sc.xyz[i - gone] = sc.xyz[i];
        sc.pinned[i - gone] = sc.pinned[i];
    }
    np -= gone;
    if (kept >= 3) {
        sc.loop_sizes[L.index] = kept;
    } else {
        for (uint32_t l = L.index; l + 1 < nl; ++l) sc.loop_sizes[l] = sc.loop_sizes[l + 1];
        --nl;
    }
    return {};
}

} // namespace

Result untangle(FaceScratch& sc, uint32_t& np, uint32_t& nl, uint32_t& slivers, uint32_t from, uint32_t to) {
    const Result refused = Result::fail(Status::Crossing, "loops cross");
    if (from >= np || to >= np) return refused;
    const LoopSpan A = loop_of(sc, nl, from);
    if (A.index == nl || A.next(from) != to) return refused;
    const cdt::Point a = sc.loop_points[from], b = sc.loop_points[to];
    // The segment the refused one crosses: the first along the loops (any will do: the next
    // attempt finds the others).
    LoopSpan B;
    uint32_t partner = np;
    for (uint32_t l = 0, start = 0; l < nl && partner == np; start += sc.loop_sizes[l++]) {
        const LoopSpan L{l, start, sc.loop_sizes[l]};
        for (uint32_t i = start; i < start + L.size; ++i) {
            const uint32_t j = L.next(i);
            if (i == from || !cross(a, b, sc.loop_points[i], sc.loop_points[j])) continue;
            B = L, partner = i;
            break;
        }
    }
    if (partner == np) return refused;
    const float perimeter_a = chain_length(sc, A, 0, A.size);
    Run run;
    if (B.index == A.index) {
        // One loop crossing itself: it is two loops joined at the crossing. The one with the
        // shorter boundary goes.
        const uint32_t pa = from - A.start, pb = partner - A.start;
        const uint32_t ab = (pb + A.size - pa) % A.size; // segments from a's start to the partner's
        // Each piece measured by its points alone, closed on itself (the crossing segments'
        // lengths belong to both sides).
        auto closed_length = [&](uint32_t first, uint32_t count) {
            const uint32_t last = A.at(first + count - 1);
            return chain_length(sc, A, first, count - 1) + length(sc.xyz[A.at(first)] - sc.xyz[last]);
        };
        Run one{A, (pa + 1) % A.size, ab, closed_length((pa + 1) % A.size, ab)};
        Run other{A, (pb + 1) % A.size, A.size - ab, closed_length((pb + 1) % A.size, A.size - ab)};
        run = one.length <= other.length ? one : other;
        // A piece of a quarter of the loop or more is no artefact: the face is wrong, not its edge.
        if (!(run.length <= 0.25f * perimeter_a)) return refused;
    } else {
        // Two loops crossing: each such pair crosses twice or more. One point at a time goes,
        // the one whose sliver is the smallest.
        const uint32_t ends[4] = {from, to, partner, B.next(partner)};
        float best = INFINITY;
        for (const uint32_t p : ends) {
            const LoopSpan& L = p == from || p == to ? A : B;
            const uint32_t k = p - L.start;
            const float len = chain_length(sc, L, (k + L.size - 1) % L.size, 2);
            const float perimeter = &L == &A ? perimeter_a : chain_length(sc, B, 0, B.size);
            if (len < best && len <= 0.25f * perimeter) best = len, run = {L, k, 1, len};
        }
        if (!(best < INFINITY)) return refused;
    }
    return drop(sc, np, nl, slivers, run);
}

Result stitch(FaceScratch& sc, uint32_t np, uint32_t nl, const cdt::Cdt<uint16_t>& cdt, uint32_t& slivers) {
    // Nothing to do unless two loop points share a vertex at different 3D points, or the CDT split
    // a segment: the face's common case costs one pass over its points.
    bool merged = false;
    for (uint32_t i = 0; i < np && !merged; ++i) {
        const uint32_t j = sc.mesh_of[sc.arena.keys[i]];
        merged = j != i && !same_point(sc.xyz[j], sc.xyz[i]);
    }
    if (!merged && cdt.stats().splits == 0) return {};
    const uint32_t vertices = cdt.vertex_count();
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (same_point(sc.xyz[a], sc.xyz[b]) || same_point(sc.xyz[b], sc.xyz[c]) || same_point(sc.xyz[c], sc.xyz[a])) return true; // no triangle
        if (slivers >= sc.slivers.size()) return false;
        sc.slivers[slivers++] = {{sc.xyz[a], sc.xyz[b], sc.xyz[c]}, {sc.uv[a], sc.uv[b], sc.uv[c]}};
        return true;
    };
    const Result full = Result::fail(Status::Full, "more collapsed loop points than the face scratch holds");
    for (uint32_t l = 0, start = 0; l < nl; start += sc.loop_sizes[l++]) {
        const LoopSpan L{l, start, sc.loop_sizes[l]};
        for (uint32_t a = start; a < start + L.size; ++a) {
            // The segment a -> b is, in the triangulation, the path of edges from a's vertex to b's:
            // the polygon a, b, then the points of that path backwards, is the gap; a fan from a
            // fills it (its triangles with two corners at one 3D point are none).
            const uint32_t b = L.next(a);
            const uint16_t va = uint16_t(sc.arena.keys[a]), vb = uint16_t(sc.arena.keys[b]);
            if (va == vb) continue; // one grid point: clean_loops kept none such
            uint16_t w = cdt.step_along(va, vb);
            if (w == cdt::kNone<uint16_t>) {
                return Result::fail(Status::Corrupt, "a loop's segment is not in the triangulation", {"loop", l});
            }
            uint32_t prev = sc.mesh_of[vb]; // the path's points, from b's end back towards a's
            if (!add(a, b, prev)) return full;
            // Then the path walked from a's end: each step's point joins the fan with the one before.
            uint32_t last = sc.mesh_of[va];
            for (uint32_t steps = 0; w != vb; ++steps) {
                if (steps >= vertices) return Result::fail(Status::Corrupt, "a loop's segment is not in the triangulation", {"loop", l});
                const uint32_t m = sc.mesh_of[w];
                if (!add(a, m, last)) return full;
                last = m;
                const uint16_t next = cdt.step_along(w, vb);
                if (next == cdt::kNone<uint16_t>) {
                    return Result::fail(Status::Corrupt, "a loop's segment is not in the triangulation", {"loop", l});
                }
                w = next;
            }
            if (!add(a, prev, last)) return full;
        }
    }
    return {};
}

} // namespace facet::geom::detail
