#include "cdt/face.h"

#include "kdtree.h"

#include <algorithm>
#include <bit>

namespace facet::cdt {

// Hilbert index by a state machine: at each level the curve's orientation (4 states) and the
// quadrant of (x, y) give the next two digits and the next orientation. Tables from the
// standard construction (state 0: the curve enters at (0,0) and leaves at (1,0)).
uint32_t hilbert_index(uint32_t x, uint32_t y, int levels) {
    static constexpr uint8_t kDigit[4][4] = {{0, 1, 3, 2}, {0, 3, 1, 2}, {2, 3, 1, 0}, {2, 1, 3, 0}};
    static constexpr uint8_t kNext[4][4] = {{1, 0, 3, 0}, {0, 2, 1, 1}, {2, 1, 2, 3}, {3, 3, 0, 2}};
    uint32_t d = 0, state = 0;
    for (int level = levels - 1; level >= 0; --level) {
        const uint32_t q = (((x >> level) & 1) << 1) | ((y >> level) & 1);
        d = (d << 2) | kDigit[state][q];
        state = kNext[state][q];
    }
    return d;
}

namespace {

// Stable LSD radix sort of ins[from, n) by keys[] (below 2^key_bits), 8-bit passes through tmp.
template <typename Index>
void radix_sort(Index* ins, Index* tmp, uint32_t from, uint32_t n, const uint32_t* keys, int key_bits) {
    Index* src = ins + from;
    Index* dst = tmp;
    const uint32_t count = n - from;
    for (int shift = 0; shift < key_bits; shift += 8) {
        uint32_t bucket[257] = {};
        for (uint32_t i = 0; i < count; ++i) ++bucket[((keys[src[i]] >> shift) & 255) + 1];
        for (int b = 0; b < 256; ++b) bucket[b + 1] += bucket[b];
        for (uint32_t i = 0; i < count; ++i) dst[bucket[(keys[src[i]] >> shift) & 255]++] = src[i];
        Index* t = src;
        src = dst;
        dst = t;
    }
    if (src != ins + from) std::copy(src, src + count, ins + from); // an odd number of passes
}

} // namespace

namespace {

const char* what_failed(Status s) {
    switch (s) {
    case Status::Full: return "more points than the CDT arena holds";
    case Status::Crossing: return "loops cross";
    case Status::OutOfRange: return "a point lies outside the CDT's coordinate range";
    case Status::Corrupt: return "the loop sizes do not add up to the points";
    case Status::Degenerate: return "a loop is open or runs the wrong way";
    default: return "triangulation failed";
    }
}

} // namespace

template <typename Index>
Point FaceBuilder<Index>::point(uint32_t i) const {
    return i < n_loop_ ? in_.loop_points[i] : in_.interior[i - n_loop_];
}

namespace {

// The builder's points by index, for the kd-tree.
template <typename Index>
struct PointOf {
    const FaceBuilder<Index>* b;
    Point operator()(uint32_t i) const { return b->point(i); }
};

int64_t dist2(Point p, Point q) {
    const int64_t dx = int64_t(p.x) - q.x, dy = int64_t(p.y) - q.y;
    return dx * dx + dy * dy;
}

} // namespace

template <typename Index>
Result FaceBuilder<Index>::start(const FaceInput& in, LocateMode mode) {
    in_ = in;
    mode_ = mode;
    stage_ = Stage::Failed;
    k_ = 0, loop_ = 0, loop_first_ = 0, cl_ = 0, cj_ = 0, cfirst_ = 0;
    tree_built_ = false;
    refused_ = {kNoPoint, kNoPoint};
    auto fail = [&](Result r) {
        result_ = r;
        return r;
    };
    n_loop_ = 0;
    for (uint32_t size : in.loop_sizes) n_loop_ += size;
    if (n_loop_ != in.loop_points.size()) return fail(Result::fail(Status::Corrupt, what_failed(Status::Corrupt)));
    n_ = n_loop_ + uint32_t(in.interior.size());
    Point lo{0, 0}, hi{0, 0};
    for (uint32_t i = 0; i < n_; ++i) {
        const Point p = point(i);
        if (p.x < -kMaxCoord || p.x > kMaxCoord || p.y < -kMaxCoord || p.y > kMaxCoord) {
            return fail(Result::fail(Status::OutOfRange, what_failed(Status::OutOfRange), {"point", i}));
        }
        if (i == 0) lo = hi = p;
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    if (Status s = cdt_.reset(lo, hi); !ok(s)) return fail(Result::fail(s, "the CDT arena is too small for its box"));
    const ArenaView<Index> a = cdt_.arena();
    if (uint64_t(n_) + kBoxVertices > a.vertices.size() || n_ > a.order.size() || n_ > a.minseq.size() ||
        n_ > a.ins.size() || n_ > a.keys.size()) {
        return fail(Result::fail(Status::Full, what_failed(Status::Full), {"points", n_}));
    }

    // Insertion order: loops as given, then the interior points along a Hilbert curve.
    Index* ins = a.ins.data();
    uint32_t* keys = a.keys.data();
    for (uint32_t i = 0; i < n_; ++i) ins[i] = Index(i);
    if (mode == LocateMode::RandomOrder) {
        uint32_t state = 0x9E3779B9u;
        for (uint32_t i = n_; i > 1; --i) { // Fisher-Yates with a fixed LCG: repeatable
            state = state * 1664525u + 1013904223u;
            std::swap(ins[i - 1], ins[(state >> 8) % i]);
        }
    } else if (mode == LocateMode::HilbertFirst || n_ > n_loop_) {
        const uint32_t from = mode == LocateMode::HilbertFirst ? 0 : n_loop_;
        int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
        for (uint32_t i = from; i < n_; ++i) {
            const Point p = point(i);
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
            x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
        // A grid of 2^levels cells a side, some 4 to 16 cells per point: finer only orders
        // points within a cell, and each level costs every key a step and the sort a pass per
        // four. Scaled by a shift (no division: 64-bit divides are a library call on 32-bit
        // cores); the same shift on both axes keeps the curve square.
        const int levels = std::clamp((int(std::bit_width(n_ - from)) + 5) / 2, 4, 16);
        const uint32_t extent = uint32_t(std::max(int64_t(x1) - x0, int64_t(y1) - y0));
        uint32_t shift = 0;
        while ((extent >> shift) >= (1u << levels)) ++shift;
        for (uint32_t i = from; i < n_; ++i) {
            const Point p = point(i);
            keys[i] = hilbert_index(uint32_t(p.x - x0) >> shift, uint32_t(p.y - y0) >> shift, levels);
        }
        radix_sort(ins, a.order.data(), from, n_, keys, 2 * levels);
    }
    for (uint32_t k = 0; k < n_; ++k) keys[ins[k]] = k; // keys: rank of each point

    // The kd-tree. KdTreeNearest asks it for every point, so it spans all points, ranked by
    // insertion order. Sequential asks it only while tracing loops (and once for the first
    // interior point), when exactly the loop points of lower index are in: there it spans the
    // loop points, ranked by index, and is built on first use.
    if (mode == LocateMode::KdTreeNearest) {
        KdTree<Index, PointOf<Index>> tree(a.order.data(), a.minseq.data(), n_, PointOf<Index>{this});
        tree.build(keys);
        tree_built_ = true;
    }
    for (uint32_t i = 0; i < n_; ++i) keys[i] = kNone<Index>; // keys: vertex of each point
    stage_ = Stage::Points;
    result_ = Result::fail(Status::Busy, "unfinished");
    return {};
}

template <typename Index>
Result FaceBuilder<Index>::run(uint32_t units) {
    if (stage_ == Stage::Done || stage_ == Stage::Failed) return result_;
    const ArenaView<Index> a = cdt_.arena();
    const Index* ins = a.ins.data();
    uint32_t* keys = a.keys.data();
    const bool points_first = mode_ == LocateMode::RandomOrder || mode_ == LocateMode::HilbertFirst;
    auto fail = [&](Status s, uint32_t loop, uint32_t point) {
        stage_ = Stage::Failed;
        result_ = Result::fail(s, what_failed(s), {"loop", loop}, {"point", point});
        return result_;
    };
    auto refuse = [&](Status s, uint32_t loop, uint32_t point, uint32_t from, uint32_t to) { // a segment failed
        refused_ = {from, to};
        return fail(s, loop, point);
    };
    const uint32_t tree_size = mode_ == LocateMode::KdTreeNearest ? n_ : (mode_ == LocateMode::Sequential ? n_loop_ : 0);
    KdTree<Index, PointOf<Index>> tree(a.order.data(), a.minseq.data(), tree_size, PointOf<Index>{this});
    auto nearest = [&](Point p, uint32_t rank) -> Index {
        if (!tree_built_) {
            tree.build(nullptr);
            tree_built_ = true;
        }
        const int64_t i = tree.nearest(p, rank, [&](Index j) { return keys[j] != kNone<Index>; });
        return i < 0 ? kNone<Index> : Index(keys[i]);
    };
    // Where a run (a loop, or the interior points) starts: walk from the last vertex when it is
    // near, compared with the run's own first step (`next`); ask the kd-tree otherwise.
    auto run_start = [&](Point p, Point next, uint32_t rank) -> Index {
        const Index last = cdt_.last_vertex();
        if (last != kNone<Index>) {
            const int64_t step = std::max<int64_t>(dist2(p, next), 1);
            if (dist2(cdt_.vertex(last).p, p) <= 16 * step) return last;
        }
        return nearest(p, rank);
    };

    uint32_t done = 0;
    used_ = 0;
    // Every point, in order; the paper's modes trace each loop as its points arrive.
    for (; stage_ == Stage::Points && k_ < n_ && done < units; ++k_, ++done) {
        const uint32_t k = k_, i = ins[k];
        const Point p = point(i);
        Index hint = kNone<Index>;
        const bool is_loop_point = i < n_loop_;
        if (is_loop_point && !points_first) {
            while (i >= loop_first_ + in_.loop_sizes[loop_]) loop_first_ += in_.loop_sizes[loop_++];
        }
        if (mode_ == LocateMode::KdTreeNearest) {
            hint = nearest(p, k);
        } else if (mode_ == LocateMode::Sequential) {
            if (is_loop_point && i == loop_first_) {
                const uint32_t size = in_.loop_sizes[loop_];
                hint = run_start(p, point(size > 1 ? i + 1 : i), k);
            } else if (i == n_loop_) {
                hint = run_start(p, k + 1 < n_ ? point(ins[k + 1]) : p, k);
            } else {
                hint = cdt_.last_vertex();
            }
        } else {
            hint = cdt_.last_vertex();
        }
        Index v;
        if (Status s = cdt_.insert_point(p, v, hint); !ok(s)) return fail(s, loop_, i);
        keys[i] = v;
        if (points_first || !is_loop_point) continue;
        // Sequential / kd-tree: trace the loop as its points arrive.
        if (i != loop_first_) {
            if (Status s = cdt_.insert_constraint(Index(keys[i - 1]), v); !ok(s)) return refuse(s, loop_, i, i - 1, i);
        }
        if (i == loop_first_ + in_.loop_sizes[loop_] - 1) {
            if (Status s = cdt_.insert_constraint(v, Index(keys[loop_first_])); !ok(s)) return refuse(s, loop_, i, i, loop_first_);
        }
    }
    if (stage_ == Stage::Points && k_ == n_) stage_ = points_first ? Stage::Constraints : Stage::Inner;
    // Points first: then the loops' segments, most of them edges already.
    while (stage_ == Stage::Constraints && done < units) {
        if (cl_ == in_.loop_sizes.size()) {
            stage_ = Stage::Inner;
            break;
        }
        const uint32_t size = in_.loop_sizes[cl_];
        const uint32_t i = cfirst_ + cj_, next = cfirst_ + (cj_ + 1) % size;
        if (Status s = cdt_.insert_constraint(Index(keys[i]), Index(keys[next])); !ok(s)) return refuse(s, cl_, i, i, next);
        ++done;
        if (++cj_ == size) cfirst_ += size, cj_ = 0, ++cl_;
    }
    used_ = done;
    if (stage_ == Stage::Inner && done < units) {
        ++used_;
        if (Status s = cdt_.mark_inner(); !ok(s)) {
            stage_ = Stage::Failed;
            result_ = Result::fail(s, what_failed(s));
            return result_;
        }
        stage_ = Stage::Done;
        result_ = {};
    }
    return stage_ == Stage::Done ? result_ : Result::fail(Status::Busy, "unfinished");
}

template <typename Index>
Result triangulate_face(Cdt<Index>& cdt, const FaceInput& in, LocateMode mode) {
    FaceBuilder<Index> b(cdt);
    if (Result r = b.start(in, mode); !r.ok()) return r;
    return b.run(UINT32_MAX);
}

template class FaceBuilder<uint16_t>;
template class FaceBuilder<uint32_t>;
template Result triangulate_face(Cdt<uint16_t>&, const FaceInput&, LocateMode);
template Result triangulate_face(Cdt<uint32_t>&, const FaceInput&, LocateMode);

} // namespace facet::cdt
