#pragma once
// A static 2-d tree over a face's points, built in place once per face (no allocation).
//
// The tree is implicit: order[lo, hi) is a subtree whose root is order[(lo + hi) / 2], split
// on x at even depths and on y at odd ones. minrank[root] holds the smallest insertion rank in
// the subtree. Points are inserted by rank, so while the k-th point is placed, exactly the
// points of rank < k are in the triangulation: nearest() prunes subtrees whose smallest rank
// is >= k and so finds the nearest vertex inserted so far, exactly.
#include "cdt/types.h"

#include <algorithm>
#include <cstdint>

namespace facet::cdt {

template <typename Index, typename PointAt>
class KdTree {
public:
    KdTree(Index* order, Index* minrank, uint32_t n, PointAt point)
        : order_(order), minrank_(minrank), n_(n), point_(point) {}

    // rank[i]: the insertion rank of point i (null: its index).
    void build(const uint32_t* rank) {
        for (uint32_t i = 0; i < n_; ++i) order_[i] = Index(i);
        build(0, n_, 0, rank);
    }

    // The nearest point of rank < limit; inserted(i) tells whether point i has been placed
    // (true exactly for ranks < limit). -1 if there is none.
    template <typename Inserted>
    int64_t nearest(Point p, uint32_t limit, Inserted inserted) const {
        Best best{-1, INT64_MAX};
        search(0, n_, 0, p, limit, inserted, best);
        return best.index;
    }

private:
    struct Best {
        int64_t index;
        int64_t d2;
    };

    uint32_t build(uint32_t lo, uint32_t hi, int depth, const uint32_t* rank) {
        if (lo >= hi) return UINT32_MAX;
        const uint32_t mid = lo + (hi - lo) / 2;
        const bool by_x = (depth & 1) == 0;
        std::nth_element(order_ + lo, order_ + mid, order_ + hi, [&](Index a, Index b) {
            const Point pa = point_(a), pb = point_(b);
            return by_x ? pa.x < pb.x : pa.y < pb.y;
        });
        const uint32_t l = build(lo, mid, depth + 1, rank);
        const uint32_t r = build(mid + 1, hi, depth + 1, rank);
        const uint32_t m = std::min<uint32_t>(rank ? rank[order_[mid]] : uint32_t(order_[mid]), std::min(l, r));
        minrank_[mid] = Index(m);
        return m;
    }

    template <typename Inserted>
    void search(uint32_t lo, uint32_t hi, int depth, Point p, uint32_t limit, Inserted& inserted,
                Best& best) const {
        if (lo >= hi) return;
        const uint32_t mid = lo + (hi - lo) / 2;
        if (minrank_[mid] >= limit) return; // nothing inserted in this subtree
        const Index i = order_[mid];
        const Point q = point_(i);
        const int64_t dx = int64_t(p.x) - q.x, dy = int64_t(p.y) - q.y;
        if (inserted(i)) {
            const int64_t d2 = dx * dx + dy * dy;
            if (d2 < best.d2) best = {i, d2};
        }
        const int64_t diff = (depth & 1) == 0 ? dx : dy;
        // Points equal to the split value can lie on either side of it.
        if (diff <= 0) {
            search(lo, mid, depth + 1, p, limit, inserted, best);
            if (diff * diff <= best.d2) search(mid + 1, hi, depth + 1, p, limit, inserted, best);
        } else {
            search(mid + 1, hi, depth + 1, p, limit, inserted, best);
            if (diff * diff <= best.d2) search(lo, mid, depth + 1, p, limit, inserted, best);
        }
    }

    Index* order_;
    Index* minrank_;
    uint32_t n_;
    PointAt point_;
};

} // namespace facet::cdt
