// The module through its public API (facet/viewer.h), as an application uses it (app.h).
// Input: the toolbar and the measurement panel by touch, keys, gestures and picks, levels of
// detail, the parts list by touch.
#include "app.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <memory>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

// The on-screen interface through touch: toolbar buttons act (and pick nothing), a tapped face
// is described with its exact values, and with MEAS on a second one gives the relation.
TEST(Viewer, TheToolbarAndTheMeasurementPanelWorkByTouch) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = Interface::Full;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Overlay& o = core.overlay();
    auto tap = [&](int x, int y) { app.tap(x, y); };
    auto button = [&](Action a) { return app.button_row(o, a); };
    // MODE: the display mode changes, nothing is picked.
    const int picks = app.count(Event::Kind::Picked);
    tap(app.w - 20, button(Action::NextDisplayMode));
    EXPECT_EQ(app.v->display_mode(), DisplayMode::Shaded);
    EXPECT_EQ(app.count(Event::Kind::Picked), picks);
    // The polygon (a plane face) from the top view: described exactly.
    app.v->key('7');
    app.run();
    const module::Transform t = core.camera().transform(core.scene(), 0, app.w, app.h);
    auto screen_of = [&](float x, float y) {
        int32_t p[3] = {int32_t(std::lround(x / core.scene().unit())), int32_t(std::lround(y / core.scene().unit())), 0};
        module::Projected q;
        t.project(p, q);
        return std::pair<int, int>{q.s.x / 16, q.s.y / 16};
    };
    const auto [px, py] = screen_of(-50, 0);
    tap(px, py);
    ASSERT_EQ(app.last(Event::Kind::Picked)->pick.face, 0u);
    ASSERT_EQ(o.line_count(), 1u);
    EXPECT_STREQ(o.line(0), "#0 plane  normal (0.000, 0.000, 1.000)  offset 0.000 mm");
    // MEAS on, then the triangle: the two faces' relation (one plane: parallel, 0 apart).
    tap(app.w - 20, button(Action::Measure));
    EXPECT_TRUE(o.measuring());
    EXPECT_STREQ(o.line(1), "MEAS: tap a second face");
    const auto [tx, ty] = screen_of(125, 5);
    tap(tx, ty);
    ASSERT_EQ(app.last(Event::Kind::Picked)->pick.face, 1u);
    ASSERT_EQ(o.line_count(), 3u);
    EXPECT_STREQ(o.line(2), "parallel planes: distance 0.000 mm");
    // HELP on, its button (what a finger has for key t) leaves tangent edges out and brings
    // them back, picking nothing; HELP off; a tap on nothing clears the selection.
    tap(app.w - 20, button(Action::Help));
    EXPECT_TRUE(o.help());
    const Area tangent = o.help_button();
    ASSERT_GE(tangent.height, 28) << "a finger's height";
    ASSERT_LE(tangent.y + tangent.height, app.h);
    const int picked = app.count(Event::Kind::Picked);
    tap(tangent.x + tangent.width / 2, tangent.y + tangent.height / 2);
    EXPECT_FALSE(app.v->tangent_edges());
    tap(tangent.x + 5, tangent.y + 5);
    EXPECT_TRUE(app.v->tangent_edges());
    EXPECT_EQ(app.count(Event::Kind::Picked), picked);
    tap(app.w - 20, button(Action::Help));
    EXPECT_FALSE(o.help());
    tap(5, app.h - 5);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit);
    EXPECT_EQ(o.line_count(), 0u);
}

