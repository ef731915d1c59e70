// Parts' proxies (geom/host/proxies.h, issue 52): each part of a model of every surface kind
// gets a coarse mesh within its triangle cap, inside its box, wound as its faces (its normals
// point out of a closed solid), with an error bound that covers how far it strays; the index
// carries them (ProxyParts, ProxyVertices, ProxyTriangles), checked when it is opened. Groups of
// nearby instances (geom/host/groups.h) hold every instance once, and their proxies within their
// caps and boxes; the index carries them (Groups, GroupMembers, GroupPieces, InstanceGroups).
#include "../geom/shapes.h"
#include "geom/bounds.h"
#include "geom/pack_index.h"
#include "groups.h"
#include "pack_blocks.h"
#include "proxies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;
using facet::test::Bytes;

namespace {

Bytes shapes_pack(uint32_t copies) {
    const test::Bytes shapes[] = {test::plate_with_holes(), test::sphere(), test::torus(), test::trimmed_bspline()};
    std::vector<Pack> packs(copies);
    for (uint32_t k = 0; k < copies; ++k) EXPECT_TRUE(packs[k].open(shapes[k % 4].data(), uint32_t(shapes[k % 4].size())).ok());
    return combine_packs(packs, 150.0f);
}

// `pack` blocked with its parts' proxies at `caps` (made into `proxies`) and its groups' at
// `group_caps` (none: no groups), as `file` and as words a PackIndex opens in place.
std::vector<uint32_t> blocked_aligned(const Pack& pack, std::span<const uint32_t> caps, std::span<const uint32_t> group_caps,
                                      std::vector<Proxy>& proxies, Bytes& file) {
    std::string error;
    EXPECT_TRUE(make_proxies(pack, caps, proxies, error)) << error;
    EXPECT_TRUE(make_blocked(pack, {}, {1, BlockStore::Lzma, &proxies, group_caps}, file, error)) << error;
    std::vector<uint32_t> aligned(file.size() / 4 + 1);
    std::memcpy(aligned.data(), file.data(), file.size());
    return aligned;
}

} // namespace

TEST(Proxies, EachPartHasACoarseMeshWithinItsCapAndBox) {
    const Bytes bytes = shapes_pack(4);
    Pack pack;
    ASSERT_TRUE(pack.open(bytes.data(), uint32_t(bytes.size())).ok());
    for (const uint32_t cap : {12u, 40u, 200u}) {
        std::vector<Proxy> proxies;
        std::string error;
        ASSERT_TRUE(make_proxies(pack, std::span(&cap, 1), proxies, error)) << error;
        ASSERT_EQ(proxies.size(), pack.shells().size());
        for (uint32_t s = 0; s < proxies.size(); ++s) {
            const Proxy& p = proxies[s];
            ASSERT_GT(p.triangles.size(), 0u) << "shell " << s;
            EXPECT_LE(p.triangles.size() / 3, std::max(cap, 4u) * 2) << "shell " << s << " near its cap (the coarsest grid takes what is left)";
            EXPECT_EQ(p.normals.size(), p.triangles.size() / 3);
            for (uint32_t v : p.triangles) EXPECT_LT(v, p.points.size());
            for (const Vec3& n : p.normals) EXPECT_NEAR(length(n), 1.0f, 1e-3f);
            // Inside the shell's box, grown by the error bound.
            const Box3 box = shell_box(pack, s);
            for (const Vec3& q : p.points) {
                const float c[3] = {q.x, q.y, q.z};
                for (int k = 0; k < 3; ++k) {
                    EXPECT_GE(c[k], box.lo[k] - p.error_mm) << "shell " << s;
                    EXPECT_LE(c[k], box.hi[k] + p.error_mm) << "shell " << s;
                }
            }
            EXPECT_GT(p.error_mm, 0.0f);
        }
    }
}

// A closed solid's proxy is wound as its faces: its triangles' normals point away from its
// centre on the whole (the sphere's all of them).
TEST(Proxies, AClosedSolidsProxyFacesOut) {
    const test::Bytes sphere = test::sphere();
    Pack pack;
    ASSERT_TRUE(pack.open(sphere.data(), uint32_t(sphere.size())).ok());
    std::vector<Proxy> proxies;
    std::string error;
    const uint32_t caps[] = {80};
    ASSERT_TRUE(make_proxies(pack, caps, proxies, error)) << error;
    ASSERT_EQ(proxies.size(), 1u);
    const Proxy& p = proxies[0];
    Vec3 centre{0, 0, 0};
    for (const Vec3& q : p.points) centre = centre + q;
    centre = centre * (1.0f / float(p.points.size()));
    uint32_t out = 0;
    for (size_t t = 0; t < p.normals.size(); ++t) {
        const Vec3 mid = (p.points[p.triangles[3 * t]] + p.points[p.triangles[3 * t + 1]] + p.points[p.triangles[3 * t + 2]]) * (1.0f / 3);
        out += dot(p.normals[t], mid - centre) > 0;
    }
    EXPECT_EQ(out, p.normals.size());
}

