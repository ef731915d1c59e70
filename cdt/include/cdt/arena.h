#pragma once
// Storage for one face's triangulation, owned by the caller.
//
// ArenaView is capacity-free: spans over buffers that can sit anywhere (a linker section on the
// device). Arena<Index, V> owns fixed arrays sized for V vertices (including the 4 box
// corners) and derives from the view, like etl::vector<T, N> from etl::ivector<T>.
//
// Worst case reserved up front: a triangulation of V vertices with a 4-vertex hull has exactly
// 2V - 6 triangles, so triangles never run out before vertices do. `work` serves the walks,
// flips, constraint cavities and the flood fill; `order`, `minseq`, `ins` and `keys` serve
// the face pipeline (kd-tree, insertion order, Hilbert keys, then point -> vertex).
#include "cdt/types.h"

#include <cstddef>
#include <span>

namespace facet::cdt {

template <typename Index>
struct ArenaView {
    std::span<Vertex<Index>> vertices;
    std::span<Triangle<Index>> triangles;
    std::span<Index> work;
    std::span<Index> order;
    std::span<Index> minseq;
    std::span<Index> ins;
    std::span<uint32_t> keys;
};

constexpr size_t triangles_for(size_t vertices) { return vertices >= 4 ? 2 * vertices - 6 : 0; }
constexpr size_t work_for(size_t vertices) { return 8 * vertices + 64; }

template <typename Index, size_t V>
struct Arena {
    static_assert(V >= 8, "an arena needs room for the box and some points");
    static_assert(triangles_for(V) < size_t(kNone<Index>), "index type too narrow for V");

    Vertex<Index> vertices[V];
    Triangle<Index> triangles[triangles_for(V)];
    Index work[work_for(V)];
    Index order[V];
    Index minseq[V];
    Index ins[V];
    uint32_t keys[V];

    ArenaView<Index> view() {
        return {vertices, triangles, work, order, minseq, ins, keys};
    }
};

// Bytes an Arena<Index, V> occupies (for budgets and documentation).
template <typename Index>
constexpr size_t arena_bytes(size_t v) {
    return v * sizeof(Vertex<Index>) + triangles_for(v) * sizeof(Triangle<Index>) +
           work_for(v) * sizeof(Index) + 3 * v * sizeof(Index) + v * sizeof(uint32_t);
}

} // namespace facet::cdt
