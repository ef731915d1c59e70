// Parts' proxies on the screen (issue 52): a part whose block is left out of a model larger than
// the memory is drawn as its proxy (a coarse mesh in the index), shaded in its colour, not as
// its box; in wireframe, where no face is drawn, its box. A view crowded past its triangles'
// bound draws its parts as their proxies where they stray little enough on the screen, and
// a part zoomed into is drawn as itself again.
#include "../geom/shapes.h"
#include "app.h"
#include "detail.h"
#include "pack_blocks.h"
#include "proxies.h"

#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

namespace {

constexpr Rgb565 kBoxColour = rgb565(96, 104, 128);  // (painter.cpp)
constexpr Rgb565 kEdgeColour = rgb565(28, 30, 38);   // (painter.cpp)

// Twelve parts (or `count`) of every surface kind in a row, a part a block, with or without
// their proxies (and with them, `grouped`: groups of at most 16 nearby parts).
Bytes twelve(bool proxies, bool grouped = false, uint32_t count = 12) {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<Pack> packs(count);
    for (uint32_t k = 0; k < count; ++k) EXPECT_TRUE(packs[k].open(shapes[k % 4].data(), uint32_t(shapes[k % 4].size())).ok());
    const Bytes combined = combine_packs(packs, 150.0f);
    Pack whole;
    EXPECT_TRUE(whole.open(combined.data(), uint32_t(combined.size())).ok());
    std::vector<Proxy> made;
    std::string error;
    const uint32_t caps[] = {16, 64};
    EXPECT_TRUE(make_proxies(whole, caps, made, error)) << error;
    Bytes file;
    const uint32_t group_caps[] = {48, 192};
    EXPECT_TRUE(make_blocked(whole, {}, {1, BlockStore::Lzma, proxies ? &made : nullptr, grouped ? group_caps : std::span<const uint32_t>{}}, file, error))
        << error;
    return file;
}

// The model in the largest workspace that leaves some parts out (as swap_test's), run to rest.
bool open_in_part(App& app, const Bytes& file, uint32_t& boxed) {
    std::vector<uint64_t> aligned(file.size() / 8 + 1);
    std::memcpy(aligned.data(), file.data(), file.size());
    ModelNeeds needs;
    if (const Result r = model_needs(aligned.data(), uint32_t(file.size()), needs); !r.ok()) {
        ADD_FAILURE() << text(r);
        return false;
    }
    const size_t base = workspace_bytes();
    for (size_t room = needs.least_workspace_bytes + needs.pack_memory_bytes - base; room > 4096; room = room * 31 / 32) {
        app = App{};
        app.w = 320, app.h = 240;
        app.workspace_size = base + room;
        if (!app.create().ok()) return false;
        if (const Result r = app.load(file); !r.ok()) {
            if (r.status == Status::Full) continue;
            ADD_FAILURE() << text(r);
            return false;
        }
        boxed = app.last(Event::Kind::Loaded)->loaded.boxed_parts;
        if (boxed >= 4 && boxed < 12) {
            app.run();
            return true;
        }
    }
    return false;
}

struct Look {
    size_t box = 0, drawn = 0; // pixels of the box colour; pixels not the background's
};
Look look(const App& app) {
    Look l;
    const std::vector<Rgb565> screen = app.screen();
    for (size_t i = 0; i < screen.size(); ++i) {
        l.box += screen[i] == kBoxColour;
        l.drawn += screen[i] != screen[i - i % app.w]; // (a row's background: its left end)
    }
    return l;
}

// The pixels within `reach` of instance i's part's centre on the screen that `counts` (the
// pixel, and its row's background: its left end).
template <typename Counts>
uint32_t pixels_about(const App& app, const std::vector<Rgb565>& screen, uint32_t i, int32_t reach, Counts counts) {
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    int32_t centre[3], radius;
    if (!scene.part_sphere(scene.instances()[i].shell, centre, radius)) return 0;
    module::Projected p;
    core.camera().transform(scene, i, app.w, app.h).project(centre, p);
    const int32_t x = render::subpixel::pixel_of(p.s.x), y = render::subpixel::pixel_of(p.s.y);
    uint32_t n = 0;
    for (int32_t dy = -reach; dy <= reach; ++dy)
        for (int32_t dx = -reach; dx <= reach; ++dx) {
            const int32_t px = x + dx, py = y + dy;
            if (px < 0 || py < 0 || px >= app.w || py >= app.h) continue;
            const size_t at = size_t(py) * app.w + px;
            n += counts(screen[at], screen[at - at % app.w]);
        }
    return n;
}

} // namespace