TEST(Proxies, TheIndexCarriesThemAndRefusesBadOnes) {
    const Bytes bytes = shapes_pack(8);
    Pack pack;
    ASSERT_TRUE(pack.open(bytes.data(), uint32_t(bytes.size())).ok());
    std::vector<Proxy> proxies;
    std::string error;
    const uint32_t caps[] = {12, 48};
    Bytes file;
    std::vector<uint32_t> aligned = blocked_aligned(pack, caps, {}, proxies, file);
    PackIndex index;
    ASSERT_TRUE(index.open(aligned.data(), uint32_t(file.size())).ok());
    ASSERT_EQ(index.proxy_levels(), 2u);
    ASSERT_EQ(index.proxy_parts().size(), 2 * index.parts().size());
    for (uint32_t s = 0; s < index.parts().size(); ++s) {
        for (uint32_t l = 0; l < 2; ++l) {
            const pack::ProxyPart& x = index.proxy(s, l);
            EXPECT_EQ(x.triangle_count, proxies[2 * s + l].triangles.size() / 3) << "part " << s << " level " << l;
            EXPECT_EQ(x.vertex_count, proxies[2 * s + l].points.size());
            EXPECT_LE(x.triangle_count, caps[l]);
        }
        // Each side's neighbour has the side the other way round.
        for (uint32_t l = 0; l < 2; ++l) {
            const pack::ProxyPart& x = index.proxy(s, l);
            const pack::ProxyTriangle* t = index.proxy_triangles().data() + x.first_triangle;
            for (uint32_t k = 0; k < x.triangle_count; ++k)
                for (int side = 0; side < 3; ++side) {
                    const uint16_t n = t[k].across[side];
                    if (n == pack::kNoProxyNeighbour) continue;
                    ASSERT_LT(n, x.triangle_count);
                    const uint16_t a = t[k].v[side], b = t[k].v[(side + 1) % 3];
                    bool back = false;
                    for (int j = 0; j < 3; ++j) back = back || (t[n].v[j] == b && t[n].v[(j + 1) % 3] == a);
                    EXPECT_TRUE(back) << "part " << s << " level " << l << " triangle " << k << " side " << side;
                }
        }
        // The coarser level as far as the finer, or farther; fewer triangles.
        EXPECT_GE(index.proxy(s, 0).error_mm, index.proxy(s, 1).error_mm);
        EXPECT_LE(index.proxy(s, 0).triangle_count, index.proxy(s, 1).triangle_count);
    }
    // Without proxies: an index as before (none).
    Bytes plain;
    ASSERT_TRUE(make_blocked(pack, {}, {1, BlockStore::Lzma, nullptr}, plain, error));
    std::vector<uint32_t> a2(plain.size() / 4 + 1);
    std::memcpy(a2.data(), plain.data(), plain.size());
    ASSERT_TRUE(index.open(a2.data(), uint32_t(plain.size())).ok());
    EXPECT_TRUE(index.proxy_parts().empty());
    // A triangle's corner past its part's vertices, fixed up with the CRC: refused, with its place.
    ASSERT_TRUE(index.open(aligned.data(), uint32_t(file.size())).ok());
    const auto* h = reinterpret_cast<const pack::IndexHeader*>(aligned.data());
    auto* tri = const_cast<pack::ProxyTriangle*>(index.proxy_triangles().data());
    auto* levels = const_cast<pack::ProxyPart*>(index.proxy_parts().data());
    const uint16_t corner = tri[0].v[1];
    tri[0].v[1] = 60000;
    auto* mh = reinterpret_cast<pack::IndexHeader*>(aligned.data());
    mh->crc32 = pack::crc32(reinterpret_cast<const uint8_t*>(aligned.data()) + pack::kIndexCrcFrom, h->index_bytes - pack::kIndexCrcFrom);
    const Result r = index.open(aligned.data(), uint32_t(file.size()));
    EXPECT_EQ(r.status, Status::Corrupt);
    EXPECT_NE(std::string(r.where.kind ? r.where.kind : "").find("ProxyTriangles"), std::string::npos);
    // A neighbour past its level's triangles: refused.
    tri[0].v[1] = corner;
    const uint16_t across = tri[0].across[0];
    tri[0].across[0] = pack::kNoProxyNeighbour - 1; // (no level has so many)
    mh->crc32 = pack::crc32(reinterpret_cast<const uint8_t*>(aligned.data()) + pack::kIndexCrcFrom, h->index_bytes - pack::kIndexCrcFrom);
    const Result stranger = index.open(aligned.data(), uint32_t(file.size()));
    EXPECT_EQ(stranger.status, Status::Corrupt);
    EXPECT_NE(std::string(stranger.what).find("neighbour"), std::string::npos) << stranger.what;
    tri[0].across[0] = across;
    // A finer level that claims to stray farther than the coarser: refused, with its record.
    levels[3].error_mm = levels[2].error_mm * 2 + 1;
    mh->crc32 = pack::crc32(reinterpret_cast<const uint8_t*>(aligned.data()) + pack::kIndexCrcFrom, h->index_bytes - pack::kIndexCrcFrom);
    const Result farther = index.open(aligned.data(), uint32_t(file.size()));
    EXPECT_EQ(farther.status, Status::Corrupt);
    EXPECT_NE(std::string(farther.what).find("farther"), std::string::npos) << farther.what;
    EXPECT_EQ(farther.where.index, 3u);
}

