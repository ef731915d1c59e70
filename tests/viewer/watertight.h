#pragma once
// Whether a part's mesh is watertight: its triangles' sides each shared by two, but along the
// edges of its faces left to their edges (their neighbours' triangles end on those samples).
#include "core.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

namespace facet::test {

// The sides of a part's triangles not shared by exactly two of them (by their ends' positions):
// none for a closed part that is watertight, but along the edges of its faces left to their
// edges (deferred), whose samples the neighbours' triangles end on.
inline size_t open_sides(const module::Scene& scene, uint32_t s) {
    using Point = std::array<int32_t, 3>;
    const module::Part part = scene.part(s);
    std::set<Point> waiting; // the samples of the deferred faces' edges
    const module::Block& block = scene.block(part.block);
    for (uint32_t f = part.first_face; f < part.first_face + part.face_count; ++f) {
        if (scene.face(f).state != module::FaceState::Deferred) continue;
        const pack::Face& F = block.pack.faces()[f - block.first_face];
        for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
            const pack::Loop& L = block.pack.loops()[l];
            for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
                const uint32_t e = block.first_edge + block.pack.coedges()[c].edge();
                for (uint32_t k = 0; k < scene.samples().count[e]; ++k) {
                    const int32_t* q = scene.sample_q(scene.samples().first[e] + k);
                    waiting.insert({q[0], q[1], q[2]});
                }
            }
        }
    }
    std::map<std::pair<Point, Point>, int> uses;
    for (uint32_t f = part.first_face; f < part.first_face + part.face_count; ++f) {
        const module::FaceInfo& F = scene.face(f);
        const uint16_t* id = scene.indices() + F.first_index;
        for (uint32_t t = 0; t < F.triangle_count; ++t, id += 3) {
            for (int k = 0; k < 3; ++k) {
                const int32_t* a = scene.vertices()[F.first_vertex + id[k]].p;
                const int32_t* b = scene.vertices()[F.first_vertex + id[(k + 1) % 3]].p;
                Point pa{a[0], a[1], a[2]}, pb{b[0], b[1], b[2]};
                if (pb < pa) std::swap(pa, pb);
                ++uses[{pa, pb}];
            }
        }
    }
    size_t open = 0;
    for (const auto& [side, n] : uses) open += n != 2 && !(n == 1 && waiting.count(side.first) && waiting.count(side.second));
    return open;
}

// Whether part s is closed, some of its faces tessellated and none failed: what open_sides()
// checks.
inline bool whole(const module::Scene& scene, uint32_t s) {
    const module::Part part = scene.part(s);
    bool some = false, failed = false;
    for (uint32_t f = part.first_face; f < part.first_face + part.face_count; ++f) {
        some = some || scene.face(f).state == module::FaceState::Done;
        failed = failed || scene.face(f).state == module::FaceState::Failed;
    }
    return part.closed && some && !failed;
}

} // namespace facet::test
