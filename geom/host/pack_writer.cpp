#include "pack_writer.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace facet::geom {

using namespace facet::pack;

uint32_t PackWriter::add_floats(const std::vector<float>& values) {
    std::string key(values.size() * sizeof(float), '\0');
    if (!values.empty()) std::memcpy(key.data(), values.data(), key.size());
    const auto [it, added] = blocks_.try_emplace(std::move(key), uint32_t(floats_.size()));
    if (added) floats_.insert(floats_.end(), values.begin(), values.end());
    return it->second;
}

uint32_t PackWriter::add_surface_record(SurfaceType type, const std::vector<float>& params, uint32_t ref) {
    surfaces_.push_back({uint8_t(type), 0, 0, add_floats(params), uint32_t(params.size()), ref});
    return uint32_t(surfaces_.size() - 1);
}

uint32_t PackWriter::add_curve_record(CurveType type, uint8_t dim, const std::vector<float>& params) {
    auto& list = dim == 3 ? curves3_ : curves2_;
    list.push_back({uint8_t(type), dim, 0, add_floats(params), uint32_t(params.size())});
    return uint32_t(list.size() - 1);
}

uint32_t PackWriter::add_vertex(float x, float y, float z) {
    vertices_.push_back({{x, y, z}});
    return uint32_t(vertices_.size() - 1);
}
uint32_t PackWriter::add_edge(const Edge& e) { edges_.push_back(e); return uint32_t(edges_.size() - 1); }

void PackWriter::set_smooth_edge(uint32_t e) {
    if (smooth_.size() <= e) smooth_.resize(e + 1, false);
    smooth_[e] = true;
}
uint32_t PackWriter::add_coedge(const Coedge& c) { coedges_.push_back(c); return uint32_t(coedges_.size() - 1); }
uint32_t PackWriter::add_loop(const Loop& l) { loops_.push_back(l); return uint32_t(loops_.size() - 1); }
uint32_t PackWriter::add_face(const pack::Face& f) { faces_.push_back(f); return uint32_t(faces_.size() - 1); }
uint32_t PackWriter::add_shell(const Shell& s) { shells_.push_back(s); return uint32_t(shells_.size() - 1); }
uint32_t PackWriter::add_instance(const Instance& i) { instances_.push_back(i); return uint32_t(instances_.size() - 1); }
uint32_t PackWriter::add_colour(Colour c) { colours_.push_back(c); return uint32_t(colours_.size() - 1); }

namespace {
std::string cut_name(const std::string& name) { return cut_utf8(name, kMaxNameBytes); }
} // namespace

std::string cut_utf8(const std::string& text, size_t bytes) {
    if (text.size() <= bytes) return text;
    size_t n = bytes;
    while (n > 0 && (uint8_t(text[n]) & 0xC0) == 0x80) --n; // not inside a UTF-8 character
    return text.substr(0, n);
}

uint32_t PackWriter::add_name(const std::string& name) {
    const std::string s = cut_name(name);
    if (s.empty()) return kNoIndex;
    const auto [it, added] = name_at_.try_emplace(s, uint32_t(names_.size()));
    if (added) {
        names_.insert(names_.end(), s.begin(), s.end());
        names_.push_back(0);
    }
    return it->second;
}

void PackWriter::set_model_name(const std::string& name) { model_name_ = cut_name(name); }

void PackWriter::set_tree(std::vector<pack::Node> nodes, std::vector<TreeNodeNames> names, std::vector<pack::InstanceNode> instances) {
    for (size_t n = 0; n < nodes.size() && n < names.size(); ++n) {
        nodes[n].name = add_name(names[n].name);
        nodes[n].occurrence = add_name(names[n].occurrence);
    }
    tree_ = std::move(nodes), tree_instances_ = std::move(instances);
}

void PackWriter::name_shell(uint32_t shell, const std::string& name) {
    if (shell_names_.size() <= shell) shell_names_.resize(shell + 1, kNoIndex);
    shell_names_[shell] = add_name(name);
}

void PackWriter::name_instance(uint32_t instance, const std::string& name) {
    if (instance_names_.size() <= instance) instance_names_.resize(instance + 1, kNoIndex);
    instance_names_[instance] = add_name(name);
}

namespace {
template <typename T>
void append_section(std::vector<uint8_t>& out, std::vector<SectionEntry>& table, auto id, const std::vector<T>& records) {
    out.resize((out.size() + 3) & ~size_t(3), 0); // (every section 4-byte aligned: a 6-byte record's may end between)
    const uint32_t offset = uint32_t(out.size());
    const size_t bytes = records.size() * sizeof(T);
    out.resize(out.size() + bytes);
    if (bytes) std::memcpy(out.data() + offset, records.data(), bytes);
    table.push_back({uint32_t(id), offset, uint32_t(records.size()), uint32_t(sizeof(T))});
}
} // namespace

