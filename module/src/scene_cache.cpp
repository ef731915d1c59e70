// The mesh and the edges' samples as caches of fixed bytes. Both are written at their ends: a
// face tessellated again (its block refined as the view came nearer) takes new room and leaves
// its old mesh behind; a block's edges sampled again leave their old samples behind. Nothing
// points into either but the faces' FaceInfo and the edges' first sample, so the live parts
// can be moved down over what was left behind, in the order they lie. And the blocks of a
// model larger than the memory, in and out as the view asks (swap.cpp): a block brought in
// numbered as it was at load, one left out leaving its meshes and samples behind.
#include "scene.h"

#include <cstring>

namespace facet::module {

void Scene::evict(uint32_t f) {
    FaceInfo& info = mem_.faces[f];
    if (info.state != FaceState::Done) return;
    Totals& t = totals_;
    t.vertices -= info.vertex_count, t.triangles -= info.triangle_count;
    uint32_t* order = mem_.done_order.data();
    for (uint32_t k = 0; k < t.done; ++k) {
        if (order[k] != f) continue;
        std::memmove(order + k, order + k + 1, (t.done - k - 1) * sizeof(uint32_t));
        break;
    }
    --t.done, ++t.deferred;
    info.first_vertex = info.vertex_count = info.first_index = info.triangle_count = 0;
    info.state = FaceState::Deferred;
}

bool Scene::compact() {
    if (vertex_top_ == totals_.vertices && triangle_top_ == totals_.triangles) return false;
    // The done faces by where their meshes lie (a heap sort: no memory but the order itself).
    uint32_t* order = mem_.done_order.data();
    const uint32_t n = totals_.done;
    const FaceInfo* faces = mem_.faces.data();
    auto key = [&](uint32_t k) { return faces[order[k]].first_vertex; };
    auto sift = [&](uint32_t root, uint32_t end) {
        for (uint32_t child; (child = 2 * root + 1) < end; root = child) {
            if (child + 1 < end && key(child + 1) > key(child)) ++child;
            if (key(root) >= key(child)) return;
            std::swap(order[root], order[child]);
        }
    };
    for (uint32_t k = n / 2; k-- > 0;) sift(k, n);
    for (uint32_t end = n; end > 1; --end) {
        std::swap(order[0], order[end - 1]);
        sift(0, end - 1);
    }
    uint32_t vertices = 0, triangles = 0;
    for (uint32_t k = 0; k < n; ++k) {
        FaceInfo& info = mem_.faces[order[k]];
        if (info.first_vertex != vertices) {
            std::memmove(&mem_.vertices[vertices], &mem_.vertices[info.first_vertex], info.vertex_count * sizeof(DrawVertex));
            info.first_vertex = vertices;
        }
        if (info.first_index != 3 * triangles) {
            std::memmove(&mem_.indices[3 * triangles], &mem_.indices[info.first_index], 3 * info.triangle_count * sizeof(uint16_t));
            info.first_index = 3 * triangles;
        }
        vertices += info.vertex_count, triangles += info.triangle_count;
    }
    vertex_top_ = vertices, triangle_top_ = triangles;
    ++moves_;
    return true;
}

bool Scene::compact_samples(std::span<uint32_t> scratch) {
    const uint32_t blocks = block_count();
    if (scratch.size() < 3 * size_t(blocks)) return false;
    uint32_t *start = scratch.data(), *end = start + blocks, *order = end + blocks;
    geom::EdgeSamples& s = mem_.samples;
    for (uint32_t b = 0; b < blocks; ++b) {
        const Block& block = blocks_[b];
        start[b] = UINT32_MAX, end[b] = 0;
        for (uint32_t e = block.first_edge; e < block.first_edge + block.pack.edges().size(); ++e) {
            if (s.count[e] == 0) continue;
            start[b] = std::min(start[b], s.first[e]);
            end[b] = std::max(end[b], s.first[e] + s.count[e]);
        }
        // By where they lie (an insertion sort: a few hundred blocks, and this is rare).
        uint32_t k = b;
        for (; k > 0 && start[order[k - 1]] > start[b]; --k) order[k] = order[k - 1];
        order[k] = b;
    }
    uint32_t top = 0;
    for (uint32_t k = 0; k < blocks; ++k) {
        const uint32_t b = order[k];
        if (start[b] == UINT32_MAX) continue; // no samples
        const uint32_t count = end[b] - start[b], down = start[b] - top;
        if (down) {
            std::memmove(&s.t[top], &s.t[start[b]], count * sizeof(float));
            std::memmove(&s.p[top], &s.p[start[b]], count * sizeof(geom::Vec3));
            std::memmove(&mem_.sample_q[3 * size_t(top)], &mem_.sample_q[3 * size_t(start[b])], 3 * count * sizeof(int32_t));
            const Block& block = blocks_[b];
            for (uint32_t e = block.first_edge; e < block.first_edge + block.pack.edges().size(); ++e) {
                if (s.count[e]) s.first[e] -= down;
            }
        }
        top += count;
    }
    if (top == s.used) return false;
    s.used = top; // (the same samples, moved: nothing drawn changes)
    return true;
}

Result Scene::take_block(uint32_t b) {
    Block& block = blocks_[b];
    if (!blocked_ || !block.left_out) return Result::fail(Status::OutOfRange, "the block is not left out", {"block", b});
    if (Result r = check_block(index_, b); !r.ok()) {
        block.pack = {};
        return r;
    }
    block.left_out = false, block.refused = false;
    block.tolerance = block.previous_tolerance = 0;
    for (uint32_t e = block.first_edge; e < block.first_edge + block.edges; ++e) mem_.samples.first[e] = 0, mem_.samples.count[e] = 0;
    for (uint32_t f = block.first_face; f < block.first_face + block.faces; ++f) mem_.faces[f] = no_mesh(FaceState::Pending);
    tally_left_out(b, false);
    totals_.faces += block.faces; // (drawn as while left out, its proxy or box, until its edges are sampled)
    return {};
}

void Scene::drop_block(uint32_t b) {
    Block& block = blocks_[b];
    if (!blocked_ || block.left_out) return;
    Totals& t = totals_;
    const uint32_t first = block.first_face, end = block.first_face + block.faces;
    for (uint32_t f = first; f < end; ++f) { // (a done face's mesh garbage until compact())
        FaceInfo& info = mem_.faces[f];
        if (info.state == FaceState::Done) t.vertices -= info.vertex_count, t.triangles -= info.triangle_count;
        if (info.state == FaceState::Deferred) --t.deferred;
        if (info.state == FaceState::Failed) --t.failed;
        info = no_mesh(FaceState::Absent);
    }
    uint32_t kept = 0;
    for (uint32_t k = 0; k < t.done; ++k) {
        const uint32_t f = mem_.done_order[k];
        if (f < first || f >= end) mem_.done_order[kept++] = f;
    }
    t.done = kept;
    for (uint32_t e = block.first_edge; e < block.first_edge + block.edges; ++e) mem_.samples.count[e] = 0; // (garbage in the pool)
    block.left_out = true, block.pack = {}, block.data = nullptr, block.tolerance = block.previous_tolerance = 0;
    tally_left_out(b, true);
    totals_.faces -= block.faces;
    ++moves_;
}

} // namespace facet::module
