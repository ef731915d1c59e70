#pragma once
// A model's assembly tree (geom/tree_format.h), read in place from a whole pack or a blocked
// pack's index after checking all of it: node 0 the root with every instance under it, each
// other node's parent an earlier node, its first child the node right after it, its siblings
// later nodes of its parent, one after another in its parent's instances; names that start a
// name of the pool; at most kMaxTreeDepth levels; each instance's node holding it, its explode
// offset finite. A pack without the sections has no tree (count() 0): its parts are a flat list.
#include "core/status.h"
#include "geom/pack_format.h"
#include "geom/sections.h"
#include "geom/tree_format.h"

#include <cstdint>
#include <span>

namespace facet::geom {

class Pack;
class PackIndex;

class ProductTree {
public:
    Result open(const Pack& pack);
    Result open(const PackIndex& index);

    uint32_t count() const { return uint32_t(nodes_.size()); }
    const pack::Node& operator[](uint32_t n) const { return nodes_[n]; }
    const char* name(uint32_t n) const { return text(nodes_[n].name); }
    const char* occurrence(uint32_t n) const { return text(nodes_[n].occurrence); }
    uint32_t depth(uint32_t n) const; // the root's 0
    // The deepest node an instance is under (kNoIndex: no tree), and its exploded view's offset.
    uint32_t node_of(uint32_t instance) const { return instance < instances_.size() ? instances_[instance].node : pack::kNoIndex; }
    const float* explode(uint32_t instance) const { return instance < instances_.size() ? instances_[instance].explode : nullptr; }
    std::span<const pack::InstanceNode> instance_nodes() const { return instances_; } // (each instance's, or none)
    // Whether an instance is n's own (under it and under none of its children).
    bool own(uint32_t n, uint32_t instance) const { return node_of(instance) == n; }

private:
    Result read(const SectionTable& table, uint32_t instances, std::span<const char> names, bool index);
    Result check(uint32_t instances, std::span<const char> names, bool index);
    const char* text(uint32_t at) const { return at == pack::kNoIndex ? "" : names_.data() + at; }

    std::span<const pack::Node> nodes_;
    std::span<const pack::InstanceNode> instances_;
    std::span<const char> names_;
};

} // namespace facet::geom