std::vector<uint8_t> PackWriter::finish() const {
    const bool named = !names_.empty() || !model_name_.empty() || !tree_.empty();
    std::vector<uint32_t> smooth_words; // (written when some edge is smooth)
    for (uint32_t e = 0; e < smooth_.size() && e < edges_.size(); ++e) {
        if (!smooth_[e]) continue;
        smooth_words.resize(pack::smooth_words(uint32_t(edges_.size())), 0);
        smooth_words[e / 32] |= 1u << (e % 32);
    }
    // (a name table is written when it names something)
    const auto names_some = [](const std::vector<uint32_t>& t) { return std::any_of(t.begin(), t.end(), [](uint32_t v) { return v != kNoIndex; }); };
    const bool shell_names = names_some(shell_names_), instance_names = names_some(instance_names_);
    // The sections laid out from 0, then placed after the header and the table.
    std::vector<uint8_t> out;
    std::vector<SectionEntry> table;
    if (has_needs_) append_section(out, table, SectionId::Needs, std::vector<pack::Needs>{needs_}); // (in the pack's head)
    append_section(out, table, SectionId::Floats, floats_);
    append_section(out, table, SectionId::Surfaces, surfaces_);
    append_section(out, table, SectionId::Curves3, curves3_);
    append_section(out, table, SectionId::Curves2, curves2_);
    append_section(out, table, SectionId::Vertices, vertices_);
    append_section(out, table, SectionId::Edges, edges_);
    append_section(out, table, SectionId::Coedges, coedges_);
    append_section(out, table, SectionId::Loops, loops_);
    append_section(out, table, SectionId::Faces, faces_);
    append_section(out, table, SectionId::Shells, shells_);
    append_section(out, table, SectionId::Instances, instances_);
    append_section(out, table, SectionId::Colours, colours_);
    if (named) {
        // The pool: the model's name first, then the others (their offsets move behind it),
        // unless the first of them is the model's (a part named as its file is: stored once).
        const bool model_name_first = names_.size() > model_name_.size() &&
                                      std::memcmp(names_.data(), model_name_.c_str(), model_name_.size() + 1) == 0;
        const uint32_t shift = model_name_first ? 0 : uint32_t(model_name_.size() + 1);
        std::vector<uint32_t> shells = shell_names_, instances = instance_names_;
        shells.resize(shells_.size(), kNoIndex);
        instances.resize(instances_.size(), kNoIndex);
        for (auto* t : {&shells, &instances})
            for (uint32_t& v : *t)
                if (v != kNoIndex) v += shift;
        if (shell_names) append_section(out, table, SectionId::ShellNames, shells);
        if (instance_names) append_section(out, table, SectionId::InstanceNames, instances);
        if (!tree_.empty()) { // the nodes' names move as the others do
            std::vector<pack::Node> nodes = tree_;
            for (pack::Node& n : nodes) {
                if (n.name != kNoIndex) n.name += shift;
                if (n.occurrence != kNoIndex) n.occurrence += shift;
            }
            append_section(out, table, pack::TreeSectionId::Nodes, nodes);
            append_section(out, table, pack::TreeSectionId::InstanceNodes, tree_instances_);
        }
        std::vector<char> pool;
        if (!model_name_first) pool.assign(model_name_.c_str(), model_name_.c_str() + model_name_.size() + 1);
        pool.insert(pool.end(), names_.begin(), names_.end());
        pool.resize((pool.size() + 3) & ~size_t(3), 0);
        append_section(out, table, SectionId::Names, pool);
    }
    if (!smooth_words.empty()) append_section(out, table, SectionId::SmoothEdges, smooth_words);
    if (const AnnotationTables& a = annotations_; !a.records.empty()) {
        std::vector<char> text = a.text;
        text.resize((text.size() + 3) & ~size_t(3), 0);
        append_section(out, table, pack::PmiSectionId::Annotations, a.records);
        append_section(out, table, pack::PmiSectionId::PmiText, text);
        append_section(out, table, pack::PmiSectionId::PmiFaces, a.faces);
        append_section(out, table, pack::PmiSectionId::PmiPolylines, a.polylines);
        append_section(out, table, pack::PmiSectionId::PmiPoints, a.points);
    }
    out.resize((out.size() + 3) & ~size_t(3), 0); // (the pack a whole number of words)
    const uint32_t sections = uint32_t(table.size()), head = uint32_t(sizeof(Header) + sections * sizeof(SectionEntry));
    for (SectionEntry& e : table) e.offset += head;
    out.insert(out.begin(), head, 0);
    std::memcpy(out.data() + sizeof(Header), table.data(), table.size() * sizeof(SectionEntry));

    Header h{};
    std::memcpy(h.magic, kMagic, 4);
    h.version = kVersion;
    h.header_bytes = sizeof(Header);
    h.total_bytes = uint32_t(out.size());
    h.section_count = sections;
    h.source_unit_mm = unit_mm_;
    for (int k = 0; k < 3; ++k) {
        h.bbox_min[k] = std::numeric_limits<float>::max();
        h.bbox_max[k] = std::numeric_limits<float>::lowest();
    }
    for (const Vertex& v : vertices_) {
        for (int k = 0; k < 3; ++k) {
            h.bbox_min[k] = std::min(h.bbox_min[k], v.p[k]);
            h.bbox_max[k] = std::max(h.bbox_max[k], v.p[k]);
        }
    }
    if (vertices_.empty()) {
        for (int k = 0; k < 3; ++k) h.bbox_min[k] = h.bbox_max[k] = 0;
    }
    h.crc32 = crc32(out.data() + sizeof(Header), uint32_t(out.size() - sizeof(Header)));
    std::memcpy(out.data(), &h, sizeof h);
    return out;
}

std::string PackWriter::summary() const {
    auto kb = [](size_t bytes) { return std::to_string((bytes + 512) / 1024) + " KB"; };
    return "floats " + kb(floats_.size() * 4) + ", surfaces " + std::to_string(surfaces_.size()) +
           ", curves " + std::to_string(curves3_.size()) + " 3D / " + std::to_string(curves2_.size()) +
           " 2D, vertices " + std::to_string(vertices_.size()) + ", edges " + std::to_string(edges_.size()) +
           ", coedges " + std::to_string(coedges_.size()) + ", loops " + std::to_string(loops_.size()) +
           ", faces " + std::to_string(faces_.size()) + ", shells " + std::to_string(shells_.size()) +
           ", instances " + std::to_string(instances_.size()) + ", colours " + std::to_string(colours_.size());
}

} // namespace facet::geom