TEST(Proxies, PartsLeftOutAreDrawnAsTheirProxiesNotBoxes) {
    App with, without;
    uint32_t boxed_with = 0, boxed_without = 0;
    ASSERT_TRUE(open_in_part(with, twelve(true), boxed_with));
    ASSERT_TRUE(open_in_part(without, twelve(false), boxed_without));
    const Look a = look(with), b = look(without);
    EXPECT_GT(b.box, 0u) << "without proxies, the parts left out are boxes";
    EXPECT_EQ(a.box, 0u) << "with them, no box at rest";
    // Each part left out covers pixels of its own about its centre (shaded triangles).
    const Core& core = *static_cast<const Core*>(with.v);
    const module::Scene& scene = core.scene();
    const std::vector<Rgb565> screen = with.screen();
    uint32_t shown = 0;
    for (uint32_t i = 0; i < scene.instances().size(); ++i) {
        const uint32_t part = scene.instances()[i].shell;
        if (!scene.part_left_out(part)) continue;
        const uint32_t covered = pixels_about(with, screen, i, 4, [](Rgb565 c, Rgb565 back) { return c != back && c != kBoxColour; });
        EXPECT_GT(covered, 4u) << "part " << part << " left out, drawn as its proxy";
        ++shown;
    }
    EXPECT_EQ(shown, scene.left_out().parts);
    EXPECT_GT(shown, 0u);
    // Wireframe draws no face: the boxes again.
    ASSERT_TRUE(with.v->set_display_mode(DisplayMode::Wireframe).ok());
    with.run();
    EXPECT_GT(look(with).box, 0u);
    ASSERT_TRUE(with.v->set_display_mode(DisplayMode::HiddenLine).ok());
    with.run();
    EXPECT_EQ(look(with).box, 0u) << "hidden line: proxies as paper faces";
    // ... outlined: lines about each part left out.
    const std::vector<Rgb565> lined = with.screen();
    for (uint32_t i = 0; i < scene.instances().size(); ++i) {
        const uint32_t part = scene.instances()[i].shell;
        if (!scene.part_left_out(part)) continue;
        const uint32_t lines = pixels_about(with, lined, i, 12, [](Rgb565 c, Rgb565) { return c == kEdgeColour; });
        EXPECT_GT(lines, 4u) << "part " << part << " left out, outlined in hidden line";
    }
}

// A crowded view (more triangles than its bound: a small screen, the detail 8 times finer):
// with proxies standing for the parts whose own meshes are larger, it comes within its bound
// at a finer screen error than without; every part still shows about its centre, and no box;
// a part then framed alone is drawn as itself (its block in, its faces tessellated, its edges
// drawn: a proxy has none).
TEST(Proxies, ACrowdedViewDrawsPartsAsProxiesAndAPartZoomedIntoAsItself) {
    float crowd[2] = {};
    for (const bool proxies : {false, true}) {
        App app;
        app.w = 320, app.h = 240, app.lines = app.h;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(twelve(proxies)).ok());
        app.run();
        ASSERT_TRUE(app.v->set_detail(0.125f).ok());
        app.run();
        const Core& core = *static_cast<const Core*>(app.v);
        EXPECT_GT(core.detail_level().crowd(), 1.0f) << "the bound was reached";
        const Event* frame = app.last_full_frame();
        ASSERT_NE(frame, nullptr);
        EXPECT_LE(frame->frame.triangles + frame->frame.culled, core.detail_level().triangle_bound()) << "within the bound at rest";
        crowd[proxies] = core.detail_level().crowd();
        if (!proxies) continue;
        EXPECT_EQ(look(app).box, 0u);
        const module::Scene& scene = core.scene();
        const std::vector<Rgb565> screen = app.screen();
        for (uint32_t i = 0; i < scene.instances().size(); ++i) {
            const uint32_t covered = pixels_about(app, screen, i, 3, [](Rgb565 c, Rgb565 back) { return c != back; });
            EXPECT_GT(covered, 4u) << "instance " << i << " shows";
        }
        // One part framed: the part is itself, edges and all.
        const uint32_t part = 7; // (a trimmed B-spline sheet: its boundary drawn as edges)
        ASSERT_TRUE(app.v->fit_part(part).ok());
        app.run();
        EXPECT_FALSE(scene.part_left_out(part));
        const module::Part sh = scene.part(part);
        ASSERT_GT(sh.face_count, 0u);
        EXPECT_EQ(scene.face(sh.first_face).state, module::FaceState::Done);
        size_t edges = 0;
        for (const Rgb565 c : app.screen()) edges += c == kEdgeColour;
        EXPECT_GT(edges, size_t(app.w)) << "its edges drawn";
    }
    EXPECT_LT(crowd[1], crowd[0]) << "with proxies, the view is within its bound at a finer screen error";
}

