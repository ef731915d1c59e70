#include "geom/pack_index.h"

#include <cmath>
#include <cstddef>
#include <cstring>

namespace facet::geom {
namespace {

using namespace facet::pack;

bool finite(float f) { return std::fabs(f) <= kMaxMagnitude; }

bool box_ok(const float lo[3], const float hi[3]) {
    for (int k = 0; k < 3; ++k) {
        if (!finite(lo[k]) || !finite(hi[k]) || lo[k] > hi[k]) return false;
    }
    return true;
}

} // namespace

uint32_t first_bad_name(std::span<const char> pool, std::span<const uint32_t> table) {
    for (uint32_t i = 0; i < table.size(); ++i) {
        const uint32_t at = table[i];
        if (at != kNoIndex && (at >= pool.size() || (at > 0 && pool[at - 1] != 0))) return i;
    }
    return kNoIndex;
}

Place index_place(uint32_t id, uint32_t index) {
    switch (IndexSectionId(id)) {
    case IndexSectionId::Instances: return {"index section Instances record", index};
    case IndexSectionId::Names: return {"index section Names byte", index};
    case IndexSectionId::PartNames: return {"index section PartNames record", index};
    case IndexSectionId::InstanceNames: return {"index section InstanceNames record", index};
    case IndexSectionId::Blocks: return {"index section Blocks record", index};
    case IndexSectionId::Parts: return {"index section Parts record", index};
    case IndexSectionId::Needs: return {"index section Needs record", index};
    case IndexSectionId::ProxyParts: return {"index section ProxyParts record", index};
    case IndexSectionId::ProxyVertices: return {"index section ProxyVertices record", index};
    case IndexSectionId::ProxyTriangles: return {"index section ProxyTriangles record", index};
    case IndexSectionId::Groups: return {"index section Groups record", index};
    case IndexSectionId::GroupMembers: return {"index section GroupMembers record", index};
    case IndexSectionId::GroupPieces: return {"index section GroupPieces record", index};
    case IndexSectionId::InstanceGroups: return {"index section InstanceGroups record", index};
    }
    return {"index header"};
}

void PackIndex::parts_box(float lo[3], float hi[3]) const {
    for (int k = 0; k < 3; ++k) lo[k] = INFINITY, hi[k] = -INFINITY;
    for (const pack::Part& part : parts_) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = part.box_min[k] < lo[k] ? part.box_min[k] : lo[k];
            hi[k] = part.box_max[k] > hi[k] ? part.box_max[k] : hi[k];
        }
    }
    if (!(lo[0] <= hi[0])) {
        for (int k = 0; k < 3; ++k) lo[k] = hi[k] = 0;
    }
}

Result PackIndex::fail(const char* what, uint32_t section, uint32_t index) {
    *this = PackIndex{};
    return Result::fail(Status::Corrupt, what, index_place(section, index));
}

