#include "assembly_tree.h"

#include "geom/pack.h"

#include <algorithm>
#include <array>

namespace facet::packer {

bool set_tree(const std::vector<TreeNode>& tree, const std::vector<uint32_t>& instance_nodes, const geom::Pack& pack,
              const std::vector<geom::PartBox>& boxes, geom::PackWriter& w, std::string& error) {
    const uint32_t n = uint32_t(tree.size());
    if (n == 0) return true;
    const auto instances = pack.instances();
    if (instance_nodes.size() != instances.size() || !std::is_sorted(instance_nodes.begin(), instance_nodes.end()) ||
        (!instance_nodes.empty() && instance_nodes.back() >= n)) {
        error = "the instances are not in the assembly tree's order";
        return false;
    }
    // A node's subtree is the nodes [k, end[k]) (depth-first), its instances those whose node
    // lies there: a run, the instances being in the nodes' order.
    std::vector<uint32_t> end(n);
    for (uint32_t k = 0; k < n; ++k) end[k] = k + 1;
    for (uint32_t k = n; k-- > 1;) end[tree[k].parent] = std::max(end[tree[k].parent], end[k]);
    auto first_at = [&](uint32_t node) {
        return uint32_t(std::lower_bound(instance_nodes.begin(), instance_nodes.end(), node) - instance_nodes.begin());
    };
    std::vector<pack::Node> nodes(n);
    std::vector<geom::PackWriter::TreeNodeNames> names(n);
    for (uint32_t k = 0; k < n; ++k) {
        pack::Node& x = nodes[k];
        x.parent = k == 0 ? pack::kNoIndex : tree[k].parent;
        x.first_child = k + 1 < n && tree[k + 1].parent == k ? k + 1 : pack::kNoIndex;
        x.next_sibling = k > 0 && end[k] < n && tree[end[k]].parent == tree[k].parent ? end[k] : pack::kNoIndex;
        x.first_instance = first_at(k);
        x.instance_count = first_at(end[k]) - x.first_instance;
        names[k] = {tree[k].name, tree[k].occurrence};
    }
    // Centres: each instance's placed box's, each node's box of its instances' (one with none:
    // its parent's). An instance's offset at an explode of 1 is its centre's way from its node's,
    // plus its node's from its parent's, and so on up to the root's: each level moves out from
    // the assembly that holds it.
    using Box = std::array<float, 6>; // min, max
    const Box empty{1e30f, 1e30f, 1e30f, -1e30f, -1e30f, -1e30f};
    auto centre = [](const Box& b, float c[3]) {
        for (int a = 0; a < 3; ++a) c[a] = 0.5f * (b[a] + b[a + 3]);
    };
    std::vector<Box> instance_box(instances.size(), empty), node_box(n, empty);
    for (uint32_t i = 0; i < instances.size(); ++i) {
        Box& b = instance_box[i];
        if (instances[i].shell < boxes.size()) geom::grow_by_placed(instances[i], boxes[instances[i].shell], b.data(), b.data() + 3);
        for (uint32_t k = instance_nodes[i];; k = tree[k].parent) {
            for (int a = 0; a < 3; ++a) node_box[k][a] = std::min(node_box[k][a], b[a]), node_box[k][a + 3] = std::max(node_box[k][a + 3], b[a + 3]);
            if (k == 0) break;
        }
    }
    std::vector<std::array<float, 3>> node_centre(n);
    for (uint32_t k = 0; k < n; ++k) {
        if (node_box[k][0] <= node_box[k][3]) centre(node_box[k], node_centre[k].data());
        else node_centre[k] = k ? node_centre[tree[k].parent] : std::array<float, 3>{0, 0, 0};
    }
    std::vector<pack::InstanceNode> placed(instances.size());
    for (uint32_t i = 0; i < instances.size(); ++i) {
        float c[3];
        centre(instance_box[i], c);
        uint32_t k = instance_nodes[i];
        placed[i].node = k;
        for (int a = 0; a < 3; ++a) placed[i].explode[a] = c[a] - node_centre[k][a];
        for (; k != 0; k = tree[k].parent)
            for (int a = 0; a < 3; ++a) placed[i].explode[a] += node_centre[k][a] - node_centre[tree[k].parent][a];
    }
    w.set_tree(std::move(nodes), std::move(names), std::move(placed));
    return true;
}

} // namespace facet::packer
