// Parts' proxies: a coarse tessellation, merged on a grid (proxies.h).
#include "proxies.h"

#include "edge_pool.h"
#include "geom/tessellate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace facet::geom {
namespace {

constexpr float kCoarser = 8.0f; // the proxies' tolerance: this times the model's default

// One shell's triangles (shell coordinates) and the colour of each.
struct Soup {
    std::vector<Vec3> points;
    std::vector<uint32_t> triangles;
    std::vector<uint32_t> colour; // per triangle: its face's colour index (kNoIndex: none)
};

// The soup merged on a grid of `cells` along the box's longest side: each cell's points become
// their mean, triangles that collapse or repeat are dropped.
Proxy cluster(const Soup& soup, const float lo[3], const float hi[3], uint32_t cells) {
    float extent = 0;
    for (int k = 0; k < 3; ++k) extent = std::max(extent, hi[k] - lo[k]);
    const float cell = extent > 0 ? extent / float(cells) : 1.0f;
    std::map<std::tuple<int, int, int>, uint32_t> cell_of;
    std::vector<uint32_t> remap(soup.points.size());
    std::vector<Vec3> sum;
    std::vector<uint32_t> count;
    for (size_t i = 0; i < soup.points.size(); ++i) {
        const Vec3 p = soup.points[i];
        const auto key = std::make_tuple(int(std::floor((p.x - lo[0]) / cell)), int(std::floor((p.y - lo[1]) / cell)),
                                         int(std::floor((p.z - lo[2]) / cell)));
        auto [it, fresh] = cell_of.try_emplace(key, uint32_t(sum.size()));
        if (fresh) sum.push_back({0, 0, 0}), count.push_back(0);
        sum[it->second] = sum[it->second] + p;
        ++count[it->second];
        remap[i] = it->second;
    }
    Proxy out;
    out.points.resize(sum.size());
    for (size_t c = 0; c < sum.size(); ++c) out.points[c] = sum[c] * (1.0f / float(count[c]));
    std::map<std::tuple<uint32_t, uint32_t, uint32_t>, bool> seen;
    std::map<uint32_t, uint32_t> colour_votes;
    for (size_t t = 0; t + 2 < soup.triangles.size(); t += 3) {
        const uint32_t a = remap[soup.triangles[t]], b = remap[soup.triangles[t + 1]], c = remap[soup.triangles[t + 2]];
        if (a == b || b == c || a == c) continue;
        // (the same three corners in the same turn: one triangle; opposite turns: two sides of a thin wall)
        const uint32_t m = std::min({a, b, c});
        const auto key = m == a ? std::make_tuple(a, b, c) : m == b ? std::make_tuple(b, c, a) : std::make_tuple(c, a, b);
        const Vec3 n = cross(out.points[b] - out.points[a], out.points[c] - out.points[a]);
        if (!(length2(n) > 0)) continue;
        // A triangle the merging turned over (against the one it came from) would show its back.
        const Vec3 &p0 = soup.points[soup.triangles[t]], &p1 = soup.points[soup.triangles[t + 1]], &p2 = soup.points[soup.triangles[t + 2]];
        if (!(dot(n, cross(p1 - p0, p2 - p0)) > 0)) continue;
        if (!seen.emplace(key, true).second) continue;
        out.triangles.insert(out.triangles.end(), {a, b, c});
        out.normals.push_back(normalized(n));
        ++colour_votes[soup.colour[t / 3]];
    }
    // The points no triangle uses dropped, the rest renumbered.
    std::vector<uint32_t> used(out.points.size(), UINT32_MAX);
    std::vector<Vec3> kept;
    for (uint32_t& v : out.triangles) {
        if (used[v] == UINT32_MAX) used[v] = uint32_t(kept.size()), kept.push_back(out.points[v]);
        v = used[v];
    }
    out.points = std::move(kept);
    out.error_mm = std::sqrt(3.0f) * cell;
    uint32_t votes = 0;
    for (const auto& [c, n] : colour_votes)
        if (n > votes) out.colour = c, votes = n;
    return out;
}

} // namespace

bool make_proxies(const Pack& pack, uint32_t max_triangles, std::vector<Proxy>& out, std::string& error) {
    out.assign(pack.shells().size(), Proxy{});
    TessOptions opt;
    opt.tolerance = kCoarser * default_tolerance(pack);
    EdgePool edges;
    if (const Result r = edges.sample(pack, opt, pack.edges().size() * 16 + 1024); !r.ok()) {
        error = std::string("proxies: the edges cannot be sampled: ") + r.what;
        return false;
    }
    const EdgeSamples& samples = edges.samples;
    const FaceCapacity capacity{32760, 32760, 4096, kPatchCacheWords};
    std::vector<uint64_t> face_memory(face_storage_bytes(capacity) / 8 + 1);
    FaceStorage storage;
    if (!storage.bind(face_memory.data(), face_memory.size() * 8, capacity).ok()) {
        error = "proxies: no face storage";
        return false;
    }
    std::vector<MeshVertex> mv(1 << 20);
    std::vector<uint32_t> mi(3u << 20);
    for (uint32_t s = 0; s < pack.shells().size(); ++s) {
        const pack::Shell& sh = pack.shells()[s];
        Soup soup;
        float lo[3] = {3e38f, 3e38f, 3e38f}, hi[3] = {-3e38f, -3e38f, -3e38f};
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            Mesh mesh{mv, mi, {}};
            FaceStats st;
            if (!tessellate_face(pack, f, samples, opt, storage, mesh, st).ok()) continue; // (a face that fails: left out of the proxy)
            const uint32_t base = uint32_t(soup.points.size());
            for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
                const Vec3 p = mv[v].p;
                soup.points.push_back(p);
                lo[0] = std::min(lo[0], p.x), lo[1] = std::min(lo[1], p.y), lo[2] = std::min(lo[2], p.z);
                hi[0] = std::max(hi[0], p.x), hi[1] = std::max(hi[1], p.y), hi[2] = std::max(hi[2], p.z);
            }
            for (uint32_t t = 0; t < 3 * mesh.triangle_count; ++t) soup.triangles.push_back(base + mi[t]);
            const uint32_t colour = pack.faces()[f].colour != pack::kNoIndex ? pack.faces()[f].colour : sh.colour;
            soup.colour.insert(soup.colour.end(), mesh.triangle_count, colour);
        }
        if (soup.triangles.empty()) continue;
        for (uint32_t cells = 64; cells >= 1; cells = cells * 3 / 4) {
            Proxy p = cluster(soup, lo, hi, cells);
            if (p.triangles.size() / 3 <= max_triangles || cells <= 2) {
                p.error_mm += opt.tolerance;
                out[s] = std::move(p);
                break;
            }
        }
    }
    return true;
}

} // namespace facet::geom
