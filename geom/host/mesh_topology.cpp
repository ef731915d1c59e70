#include "mesh_topology.h"

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

namespace facet::geom {

EdgeTopology edge_topology(const std::vector<TopoTriangle>& triangles, const std::function<void(const BadEdge&)>& on_bad_edge) {
    std::map<std::tuple<uint32_t, float, float, float>, uint32_t> weld;
    std::vector<const float*> position;
    std::vector<std::array<uint32_t, 3>> ids(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        const TopoTriangle& T = triangles[t];
        for (int k = 0; k < 3; ++k) {
            const auto [it, added] = weld.emplace(std::make_tuple(T.group, T.p[k][0], T.p[k][1], T.p[k][2]), uint32_t(position.size()));
            if (added) position.push_back(T.p[k]);
            ids[t][k] = it->second;
        }
    }
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> uses; // welded edge -> triangles
    std::map<std::array<uint32_t, 3>, std::vector<uint32_t>> by_corners;  // sorted corners -> faces
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            uint32_t a = ids[t][k], b = ids[t][(k + 1) % 3];
            if (a == b) continue;
            if (a > b) std::swap(a, b);
            uses[{a, b}].push_back(t);
        }
        std::array<uint32_t, 3> c = ids[t];
        std::sort(c.begin(), c.end());
        by_corners[c].push_back(triangles[t].face);
    }
    auto doubled = [&](uint32_t t) {
        std::array<uint32_t, 3> c = ids[t];
        std::sort(c.begin(), c.end());
        const std::vector<uint32_t>& f = by_corners[c];
        return std::any_of(f.begin(), f.end(), [&](uint32_t x) { return x != f[0]; });
    };
    EdgeTopology n;
    for (const auto& [e, ts] : uses) {
        if (ts.size() == 1) ++n.free;
        else if (ts.size() > 2) (std::any_of(ts.begin(), ts.end(), doubled) ? n.overlap : n.nonmanifold) += 1;
        if (ts.size() != 2 && on_bad_edge) on_bad_edge({position[e.first], position[e.second], ts});
    }
    return n;
}

} // namespace facet::geom
