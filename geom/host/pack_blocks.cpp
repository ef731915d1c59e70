#include "pack_blocks.h"

#include "geom/pmi.h"
#include "geom/tree.h"

#include "pack_io.h"
#include "pack_writer.h"
#include "groups.h"
#include "proxies.h"

#include "core/format.h"
#include "geom/bounds.h"
#include "geom/pack_file.h"
#include "geom/pack_index.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

namespace facet::geom {
namespace {

using namespace facet::pack;

std::vector<float> floats_of(const Pack& p, uint32_t first, uint32_t count) {
    const auto f = p.params(first, count);
    return {f.begin(), f.end()};
}

// Copies shells of one pack into another. Surfaces, 3D curves and colours are shared by the
// shells copied through one Copier (one block); each shell gets its own vertices and edges, in
// the order its faces first use them, so a shell's edges follow the previous shell's.
class Copier {
public:
    Copier(const Pack& from, PackWriter& to) : from_(from), to_(to) {}

    // Returns the shell's index in `to` and how many edges it took.
    uint32_t shell(uint32_t s, uint32_t& edge_count) {
        const Shell& sh = from_.shells()[s];
        vertices_.clear(), edges_.clear();
        const uint32_t first_face = to_.face_count();
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) face(f);
        edge_count = uint32_t(edges_.size());
        return to_.add_shell({first_face, sh.face_count, colour(sh.colour), sh.closed});
    }

private:
    uint32_t colour(uint32_t c) {
        if (c == kNoIndex) return kNoIndex;
        const auto [it, added] = colours_.try_emplace(c, 0);
        if (added) it->second = to_.add_colour(from_.colours()[c]);
        return it->second;
    }
    uint32_t curve3(uint32_t c) {
        const auto [it, added] = curves_.try_emplace(c, 0);
        if (added) {
            const Curve& k = from_.curves3()[c];
            it->second = to_.add_curve_record(CurveType(k.type), 3, floats_of(from_, k.params, k.count));
        }
        return it->second;
    }
    uint32_t surface(uint32_t s) {
        const auto [it, added] = surfaces_.try_emplace(s, 0);
        if (added) {
            const Surface& k = from_.surfaces()[s];
            const uint32_t ref = k.ref == kNoIndex ? kNoIndex : curve3(k.ref);
            it->second = to_.add_surface_record(SurfaceType(k.type), floats_of(from_, k.params, k.count), ref);
        }
        return it->second;
    }
    uint32_t vertex(uint32_t v) {
        const auto [it, added] = vertices_.try_emplace(v, 0);
        if (added) {
            const float* p = from_.vertices()[v].p;
            it->second = to_.add_vertex(p[0], p[1], p[2]);
        }
        return it->second;
    }
    uint32_t edge(uint32_t e) {
        const auto [it, added] = edges_.try_emplace(e, 0);
        if (added) {
            Edge k = from_.edges()[e];
            k.v0 = vertex(k.v0), k.v1 = vertex(k.v1);
            if (k.curve != kNoIndex && k.curve != kStraight) k.curve = curve3(k.curve);
            it->second = to_.add_edge(k);
            if (from_.smooth_edge(e)) to_.set_smooth_edge(it->second);
        }
        return it->second;
    }
    void face(uint32_t f) {
        pack::Face F = from_.faces()[f];
        const uint32_t first_loop = to_.loop_count();
        const uint32_t first_pcurve = to_.curve2_count();
        for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
            const Loop& L = from_.loops()[l];
            const uint32_t first = to_.coedge_count();
            for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
                const Coedge C = from_.coedges()[c];
                (void)to_.add_coedge(Coedge::make(edge(C.edge()), C.reversed(), C.seam()));
                if (F.first_pcurve != kNoIndex) {
                    const Curve& k = from_.curves2()[from_.pcurve_of(F, c)];
                    (void)to_.add_curve_record(CurveType(k.type), 2, floats_of(from_, k.params, k.count));
                }
            }
            (void)to_.add_loop({first, L.coedge_count});
        }
        F.surface = surface(F.surface);
        F.first_loop = first_loop;
        F.first_pcurve = F.first_pcurve == kNoIndex ? kNoIndex : first_pcurve;
        F.colour = colour(F.colour);
        (void)to_.add_face(F);
    }

    const Pack& from_;
    PackWriter& to_;
    std::map<uint32_t, uint32_t> colours_, curves_, surfaces_, vertices_, edges_;
};

