// Groups of instances in a frame (presenter.h; a blocked pack's index: pack::Group): a group
// off the view is passed whole, and one the view shows small enough, in a crowded view or one
// of the layout, is drawn as its proxy instead of its members.
#include "presenter.h"

#include <cmath>

namespace facet::module {

uint32_t Presenter::instance_at(uint32_t k) const {
    return scene_.blocked() && !scene_.index().groups().empty() ? scene_.index().group_members()[k] : k;
}

Presenter::GroupVerdict Presenter::judge_group(uint32_t g, uint32_t& level) {
    if (scene_.explode() != 0) return GroupVerdict::Members; // (its box and proxy are the assembled model's)
    const geom::PackIndex& index = scene_.index();
    const pack::Group& group = index.groups()[g];
    const float inv = 1.0f / scene_.unit();
    int32_t centre[3];
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        centre[k] = int32_t(std::lround(0.5f * (group.box_min[k] + group.box_max[k]) * inv));
        const float half = 0.5f * (group.box_max[k] - group.box_min[k]) * inv + 1.0f;
        r2 += half * half;
    }
    const int32_t radius = int32_t(std::sqrt(r2)) + 2;
    bool closed = true;
    const auto members = index.group_members().subspan(group.first_member, group.member_count);
    for (const uint32_t i : members) closed = closed && index.parts()[scene_.instances()[i].shell].closed;
    group_transform_ = model_transform(closed);
    const Transform& t = group_transform_;
    const Transform::Sight sight = t.sight(centre, radius, painter_.rows(t));
    if (sight == Transform::Sight::Out) return GroupVerdict::Out;
    // Its members stand as proxies anyway where every one is left out (or not sampled yet), or
    // a few pixels across: parts that small merge into its proxy.
    bool left_out = true;
    uint32_t fewest = 0; // the triangles of the members' coarsest proxies
    for (const uint32_t i : members) {
        const uint32_t shell = scene_.instances()[i].shell;
        left_out = left_out && scene_.part_boxed(shell);
        fewest += index.proxy_levels() ? index.proxy(shell, 0).triangle_count : 0;
    }
    using Need = Painter::ProxyNeed;
    const int32_t largest = int32_t(group.member_radius_mm * inv) + 2; // (the largest member's sphere)
    const bool small = !left_out && painter_.all_tiny(centre, radius, largest, t);
    const Need need = job_.boxes ? Need::Coarsest : left_out || small ? Need::Must : Need::Optional;
    // A level stands for the members where it costs no more than they would at the least: their
    // coarsest proxies, and each instance's own work (its transform, sphere and level: about
    // kInstanceTriangles triangles' worth on the ARM926).
    constexpr uint32_t kInstanceTriangles = 12;
    level = painter_.group_level(g, centre, radius, t, need, fewest + kInstanceTriangles * group.member_count);
    if (level == kNone) return GroupVerdict::Members;
    if (t.cut_may_cross(centre, radius)) return GroupVerdict::Members; // (the section draws its members cut, each)
    for (const uint32_t i : members) {
        if (!scene_.shown(i) || painter_.lit_instance(i)) return GroupVerdict::Members;
    }
    return GroupVerdict::Proxy;
}

bool Presenter::in_group_whole(uint32_t instance) {
    if (!scene_.blocked() || scene_.index().groups().empty()) return false;
    const uint32_t g = scene_.index().group_of(instance);
    if (job_.judged_group != g) { // (one verdict a group and frame: its members' faces come one after another)
        uint32_t level;
        job_.judged_group = g, job_.group_whole = judge_group(g, level) != GroupVerdict::Members;
    }
    return job_.group_whole;
}

uint32_t Presenter::pass_group(bool faces, uint32_t& spent) {
    if (!scene_.blocked() || scene_.index().groups().empty()) return 0;
    const geom::PackIndex& index = scene_.index();
    const uint32_t g = index.group_of(index.group_members()[job_.instance]);
    const pack::Group& group = index.groups()[g];
    if (group.first_member != job_.instance) return 0; // (within a group whose members are drawn each)
    uint32_t level = kNone;
    const GroupVerdict verdict = judge_group(g, level);
    spent += 1 + group.member_count / 8;
    if (verdict == GroupVerdict::Members) return 0;
    if (verdict == GroupVerdict::Proxy && faces) spent += painter_.group_proxy(g, group_transform_, level), ++job_.groups_drawn;
    return group.member_count;
}

} // namespace facet::module
