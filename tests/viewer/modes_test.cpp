// The module through its public API (facet/viewer.h), as an application uses it (app.h).
// How the model is drawn: display modes, hidden line's outlines, see-through, a section.
#include "app.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <memory>
#include <utility>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

// The display modes, told apart by their pixels: the B-rep edges' colour, the faces' shading,
// the white of hidden-line faces, the background through a wireframe.
TEST(Viewer, DisplayModesDrawFacesAndEdgesAsNamed) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const Rgb565 edge = rgb565(28, 30, 38), white = rgb565(255, 255, 255);
    auto look = [&]() {
        const std::vector<Rgb565> s = app.screen();
        struct {
            int edges = 0, white = 0;
            Rgb565 centre, row_start;
        } r;
        for (Rgb565 p : s) r.edges += p == edge, r.white += p == white;
        // The polygon's middle (a tap there picks it), and the same row at the screen's left edge (background).
        r.centre = s[size_t(app.h / 2) * app.w + app.w / 2 - 10];
        r.row_start = s[size_t(app.h / 2) * app.w];
        return r;
    };
    EXPECT_EQ(app.v->display_mode(), DisplayMode::ShadedEdges);
    const auto shaded_edges = look();
    EXPECT_GT(shaded_edges.edges, 100);
    EXPECT_NE(shaded_edges.centre, shaded_edges.row_start) << "a face over the background";
    app.v->key('m');
    app.run();
    EXPECT_EQ(app.v->display_mode(), DisplayMode::Shaded);
    const auto shaded = look();
    EXPECT_EQ(shaded.edges, 0);
    EXPECT_EQ(shaded.centre, shaded_edges.centre) << "the same shaded face";
    app.v->key('m');
    app.run();
    EXPECT_EQ(app.v->display_mode(), DisplayMode::Wireframe);
    const auto wire = look();
    EXPECT_GT(wire.edges, 100);
    EXPECT_EQ(wire.centre, wire.row_start) << "no face: the background through the polygon";
    app.v->key('m');
    app.run();
    EXPECT_EQ(app.v->display_mode(), DisplayMode::HiddenLine);
    const auto hidden = look();
    EXPECT_GT(hidden.edges, 100);
    const uint32_t r = hidden.centre >> 11, g = (hidden.centre >> 5) & 63, b = hidden.centre & 31;
    EXPECT_TRUE(r >= 24 && g >= 48 && b >= 24) << "paper-white faces, lightly shaded: " << hidden.centre;
    ASSERT_TRUE(app.v->set_display_mode(DisplayMode::ShadedEdges).ok());
    app.run();
    EXPECT_EQ(app.screen()[size_t(app.h / 2) * app.w + app.w / 2 - 10], shaded_edges.centre);
}

// Tangent edges (those the pack marks: their faces meet smoothly) are drawn by default and left
// out on request: a disc with two of its four arcs so marked loses those arcs' pixels and
// nothing else (every pixel that changes was an edge's, and becomes the face's or the
// background's), keeps the other two; with all four marked no edge is left; key t toggles.
TEST(Viewer, TangentEdgesAreDrawnByDefaultAndLeftOutOnRequest) {
    const Rgb565 edge = rgb565(28, 30, 38);
    auto edges = [&](const std::vector<Rgb565>& s) { return std::count(s.begin(), s.end(), edge); };
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(disc({0, 1})).ok());
    app.run();
    EXPECT_TRUE(app.v->tangent_edges());
    const std::vector<Rgb565> all = app.screen();
    app.v->set_tangent_edges(false);
    EXPECT_FALSE(app.v->tangent_edges());
    app.run();
    const std::vector<Rgb565> sharp = app.screen();
    EXPECT_GT(edges(sharp), 100) << "the two sharp arcs stay";
    EXPECT_LT(edges(sharp), edges(all) - 100) << "the two tangent ones go";
    ASSERT_EQ(all.size(), sharp.size());
    size_t changed = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        if (all[i] == sharp[i]) continue;
        ++changed;
        EXPECT_EQ(all[i], edge) << "pixel " << i << " changed and was no edge's";
    }
    EXPECT_GT(changed, 100u);
    app.v->key('t');
    app.run();
    EXPECT_TRUE(app.v->tangent_edges());
    EXPECT_TRUE(app.screen() == all) << "back as it was";

    App round;
    ASSERT_TRUE(round.create().ok());
    ASSERT_TRUE(round.load(disc({0, 1, 2, 3})).ok());
    round.v->set_tangent_edges(false);
    round.run();
    EXPECT_EQ(edges(round.screen()), 0);
}