// The pack of shells [first, first + count) of `whole`, and each one's edge count.
std::vector<uint8_t> block_of(const Pack& whole, uint32_t first, uint32_t count, std::vector<uint32_t>* edge_counts) {
    PackWriter w;
    w.set_source_unit_mm(whole.header().source_unit_mm);
    Copier copy(whole, w);
    for (uint32_t s = first; s < first + count; ++s) {
        uint32_t edges = 0;
        (void)copy.shell(s, edges);
        if (edge_counts) edge_counts->push_back(edges);
    }
    return w.finish();
}

std::vector<uint8_t> stored(const std::vector<uint8_t>& pack, BlockStore store) {
    switch (store) {
    case BlockStore::Lzma: return lzma_pack(pack);
    case BlockStore::Deflated: return deflate_pack(pack);
    case BlockStore::Plain: return pack;
    }
    return {};
}

// A pack's (or an index's) annotation sections as tables (geom/pmi_format.h), copied as they
// lie: their reader checked them (Annotations::open) first.
AnnotationTables annotation_tables(const SectionTable& table) {
    AnnotationTables t;
    auto take = [&](auto& out, const SectionEntry& s) {
        using T = typename std::remove_reference_t<decltype(out)>::value_type;
        const std::span<const T> records = table.records<T>(s);
        out.assign(records.begin(), records.end());
    };
    for (const SectionEntry& s : table.entries) {
        switch (pack::PmiSectionId(s.id)) {
        case pack::PmiSectionId::Annotations: take(t.records, s); break;
        case pack::PmiSectionId::PmiText: take(t.text, s); break;
        case pack::PmiSectionId::PmiFaces: take(t.faces, s); break;
        case pack::PmiSectionId::PmiPolylines: take(t.polylines, s); break;
        case pack::PmiSectionId::PmiPoints: take(t.points, s); break;
        default: break;
        }
    }
    return t;
}

// The tree's instances' records as they are (none: no tree).
std::vector<pack::InstanceNode> instance_nodes(const ProductTree& tree) {
    return {tree.instance_nodes().begin(), tree.instance_nodes().end()};
}

template <typename T>
void append(std::vector<uint8_t>& out, std::vector<SectionEntry>& table, auto id, const std::vector<T>& records) {
    out.resize((out.size() + 3) & ~size_t(3), 0);
    const uint32_t offset = uint32_t(out.size());
    const size_t bytes = records.size() * sizeof(T);
    out.resize(out.size() + bytes);
    if (bytes) std::memcpy(out.data() + offset, records.data(), bytes);
    table.push_back({uint32_t(id), offset, uint32_t(records.size()), uint32_t(sizeof(T))});
}

// Two proxies of one mesh (a part simple enough that a coarser level is the finer one).
bool same_mesh(const Proxy& a, const Proxy& b) {
    return a.triangles == b.triangles && a.points.size() == b.points.size() &&
           std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Vec3)) == 0;
}