Result PackIndex::open(const void* data, uint32_t size, uint32_t file_bytes) {
    *this = PackIndex{};
    const uint8_t* base = static_cast<const uint8_t*>(data);
    if (!data || (reinterpret_cast<uintptr_t>(data) & 3)) return fail("the index is not 4-byte aligned", 0, 0);
    if (size < sizeof(IndexHeader)) return fail("shorter than the index header (truncated)", 0, 0);
    const IndexHeader* h = reinterpret_cast<const IndexHeader*>(base);
    if (std::memcmp(h->magic, kBlockedMagic, 4) != 0) return fail("not a blocked pack (bad magic)", 0, 0);
    if (h->version != kBlockedVersion) return fail("unsupported version", 0, 0);
    if (h->header_bytes != sizeof(IndexHeader)) return fail("unexpected header size", 0, 0);
    if (h->flags != 0 || h->reserved[0] != 0 || h->reserved[1] != 0) return fail("the header's flags or reserved fields are not 0", 0, 0);
    if (h->total_bytes > file_bytes) return fail("the file is longer than the bytes given (truncated)", 0, 0);
    if (h->total_bytes > kMaxBlockedBytes) return fail("larger than the 256 MiB limit", 0, 0);
    if (h->index_bytes < sizeof(IndexHeader) || h->index_bytes > h->total_bytes || (h->index_bytes & 3)) {
        return fail("the index's size is out of range", 0, 0);
    }
    if (h->index_bytes > size) return fail("the index is longer than the bytes read of it", 0, 0);
    if (h->section_count > kMaxSections) return fail("too many sections", 0, 0);
    const uint64_t table_end = sizeof(IndexHeader) + uint64_t(h->section_count) * sizeof(SectionEntry);
    if (table_end > h->index_bytes) return fail("section table runs past the index", 0, 0);
    static_assert(offsetof(IndexHeader, crc32) + sizeof(uint32_t) == kIndexCrcFrom);
    if (pack::crc32(base + kIndexCrcFrom, h->index_bytes - kIndexCrcFrom) != h->crc32) return fail("CRC mismatch", 0, 0);
    if (!box_ok(h->bbox_min, h->bbox_max)) return fail("bounding box is not finite, beyond +-1e8 or inverted", 0, 0);
    if (!finite(h->source_unit_mm) || !(h->source_unit_mm > 0)) return fail("bad source unit", 0, 0);

    const SectionEntry* table = reinterpret_cast<const SectionEntry*>(base + sizeof(IndexHeader));
    uint32_t seen = 0;
    for (uint32_t i = 0; i < h->section_count; ++i) {
        const SectionEntry& s = table[i];
        uint32_t record = 0;
        switch (IndexSectionId(s.id)) {
        case IndexSectionId::Instances: record = sizeof(Instance); break;
        case IndexSectionId::Names: record = 1; break;
        case IndexSectionId::PartNames:
        case IndexSectionId::InstanceNames: record = 4; break;
        case IndexSectionId::Blocks: record = sizeof(pack::Block); break;
        case IndexSectionId::Parts: record = sizeof(pack::Part); break;
        case IndexSectionId::Needs: record = sizeof(pack::Needs); break;
        case IndexSectionId::ProxyParts: record = sizeof(pack::ProxyPart); break;
        case IndexSectionId::ProxyVertices: record = sizeof(pack::ProxyVertex); break;
        case IndexSectionId::ProxyTriangles: record = sizeof(pack::ProxyTriangle); break;
        case IndexSectionId::Groups: record = sizeof(pack::Group); break;
        case IndexSectionId::GroupMembers:
        case IndexSectionId::InstanceGroups: record = 4; break;
        case IndexSectionId::GroupPieces: record = sizeof(pack::ProxyPart); break;
        default: continue; // unknown sections are skipped
        }
        if (seen & (1u << s.id)) return fail("section appears twice", s.id, 0);
        seen |= 1u << s.id;
        if (s.record_bytes != record) return fail("record size does not match this reader", s.id, 0);
        if (s.offset & 3) return fail("section offset is not 4-byte aligned", s.id, 0);
        if (s.offset < table_end || uint64_t(s.offset) + uint64_t(s.count) * s.record_bytes > h->index_bytes) {
            return fail("section lies outside the index (bad offset or count)", s.id, 0);
        }
        const uint8_t* at = base + s.offset;
        switch (IndexSectionId(s.id)) {
        case IndexSectionId::Instances: instances_ = {reinterpret_cast<const Instance*>(at), s.count}; break;
        case IndexSectionId::Names: names_ = {reinterpret_cast<const char*>(at), s.count}; break;
        case IndexSectionId::PartNames: part_names_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        case IndexSectionId::InstanceNames: instance_names_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        case IndexSectionId::Blocks: blocks_ = {reinterpret_cast<const pack::Block*>(at), s.count}; break;
        case IndexSectionId::Parts: parts_ = {reinterpret_cast<const pack::Part*>(at), s.count}; break;
        case IndexSectionId::Needs:
            if (s.count != 1) return fail("the Needs section is not one record", s.id, 0);
            if (const char* why = pack::needs_problem(*reinterpret_cast<const pack::Needs*>(at))) return fail(why, s.id, 0);
            needs_ = {reinterpret_cast<const pack::Needs*>(at), 1};
            break;
        case IndexSectionId::ProxyParts: proxy_parts_ = {reinterpret_cast<const pack::ProxyPart*>(at), s.count}; break;
        case IndexSectionId::ProxyVertices: proxy_vertices_ = {reinterpret_cast<const pack::ProxyVertex*>(at), s.count}; break;
        case IndexSectionId::ProxyTriangles: proxy_triangles_ = {reinterpret_cast<const pack::ProxyTriangle*>(at), s.count}; break;
        case IndexSectionId::Groups: groups_ = {reinterpret_cast<const pack::Group*>(at), s.count}; break;
        case IndexSectionId::GroupMembers: group_members_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        case IndexSectionId::GroupPieces: group_pieces_ = {reinterpret_cast<const pack::ProxyPart*>(at), s.count}; break;
        case IndexSectionId::InstanceGroups: instance_groups_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        }
    }
    base_ = base;
    header_ = h;
    mapped_ = size >= h->total_bytes;
    if (Result r = check_records(); !r.ok()) return r;
    if (Result r = check_proxies(); !r.ok()) return r;
    return check_groups();
}