TEST(Viewer, KeysGesturesAndPicks) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    auto view = [&]() { return app.last(Event::Kind::ViewChanged)->view; };
    app.v->key('d');
    ASSERT_NE(app.last(Event::Kind::ViewChanged), nullptr);
    const float yaw = view().yaw_deg, fitted = view().zoom; // the dolly the framing chose
    app.v->key(KeyLeft);
    EXPECT_NEAR(view().yaw_deg, yaw - 15, 0.01f);
    app.v->key('+');
    EXPECT_NEAR(view().zoom, 0.8f * fitted, 1e-5f);
    app.v->wheel(-1);
    EXPECT_NEAR(view().zoom, fitted, 1e-5f);
    const int changes = app.count(Event::Kind::ViewChanged);
    app.v->key('%'); // no key of the table
    EXPECT_EQ(app.count(Event::Kind::ViewChanged), changes);
    // One finger: small motions are a tap's; a drag orbits.
    app.v->touch(0, 80, 60, true);
    app.v->touch(0, 83, 60, true);
    EXPECT_EQ(app.count(Event::Kind::ViewChanged), changes) << "within the tap slop";
    app.v->touch(0, 100, 60, true);
    EXPECT_NEAR(view().yaw_deg, yaw - 15 + 20 * 0.5f, 0.01f) << "half a degree a pixel, from where it landed";
    app.v->touch(0, 100, 60, false);
    EXPECT_EQ(app.count(Event::Kind::Picked), 0) << "a drag is no tap";
    // Two fingers apart: zoom in.
    app.v->touch(0, 60, 60, true);
    app.v->touch(1, 100, 60, true);
    const float zoom = view().zoom;
    app.v->touch(1, 140, 60, true);
    EXPECT_LT(view().zoom, zoom);
    app.v->touch(1, 140, 60, false);
    app.v->touch(0, 60, 60, false);
    EXPECT_EQ(app.count(Event::Kind::Picked), 0) << "a pinch is no tap";
    // Back to the fitted view: a tap in the middle picks the polygon, one in a corner nothing.
    app.v->key('f');
    app.run();
    app.v->touch(0, 60, 60, true);
    app.v->touch(0, 60, 60, false);
    ASSERT_EQ(app.count(Event::Kind::Picked), 1);
    EXPECT_TRUE(app.last(Event::Kind::Picked)->pick.hit);
    EXPECT_EQ(app.last(Event::Kind::Picked)->pick.face, 0u);
    app.v->touch(0, 1, 1, true);
    app.v->touch(0, 1, 1, false);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit);
    // A mouse click picks where the pointer is (it starts in the middle).
    app.v->pointer(0, 0, 1);
    app.v->pointer(0, 0, 0);
    EXPECT_EQ(app.count(Event::Kind::Picked), 3);
    EXPECT_TRUE(app.last(Event::Kind::Picked)->pick.hit);
}

TEST(Viewer, LevelsOfDetailRetessellateWithinTheirLimits) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const float t0 = app.v->stats().tolerance_mm;
    app.v->key(']');
    app.run();
    EXPECT_NEAR(app.v->stats().tolerance_mm, t0 / 2, t0 * 1e-6f);
    EXPECT_EQ(app.v->stats().pass, 1u);
    EXPECT_EQ(app.count(Event::Kind::Tessellated), 2);
    for (int i = 0; i < 10; ++i) app.v->key(']');
    app.run();
    EXPECT_NEAR(app.v->stats().tolerance_mm, t0 / 8, t0 * 1e-6f) << "no finer than an eighth";
}

TEST(Viewer, AFirstLevelWhoseEdgesDoNotFitGoesCoarserUpToSixteenTimes) {
    // The disc's circle takes 48 samples at the default level: in a pool of 30 the first level
    // takes twice the tolerance (and again while short), shows the face and says each level it
    // tried; in a pool that holds no level up to 16 times the tolerance, the pass fails and
    // nothing is shown, as before.
    App app;
    app.capacity.samples = 30;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(disc()).ok());
    app.run();
    EXPECT_EQ(app.count(Event::Kind::PassFailed), 0) << (app.last(Event::Kind::PassFailed) ? text(app.last(Event::Kind::PassFailed)->why) : "");
    EXPECT_EQ(app.v->stats().done, 1u);
    const float detail = app.v->detail();
    EXPECT_GT(detail, 1.0f);
    EXPECT_LE(detail, 16.0f);
    EXPECT_EQ(detail, std::exp2(std::round(std::log2(detail)))) << "a power of two of the default";
    EXPECT_GE(app.count(Event::Kind::Pass), 2);
    EXPECT_EQ(app.last(Event::Kind::Pass)->pass.tolerance_mm, app.v->stats().tolerance_mm);
    EXPECT_LE(app.last(Event::Kind::Sampled)->pass.samples, 30u);
    App none;
    none.capacity.samples = 10; // (the plan's least for four edges; 16 times the tolerance takes more)
    ASSERT_TRUE(none.create().ok());
    ASSERT_TRUE(none.load(disc()).ok());
    none.run();
    EXPECT_EQ(none.count(Event::Kind::PassFailed), 1);
    EXPECT_EQ(none.v->stats().done, 0u);
    // A finer level later that does not fit goes back to the one shown (not coarser).
    app.v->key(']');
    app.run();
    EXPECT_EQ(app.count(Event::Kind::PassFailed), 1);
    EXPECT_EQ(app.v->detail(), detail);
    EXPECT_EQ(app.v->stats().done, 1u);
}

