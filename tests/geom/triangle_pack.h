#pragma once
// A small valid pack for the pack file tests: one plane face, a triangle of straight edges.
#include "geom/pack_format.h"
#include "pack_writer.h"

#include <cstdint>
#include <vector>

namespace facet::geom::test {

inline std::vector<uint8_t> triangle_pack() {
    PackWriter w;
    const uint32_t v0 = w.add_vertex(0, 0, 0), v1 = w.add_vertex(10, 0, 0), v2 = w.add_vertex(0, 10, 0);
    const uint32_t e0 = w.add_edge({pack::kStraight, 0, 10, v0, v1, 1e-7f, 0});
    const uint32_t e1 = w.add_edge({pack::kStraight, 0, 14.142f, v1, v2, 1e-7f, 0});
    const uint32_t e2 = w.add_edge({pack::kStraight, 0, 10, v2, v0, 1e-7f, 0});
    const uint32_t first = w.coedge_count();
    for (uint32_t e : {e0, e1, e2}) w.add_coedge(pack::Coedge::make(e, false, pack::Seam::None));
    const uint32_t loop = w.add_loop({first, 3});
    const uint32_t s = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
    w.add_face({s, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {0, 0}, {10, 10}});
    const uint32_t shell = w.add_shell({0, 1, pack::kNoIndex, 0});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

} // namespace facet::geom::test