// The proxies, when there are: 1 to kMostProxyLevels records per part, each inside the pools,
// each level as far as the next finer or farther, every triangle's corners its part's and
// neighbours its level's, normals of about unit length.
Result PackIndex::check_proxies() {
    constexpr uint32_t P = uint32_t(IndexSectionId::ProxyParts);
    if (proxy_parts_.empty() && proxy_vertices_.empty() && proxy_triangles_.empty()) return {};
    const size_t levels = proxy_parts_.size() / parts_.size();
    if (proxy_parts_.size() % parts_.size() || levels < 1 || levels > pack::kMostProxyLevels) {
        return fail("not 1 to kMostProxyLevels proxy levels per part", P, 0);
    }
    for (uint32_t p = 0; p < proxy_parts_.size(); ++p) {
        if (Result r = check_proxy(proxy_parts_[p], P, p); !r.ok()) return r;
        if (p % levels && !(proxy_parts_[p].error_mm <= proxy_parts_[p - 1].error_mm)) return fail("a proxy level is farther than the one coarser", P, p);
    }
    return {};
}

// One proxy (a part's level, a group's piece): inside the pools, a finite error, every
// triangle's corners its own and neighbours its level's, normals of about unit length.
Result PackIndex::check_proxy(const pack::ProxyPart& x, uint32_t section, uint32_t record) {
    constexpr uint32_t T = uint32_t(IndexSectionId::ProxyTriangles);
    if (uint64_t(x.first_vertex) + x.vertex_count > proxy_vertices_.size() || x.vertex_count > 65535 ||
        uint64_t(x.first_triangle) + x.triangle_count > proxy_triangles_.size()) {
        return fail("the proxy's vertices or triangles lie outside their pools", section, record);
    }
    if (!finite(x.error_mm) || !(x.error_mm >= 0)) return fail("the proxy's error is not a finite length", section, record);
    for (uint32_t t = x.first_triangle; t < x.first_triangle + x.triangle_count; ++t) {
        const pack::ProxyTriangle& tri = proxy_triangles_[t];
        if (tri.v[0] >= x.vertex_count || tri.v[1] >= x.vertex_count || tri.v[2] >= x.vertex_count || tri.reserved) {
            return fail("a proxy triangle's corner is not its part's (or reserved is not 0)", T, t);
        }
        for (const uint16_t a : tri.across) {
            if (a != pack::kNoProxyNeighbour && a >= x.triangle_count) return fail("a proxy triangle's neighbour is not its level's", T, t);
        }
        const int32_t n2 = tri.n[0] * tri.n[0] + tri.n[1] * tri.n[1] + tri.n[2] * tri.n[2];
        if (n2 < 90 * 90 || n2 > 140 * 140) return fail("a proxy triangle's normal is not of unit length", T, t);
    }
    return {};
}