// Proxy x's record, its corners quantized over `box` and its triangles (with the triangle across
// each side: the one with the same side the other way, the first found where a collapse left
// three on one side) appended to the pools.
pack::ProxyPart proxy_record(const Pack& whole, const Proxy& x, const PartBox& box, std::vector<pack::ProxyVertex>& corners,
                             std::vector<pack::ProxyTriangle>& triangles) {
    pack::ProxyPart r{uint32_t(corners.size()), uint32_t(x.points.size()), uint32_t(triangles.size()), uint32_t(x.triangles.size() / 3),
                      x.error_mm, {0, 0, 0, 0}};
    if (x.colour < whole.colours().size()) r.colour = whole.colours()[x.colour], r.colour.a = 255;
    if (x.points.size() > 65535) { // (never: proxies are small)
        r.vertex_count = r.triangle_count = 0;
        return r;
    }
    for (uint32_t v = 0; v < r.vertex_count; ++v) {
        pack::ProxyVertex q{};
        const float p[3] = {x.points[v].x, x.points[v].y, x.points[v].z};
        for (int k = 0; k < 3; ++k) {
            const float e = box.max[k] - box.min[k];
            const float f = e > 0 ? (p[k] - box.min[k]) / e : 0.0f;
            q.q[k] = uint16_t(std::lround(std::clamp(f, 0.0f, 1.0f) * 65535.0f));
        }
        corners.push_back(q);
    }
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> side_of;
    for (uint32_t t = 0; t < r.triangle_count; ++t)
        for (int k = 0; k < 3; ++k) side_of.try_emplace({x.triangles[3 * t + k], x.triangles[3 * t + (k + 1) % 3]}, t);
    for (uint32_t t = 0; t < r.triangle_count; ++t) {
        pack::ProxyTriangle tri{};
        for (int k = 0; k < 3; ++k) tri.v[k] = uint16_t(x.triangles[3 * t + k]);
        for (int k = 0; k < 3; ++k) {
            const auto other = side_of.find({x.triangles[3 * t + (k + 1) % 3], x.triangles[3 * t + k]});
            tri.across[k] = other != side_of.end() && other->second < pack::kNoProxyNeighbour ? uint16_t(other->second)
                                                                                               : pack::kNoProxyNeighbour;
        }
        const float n[3] = {x.normals[t].x, x.normals[t].y, x.normals[t].z};
        for (int k = 0; k < 3; ++k) tri.n[k] = int8_t(std::lround(std::clamp(n[k], -1.0f, 1.0f) * 127.0f));
        triangles.push_back(tri);
    }
    return r;
}

} // namespace

void grow_by_placed(const Instance& inst, const PartBox& b, float lo[3], float hi[3]) {
    for (int corner = 0; corner < 8; ++corner) {
        const float c[3] = {corner & 1 ? b.max[0] : b.min[0], corner & 2 ? b.max[1] : b.min[1], corner & 4 ? b.max[2] : b.min[2]};
        for (int k = 0; k < 3; ++k) {
            const float w = inst.m[4 * k] * c[0] + inst.m[4 * k + 1] * c[1] + inst.m[4 * k + 2] * c[2] + inst.m[4 * k + 3];
            lo[k] = std::min(lo[k], w), hi[k] = std::max(hi[k], w);
        }
    }
}