// Hidden line draws a curved face's outline, which no B-rep edge gives: the tube seen from the
// front in a parallel view has its two sides as lines, at its leftmost and rightmost points,
// all the way from its bottom to its top; shaded with edges, those columns have none.
TEST(Viewer, HiddenLineDrawsTheOutlinesOfCurvedFaces) {
    App app;
    app.w = 320, app.h = 240, app.lines = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(tube()).ok());
    app.run();
    app.v->key('1'); // the front: looking along +y, z up
    app.v->key('5'); // parallel (during the glide: the front view stays its end)
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    ASSERT_TRUE(core.camera().view().ortho);
    const module::FaceInfo& F = core.scene().face(0);
    ASSERT_GT(F.triangle_count, 20u);
    const auto [l, top, r, b] = box_of(core, 0, app.w, app.h, 0);
    ASSERT_TRUE(l >= 2 && top >= 0 && r < app.w - 2 && b < app.h) << "the tube on the screen";
    ASSERT_GT(r - l, 60);
    ASSERT_GT(b - top, 60);
    const Rgb565 ink = rgb565(28, 30, 38); // painter.cpp's kEdgeColour
    // Rows strictly between the circles (seen edge-on: the top and bottom lines): how many have
    // an outline pixel within two pixels of each side.
    auto sides = [&](const std::vector<Rgb565>& px) {
        int left = 0, right = 0;
        for (int y = top + 3; y <= b - 3; ++y) {
            bool at_l = false, at_r = false;
            for (int dx = -2; dx <= 2; ++dx) {
                at_l |= px[size_t(y) * app.w + size_t(l + dx)] == ink;
                at_r |= px[size_t(y) * app.w + size_t(r + dx)] == ink;
            }
            left += at_l, right += at_r;
        }
        return std::array<int, 2>{left, right};
    };
    const int rows = b - top - 5;
    const auto shaded = sides(app.screen());
    EXPECT_EQ(shaded[0], 0) << "shaded with edges: no outline";
    EXPECT_EQ(shaded[1], 0);
    app.v->key('m'), app.v->key('m'), app.v->key('m');
    app.run();
    ASSERT_EQ(app.v->display_mode(), DisplayMode::HiddenLine);
    const std::vector<Rgb565> hidden = app.screen();
    const auto outlined = sides(hidden);
    EXPECT_EQ(outlined[0], rows) << "the left side, every row";
    EXPECT_EQ(outlined[1], rows) << "the right side, every row";
    // And nowhere else between them: the middle columns hold no ink below the top circle.
    long inside = 0;
    for (int y = top + 3; y <= b - 3; ++y)
        for (int x = l + 4; x <= r - 4; ++x) inside += hidden[size_t(y) * app.w + size_t(x)] == ink;
    EXPECT_EQ(inside, 0);
}

