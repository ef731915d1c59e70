#pragma once
// A part's proxy (issue 52): a coarse mesh that stands for the part wherever the view shows it
// small, so that a part whose block is not in memory is drawn as itself, not as a box. Made by
// the packer from the exact geometry: the part's faces tessellated at a coarse tolerance, then
// its vertices merged on a grid over the part's box (vertex clustering), the grid coarsened
// until at most `max_triangles` remain. Its error bound is the tolerance plus a grid cell's
// diagonal: the device draws the proxy while that is under its screen-error bound, and brings
// the part's block in when it is not.
#include "geom/pack.h"
#include "geom/vec.h"

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

// The proxies of every shell of `pack`, each at most `max_triangles` triangles. False (with the
// reason) when the pack's edges cannot be sampled; a shell whose faces give no triangle has an
// empty proxy (drawn as its box).
bool make_proxies(const Pack& pack, uint32_t max_triangles, std::vector<Proxy>& out, std::string& error);

} // namespace facet::geom
