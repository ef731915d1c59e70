#pragma once
// A model's product structure: its assembly tree (optional sections of a whole pack, and of a
// blocked pack's index alike; a pack without them reads as before, flat). The sub-assemblies
// are nodes in depth-first order, node 0 the model's top product; each holds the instances
// under it (its own parts' and its sub-assemblies'), a range of the Instances: a node's range
// holds its children's, one after another. docs/pack-format.md, "The assembly tree".
#include "geom/pack_format.h"

#include <cstdint>

namespace facet::pack {

enum class TreeSectionId : uint32_t {
    Nodes = 31,         // Node records
    InstanceNodes = 32, // an InstanceNode per instance
};

struct Node {
    uint32_t parent;        // an earlier node; kNoIndex for node 0, the root
    uint32_t first_child;   // the next node (depth-first), or kNoIndex: none
    uint32_t next_sibling;  // a later node of the same parent, or kNoIndex
    uint32_t name;          // byte of Names where its product's name starts, or kNoIndex
    uint32_t occurrence;    // and its occurrence's in its parent (when the file names it), or kNoIndex
    uint32_t first_instance, instance_count; // the instances under it
};
static_assert(sizeof(Node) == 28, "pack::Node is 28 bytes");

struct InstanceNode {
    uint32_t node;      // the deepest node the instance is under
    float explode[3];   // mm: where it goes in an exploded view of factor 1 (its centre's way from
                        // its node's centre, plus its node's from its parent's, ... up to the root)
};
static_assert(sizeof(InstanceNode) == 16, "pack::InstanceNode is 16 bytes");

constexpr uint32_t kMaxTreeDepth = 32; // nodes under the root, at most

} // namespace facet::pack