namespace {

// Whether group x's box holds the part placed by the instance (its box's eight corners placed as
// the packer placed them, within a rounding's slack) and its radius the part's box's half
// diagonal: the viewer passes a group off the view whole, and takes its members' size from it.
bool holds(const pack::Group& x, const Instance& inst, const pack::Part& part) {
    const float* m = inst.m;
    for (int corner = 0; corner < 8; ++corner) {
        const float c[3] = {corner & 1 ? part.box_max[0] : part.box_min[0], corner & 2 ? part.box_max[1] : part.box_min[1],
                            corner & 4 ? part.box_max[2] : part.box_min[2]};
        for (int k = 0; k < 3; ++k) {
            const float w = m[4 * k] * c[0] + m[4 * k + 1] * c[1] + m[4 * k + 2] * c[2] + m[4 * k + 3];
            const float slack = 1e-4f * (std::fabs(w) + (x.box_max[k] - x.box_min[k])) + 1e-3f;
            if (!(w >= x.box_min[k] - slack && w <= x.box_max[k] + slack)) return false;
        }
    }
    float d2 = 0;
    for (int k = 0; k < 3; ++k) {
        const float h = 0.5f * (part.box_max[k] - part.box_min[k]);
        d2 += h * h;
    }
    return std::sqrt(d2) <= x.member_radius_mm * (1 + 1e-4f) + 1e-3f;
}

} // namespace

// The groups, when there are (all four sections): the members of group after group in
// GroupMembers, ascending within each, every one an instance whose InstanceGroups entry is that
// group (so every instance is a member once), a box, 1 to kMostProxyLevels levels of pieces
// over the groups' colours, each piece sound and each level as far as the finer or farther.
Result PackIndex::check_groups() {
    constexpr uint32_t G = uint32_t(IndexSectionId::Groups), M = uint32_t(IndexSectionId::GroupMembers);
    constexpr uint32_t X = uint32_t(IndexSectionId::GroupPieces), I = uint32_t(IndexSectionId::InstanceGroups);
    if (groups_.empty() && group_members_.empty() && group_pieces_.empty() && instance_groups_.empty()) return {};
    if (groups_.empty()) return fail("group members or pieces without groups", G, 0);
    if (instance_groups_.size() != instances_.size()) return fail("not one group per instance", I, 0);
    if (group_members_.size() != instances_.size()) return fail("not one member per instance", M, 0);
    uint64_t colours = 0;
    for (uint32_t g = 0; g < groups_.size(); ++g) {
        if (groups_[g].colours == 0 || groups_[g].colours > 255) return fail("the group's colours are not 1 to 255", G, g);
        colours += groups_[g].colours;
    }
    const uint64_t levels = group_pieces_.size() / colours;
    if (levels < 1 || levels > pack::kMostProxyLevels || levels * colours != group_pieces_.size()) {
        return fail("not 1 to kMostProxyLevels levels of pieces over the groups' colours", X, 0);
    }
    group_levels_ = uint32_t(levels);
    uint64_t next_member = 0, next_piece = 0;
    for (uint32_t g = 0; g < groups_.size(); ++g) {
        const pack::Group& x = groups_[g];
        if (x.first_member != next_member || x.member_count == 0 || uint64_t(x.first_member) + x.member_count > group_members_.size()) {
            return fail("the group's members do not follow the group before's", G, g);
        }
        next_member += x.member_count;
        if (x.first_piece != next_piece) return fail("the group's pieces do not follow the group before's", G, g);
        next_piece += levels * x.colours;
        if (!box_ok(x.box_min, x.box_max)) return fail("the group's box is not finite, beyond +-1e8 or inverted", G, g);
        if (!finite(x.member_radius_mm) || !(x.member_radius_mm >= 0) || !(x.member_radius_mm <= 1e8f)) {
            return fail("the group's members' radius is not a finite length", G, g);
        }
        for (uint32_t m = x.first_member; m < x.first_member + x.member_count; ++m) {
            const uint32_t i = group_members_[m];
            if (i >= instances_.size() || instance_groups_[i] != g || (m > x.first_member && !(i > group_members_[m - 1]))) {
                return fail("a member is not an instance of this group's, or not after the one before", M, m);
            }
            if (!holds(x, instances_[i], parts_[instances_[i].shell])) {
                return fail("a member's part, placed, lies outside its group's box or is larger than its radius", M, m);
            }
        }
    }
    for (uint32_t g = 0; g < groups_.size(); ++g) {
        const pack::Group& x = groups_[g];
        for (uint32_t l = 0; l < levels; ++l) {
            for (uint32_t c = 0; c < x.colours; ++c) {
                const uint32_t p = group_piece_at(g, l, c);
                if (Result r = check_proxy(group_pieces_[p], X, p); !r.ok()) return r;
                if (l && !(group_pieces_[p].error_mm <= group_pieces_[group_piece_at(g, l - 1, c)].error_mm)) {
                    return fail("a group's level is farther than the one coarser", X, p);
                }
            }
        }
    }
    return {};
}

