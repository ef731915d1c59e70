// libFuzzer target for cdt/: arbitrary points and loops in, the independent checker on the
// result. Coordinates come from a small grid (so collinear, cocircular and duplicate points
// are the rule, not the exception), scaled by a power of two up to the full +-2^24 range.
//
// Byte 0 picks the shape: even = arbitrary loops (any orientation, crossing or not) checked for
// topology, constraints and the Delaunay property; odd = a valid face (outer rectangle, holes in
// separate cells) also checked for the inner set.
#include "cdt/check.h"
#include "core/format.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace facet;
using namespace facet::cdt;

namespace {

struct Reader {
    const uint8_t* p;
    size_t n;
    uint8_t byte() { return n ? (--n, *p++) : 0; }
    bool more() const { return n > 0; }
};

struct Arena32 {
    std::vector<Vertex<uint32_t>> v;
    std::vector<Triangle<uint32_t>> t;
    std::vector<uint32_t> work, order, minseq, ins;
    std::vector<uint32_t> keys;
    explicit Arena32(size_t n) : v(n), t(triangles_for(n)), work(work_for(n)), order(n), minseq(n), ins(n), keys(n) {}
    ArenaView<uint32_t> view() { return {v, t, work, order, minseq, ins, keys}; }
};

void require(const Result& r) {
    if (!r.ok()) {
        char text[200];
        describe(r, text, sizeof text);
        std::fprintf(stderr, "checker: %s\n", text);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 2) return 0;
    Reader in{data, size};
    const uint8_t shape = in.byte();
    const int shift = in.byte() % 19; // grid step 2^shift: up to 32 * 2^18 < 2^24
    auto coord = [&](uint8_t b) { return (int32_t(b % 32) - 16) << shift; };

    std::vector<std::vector<Point>> loops;
    std::vector<Point> interior;
    if (shape % 2 == 0) {
        while (in.more() && loops.size() < 8) {
            const uint8_t n = in.byte() % 12;
            if (n == 0) break;
            std::vector<Point> loop;
            for (int i = 0; i < n && in.more(); ++i) loop.push_back({coord(in.byte()), coord(in.byte())});
            loops.push_back(loop);
        }
    } else {
        // Outer square (-16..16 grid) and up to 8 holes, each strictly inside its own 8x16
        // cell (holes may not share edges with each other or the outer loop: not a face).
        const int32_t s = int32_t(1) << shift;
        loops.push_back({{-16 * s, -16 * s}, {16 * s, -16 * s}, {16 * s, 16 * s}, {-16 * s, 16 * s}});
        const uint8_t mask = in.byte();
        for (int c = 0; c < 8; ++c) {
            if (!(mask & (1 << c))) continue;
            const int32_t x = (-16 + 8 * (c % 4)) * s;
            const int32_t w = (1 + in.byte() % 6) * s, h = (1 + in.byte() % 12) * s;
            const int32_t ox = x + s * (1 + in.byte() % 1), oy = (c < 4 ? -15 : 1) * s + s * (in.byte() % 2);
            loops.push_back({{ox, oy}, {ox, oy + h}, {ox + w, oy + h}, {ox + w, oy}}); // clockwise
        }
    }
    while (in.more() && interior.size() < 200) interior.push_back({coord(in.byte()), coord(in.byte())});

    size_t total = interior.size();
    for (auto& l : loops) total += l.size();
    Arena32 arena(total + 8);
    Cdt<uint32_t> cdt(arena.view());
    if (!ok(cdt.reset())) std::abort();

    std::vector<Segment> inserted;
    bool all_loops = true;
    for (auto& loop : loops) {
        std::vector<uint32_t> ids;
        for (Point p : loop) {
            uint32_t v;
            if (!ok(cdt.insert_point(p, v, cdt.last_vertex()))) std::abort(); // room was reserved
            ids.push_back(v);
        }
        for (size_t i = 0; i < ids.size(); ++i) {
            const uint32_t a = ids[i], b = ids[(i + 1) % ids.size()];
            const Status s = cdt.insert_constraint(a, b);
            if (ok(s)) inserted.push_back({cdt.vertex(a).p, cdt.vertex(b).p});
            else if (s == Status::Crossing) all_loops = false;
            else std::abort();
        }
    }
    for (Point p : interior) {
        uint32_t v;
        if (!ok(cdt.insert_point(p, v, cdt.last_vertex()))) std::abort();
    }
    const bool inner = shape % 2 == 1 && all_loops && ok(cdt.mark_inner());
    std::vector<uint32_t> scratch(check_scratch_words(cdt.vertex_count(), cdt.triangle_count(), std::span<const Segment>(inserted)));
    require(check(cdt, std::span<const Segment>(inserted), inner, std::span<uint32_t>(scratch)));
    return 0;
}