// See-through: the chosen part solid, the others screen-door (every other pixel shows what is
// behind them).
TEST(Viewer, SeeThroughDrawsTheOtherPartsAsAScreenDoor) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7');
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const std::vector<Rgb565> solid = app.screen();
    ASSERT_TRUE(app.v->show_part(1, false).ok());
    app.run();
    const std::vector<Rgb565> without = app.screen();
    ASSERT_TRUE(app.v->show_part(1, true).ok());
    ASSERT_TRUE(app.v->choose_part(0).ok());
    ASSERT_TRUE(app.v->set_display_mode(DisplayMode::SeeThrough).ok());
    app.run();
    const std::vector<Rgb565> door = app.screen();
    // Inside the top face and inside the bottom face's outline seen through it (the edges, lines,
    // are drawn whole).
    const auto top = box_of(core, 1, app.w, app.h, 5), bottom = box_of(core, 1, app.w, app.h, 4);
    const std::array<int, 4> b = {std::max(top[0], bottom[0]), std::max(top[1], bottom[1]), std::min(top[2], bottom[2]),
                                  std::min(top[3], bottom[3])};
    int face = 0, behind = 0, n = 0;
    for (int y = b[1] + 3; y < b[3] - 3; ++y) {
        for (int x = b[0] + 3; x < b[2] - 3; ++x, ++n) {
            const size_t i = size_t(y) * app.w + x;
            face += door[i] == solid[i];
            behind += door[i] == without[i];
            EXPECT_EQ(door[i], ((x ^ y) & 1) ? without[i] : solid[i]) << x << "," << y;
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(n, 1000);
    EXPECT_NEAR(double(face) / n, 0.5, 0.02);
    EXPECT_NEAR(double(behind) / n, 0.5, 0.02);
}

// A section: across x through the middle cuts the second block away; moved into the first, the
// inside of the cut solid shows in the cap colour; the slider moves the plane; the cut part is
// not picked.
TEST(Viewer, ASectionCutsTheModelAndShowsTheSolidsInside) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = Interface::Full;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7');
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const std::vector<Rgb565> whole = app.screen();
    const auto second = box_of(core, 1, app.w, app.h);
    const int cx = (second[0] + second[2]) / 2, cy = (second[1] + second[3]) / 2;
    app.v->key('c'); // no face picked: across x, through the model's middle (x = 125)
    app.run();
    ASSERT_TRUE(app.v->section().on);
    EXPECT_FLOAT_EQ(app.v->section().normal[0], 1.0f);
    EXPECT_NEAR(app.v->section().offset_mm, 125.0f, 0.01f);
    const std::vector<Rgb565> cut = app.screen();
    EXPECT_NE(cut[size_t(cy) * app.w + cx], whole[size_t(cy) * app.w + cx]) << "the second block is cut away";
    app.v->touch(0, int16_t(cx), int16_t(cy), true);
    app.v->touch(0, int16_t(cx), int16_t(cy), false);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit) << "what is cut away is not picked";
    // Into the first block, seen from the isometric view: its inside in the cap colour.
    ASSERT_TRUE(app.v->set_section({true, {1, 0, 0}, 50}).ok());
    app.v->key('0');
    app.run();
    const Rgb565 cap = rgb565(205, 70, 60); // painter.cpp's kCap, flat
    const std::vector<Rgb565> iso = app.screen();
    const long caps = std::count(iso.begin(), iso.end(), cap);
    EXPECT_GT(caps, 500) << "the inside of the cut block";
    // The other half kept (the plane x = 50 cutting away x < 50): the eye (isometric, at +x) is
    // on the kept side, where the block's own front faces hide all its back faces: they are
    // skipped as without a section (a clipped face: a triangle or two more).
    ASSERT_TRUE(app.v->set_section({false, {1, 0, 0}, 0}).ok());
    app.run();
    const uint32_t front_only = app.last(Event::Kind::FrameDone)->frame.triangles;
    ASSERT_TRUE(app.v->set_section({true, {-1, 0, 0}, -50}).ok());
    app.run();
    const std::vector<Rgb565> kept = app.screen();
    EXPECT_EQ(std::count(kept.begin(), kept.end(), cap), 0) << "no inside shows from the kept side";
    EXPECT_LE(app.last(Event::Kind::FrameDone)->frame.triangles, front_only + 4);
    ASSERT_TRUE(app.v->set_section({true, {1, 0, 0}, 50}).ok());
    app.run();
    EXPECT_EQ(app.screen(), iso);
    // The slider: a finger on it at the top puts the plane at the model's far end, dragged to
    // the bottom at its near end.
    const Area s = core.overlay().slider();
    ASSERT_GT(s.width, 0);
    app.v->touch(0, int16_t(s.x + s.width / 2), int16_t(s.y + 2), true);
    const float hi = app.v->section().offset_mm;
    app.v->touch(0, int16_t(s.x + s.width / 2), int16_t(s.y + s.height - 2), true);
    app.v->touch(0, int16_t(s.x + s.width / 2), int16_t(s.y + s.height - 2), false);
    const float lo = app.v->section().offset_mm;
    const float radius = 0.5f * std::sqrt(250.0f * 250 + 100 * 100 + 100 * 100);
    EXPECT_NEAR(hi, 125 + radius, 0.5f);
    EXPECT_NEAR(lo, 125 - radius, 0.5f);
    EXPECT_EQ(app.count(Event::Kind::Picked), 1) << "a slide is no tap";
    // Off again (after a plane of the application's, c turns it off).
    app.v->key('c');
    app.run();
    EXPECT_FALSE(app.v->section().on);
    app.v->key('7');
    app.run();
    // The same picture; the status bar's triangle count has the cube's back planes now (the
    // section brought them in: without it they wait, turned away, as detail.cpp says).
    const std::vector<Rgb565> after = app.screen();
    const size_t bar = size_t(core.overlay().taken().top) * app.w;
    EXPECT_TRUE(std::equal(after.begin() + bar, after.end(), whole.begin() + bar));
}