bool make_blocked(const Pack& whole, const std::vector<PartBox>& given, const BlockOptions& options, std::vector<uint8_t>& out,
                  std::string& error) {
    const uint32_t shells = uint32_t(whole.shells().size());
    if (shells == 0 || whole.instances().empty()) {
        error = "the pack has no shells or no instances";
        return false;
    }
    if (!given.empty() && given.size() != shells) {
        error = "one box per shell is needed";
        return false;
    }
    std::vector<PartBox> boxes = given;
    if (boxes.empty()) {
        for (uint32_t s = 0; s < shells; ++s) {
            const Box3 b = shell_box(whole, s);
            PartBox p{};
            for (int k = 0; k < 3; ++k) p.min[k] = b.empty() ? 0 : b.lo[k], p.max[k] = b.empty() ? 0 : b.hi[k];
            boxes.push_back(p);
        }
    }
    // Shells grouped in order: a block takes the next shell while it stays under the size aimed at.
    std::vector<uint32_t> alone; // each shell's pack size on its own
    for (uint32_t s = 0; s < shells; ++s) alone.push_back(uint32_t(block_of(whole, s, 1, nullptr).size()));
    std::vector<std::pair<uint32_t, uint32_t>> groups; // first shell, count
    for (uint32_t s = 0; s < shells;) {
        uint32_t n = 1, bytes = alone[s];
        while (s + n < shells && bytes + alone[s + n] <= options.block_bytes) bytes += alone[s + n++];
        groups.push_back({s, n});
        s += n;
    }
    std::vector<pack::Part> parts;
    std::vector<pack::Block> blocks;
    std::vector<std::vector<uint8_t>> payloads;
    for (const auto& [first, count] : groups) {
        std::vector<uint32_t> edges;
        const std::vector<uint8_t> pack = block_of(whole, first, count, &edges);
        std::vector<uint8_t> bytes = stored(pack, options.store);
        if (bytes.empty()) {
            error = "could not compress a block";
            return false;
        }
        pack::Block b{};
        b.stored_bytes = uint32_t(bytes.size());
        b.pack_bytes = uint32_t(pack.size());
        b.first_part = first, b.part_count = count;
        for (int k = 0; k < 3; ++k) b.box_min[k] = 3e38f, b.box_max[k] = -3e38f;
        for (uint32_t s = first; s < first + count; ++s) {
            const Shell& sh = whole.shells()[s];
            pack::Part p{};
            p.block = uint32_t(blocks.size());
            p.face_count = sh.face_count;
            p.edge_count = edges[s - first];
            p.closed = sh.closed;
            std::memcpy(p.box_min, boxes[s].min, sizeof p.box_min);
            std::memcpy(p.box_max, boxes[s].max, sizeof p.box_max);
            parts.push_back(p);
            for (const Instance& inst : whole.instances())
                if (inst.shell == s) grow_by_placed(inst, boxes[s], b.box_min, b.box_max);
        }
        blocks.push_back(b);
        payloads.push_back(std::move(bytes));
    }
    // The index: header, table, sections; then the blocks.
    std::vector<Instance> instances(whole.instances().begin(), whole.instances().end());
    const size_t levels = options.proxies && shells ? options.proxies->size() / shells : 0;
    const bool proxied = levels >= 1 && levels <= pack::kMostProxyLevels && options.proxies->size() == levels * shells;
    std::vector<ProxyGroup> near; // groups of instances near each other (groups.h)
    if (proxied && !options.group_caps.empty() && !make_groups(whole, boxes, *options.proxies, levels, options.group_caps, near, error)) return false;
    ProductTree tree; // (the whole pack's assembly tree and annotations, into the index as they are)
    Annotations pmi;
    if (const Result r = tree.open(whole); !r.ok()) {
        error = std::string("the pack's assembly tree: ") + r.what;
        return false;
    }
    if (const Result r = pmi.open(whole); !r.ok()) {
        error = std::string("the pack's annotations: ") + r.what;
        return false;
    }
    const AnnotationTables notes = pmi.count() ? annotation_tables(SectionTable::of(whole)) : AnnotationTables{};
    const uint32_t kSections = 6 + (whole.needs() ? 1 : 0) + (proxied ? 3 : 0) + (near.empty() ? 0 : 4) + (tree.count() ? 2 : 0) +
                               (notes.records.empty() ? 0 : 5);
    out.assign(sizeof(IndexHeader) + kSections * sizeof(SectionEntry), 0);
    std::vector<SectionEntry> table;
    append(out, table, IndexSectionId::Blocks, blocks); // offsets filled in below
    const size_t blocks_at = table.back().offset;
    append(out, table, IndexSectionId::Parts, parts);
    append(out, table, IndexSectionId::Instances, instances);
    // Names: the whole pack's pool and tables as they are (a pool padded to 4 bytes).
    const char* model = whole.model_name();
    std::vector<char> pool;
    std::vector<uint32_t> part_names(shells, kNoIndex), instance_names(instances.size(), kNoIndex);
    auto add = [&](const char* name) -> uint32_t {
        if (!*name && !pool.empty()) return kNoIndex;
        const uint32_t at = uint32_t(pool.size());
        pool.insert(pool.end(), name, name + std::strlen(name) + 1);
        return at;
    };
    (void)add(model); // the model's first, even when empty
    for (uint32_t s = 0; s < shells; ++s) part_names[s] = add(whole.shell_name(s));
    for (uint32_t i = 0; i < instances.size(); ++i) instance_names[i] = add(whole.instance_name(i));
    std::vector<pack::Node> nodes; // (their names in this pool)
    for (uint32_t n = 0; n < tree.count(); ++n) {
        pack::Node x = tree[n];
        x.name = add(tree.name(n)), x.occurrence = add(tree.occurrence(n));
        nodes.push_back(x);
    }
    pool.resize((pool.size() + 3) & ~size_t(3), 0);
    append(out, table, IndexSectionId::PartNames, part_names);
    append(out, table, IndexSectionId::InstanceNames, instance_names);
    append(out, table, IndexSectionId::Names, pool);
    if (tree.count()) {
        append(out, table, pack::TreeSectionId::Nodes, nodes);
        append(out, table, pack::TreeSectionId::InstanceNodes, instance_nodes(tree));
    }
    if (!notes.records.empty()) { // (their faces numbered as the whole pack's: the blocks' parts are its shells in order)
        append(out, table, pack::PmiSectionId::Annotations, notes.records);
        append(out, table, pack::PmiSectionId::PmiText, notes.text);
        append(out, table, pack::PmiSectionId::PmiFaces, notes.faces);
        append(out, table, pack::PmiSectionId::PmiPolylines, notes.polylines);
        append(out, table, pack::PmiSectionId::PmiPoints, notes.points);
    }
    if (whole.needs()) append(out, table, IndexSectionId::Needs, std::vector<pack::Needs>{*whole.needs()});
    if (proxied) { // each part's proxies, their corners quantized over its box
        std::vector<pack::ProxyPart> records(levels * shells);
        std::vector<pack::ProxyVertex> corners;
        std::vector<pack::ProxyTriangle> triangles;
        for (uint32_t s = 0; s < shells; ++s) {
            for (size_t l = levels; l-- > 0;) { // finest first: a coarser level is as far as it, or farther
                const Proxy& x = (*options.proxies)[s * levels + l];
                pack::ProxyPart& r = records[s * levels + l];
                if (l + 1 < levels && same_mesh(x, (*options.proxies)[s * levels + l + 1])) { // the finer one's: shared
                    r = records[s * levels + l + 1];
                    r.error_mm = std::max(x.error_mm, r.error_mm);
                    if (x.colour < whole.colours().size()) r.colour = whole.colours()[x.colour], r.colour.a = 255;
                    continue;
                }
                r = proxy_record(whole, x, boxes[s], corners, triangles);
                if (l + 1 < levels) r.error_mm = std::max(r.error_mm, records[s * levels + l + 1].error_mm);
            }
        }
        // The groups' pieces, their corners over each group's box, in the same pools.
        std::vector<pack::Group> group_records;
        std::vector<uint32_t> members, instance_group(instances.size(), 0);
        std::vector<pack::ProxyPart> pieces;
        for (uint32_t g = 0; g < near.size(); ++g) {
            const ProxyGroup& x = near[g];
            pack::Group r{uint32_t(members.size()), uint32_t(x.members.size()), uint32_t(pieces.size()), uint32_t(x.colours.size()), {}, {},
                          x.member_radius_mm};
            std::memcpy(r.box_min, x.box.min, sizeof r.box_min);
            std::memcpy(r.box_max, x.box.max, sizeof r.box_max);
            for (const uint32_t i : x.members) members.push_back(i), instance_group[i] = g;
            for (const Proxy& piece : x.pieces) pieces.push_back(proxy_record(whole, piece, x.box, corners, triangles));
            group_records.push_back(r);
        }
        append(out, table, IndexSectionId::ProxyParts, records);
        append(out, table, IndexSectionId::ProxyVertices, corners);
        append(out, table, IndexSectionId::ProxyTriangles, triangles);
        if (!near.empty()) {
            append(out, table, IndexSectionId::Groups, group_records);
            append(out, table, IndexSectionId::GroupMembers, members);
            append(out, table, IndexSectionId::GroupPieces, pieces);
            append(out, table, IndexSectionId::InstanceGroups, instance_group);
        }
    }
    std::memcpy(out.data() + sizeof(IndexHeader), table.data(), table.size() * sizeof(SectionEntry));
    out.resize((out.size() + 3) & ~size_t(3), 0);
    const uint32_t index_bytes = uint32_t(out.size());
    for (size_t b = 0; b < blocks.size(); ++b) {
        blocks[b].offset = uint32_t(out.size());
        out.insert(out.end(), payloads[b].begin(), payloads[b].end());
        out.resize((out.size() + 3) & ~size_t(3), 0);
    }
    std::memcpy(out.data() + blocks_at, blocks.data(), blocks.size() * sizeof(pack::Block));
    IndexHeader h{};
    std::memcpy(h.magic, kBlockedMagic, 4);
    h.version = kBlockedVersion;
    h.header_bytes = sizeof(IndexHeader);
    h.total_bytes = uint32_t(out.size());
    h.index_bytes = index_bytes;
    h.section_count = kSections;
    h.source_unit_mm = whole.header().source_unit_mm;
    for (int k = 0; k < 3; ++k) h.bbox_min[k] = 3e38f, h.bbox_max[k] = -3e38f;
    for (const pack::Block& b : blocks) {
        if (b.box_min[0] > b.box_max[0]) continue;
        for (int k = 0; k < 3; ++k) h.bbox_min[k] = std::min(h.bbox_min[k], b.box_min[k]), h.bbox_max[k] = std::max(h.bbox_max[k], b.box_max[k]);
    }
    if (h.bbox_min[0] > h.bbox_max[0]) {
        for (int k = 0; k < 3; ++k) h.bbox_min[k] = h.bbox_max[k] = 0;
    }
    std::memcpy(out.data(), &h, sizeof h);
    h.crc32 = crc32(out.data() + kIndexCrcFrom, index_bytes - kIndexCrcFrom);
    std::memcpy(out.data(), &h, sizeof h);
    if (out.size() > kMaxBlockedBytes) {
        error = "the blocked pack would be larger than the 256 MiB limit";
        return false;
    }
    return true;
}

