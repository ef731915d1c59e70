#pragma once
// The pack's assembly tree (geom/tree_format.h) from the file's (StepModel::nodes): each node's
// instances (a run: the parts are in the tree's depth-first order), its first child and next
// sibling, and each instance's node and exploded-view offset.
#include "pack_blocks.h"
#include "pack_writer.h"
#include "step_reader.h"

#include <vector>

namespace facet::geom {
class Pack;
}

namespace facet::packer {

// `instance_nodes`: each packed instance's node (StepModel's parts in order, less those left out),
// in depth-first order; `boxes`: each shell's own box (part_boxes()). False (with the reason)
// when the instances are not in the tree's order.
bool set_tree(const std::vector<TreeNode>& nodes, const std::vector<uint32_t>& instance_nodes, const geom::Pack& pack,
              const std::vector<geom::PartBox>& boxes, geom::PackWriter& w, std::string& error);

} // namespace facet::packer
