// Groups of parts and their proxies (groups.h).
#include "groups.h"

#include "simplify.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace facet::geom {
namespace {

Vec3 placed(const pack::Instance& inst, Vec3 p) {
    const float* m = inst.m;
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}

// Splits instances [first, last) of `order` at the median of their centres along the longest
// side of the centres' box until each part has at most kMostMembers.
void split(std::vector<uint32_t>& order, size_t first, size_t last, const std::vector<PartBox>& at,
           std::vector<std::pair<size_t, size_t>>& groups) {
    if (last - first <= kMostMembers) {
        groups.push_back({first, last});
        return;
    }
    auto centre = [&](uint32_t i, int k) { return 0.5f * (at[i].min[k] + at[i].max[k]); };
    float lo[3] = {3e38f, 3e38f, 3e38f}, hi[3] = {-3e38f, -3e38f, -3e38f};
    for (size_t j = first; j < last; ++j)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], centre(order[j], k)), hi[k] = std::max(hi[k], centre(order[j], k));
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    const size_t mid = first + (last - first) / 2;
    std::nth_element(order.begin() + std::ptrdiff_t(first), order.begin() + std::ptrdiff_t(mid), order.begin() + std::ptrdiff_t(last),
                     [&](uint32_t a, uint32_t b) { return centre(a, axis) < centre(b, axis) || (centre(a, axis) == centre(b, axis) && a < b); });
    split(order, first, mid, at, groups);
    split(order, mid, last, at, groups);
}

Vec3 normal_of(const TriangleMesh& m, size_t t) {
    const Vec3 a = m.points[m.triangles[t]];
    return normalized(cross(m.points[m.triangles[t + 1]] - a, m.points[m.triangles[t + 2]] - a));
}

} // namespace

bool make_groups(const Pack& pack, const std::vector<PartBox>& boxes, const std::vector<Proxy>& proxies, size_t part_levels,
                 std::span<const uint32_t> caps, std::vector<ProxyGroup>& out, std::string& error) {
    const auto instances = pack.instances();
    const size_t shells = pack.shells().size();
    if (boxes.size() != shells || part_levels == 0 || proxies.size() != shells * part_levels || instances.empty()) {
        error = "groups: one box and every level of proxies per part are needed";
        return false;
    }
    if (caps.empty() || caps.size() > pack::kMostProxyLevels || !std::is_sorted(caps.begin(), caps.end())) {
        error = "groups: 1 to " + std::to_string(pack::kMostProxyLevels) + " levels, the coarsest first";
        return false;
    }
    std::vector<PartBox> at(instances.size(), PartBox{{3e38f, 3e38f, 3e38f}, {-3e38f, -3e38f, -3e38f}});
    for (size_t i = 0; i < instances.size(); ++i) grow_by_placed(instances[i], boxes[instances[i].shell], at[i].min, at[i].max);
    std::vector<uint32_t> order(instances.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::vector<std::pair<size_t, size_t>> ranges;
    split(order, 0, order.size(), at, ranges);
    out.clear();
    for (const auto& [first, last] : ranges) {
        ProxyGroup g;
        g.members.assign(order.begin() + std::ptrdiff_t(first), order.begin() + std::ptrdiff_t(last));
        std::sort(g.members.begin(), g.members.end()); // (the model's order within a group)
        g.box = {{3e38f, 3e38f, 3e38f}, {-3e38f, -3e38f, -3e38f}};
        // The members' finest proxies placed, a soup per colour; the farthest any strays.
        std::map<uint32_t, TriangleMesh> soups;
        float strays = 0;
        for (uint32_t i : g.members) {
            for (int k = 0; k < 3; ++k) g.box.min[k] = std::min(g.box.min[k], at[i].min[k]), g.box.max[k] = std::max(g.box.max[k], at[i].max[k]);
            const PartBox& pb = boxes[instances[i].shell];
            const Vec3 half{0.5f * (pb.max[0] - pb.min[0]), 0.5f * (pb.max[1] - pb.min[1]), 0.5f * (pb.max[2] - pb.min[2])};
            g.member_radius_mm = std::max(g.member_radius_mm, length(half));
            const Proxy& x = proxies[instances[i].shell * part_levels + part_levels - 1];
            if (x.triangles.empty()) continue;
            strays = std::max(strays, x.error_mm);
            TriangleMesh& soup = soups[x.colour];
            const uint32_t base = uint32_t(soup.points.size());
            for (const Vec3& p : x.points) soup.points.push_back(placed(instances[i], p));
            // (a mirroring placement turns the winding: put back, so the outside stays out)
            const float* m = instances[i].m;
            const bool mirrored = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                                      m[2] * (m[4] * m[9] - m[5] * m[8]) < 0;
            for (size_t t = 0; t + 2 < x.triangles.size(); t += 3) {
                soup.triangles.push_back(base + x.triangles[t]);
                soup.triangles.push_back(base + x.triangles[t + (mirrored ? 2 : 1)]);
                soup.triangles.push_back(base + x.triangles[t + (mirrored ? 1 : 2)]);
            }
        }
        size_t all = 0;
        for (const auto& [colour, soup] : soups) all += soup.triangle_count(), g.colours.push_back(colour);
        g.pieces.assign(caps.size() * g.colours.size(), Proxy{});
        // Each colour's share of each level's triangles (at least four); each level simplified
        // from the finer one, measured against the whole soup; a level as far as the finer, or farther.
        std::vector<TriangleMesh> whole, level;
        for (const auto& [colour, soup] : soups) whole.push_back(welded(soup)), level.push_back(whole.back());
        float finer_error = 0;
        for (size_t l = caps.size(); l-- > 0;) {
            float error = 0;
            for (size_t c = 0; c < g.colours.size(); ++c) {
                const uint32_t share = std::max<uint32_t>(4, uint32_t(uint64_t(caps[l]) * soups[g.colours[c]].triangle_count() / std::max<size_t>(all, 1)));
                level[c] = simplified(level[c], share);
                if (!level[c].triangles.empty()) error = std::max({error, farthest(whole[c], level[c]), farthest(level[c], whole[c])});
            }
            error = std::max(error + strays, finer_error);
            finer_error = error;
            for (size_t c = 0; c < g.colours.size(); ++c) {
                Proxy& p = g.pieces[l * g.colours.size() + c];
                p.points = level[c].points, p.triangles = level[c].triangles;
                for (size_t t = 0; t + 2 < level[c].triangles.size(); t += 3) p.normals.push_back(normal_of(level[c], t));
                p.error_mm = error, p.colour = g.colours[c];
            }
        }
        out.push_back(std::move(g));
    }
    return true;
}

} // namespace facet::geom