TEST(Viewer, ALevelOfDetailWhoseEdgesDoNotFitGoesBackToThePreviousOne) {
    // The pool of edge samples holds the disc's circle at the default level of detail (48
    // samples) but not at a finer one (64): that pass fails and says why, the previous level's
    // samples come back, and the picture stays the previous level's; a coarser one then works.
    App app;
    app.capacity.samples = 60;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(disc()).ok());
    app.run();
    ASSERT_EQ(app.v->stats().done, 1u) << (app.last(Event::Kind::FaceFailed) ? text(app.last(Event::Kind::FaceFailed)->why) : "")
                                       << (app.last(Event::Kind::PassFailed) ? text(app.last(Event::Kind::PassFailed)->why) : "");
    ASSERT_EQ(app.count(Event::Kind::PassFailed), 0);
    const std::vector<Rgb565> before = app.screen();
    const float t0 = app.v->stats().tolerance_mm;
    app.v->key(']');
    app.run();
    ASSERT_EQ(app.count(Event::Kind::PassFailed), 1);
    EXPECT_EQ(app.last(Event::Kind::PassFailed)->why.status, Status::Full);
    EXPECT_NE(text(app.last(Event::Kind::PassFailed)->why).find("edge "), std::string::npos);
    EXPECT_FLOAT_EQ(app.v->stats().tolerance_mm, t0) << "back to the previous level";
    EXPECT_EQ(app.v->stats().done, 1u);
    EXPECT_EQ(app.screen(), before);
    app.v->key('d');
    app.run();
    app.v->key('a');
    app.run();
    EXPECT_EQ(app.screen(), before) << "the previous level's samples and mesh, intact";
    app.v->key('[');
    app.run();
    EXPECT_EQ(app.count(Event::Kind::PassFailed), 1);
    EXPECT_FLOAT_EQ(app.v->stats().tolerance_mm, t0 * 2);
    EXPECT_EQ(app.v->stats().done, 1u);
}

// The parts list by touch: PART opens it, a tap on a name chooses the part (highlighted), a tap
// on its box hides it (gone from the screen, not pickable), ISOL shows it alone, ALL shows all.
TEST(Viewer, ThePartsListHidesShowsAndIsolatesByTouch) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = Interface::Full;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7'); // from the top: the blocks side by side
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Overlay& o = core.overlay();
    auto tap = [&](int x, int y) { app.tap(x, y); };
    auto button = [&](Action a) { return app.button_row(o, a); };
    const std::vector<Rgb565> both = app.screen();
    const auto second = box_of(core, 1, app.w, app.h);
    const int cx = (second[0] + second[2]) / 2, cy = (second[1] + second[3]) / 2;
    tap(app.w - 20, button(Action::Parts));
    ASSERT_TRUE(o.parts_open());
    const Area panel = o.parts_panel();
    EXPECT_LT(panel.x + panel.width, second[0]) << "the list leaves the second block in view";
    const int row1 = panel.y + module::Overlay::kRow + module::Overlay::kRow + module::Overlay::kRow / 2; // the second row
    tap(60, row1);
    EXPECT_EQ(app.v->chosen_part(), 1u);
    const Rgb565 magenta = app.screen()[size_t(cy) * app.w + cx];
    EXPECT_NE(magenta, both[size_t(cy) * app.w + cx]) << "the chosen part is highlighted";
    tap(10, row1); // its box: hidden
    EXPECT_FALSE(app.v->part(1).shown);
    const std::vector<Rgb565> hidden = app.screen();
    EXPECT_NE(hidden[size_t(cy) * app.w + cx], magenta);
    app.v->touch(0, int16_t(cx), int16_t(cy), true);
    app.v->touch(0, int16_t(cx), int16_t(cy), false);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit) << "a hidden part is not picked";
    // ISOL with the first part chosen: the second stays hidden, ALL brings it back.
    tap(60, row1 - module::Overlay::kRow);
    EXPECT_EQ(app.v->chosen_part(), 0u);
    // (The footer: HIDE, ISOL, ALL, FIT, EXPL, a fifth of the panel each.)
    tap(panel.width * 3 / 10, panel.y + panel.height - 5);
    EXPECT_TRUE(app.v->part(0).shown);
    EXPECT_FALSE(app.v->part(1).shown);
    tap(panel.width / 2, panel.y + panel.height - 5);
    EXPECT_TRUE(app.v->part(1).shown);
    tap(60, row1 - module::Overlay::kRow); // a second tap on the chosen name lets it go
    EXPECT_EQ(app.v->chosen_part(), ~0u);
    tap(app.w - 20, button(Action::Parts));
    EXPECT_FALSE(o.parts_open());
    EXPECT_EQ(app.screen(), both) << "everything as it was";
}