// A point projected once in an instance's drawing is taken from the projection cache after
// (Painter::point): a vertex two faces share, an edge's sample at a face's vertex, the end two
// edges share. The same points, so the same pixels as projecting every point again, in each
// display mode, turned, and through a section (whose side is measured per segment, not taken
// from the face's cut vertices); and most points come from the cache.
TEST(Viewer, PointsFromTheProjectionCacheDrawWhatProjectingEachAgainDraws) {
    const std::pair<const char*, Bytes> models[] = {{"polygon and triangle", polygon_and_triangle(40)}, {"disc", disc()},
                                                    {"tube", tube()}, {"two blocks", two_blocks()}};
    for (const auto& [name, bytes] : models) {
        SCOPED_TRACE(name);
        std::vector<std::vector<Rgb565>> screens[2];
        module::Painter::PointCounts tally[2]; // the turned frame's
        for (int cache = 0; cache < 2; ++cache) {
            App app;
            ASSERT_TRUE(app.create().ok());
            Core& core = *static_cast<Core*>(app.v);
            core.painter().set_point_cache(cache == 1);
            ASSERT_TRUE(app.load(bytes).ok());
            app.run();
            auto look = [&]() {
                app.run();
                screens[cache].push_back(app.screen());
            };
            (void)core.painter().take_point_counts(); // (the wireframe while the faces came in)
            app.v->key('d'), look(); // shaded with edges, turned: counted
            tally[cache] = core.painter().take_point_counts();
            for (int mode = 0; mode < 4; ++mode) app.v->key('m'), look();
            app.v->key('m'), (void)app.v->set_section({true, {0.6f, 0.0f, 0.8f}, 10.0f}), look();
        }
        ASSERT_EQ(screens[0].size(), screens[1].size());
        for (size_t k = 0; k < screens[0].size(); ++k) EXPECT_TRUE(screens[0][k] == screens[1][k]) << "picture " << k;
        EXPECT_EQ(tally[0].cached, 0u);
        EXPECT_EQ(tally[1].cached + tally[1].projected, tally[0].projected) << "the same points asked for";
        // (Each edge sample at a face's vertex is asked for twice, and the disc's mesh has no
        // other vertex; the slots two points' hashes share make the rest.)
        EXPECT_GE(3 * tally[1].cached, tally[0].projected) << "a third of the points or more from the cache";
    }
}

