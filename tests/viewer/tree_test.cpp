// The assembly tree and the exploded view (issue 53) on the viewer: the reader takes a tree and
// refuses one that lies; its nodes walk and act on their parts (hide, isolate, choose, fit);
// the exploded view moves the parts out and back to the same pixels, and a measurement taken
// exploded is the assembled model's.
#include "../geom/shapes.h"
#include "app.h"
#include "geom/pack.h"
#include "geom/tree.h"
#include "pack_blocks.h"
#include "sections.h"

#include <cmath>
#include <string>

using namespace facet;
using namespace facet::test;

namespace {

constexpr uint32_t kTopFace = 0, kPlateFaces = 8; // (the plate's faces: shapes.h)

// Three plates in a row (150 mm apart): the model (node 0) holds sub-assembly 1 (the first two)
// and sub-assembly 2 (the third).
struct Tree {
    std::vector<pack::Node> nodes;
    std::vector<pack::InstanceNode> instances;
};

Tree three_plates_tree() {
    constexpr uint32_t N = pack::kNoIndex;
    Tree t;
    t.nodes = {{N, 1, N, N, N, 0, 3}, {0, N, 2, N, N, 0, 2}, {0, N, N, N, N, 2, 1}};
    // Each plate out from its sub-assembly's centre, and the sub-assemblies from the model's.
    t.instances = {{1, {-150, 0, 40}}, {1, {0, 0, 80}}, {2, {150, 0, -60}}};
    return t;
}

Bytes three_plates() {
    const Bytes plate = plate_with_holes();
    std::vector<geom::Pack> packs(3);
    for (auto& p : packs) EXPECT_TRUE(p.open(plate.data(), uint32_t(plate.size())).ok());
    return geom::combine_packs(packs, 150.0f);
}

Bytes with_tree(const Tree& t) {
    return with_sections(three_plates(), {section(pack::TreeSectionId::Nodes, t.nodes), section(pack::TreeSectionId::InstanceNodes, t.instances)});
}

} // namespace

TEST(Tree, TheReaderTakesItAndRefusesEachWayItLies) {
    {
        const Bytes bytes = with_tree(three_plates_tree());
        std::vector<uint32_t> words(bytes.size() / 4 + 1);
        std::memcpy(words.data(), bytes.data(), bytes.size());
        geom::Pack pack;
        ASSERT_TRUE(pack.open(words.data(), uint32_t(bytes.size())).ok());
        geom::ProductTree tree;
        ASSERT_TRUE(tree.open(pack).ok());
        EXPECT_EQ(tree.count(), 3u);
        EXPECT_EQ(tree.depth(2), 1u);
        EXPECT_EQ(tree.node_of(1), 1u);
        EXPECT_TRUE(tree.own(2, 2) && !tree.own(0, 2));
    }
    struct Lie {
        const char* what;
        void (*make)(Tree&);
    };
    constexpr uint32_t N = pack::kNoIndex;
    const Lie lies[] = {
        {"a parent after it", [](Tree& t) { t.nodes[1].parent = 2; }},
        {"a root with a parent", [](Tree& t) { t.nodes[0].parent = 1; }},
        {"a root without every instance", [](Tree& t) { t.nodes[0].instance_count = 2; }},
        {"a first child not the next node", [](Tree& t) { t.nodes[0].first_child = 2; }},
        {"a child its parent does not name", [](Tree& t) { t.nodes[0].first_child = N; }},
        {"a sibling not of its parent", [](Tree& t) { t.nodes[2].parent = 1, t.nodes[1].first_child = 2, t.nodes[1].next_sibling = N; }},
        {"a node no walk reaches", [](Tree& t) { t.nodes[1].next_sibling = N; }},
        {"siblings' instances overlapping", [](Tree& t) { t.nodes[2].first_instance = 1, t.nodes[2].instance_count = 2; }},
        {"instances past the parent's", [](Tree& t) { t.nodes[1].instance_count = 4; }},
        {"a name inside the pool's nothing", [](Tree& t) { t.nodes[1].name = 5000; }},
        {"an instance's node out of range", [](Tree& t) { t.instances[0].node = 3; }},
        {"an instance's node that does not hold it", [](Tree& t) { t.instances[2].node = 1; }},
        {"an explode offset not finite", [](Tree& t) { t.instances[1].explode[2] = NAN; }},
        {"instances' nodes without nodes", [](Tree& t) { t.nodes.clear(); }},
        {"a record short of the instances", [](Tree& t) { t.instances.pop_back(); }},
    };
    for (const Lie& lie : lies) {
        Tree t = three_plates_tree();
        lie.make(t);
        App app;
        ASSERT_TRUE(app.create().ok());
        const Result r = app.load(with_tree(t));
        EXPECT_EQ(r.status, Status::Corrupt) << lie.what;
        EXPECT_NE(text(r).find("Nodes record"), std::string::npos) << lie.what << ": " << text(r);
    }
}

