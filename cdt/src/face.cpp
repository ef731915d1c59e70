#include "cdt/face.h"

#include "kdtree.h"

#include <algorithm>

namespace facet::cdt {

// Hilbert index by a state machine: at each level the curve's orientation (4 states) and the
// quadrant of (x, y) give the next two digits and the next orientation. Tables from the
// standard construction (state 0: the curve enters at (0,0) and leaves at (1,0)).
uint32_t hilbert_index(uint32_t x, uint32_t y) {
    static constexpr uint8_t kDigit[4][4] = {{0, 1, 3, 2}, {0, 3, 1, 2}, {2, 3, 1, 0}, {2, 1, 3, 0}};
    static constexpr uint8_t kNext[4][4] = {{1, 0, 3, 0}, {0, 2, 1, 1}, {2, 1, 2, 3}, {3, 3, 0, 2}};
    uint32_t d = 0, state = 0;
    for (int level = 15; level >= 0; --level) {
        const uint32_t q = (((x >> level) & 1) << 1) | ((y >> level) & 1);
        d = (d << 2) | kDigit[state][q];
        state = kNext[state][q];
    }
    return d;
}

namespace {

// Stable LSD radix sort of ins[from, n) by keys[], four 8-bit passes through tmp.
template <typename Index>
void radix_sort(Index* ins, Index* tmp, uint32_t from, uint32_t n, const uint32_t* keys) {
    Index* src = ins + from;
    Index* dst = tmp;
    const uint32_t count = n - from;
    for (int shift = 0; shift < 32; shift += 8) {
        uint32_t bucket[257] = {};
        for (uint32_t i = 0; i < count; ++i) ++bucket[((keys[src[i]] >> shift) & 255) + 1];
        for (int b = 0; b < 256; ++b) bucket[b + 1] += bucket[b];
        for (uint32_t i = 0; i < count; ++i) dst[bucket[(keys[src[i]] >> shift) & 255]++] = src[i];
        Index* t = src;
        src = dst;
        dst = t;
    }
    // Four passes: the result is back in ins.
}

} // namespace

template <typename Index>
Status triangulate_face(Cdt<Index>& cdt, const FaceInput& in, LocateMode mode, FaceReport& report) {
    report = {};
    auto fail = [&](Status s, uint32_t loop, uint32_t point) {
        report = {s, loop, point, 0};
        return s;
    };
    uint32_t n_loop = 0;
    for (uint32_t size : in.loop_sizes) n_loop += size;
    if (n_loop != in.loop_points.size()) return fail(Status::Corrupt, 0, 0);
    const uint32_t n = n_loop + uint32_t(in.interior.size());
    auto point = [&](uint32_t i) { return i < n_loop ? in.loop_points[i] : in.interior[i - n_loop]; };
    Point lo{0, 0}, hi{0, 0};
    for (uint32_t i = 0; i < n; ++i) {
        const Point p = point(i);
        if (p.x < -kMaxCoord || p.x > kMaxCoord || p.y < -kMaxCoord || p.y > kMaxCoord) {
            return fail(Status::OutOfRange, 0, i);
        }
        if (i == 0) lo = hi = p;
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    if (Status s = cdt.reset(lo, hi); !ok(s)) return fail(s, 0, 0);
    const ArenaView<Index> a = cdt.arena();
    if (uint64_t(n) + kBoxVertices > a.vertices.size() || n > a.order.size() ||
        n > a.minseq.size() || n > a.ins.size() || n > a.keys.size()) {
        return fail(Status::Full, 0, 0);
    }

    // Insertion order: loops as given, then the interior points along a Hilbert curve.
    Index* ins = a.ins.data();
    uint32_t* keys = a.keys.data();
    for (uint32_t i = 0; i < n; ++i) ins[i] = Index(i);
    if (mode == LocateMode::RandomOrder) {
        uint32_t state = 0x9E3779B9u;
        for (uint32_t i = n; i > 1; --i) { // Fisher-Yates with a fixed LCG: repeatable
            state = state * 1664525u + 1013904223u;
            std::swap(ins[i - 1], ins[(state >> 8) % i]);
        }
    } else if (mode == LocateMode::HilbertFirst || n > n_loop) {
        const uint32_t from = mode == LocateMode::HilbertFirst ? 0 : n_loop;
        int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
        for (uint32_t i = from; i < n; ++i) {
            const Point p = point(i);
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
            x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
        // Scale to the 16-bit Hilbert grid by a shift (no division: 64-bit divides are a
        // library call on 32-bit cores). The same shift on both axes keeps the curve square.
        const uint32_t extent = uint32_t(std::max(int64_t(x1) - x0, int64_t(y1) - y0));
        uint32_t shift = 0;
        while ((extent >> shift) > 0xFFFF) ++shift;
        for (uint32_t i = from; i < n; ++i) {
            const Point p = point(i);
            keys[i] = hilbert_index(uint32_t(p.x - x0) >> shift, uint32_t(p.y - y0) >> shift);
        }
        radix_sort(ins, a.order.data(), from, n, keys);
    }
    for (uint32_t k = 0; k < n; ++k) keys[ins[k]] = k; // keys: rank of each point

    // The kd-tree. KdTreeNearest asks it for every point, so it spans all points, ranked by
    // insertion order. Sequential asks it only while tracing loops (and once for the first
    // interior point), when exactly the loop points of lower index are in: there it spans the
    // loop points, ranked by index, and is built on first use.
    const uint32_t tree_size = mode == LocateMode::KdTreeNearest ? n : (mode == LocateMode::Sequential ? n_loop : 0);
    KdTree<Index, decltype(point)> tree(a.order.data(), a.minseq.data(), tree_size, point);
    bool built = false;
    if (mode == LocateMode::KdTreeNearest) {
        tree.build([&](Index i) { return keys[i]; });
        built = true;
    }
    for (uint32_t i = 0; i < n; ++i) keys[i] = kNone<Index>; // keys: vertex of each point

    auto nearest = [&](Point p, uint32_t rank) -> Index {
        if (!built) {
            tree.build([](Index i) { return uint32_t(i); });
            built = true;
        }
        const int64_t i = tree.nearest(p, rank, [&](Index j) { return keys[j] != kNone<Index>; });
        return i < 0 ? kNone<Index> : Index(keys[i]);
    };
    auto dist2 = [](Point p, Point q) {
        const int64_t dx = int64_t(p.x) - q.x, dy = int64_t(p.y) - q.y;
        return dx * dx + dy * dy;
    };
    // Where a run (a loop, or the interior points) starts: walk from the last vertex when it is
    // near, compared with the run's own first step (`next`); ask the kd-tree otherwise.
    auto run_start = [&](Point p, Point next, uint32_t rank) -> Index {
        const Index last = cdt.last_vertex();
        if (last != kNone<Index>) {
            const int64_t step = std::max<int64_t>(dist2(p, next), 1);
            if (dist2(cdt.vertex(last).p, p) <= 16 * step) return last;
        }
        return nearest(p, rank);
    };

    // The loop being traced and its first point (loops arrive in order except in RandomOrder).
    uint32_t loop = 0, loop_first = 0;
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t i = ins[k];
        const Point p = point(i);
        Index hint = kNone<Index>;
        const bool is_loop_point = i < n_loop;
        const bool points_first = mode == LocateMode::RandomOrder || mode == LocateMode::HilbertFirst;
        if (is_loop_point && !points_first) {
            while (i >= loop_first + in.loop_sizes[loop]) loop_first += in.loop_sizes[loop++];
        }
        if (mode == LocateMode::KdTreeNearest) {
            hint = nearest(p, k);
        } else if (mode == LocateMode::Sequential) {
            if (is_loop_point && i == loop_first) {
                const uint32_t size = in.loop_sizes[loop];
                hint = run_start(p, point(size > 1 ? i + 1 : i), k);
            } else if (i == n_loop) {
                hint = run_start(p, k + 1 < n ? point(ins[k + 1]) : p, k);
            } else {
                hint = cdt.last_vertex();
            }
        } else {
            hint = cdt.last_vertex();
        }
        Index v;
        if (Status s = cdt.insert_point(p, v, hint); !ok(s)) return fail(s, loop, i);
        keys[i] = v;
        if (points_first || !is_loop_point) continue;
        // Sequential / kd-tree: trace the loop as its points arrive.
        if (i != loop_first) {
            if (Status s = cdt.insert_constraint(Index(keys[i - 1]), v); !ok(s)) return fail(s, loop, i);
        }
        if (i == loop_first + in.loop_sizes[loop] - 1) {
            if (Status s = cdt.insert_constraint(v, Index(keys[loop_first])); !ok(s)) return fail(s, loop, i);
        }
    }
    if (mode == LocateMode::RandomOrder || mode == LocateMode::HilbertFirst) {
        uint32_t first = 0;
        for (uint32_t l = 0; l < in.loop_sizes.size(); ++l) {
            const uint32_t size = in.loop_sizes[l];
            for (uint32_t j = 0; j < size; ++j) {
                const uint32_t i = first + j, next = first + (j + 1) % size;
                if (Status s = cdt.insert_constraint(Index(keys[i]), Index(keys[next])); !ok(s)) return fail(s, l, i);
            }
            first += size;
        }
    }
    if (Status s = cdt.mark_inner(); !ok(s)) return fail(s, uint32_t(in.loop_sizes.size()), 0);
    for (Index t = 0; t < cdt.triangle_count(); ++t) report.inner += cdt.triangle(t).inner();
    return Status::Ok;
}

template Status triangulate_face(Cdt<uint16_t>&, const FaceInput&, LocateMode, FaceReport&);
template Status triangulate_face(Cdt<uint32_t>&, const FaceInput&, LocateMode, FaceReport&);

} // namespace facet::cdt