// Each instance's own part of its transform is kept from frame to frame while the view stays
// (a section moved keeps it), its eye while it is drawn from its faces
// (Presenter::transform_of, place_eye): the same pictures as transforms made afresh for every
// frame, through sections moved, turns and display modes.
TEST(Viewer, TransformsKeptFromFrameToFrameDrawWhatTransformsMadeAfreshDraw) {
    std::vector<std::vector<Rgb565>> screens[2];
    for (int keep = 0; keep < 2; ++keep) {
        App app;
        ASSERT_TRUE(app.create().ok());
        static_cast<Core*>(app.v)->presenter().set_keep_transforms(keep == 1);
        ASSERT_TRUE(app.load(two_blocks()).ok());
        auto look = [&]() {
            app.run();
            screens[keep].push_back(app.screen());
        };
        look();
        app.v->key('d'), look();
        for (const float at : {50.0f, 60.0f, 140.0f}) ASSERT_TRUE(app.v->set_section({true, {1, 0, 0}, at}).ok()), look();
        for (int mode = 0; mode < 4; ++mode) app.v->key('m'), look();
        ASSERT_TRUE(app.v->set_section({true, {0.6f, 0.0f, 0.8f}, 10.0f}).ok()), look();
        app.v->key('d'), look();
        ASSERT_TRUE(app.v->set_section({false, {1, 0, 0}, 0}).ok()), look();
    }
    ASSERT_EQ(screens[0].size(), screens[1].size());
    for (size_t k = 0; k < screens[0].size(); ++k) EXPECT_TRUE(screens[0][k] == screens[1][k]) << "picture " << k;
    EXPECT_FALSE(screens[1][2] == screens[1][3]) << "the section moved";
}

// A model whose frames of every face come near the frame budget (3/4 of a frame at rest's 33.3
// ms here) shows each new view in two frames: its faces first, then their edges over them
// (Presenter, Job::edges_owed); it ends on the picture a quicker device draws at once.
TEST(Viewer, ASlowModelShowsANewViewsFacesFirstAndTheirEdgesTheFrameAfter) {
    struct Way {
        int buffers;
        Flush mode;
    };
    for (const Way way : {Way{1, Flush::Copy}, Way{2, Flush::Copy}, Way{2, Flush::Scanout}}) {
        SCOPED_TRACE(testing::Message() << way.buffers << " buffers, " << (way.mode == Flush::Copy ? "copied" : "scanned out"));
        std::vector<Rgb565> ends[2], first_frame;
        int frames[2] = {0, 0};
        for (int slow = 0; slow < 2; ++slow) {
            App app;
            app.buffers = way.buffers, app.mode = way.mode, app.late_done = way.mode == Flush::Scanout;
            app.faces_layer = true, app.use_clock = true, app.tick_us = slow ? 20000 : 0;
            ASSERT_TRUE(app.create().ok());
            ASSERT_TRUE(app.load(two_blocks()).ok());
            app.run();
            app.v->key('d'), app.run(); // (a frame of every face, measured)
            const int before = app.count(Event::Kind::FrameDone);
            app.v->key('d');
            for (int i = 0; i < 100000 && app.v->step(100000) != Activity::Idle; ++i) {
                app.done();
                if (slow && first_frame.empty() && app.count(Event::Kind::FrameDone) == before + 1) first_frame = app.screen();
            }
            app.done(), app.run();
            frames[slow] = app.count(Event::Kind::FrameDone) - before;
            ends[slow] = app.screen();
        }
        EXPECT_EQ(frames[0], 1);
        EXPECT_EQ(frames[1], 2) << "the faces, then their edges";
        EXPECT_TRUE(ends[0] == ends[1]);
        EXPECT_FALSE(first_frame == ends[1]) << "the first frame without the edges";
    }
}