bool join_blocked(std::span<const uint8_t> file, std::vector<uint8_t>& whole, std::string& error) {
    // The index read in place wants 4-byte alignment: a copy that has it.
    std::vector<uint32_t> words((file.size() + 3) / 4);
    if (!file.empty()) std::memcpy(words.data(), file.data(), file.size());
    PackIndex index;
    char text[200];
    if (const Result r = index.open(words.data(), uint32_t(file.size())); !r.ok()) {
        describe(r, text, sizeof text);
        error = text;
        return false;
    }
    PackWriter w;
    w.set_source_unit_mm(index.header().source_unit_mm);
    w.set_model_name(index.model_name());
    if (index.needs()) w.set_needs(*index.needs());
    for (uint32_t b = 0; b < index.blocks().size(); ++b) {
        const auto stored_bytes = index.block_file(b);
        LoadedPack block;
        if (!load_pack_bytes({stored_bytes.begin(), stored_bytes.end()}, block, error)) {
            error = "block " + std::to_string(b) + ": " + error;
            return false;
        }
        Pack p;
        if (const Result r = p.open(block.data(), block.bytes); !r.ok()) {
            describe(r, text, sizeof text);
            error = "block " + std::to_string(b) + ": " + text;
            return false;
        }
        const pack::Block& k = index.blocks()[b];
        if (p.shells().size() != k.part_count) {
            error = "block " + std::to_string(b) + ": " + std::to_string(p.shells().size()) + " shells for " +
                    std::to_string(k.part_count) + " parts";
            return false;
        }
        Copier copy(p, w);
        for (uint32_t s = 0; s < k.part_count; ++s) {
            uint32_t edges = 0;
            const uint32_t shell = copy.shell(s, edges);
            w.name_shell(shell, index.part_name(k.first_part + s));
        }
    }
    for (uint32_t i = 0; i < index.instances().size(); ++i) {
        (void)w.add_instance(index.instances()[i]);
        w.name_instance(i, index.instance_name(i));
    }
    ProductTree tree; // (the index's assembly tree, into the whole pack)
    if (const Result r = tree.open(index); !r.ok()) {
        describe(r, text, sizeof text);
        error = text;
        return false;
    }
    Annotations pmi; // (the index's annotations, into the whole pack)
    if (const Result r = pmi.open(index); !r.ok()) {
        describe(r, text, sizeof text);
        error = text;
        return false;
    }
    if (pmi.count()) w.set_annotations(annotation_tables(SectionTable::of(index)));
    if (tree.count()) {
        std::vector<pack::Node> nodes;
        std::vector<PackWriter::TreeNodeNames> names;
        for (uint32_t n = 0; n < tree.count(); ++n) nodes.push_back(tree[n]), names.push_back({tree.name(n), tree.occurrence(n)});
        w.set_tree(std::move(nodes), std::move(names), instance_nodes(tree));
    }
    whole = w.finish();
    return true;
}

std::vector<uint8_t> combine_packs(std::span<const Pack> packs, float spacing_mm) {
    PackWriter w;
    uint32_t placed = 0;
    for (const Pack& p : packs) {
        Copier copy(p, w);
        for (uint32_t s = 0; s < p.shells().size(); ++s) {
            uint32_t edges = 0;
            const uint32_t shell = copy.shell(s, edges);
            w.name_shell(shell, p.shell_name(s));
            (void)w.add_instance({shell, {1, 0, 0, spacing_mm * float(placed++), 0, 1, 0, 0, 0, 0, 1, 0}});
        }
    }
    return w.finish();
}

} // namespace facet::geom
