#include "geom/tree.h"

#include "geom/pack.h"
#include "geom/pack_index.h"

#include <cmath>

namespace facet::geom {
namespace {

using pack::kNoIndex;
using pack::TreeSectionId;

Result fail(const char* what, TreeSectionId id, uint32_t index, bool in_index) {
    return Result::fail(Status::Corrupt, what,
                        {id == TreeSectionId::Nodes ? (in_index ? "index section Nodes record" : "section Nodes record")
                                                    : (in_index ? "index section InstanceNodes record" : "section InstanceNodes record"),
                         index});
}

// A name's start: kNoIndex, or the pool's start or right after a 0 byte (the pool ends in one).
bool starts_name(std::span<const char> names, uint32_t at) {
    return at == kNoIndex || (at < names.size() && (at == 0 || names[at - 1] == 0));
}

} // namespace

Result ProductTree::open(const Pack& pack) {
    *this = ProductTree{};
    return read(SectionTable::of(pack), uint32_t(pack.instances().size()), pack.names(), false);
}

Result ProductTree::open(const PackIndex& index) {
    *this = ProductTree{};
    return read(SectionTable::of(index), uint32_t(index.instances().size()), index.names(), true);
}

Result ProductTree::read(const SectionTable& table, uint32_t instances, std::span<const char> names, bool index) {
    bool seen[2] = {};
    for (const pack::SectionEntry& s : table.entries) {
        const bool nodes = s.id == uint32_t(TreeSectionId::Nodes);
        if (!nodes && s.id != uint32_t(TreeSectionId::InstanceNodes)) continue;
        const TreeSectionId id = nodes ? TreeSectionId::Nodes : TreeSectionId::InstanceNodes;
        if (seen[!nodes]) return fail("section appears twice", id, 0, index);
        seen[!nodes] = true;
        if (const char* why = table.problem(s, nodes ? sizeof(pack::Node) : sizeof(pack::InstanceNode))) return fail(why, id, 0, index);
        if (nodes) nodes_ = table.records<pack::Node>(s);
        else instances_ = table.records<pack::InstanceNode>(s);
    }
    names_ = names;
    if (Result r = check(instances, names, index); !r.ok()) {
        *this = ProductTree{};
        return r;
    }
    return {};
}

Result ProductTree::check(uint32_t instances, std::span<const char> names, bool index) {
    constexpr TreeSectionId N = TreeSectionId::Nodes, I = TreeSectionId::InstanceNodes;
    if (nodes_.empty() != instances_.empty()) return fail("nodes without their instances' nodes, or these without nodes", N, 0, index);
    if (nodes_.empty()) return {};
    if (instances_.size() != instances) return fail("one record per instance is needed", I, 0, index);
    if (nodes_.size() > instances) return fail("more nodes than instances", N, 0, index);
    const pack::Node& root = nodes_[0];
    if (root.parent != kNoIndex || root.first_instance != 0 || root.instance_count != instances || root.next_sibling != kNoIndex) {
        return fail("the root is not node 0 with every instance under it", N, 0, index);
    }
    for (uint32_t n = 0; n < nodes_.size(); ++n) {
        const pack::Node& x = nodes_[n];
        if (!starts_name(names, x.name) || !starts_name(names, x.occurrence)) return fail("a name does not start a string of Names", N, n, index);
        if (uint64_t(x.first_instance) + x.instance_count > instances) return fail("its instances lie past the model's", N, n, index);
        if (n > 0) {
            if (x.parent >= n) return fail("its parent is not an earlier node", N, n, index);
            const pack::Node& p = nodes_[x.parent];
            if (x.first_instance < p.first_instance || x.first_instance + x.instance_count > p.first_instance + p.instance_count) {
                return fail("its instances are not its parent's", N, n, index);
            }
        }
        if (x.first_child != kNoIndex && (x.first_child != n + 1 || n + 1 >= nodes_.size() || nodes_[n + 1].parent != n)) {
            return fail("its first child is not the node after it, a child of it", N, n, index);
        }
        if (x.first_child == kNoIndex && n + 1 < nodes_.size() && nodes_[n + 1].parent == n) return fail("a child it does not name", N, n, index);
        if (x.next_sibling != kNoIndex) {
            if (x.next_sibling <= n || x.next_sibling >= nodes_.size() || nodes_[x.next_sibling].parent != x.parent) {
                return fail("its next sibling is not a later node of its parent", N, n, index);
            }
            if (nodes_[x.next_sibling].first_instance < x.first_instance + x.instance_count) return fail("its siblings' instances overlap", N, n, index);
        }
        if (depth(n) > pack::kMaxTreeDepth) return fail("deeper than the tree may be", N, n, index);
    }
    // Every node is its parent's first child or its previous sibling's next one (the last node
    // before it of the same parent): walking the children from a first child meets every node
    // once. (Scanning back passes over the previous sibling's own nodes: a node is passed over
    // once for each of its ancestors at most.)
    for (uint32_t n = 1; n < nodes_.size(); ++n) {
        const uint32_t p = nodes_[n].parent;
        if (nodes_[p].first_child == n) continue;
        uint32_t before = n - 1;
        while (before > p && nodes_[before].parent != p) --before;
        if (before == p || nodes_[before].next_sibling != n) return fail("no walk of its parent's children reaches it", N, n, index);
    }
    for (uint32_t i = 0; i < instances_.size(); ++i) {
        const pack::InstanceNode& in = instances_[i];
        if (in.node >= nodes_.size()) return fail("its node is out of range", I, i, index);
        const pack::Node& x = nodes_[in.node];
        if (i < x.first_instance || i >= x.first_instance + x.instance_count) return fail("its node does not hold it", I, i, index);
        for (float f : in.explode)
            if (!(std::fabs(f) <= pack::kMaxMagnitude)) return fail("its explode offset is NaN, infinite or beyond +-1e8", I, i, index);
    }
    return {};
}

uint32_t ProductTree::depth(uint32_t n) const {
    uint32_t d = 0;
    for (; n < nodes_.size() && nodes_[n].parent != kNoIndex && d <= pack::kMaxTreeDepth; n = nodes_[n].parent) ++d;
    return d;
}

} // namespace facet::geom