// While the view is dragged, shaded faces are drawn without their B-rep edges (coarser detail
// while the view moves, issue 25); when it rests the frame is drawn again with them.
TEST(Viewer, ADragDrawsTheFacesAloneAndTheEdgesComeBackWhenItRests) {
    App app;
    app.w = 320, app.h = 240, app.lines = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(24)).ok());
    app.run();
    ASSERT_EQ(app.v->display_mode(), DisplayMode::ShadedEdges);
    auto edge_pixels = [&] {
        uint32_t n = 0;
        for (Rgb565 p : app.screen()) n += p == rgb565(28, 30, 38);
        return n;
    };
    const uint32_t at_rest = edge_pixels();
    EXPECT_GT(at_rest, 100u) << "the polygon's and the triangle's edges";
    app.v->pointer(0, 0, 1); // the left button down, then moved: an orbit
    for (int k = 0; k < 4; ++k) {
        app.v->pointer(6, 0, 1);
        app.run();
    }
    EXPECT_EQ(edge_pixels(), 0u) << "no edges while dragging";
    app.v->pointer(0, 0, 0); // released: the view rests
    app.run();
    EXPECT_GT(edge_pixels(), 100u) << "the edges back at rest";
    // A click (no motion past the tap's slop) is no drag: a pick, and the edges stay.
    app.v->pointer(0, 0, 1);
    app.v->pointer(0, 0, 0);
    app.run();
    EXPECT_GT(edge_pixels(), 100u);
}

// The interface reduced to the status line (Interface::StatusLine, facet_config.interface 2):
// the status bar as the whole interface draws it, no toolbar (its place shows the model and
// the background, and a tap there acts on the model), no panels; the model framed in the
// screen less the status bar. The product's own buttons drive the viewer with act().
TEST(Viewer, TheInterfaceReducedToTheStatusLine) {
    auto shown = [](Interface interface, App& app) {
        app.w = 480, app.h = 272, app.lines = 272, app.interface = interface;
        EXPECT_TRUE(app.create().ok());
        EXPECT_TRUE(app.load(polygon_and_triangle(40)).ok());
        app.run();
        return app.screen();
    };
    App full, line;
    const std::vector<Rgb565> with_all = shown(Interface::Full, full), status_only = shown(Interface::StatusLine, line);
    const module::Overlay& all = static_cast<const Core*>(full.v)->overlay();
    const module::Overlay& reduced = static_cast<const Core*>(line.v)->overlay();
    EXPECT_EQ(reduced.taken().top, all.taken().top) << "the status bar's rows";
    EXPECT_EQ(reduced.taken().right, 0) << "no toolbar";
    EXPECT_EQ(reduced.button_at(int16_t(line.w - 20), int16_t(line.button_row(all, Action::NextDisplayMode))), Action::None);
    // The status bar's left part (the model's name and counts) drawn alike; the toolbar's
    // place differs (the model's background, not the buttons).
    const int32_t rows = all.taken().top, left = all.time_field().x0 - 6;
    for (int32_t y = 0; y < rows; ++y) {
        for (int32_t x = 0; x < left; ++x) {
            const size_t at = size_t(y) * line.w + size_t(x);
            ASSERT_EQ(status_only[at], with_all[at]) << x << "," << y;
        }
    }
    uint32_t differ = 0;
    for (int32_t y = rows; y < line.h; ++y) {
        for (int32_t x = line.w - 40; x < line.w; ++x) differ += status_only[size_t(y) * line.w + size_t(x)] != with_all[size_t(y) * line.w + size_t(x)];
    }
    EXPECT_GT(differ, uint32_t(40 * (line.h - rows) / 2)) << "no toolbar drawn";
    // A tap where MODE would be acts on the model (a pick), not on the display mode; keys
    // that open panels draw none.
    const int picks = line.count(Event::Kind::Picked);
    line.tap(line.w - 20, line.button_row(all, Action::NextDisplayMode));
    EXPECT_EQ(line.v->display_mode(), DisplayMode::ShadedEdges);
    EXPECT_EQ(line.count(Event::Kind::Picked), picks + 1);
    const std::vector<Rgb565> before = line.screen();
    line.v->act(Action::Help);
    line.v->act(Action::Parts);
    line.run();
    EXPECT_EQ(line.screen(), before) << "no help panel, no parts list";
}