// Groups of nearby parts (the index's Groups): a group off the view is passed whole, which
// changes no pixel: the same pictures with and without groups where the view is not crowded
// (fitted, zoomed in with parts off the view, turned).
TEST(Groups, AGroupOffTheViewIsPassedWholeAndChangesNoPixel) {
    std::vector<Rgb565> shots[2][3];
    for (const bool grouped : {false, true}) {
        App app;
        app.w = 320, app.h = 240;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(twelve(true, grouped, 40)).ok()); // (four groups of ten)
        const Core& core = *static_cast<const Core*>(app.v);
        ASSERT_EQ(core.scene().index().groups().size(), grouped ? 4u : 0u);
        app.run();
        shots[grouped][0] = app.screen();
        for (int k = 0; k < 6; ++k) app.v->act(Action::ZoomIn);
        app.run();
        shots[grouped][1] = app.screen();
        for (int k = 0; k < 3; ++k) app.v->act(Action::TurnLeft);
        app.run();
        shots[grouped][2] = app.screen();
        EXPECT_EQ(static_cast<Core*>(app.v)->presenter().groups_drawn(), 0u) << "not crowded: no group drawn as its proxy";
    }
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(shots[0][k] == shots[1][k]) << "view " << k;
}

// A group a few pixels across (its members smaller still) is drawn as its proxy, one instead of
// each member's, as are the groups in the frames of the model's layout while its edges are
// sampled: no box, about as many pixels drawn as the members' own proxies cover. A part then
// framed alone is drawn as itself (its group neither small nor crowded).
TEST(Groups, AGroupAFewPixelsAcrossIsDrawnAsOneProxyAndAPartFramedAsItself) {
    size_t drawn[2] = {};
    for (const bool grouped : {false, true}) {
        App app;
        app.w = 320, app.h = 240;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(twelve(true, grouped)).ok());
        Core& core = *static_cast<Core*>(app.v);
        uint32_t layout_groups = 0;
        for (int i = 0; i < 100000 && app.count(Event::Kind::Sampled) == 0; ++i) {
            (void)app.v->step(1000);
            app.done();
            layout_groups = std::max(layout_groups, core.presenter().groups_drawn());
        }
        EXPECT_EQ(layout_groups > 0, grouped) << "the layout's frames: each group its coarsest proxy";
        app.run();
        for (int k = 0; k < 12; ++k) app.v->act(Action::ZoomOut);
        app.run();
        EXPECT_EQ(core.presenter().groups_drawn() > 0, grouped) << "groups a few pixels across";
        EXPECT_EQ(look(app).box, 0u);
        drawn[grouped] = look(app).drawn;
        const uint32_t part = 7;
        ASSERT_TRUE(app.v->fit_part(part).ok());
        app.run();
        EXPECT_EQ(core.presenter().groups_drawn(), 0u) << "the part framed: its group neither small nor crowded";
        if (!grouped) continue;
        const module::Part sh = core.scene().part(part);
        ASSERT_GT(sh.face_count, 0u);
        EXPECT_EQ(core.scene().face(sh.first_face).state, module::FaceState::Done) << "drawn as itself";
    }
    EXPECT_GT(drawn[1], drawn[0] / 2) << "the groups' proxies cover about what their members' do";
    EXPECT_LT(drawn[1], drawn[0] * 2);
}