Result PackIndex::check_records() {
    constexpr uint32_t B = uint32_t(IndexSectionId::Blocks), P = uint32_t(IndexSectionId::Parts);
    constexpr uint32_t I = uint32_t(IndexSectionId::Instances), N = uint32_t(IndexSectionId::Names);
    if (blocks_.empty()) return fail("no blocks", B, 0);
    if (parts_.empty()) return fail("no parts", P, 0);
    if (instances_.empty()) return fail("no instances", I, 0);
    // The blocks follow the index in order, and each holds the parts after the previous one's.
    uint64_t after = header_->index_bytes;
    uint32_t next_part = 0;
    for (uint32_t b = 0; b < blocks_.size(); ++b) {
        const pack::Block& k = blocks_[b];
        if ((k.offset & 3) || k.offset < after || uint64_t(k.offset) + k.stored_bytes > header_->total_bytes || k.stored_bytes == 0) {
            return fail("the block lies outside the file, overlaps the one before it or is empty", B, b);
        }
        after = uint64_t(k.offset) + k.stored_bytes;
        if (k.pack_bytes < sizeof(Header) || k.pack_bytes > kMaxBytes) return fail("the block's decoded size is out of range", B, b);
        if (k.first_part != next_part || k.part_count == 0 || uint64_t(k.first_part) + k.part_count > parts_.size()) {
            return fail("the block's parts do not follow the block before it's", B, b);
        }
        // Its parts' faces and edges fit its decoded bytes (a count that lies would plan the
        // model's memory from it: 100,000 faces claimed for a few).
        uint64_t least = 0;
        for (uint32_t p = k.first_part; p < k.first_part + k.part_count; ++p) {
            least += uint64_t(parts_[p].face_count) * sizeof(pack::Face) + uint64_t(parts_[p].edge_count) * sizeof(pack::Edge);
        }
        if (least > k.pack_bytes) return fail("the block's parts claim more faces and edges than its bytes hold", B, b);
        next_part += k.part_count;
        const bool empty = k.box_min[0] > k.box_max[0];
        if (!empty && !box_ok(k.box_min, k.box_max)) return fail("bounding box is not finite, beyond +-1e8 or inverted", B, b);
    }
    if (next_part != parts_.size()) return fail("parts no block holds", P, next_part);
    for (uint32_t p = 0; p < parts_.size(); ++p) {
        const pack::Part& part = parts_[p];
        if (part.block >= blocks_.size() || p < blocks_[part.block].first_part ||
            p >= blocks_[part.block].first_part + blocks_[part.block].part_count) {
            return fail("the part's block does not hold it", P, p);
        }
        if (part.closed > 1) return fail("bad closed flag", P, p);
        if (!box_ok(part.box_min, part.box_max)) return fail("bounding box is not finite, beyond +-1e8 or inverted", P, p);
    }
    for (uint32_t i = 0; i < instances_.size(); ++i) {
        if (instances_[i].shell >= parts_.size()) return fail("part index out of range", I, i);
        if (const char* why = pack::placement_problem(instances_[i].m)) return fail(why, I, i);
    }
    if (!names_.empty() && names_.back() != 0) return fail("the last name is not ended by a 0 byte", N, uint32_t(names_.size() - 1));
    if (names_.size() & 3) return fail("not padded to a multiple of 4 bytes", N, 0);
    const struct {
        std::span<const uint32_t> table;
        size_t count;
        IndexSectionId id;
    } tables[] = {{part_names_, parts_.size(), IndexSectionId::PartNames}, {instance_names_, instances_.size(), IndexSectionId::InstanceNames}};
    for (const auto& t : tables) {
        if (t.table.empty()) continue;
        if (t.table.size() != t.count) return fail("one name per record of its section is needed", uint32_t(t.id), 0);
        if (const uint32_t bad = first_bad_name(names_, t.table); bad != kNoIndex) {
            return fail("the name does not start a string of Names", uint32_t(t.id), bad);
        }
    }
    return {};
}

} // namespace facet::geom