TEST(Groups, EveryInstanceIsInOneGroupAndEachGroupsProxyIsWithinItsCapAndBox) {
    const Bytes bytes = shapes_pack(40); // (a row of 40 parts: groups of 10)
    Pack pack;
    ASSERT_TRUE(pack.open(bytes.data(), uint32_t(bytes.size())).ok());
    std::vector<Proxy> proxies;
    std::string error;
    const uint32_t caps[] = {12, 48}, group_caps[] = {24, 96};
    Bytes file;
    std::vector<uint32_t> aligned = blocked_aligned(pack, caps, group_caps, proxies, file);
    PackIndex index;
    ASSERT_TRUE(index.open(aligned.data(), uint32_t(file.size())).ok());
    const auto groups = index.groups();
    ASSERT_GE(groups.size(), 3u);
    ASSERT_EQ(index.group_levels(), 2u);
    std::vector<int> seen(index.instances().size(), 0);
    for (uint32_t g = 0; g < groups.size(); ++g) {
        const pack::Group& x = groups[g];
        EXPECT_LE(x.member_count, kMostMembers);
        for (uint32_t m = x.first_member; m < x.first_member + x.member_count; ++m) {
            const uint32_t i = index.group_members()[m];
            ++seen[i];
            EXPECT_EQ(index.group_of(i), g);
            // The member's part box, placed (here a shift along x), inside the group's box.
            const pack::Instance& inst = index.instances()[i];
            const pack::Part& part = index.parts()[inst.shell];
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(part.box_min[k] + inst.m[4 * k + 3], x.box_min[k] - 1e-3f) << "group " << g << " instance " << i;
                EXPECT_LE(part.box_max[k] + inst.m[4 * k + 3], x.box_max[k] + 1e-3f) << "group " << g << " instance " << i;
            }
        }
        for (uint32_t l = 0; l < 2; ++l) {
            uint32_t triangles = 0;
            for (uint32_t c = 0; c < x.colours; ++c) {
                const pack::ProxyPart& piece = index.group_piece(g, l, c);
                triangles += piece.triangle_count;
                if (l) {
                    EXPECT_LE(piece.error_mm, index.group_piece(g, 0, c).error_mm) << "the finer level strays less";
                }
            }
            EXPECT_GT(triangles, 0u);
            EXPECT_LE(triangles, group_caps[l] + 4 * x.colours) << "group " << g << " level " << l << " (each colour's share at least 4)";
        }
    }
    for (uint32_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "instance " << i;
    // Groups far apart along the row: their boxes do not overlap much (made from space).
    for (uint32_t g = 1; g < groups.size(); ++g) EXPECT_NE(groups[g].box_min[0], groups[0].box_min[0]);

    // A member listed twice (another dropped), or an instance's group that lists it not: refused.
    const auto* h = reinterpret_cast<const pack::IndexHeader*>(aligned.data());
    auto refix = [&] {
        auto* mh = reinterpret_cast<pack::IndexHeader*>(aligned.data());
        mh->crc32 = pack::crc32(reinterpret_cast<const uint8_t*>(aligned.data()) + pack::kIndexCrcFrom, h->index_bytes - pack::kIndexCrcFrom);
        return index.open(aligned.data(), uint32_t(file.size()));
    };
    auto* members = const_cast<uint32_t*>(index.group_members().data());
    const uint32_t kept = members[groups[1].first_member];
    members[groups[1].first_member] = members[0];
    const Result twice = refix();
    EXPECT_EQ(twice.status, Status::Corrupt);
    EXPECT_NE(std::string(twice.where.kind ? twice.where.kind : "").find("GroupMembers"), std::string::npos);
    members[groups[1].first_member] = kept;
    ASSERT_TRUE(refix().ok());
    auto* group_records = const_cast<pack::Group*>(index.groups().data());
    const float right = group_records[0].box_max[0];
    group_records[0].box_max[0] = group_records[0].box_min[0] - 1; // an inverted box
    const Result inverted = refix();
    EXPECT_EQ(inverted.status, Status::Corrupt);
    EXPECT_NE(std::string(inverted.where.kind ? inverted.where.kind : "").find("Groups"), std::string::npos);
    // A box that leaves out part of a member (the viewer would pass it off the view), or a radius
    // under a member's: refused.
    group_records[0].box_max[0] = right - 10; // (the records where they lie in `aligned`)
    const Result short_box = refix();
    EXPECT_EQ(short_box.status, Status::Corrupt);
    EXPECT_NE(std::string(short_box.what).find("outside its group's box"), std::string::npos) << short_box.what;
    group_records[0].box_max[0] = right;
    ASSERT_TRUE(refix().ok());
    group_records[0].member_radius_mm *= 0.5f;
    const Result small = refix();
    EXPECT_EQ(small.status, Status::Corrupt);
}