TEST(Tree, NodesWalkAndActOnTheirParts) {
    App app;
    app.w = 320, app.h = 240, app.lines = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(with_tree(three_plates_tree())).ok());
    app.run();
    Viewer& v = *app.v;
    ASSERT_EQ(v.node_count(), 3u);
    Viewer::Node n{};
    ASSERT_TRUE(v.node(0, n).ok());
    EXPECT_EQ(n.parent, kNone);
    EXPECT_EQ(n.first_child, 1u);
    EXPECT_EQ(n.part_count, 3u);
    // The children from the first one, by their next siblings.
    uint32_t children = 0, parts = 0;
    for (uint32_t c = n.first_child; c != kNone; ++children) {
        Viewer::Node child{};
        ASSERT_TRUE(v.node(c, child).ok());
        EXPECT_EQ(child.parent, 0u);
        EXPECT_EQ(child.depth, 1u);
        parts += child.part_count;
        c = child.next_sibling;
    }
    EXPECT_EQ(children, 2u);
    EXPECT_EQ(parts, 3u) << "the children's parts are the root's";
    EXPECT_EQ(v.part_node(2), 2u);
    EXPECT_EQ(v.node(3, n).status, Status::OutOfRange);

    ASSERT_TRUE(v.show_node(1, false).ok());
    EXPECT_TRUE(!v.part(0).shown && !v.part(1).shown && v.part(2).shown);
    v.show_all_parts();
    ASSERT_TRUE(v.isolate_node(2).ok());
    EXPECT_TRUE(!v.part(0).shown && !v.part(1).shown && v.part(2).shown);
    v.show_all_parts();
    ASSERT_TRUE(v.choose_node(1).ok());
    EXPECT_EQ(v.chosen_node(), 1u);
    ASSERT_TRUE(v.choose_part(2).ok());
    EXPECT_EQ(v.chosen_node(), kNone) << "a part chosen ends a node's choice";
    EXPECT_EQ(v.choose_node(7).status, Status::OutOfRange);
    const Orbit before = v.orbit();
    ASSERT_TRUE(v.fit_node(2).ok());
    app.run();
    const Orbit after = v.orbit();
    EXPECT_TRUE(after.pan_mm[0] != before.pan_mm[0] || after.dolly != before.dolly) << "the third plate framed";
    EXPECT_EQ(v.fit_node(9).status, Status::OutOfRange);

    // A model without a tree has none to walk or explode.
    ASSERT_TRUE(app.load(three_plates()).ok());
    app.run();
    EXPECT_EQ(v.node_count(), 0u);
    EXPECT_EQ(v.part_node(0), kNone);
    EXPECT_EQ(v.set_explode(1).status, Status::NotFound);
    EXPECT_EQ(v.show_node(0, false).status, Status::OutOfRange);
}

TEST(Tree, ExplodedPartsMoveOutAndComeBackAndMeasureAssembled) {
    App app;
    app.w = 320, app.h = 240, app.lines = 240;
    app.interface = Interface::Full;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(with_tree(three_plates_tree())).ok());
    app.run();
    Viewer& v = *app.v;
    const std::vector<Rgb565> together = app.screen();
    EXPECT_EQ(v.explode(), 0.0f);
    ASSERT_TRUE(v.set_explode(1).ok());
    app.run();
    EXPECT_EQ(v.explode(), 1.0f);
    EXPECT_FALSE(app.screen() == together) << "the parts drawn apart";
    EXPECT_EQ(v.set_explode(2.5f).status, Status::OutOfRange);
    EXPECT_EQ(v.set_explode(NAN).status, Status::OutOfRange);
    EXPECT_EQ(v.set_explode(-1).status, Status::OutOfRange);
    EXPECT_EQ(v.explode(), 1.0f) << "a refused call changes nothing";
    // Measured exploded: the assembled model's distance, said so.
    v.set_measuring(true);
    ASSERT_TRUE(v.select(0, kTopFace).ok());
    ASSERT_TRUE(v.select(2, 2 * kPlateFaces + kTopFace).ok());
    const char* lines[3] = {};
    ASSERT_EQ(v.measurement(lines), 3u);
    const std::string exploded = lines[2];
    EXPECT_NE(exploded.find("(assembled)"), std::string::npos) << exploded;
    ASSERT_TRUE(v.set_explode(0).ok());
    v.clear_selection();
    ASSERT_TRUE(v.select(0, kTopFace).ok());
    ASSERT_TRUE(v.select(2, 2 * kPlateFaces + kTopFace).ok());
    ASSERT_EQ(v.measurement(lines), 3u);
    EXPECT_EQ(exploded, std::string(lines[2]) + "  (assembled)") << "the same measurement as assembled";
    v.clear_selection();
    v.set_measuring(false);
    app.run();
    EXPECT_TRUE(app.screen() == together) << "back together: the same pixels";
    // The key: out (factor 1), then back.
    v.key('e');
    EXPECT_EQ(v.explode(), 1.0f);
    v.key('e');
    EXPECT_EQ(v.explode(), 0.0f);
}
