// Parts' proxies: a coarse tessellation, simplified (proxies.h).
#include "proxies.h"

#include "edge_pool.h"
#include "geom/tessellate.h"
#include "simplify.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace facet::geom {
namespace {

constexpr float kCoarser = 2.0f; // the proxies' tolerance: this times the model's default

// One shell's triangles (shell coordinates) and the colour of each.
struct Soup {
    TriangleMesh mesh;
    std::vector<uint32_t> colour; // per triangle: its face's colour index (kNoIndex: none)
};

// The proxy of `coarse`, a simplification of `whole` (the soup welded): its normals, its error
// measured both ways (the proxy's points to the tessellation, and the tessellation's to the
// proxy) plus the tessellation's own, and its colour.
Proxy proxy_of(const TriangleMesh& coarse, const TriangleMesh& whole, float tolerance, uint32_t colour) {
    Proxy out;
    out.points = coarse.points;
    out.triangles = coarse.triangles;
    for (size_t t = 0; t + 2 < coarse.triangles.size(); t += 3) {
        const Vec3 a = coarse.points[coarse.triangles[t]];
        out.normals.push_back(normalized(cross(coarse.points[coarse.triangles[t + 1]] - a, coarse.points[coarse.triangles[t + 2]] - a)));
    }
    out.error_mm = std::max(farthest(whole, coarse), farthest(coarse, whole)) + tolerance;
    out.colour = colour;
    return out;
}

// The colour most of the soup's area has.
uint32_t main_colour(const Soup& soup) {
    std::map<uint32_t, double> area_of;
    const TriangleMesh& m = soup.mesh;
    for (size_t t = 0; t + 2 < m.triangles.size(); t += 3) {
        const Vec3 a = m.points[m.triangles[t]];
        area_of[soup.colour[t / 3]] += length(cross(m.points[m.triangles[t + 1]] - a, m.points[m.triangles[t + 2]] - a));
    }
    uint32_t colour = pack::kNoIndex;
    double most = -1;
    for (const auto& [c, area] : area_of)
        if (area > most) colour = c, most = area;
    return colour;
}

} // namespace

bool make_proxies(const Pack& pack, std::span<const uint32_t> caps, std::vector<Proxy>& out, std::string& error) {
    const size_t levels = caps.size();
    if (levels == 0 || levels > pack::kMostProxyLevels || !std::is_sorted(caps.begin(), caps.end())) {
        error = "proxies: 1 to " + std::to_string(pack::kMostProxyLevels) + " levels, the coarsest first";
        return false;
    }
    out.assign(pack.shells().size() * levels, Proxy{});
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
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            Mesh mesh{mv, mi, {}};
            FaceStats st;
            if (!tessellate_face(pack, f, samples, opt, storage, mesh, st).ok()) continue; // (a face that fails: left out of the proxy)
            const uint32_t base = uint32_t(soup.mesh.points.size());
            for (uint32_t v = 0; v < mesh.vertex_count; ++v) soup.mesh.points.push_back(mv[v].p);
            for (uint32_t t = 0; t < 3 * mesh.triangle_count; ++t) soup.mesh.triangles.push_back(base + mi[t]);
            const uint32_t colour = pack.faces()[f].colour != pack::kNoIndex ? pack.faces()[f].colour : sh.colour;
            soup.colour.insert(soup.colour.end(), mesh.triangle_count, colour);
        }
        if (soup.mesh.triangles.empty()) continue;
        // Finest first, each level simplified from the one finer; each measured against the whole.
        const TriangleMesh whole = welded(soup.mesh);
        const uint32_t colour = main_colour(soup);
        TriangleMesh level = whole;
        for (size_t l = levels; l-- > 0;) {
            level = simplified(level, caps[l]);
            out[s * levels + l] = proxy_of(level, whole, opt.tolerance, colour);
        }
        // A finer level with more than half the part's own triangles (at the proxies'
        // tolerance) spares a frame little: it is the next coarser one again (shared in the
        // index), and the part itself is drawn where that is too coarse.
        for (size_t l = 1; l < levels; ++l)
            if (2 * out[s * levels + l].triangles.size() > whole.triangles.size()) out[s * levels + l] = out[s * levels + l - 1];
    }
    return true;
}

} // namespace facet::geom
