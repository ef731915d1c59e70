#pragma once
// Groups of parts (issue 52): instances near each other in the model, culled as one and drawn
// as one proxy where the view shows the group small, so that a frame of a whole machine does
// not pay for each of its parts. Made by the packer from the space the instances take (the
// assembly tree is not in the pack): the instances split at the median of their boxes' centres
// along the longest side until a group has at most kMostMembers. A group's proxy at each level
// is its members' part proxies placed, merged by colour (a piece each) and simplified to the
// level's triangles (simplify.h); its error is the simplification's, measured both ways, plus
// the part proxies' own.
#include "geom/pack.h"
#include "pack_blocks.h"
#include "proxies.h"

#include <span>
#include <string>
#include <vector>

namespace facet::geom {

struct ProxyGroup {
    std::vector<uint32_t> members;   // instance numbers
    PartBox box{};                   // the members' placed part boxes (the model's coordinates, mm)
    float member_radius_mm = 0;      // the largest member's part's box's half diagonal
    std::vector<uint32_t> colours;   // a piece per colour (the pack's Colours index, or kNoIndex)
    std::vector<Proxy> pieces;       // level l's piece c at l x colours + c: corners in the model's coordinates
};

constexpr uint32_t kMostMembers = 16;

// The groups of `pack`'s instances, each instance in exactly one. `boxes`: each shell's (its own
// coordinates); `proxies`: each shell's at `part_levels` levels (proxies.h), the finest the
// source of the groups' pieces; `caps`: the most triangles a group's proxy has at each level,
// the coarsest first (at most pack::kMostProxyLevels). One group of every instance for a model
// of at most kMostMembers instances. False (with the reason) on inputs that do not match.
bool make_groups(const Pack& pack, const std::vector<PartBox>& boxes, const std::vector<Proxy>& proxies, size_t part_levels,
                 std::span<const uint32_t> caps, std::vector<ProxyGroup>& out, std::string& error);

} // namespace facet::geom
