#pragma once
// A part's proxy (issue 52): a coarse mesh that stands for the part wherever the view shows it
// small, so that a part whose block is not in memory is drawn as itself, not as a box. Made by
// the packer from the exact geometry: the part's faces tessellated at a coarse tolerance, then
// simplified by edge collapses of least quadric error until at most `max_triangles` remain
// (simplify.h). Its error is the tolerance plus the farthest the simplified mesh and the
// tessellation are from each other, measured: the device draws the proxy while that is under
// its screen-error bound, and the part itself when it is not.
#include "geom/pack.h"
#include "geom/vec.h"

#include <span>
#include <string>
#include <vector>

namespace facet::geom {

struct Proxy {
    std::vector<Vec3> points;         // shell coordinates, mm
    std::vector<uint32_t> triangles;  // three per triangle, wound as the faces are (outward on a solid)
    std::vector<Vec3> normals;        // one per triangle, unit
    float error_mm = 0;               // how far it may stray from the part's surface
    uint32_t colour = pack::kNoIndex; // the pack's Colours index most of its triangles have (kNoIndex: none)
};

// The proxies of every shell of `pack` at each level: shell s's level l at s x levels + l, the
// level at most caps[l] triangles (caps ascending: the coarsest first, as ProxyParts orders
// them; at most pack::kMostProxyLevels); a finer level with more than half the triangles of
// the part's tessellation is the coarser one again. False (with the reason) when the pack's edges cannot
// be sampled; a shell whose faces give no triangle has empty proxies (drawn as its box).
bool make_proxies(const Pack& pack, std::span<const uint32_t> caps, std::vector<Proxy>& out, std::string& error);

} // namespace facet::geom
