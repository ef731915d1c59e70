// The module through its public API (facet/viewer.h), as an application uses it (app.h).
// Views: an assembly framed where its instances place its parts, standard views and their
// glides, the camera the viewer describes is the one it draws.
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

// Parts placed far from their own origins (an assembly's instances): the view frames the
// placed model, centred and filling the screen, not the parts where their files put them.
TEST(Viewer, AnAssemblyIsFramedWhereItsInstancesPlaceItsParts) {
    PackWriter w;
    const uint32_t plane = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
    const uint32_t v[4] = {w.add_vertex(0, 0, 0), w.add_vertex(40, 0, 0), w.add_vertex(40, 10, 0), w.add_vertex(0, 10, 0)};
    const uint32_t first = w.coedge_count();
    for (int i = 0; i < 4; ++i) {
        const uint32_t e = w.add_edge({pack::kStraight, 0, i % 2 ? 10.0f : 40.0f, v[i], v[(i + 1) % 4], 1e-7f, 0});
        w.add_coedge(pack::Coedge::make(e, false, pack::Seam::None));
    }
    const uint32_t loop = w.add_loop({first, 4});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {0, 0}, {40, 10}});
    const uint32_t shell = w.add_shell({0, 1, pack::kNoIndex, 0});
    // Three copies 5 m away from the part's origin, one turned a quarter about z.
    w.add_instance({shell, {1, 0, 0, 5000, 0, 1, 0, 3000, 0, 0, 1, 0}});
    w.add_instance({shell, {1, 0, 0, 5000, 0, 1, 0, 3020, 0, 0, 1, 0}});
    w.add_instance({shell, {0, -1, 0, 5060, 1, 0, 0, 3000, 0, 0, 1, 0}});
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(w.finish()).ok());
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    int32_t l = INT32_MAX, t = INT32_MAX, r = INT32_MIN, b = INT32_MIN;
    for (uint32_t i = 0; i < 3; ++i) {
        const module::Transform tr = core.camera().transform(core.scene(), i, app.w, app.h);
        const module::FaceInfo& F = core.scene().face(0);
        ASSERT_EQ(F.state, module::FaceState::Done);
        for (uint32_t k = 0; k < F.vertex_count; ++k) {
            module::Projected p;
            tr.project(core.scene().vertices()[F.first_vertex + k].p, p);
            ASSERT_EQ(p.out, 0) << "instance " << i << " vertex " << k;
            l = std::min(l, p.s.x), r = std::max(r, p.s.x), t = std::min(t, p.s.y), b = std::max(b, p.s.y);
        }
    }
    // In pixels: centred within a pixel and a half, the larger side filling Framer::kFill (within 2%).
    EXPECT_NEAR((l + r) / 32.0, app.w / 2.0, 1.5);
    EXPECT_NEAR((t + b) / 32.0, app.h / 2.0, 1.5);
    const double fill = std::max((r - l) / 16.0 / app.w, (b - t) / 16.0 / app.h);
    EXPECT_NEAR(fill, module::Framer::kFill, 0.02);
    // A tap in the middle lands on the model.
    app.v->touch(0, int16_t(app.w / 2), int16_t(app.h / 2), true);
    app.v->touch(0, int16_t(app.w / 2), int16_t(app.h / 2), false);
    ASSERT_NE(app.last(Event::Kind::Picked), nullptr);
}

// A standard view glides there (several frames, the angles in between) and ends framed; the
// projection key turns a parallel view on; a double tap frames the tapped face.
TEST(Viewer, StandardViewsGlideAndADoubleTapFramesAFace) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    auto outline = [&](uint32_t face) {
        const module::Transform t = core.camera().transform(core.scene(), 0, app.w, app.h);
        const module::FaceInfo& F = core.scene().face(face);
        int32_t l = INT32_MAX, r = INT32_MIN, top = INT32_MAX, b = INT32_MIN;
        for (uint32_t k = 0; k < F.vertex_count; ++k) {
            module::Projected p;
            t.project(core.scene().vertices()[F.first_vertex + k].p, p);
            l = std::min(l, p.s.x), r = std::max(r, p.s.x), top = std::min(top, p.s.y), b = std::max(b, p.s.y);
        }
        return std::array<double, 4>{l / 16.0, top / 16.0, r / 16.0, b / 16.0};
    };
    const int frames0 = app.count(Event::Kind::FrameDone), views0 = app.count(Event::Kind::ViewChanged);
    app.v->key('7'); // top: the polygon and the triangle lie in z = 0, seen face on
    app.run();
    EXPECT_GE(app.count(Event::Kind::ViewChanged) - views0, 9) << "a glide: the camera moved in steps";
    EXPECT_GE(app.count(Event::Kind::FrameDone) - frames0, 9) << "a frame at each step";
    const auto end = app.last(Event::Kind::ViewChanged)->view;
    EXPECT_NEAR(end.yaw_deg, 0, 0.01);
    EXPECT_NEAR(end.pitch_deg, 0, 0.01);
    // Framed from the top: the polygon (radius 100) and the triangle (to x = 140) fill Framer::kFill of
    // the screen's height (240 x 200 mm on a 160 x 120 screen: the height is the tighter).
    const auto a = outline(0), t = outline(1);
    EXPECT_NEAR((std::max(a[3], t[3]) - std::min(a[1], t[1])) / app.h, module::Framer::kFill, 0.02);
    // From the top the polygon is a circle on the screen (width = height).
    EXPECT_NEAR(a[2] - a[0], a[3] - a[1], 1.0);
    // Parallel projection on: the view is framed again, the circle stays round.
    app.v->key('5');
    app.run();
    const auto o = outline(0);
    EXPECT_NEAR(o[2] - o[0], o[3] - o[1], 1.0);
    // A double tap on the triangle frames it (60% of the screen's width or height).
    const int16_t tx = int16_t((t[0] + t[2]) / 2 - 2), ty = int16_t((t[1] + t[3]) / 2 + 2);
    for (int i = 0; i < 2; ++i) {
        app.v->touch(0, tx, ty, true);
        app.v->touch(0, tx, ty, false);
    }
    ASSERT_TRUE(app.last(Event::Kind::Picked)->pick.hit);
    EXPECT_EQ(app.last(Event::Kind::Picked)->pick.face, 1u);
    app.run();
    const auto f = outline(1);
    const double fill = std::max((f[2] - f[0]) / app.w, (f[3] - f[1]) / app.h);
    EXPECT_NEAR(fill, 0.6, 0.02);
    EXPECT_NEAR((f[0] + f[2]) / 2, app.w / 2.0, 1.5);
    EXPECT_NEAR((f[1] + f[3]) / 2, app.h / 2.0, 1.5);
}

// A standard view asked for while the model is still coming in (before its edges are sampled,
// or between its faces) is where the view ends, framed: the framing at load and when the
// faces are in keeps the direction the user chose.
TEST(Viewer, AStandardViewAskedForDuringLoadingSticks) {
    for (int steps : {0, 1, 3}) {
        App app;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
        for (int i = 0; i < steps; ++i) (void)app.v->step(0);
        app.v->key('7'); // top
        app.run();
        const Core& core = *static_cast<const Core*>(app.v);
        const module::View& v = core.camera().view();
        EXPECT_NEAR(v.yaw * 57.29578f, 0, 0.01) << "after " << steps << " steps";
        EXPECT_NEAR(v.pitch * 57.29578f, 0, 0.01) << "after " << steps << " steps";
        // Framed: the model fills Framer::kFill of the screen's height, as a top view does.
        const module::Transform t = core.camera().transform(core.scene(), 0, app.w, app.h);
        int32_t top = INT32_MAX, b = INT32_MIN;
        for (uint32_t face : {0u, 1u}) {
            const module::FaceInfo& F = core.scene().face(face);
            for (uint32_t k = 0; k < F.vertex_count; ++k) {
                module::Projected p;
                t.project(core.scene().vertices()[F.first_vertex + k].p, p);
                top = std::min(top, p.s.y), b = std::max(b, p.s.y);
            }
        }
        EXPECT_NEAR((b - top) / 16.0 / app.h, module::Framer::kFill, 0.02) << "after " << steps << " steps";
    }
}

// Viewer::camera() describes the camera the frames are drawn with: the model's corners,
// projected by it, bound the pixels the model covers, in perspective and parallel, turned,
// zoomed and panned.
TEST(Viewer, TheCameraItDescribesIsTheOneItDraws) {
    App app;
    app.buffers = 1; // one draw buffer and its depth: the last frame's coverage stays there
    app.w = 200, app.h = 150, app.lines = 150;
    EXPECT_EQ(Viewer::CameraView{}.distance_mm, 0.0f);
    ASSERT_TRUE(app.create().ok());
    EXPECT_EQ(app.v->camera().distance_mm, 0.0f) << "no model, no camera";
    constexpr uint32_t kSides = 40;
    ASSERT_TRUE(app.load(polygon_and_triangle(kSides)).ok());
    ASSERT_TRUE(app.v->set_display_mode(DisplayMode::Shaded).ok()); // faces only: their pixels are the model's
    app.run();
    std::vector<std::array<float, 3>> corners;
    for (uint32_t i = 0; i < kSides; ++i) {
        const double a = 2 * M_PI * i / kSides;
        corners.push_back({float(100 * std::cos(a)), float(100 * std::sin(a)), 0});
    }
    corners.push_back({120, 0, 0}), corners.push_back({140, 0, 0}), corners.push_back({120, 20, 0});
    auto check = [&](const char* what) {
        SCOPED_TRACE(what);
        const Viewer::CameraView c = app.v->camera();
        ASSERT_GT(c.distance_mm, 0.0f);
        ASSERT_GT(c.focal_px, 0.0f);
        float lo[2] = {1e9f, 1e9f}, hi[2] = {-1e9f, -1e9f};
        auto project = [&](const std::array<float, 3>& p, float& x, float& y) {
            float q[3];
            for (int i = 0; i < 3; ++i) {
                q[i] = 0;
                for (int j = 0; j < 3; ++j) q[i] += c.rotation[3 * i + j] * (p[j] - c.target_mm[j]);
            }
            const float s = c.parallel ? c.distance_mm : c.distance_mm - q[2];
            x = app.w / 2.0f + c.focal_px * q[0] / s;
            y = app.h / 2.0f - c.focal_px * q[1] / s;
        };
        for (const auto& p : corners) {
            float x, y;
            project(p, x, y);
            lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x), lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
        }
        int box[4] = {app.w, app.h, -1, -1}; // the covered pixels' bounds
        for (int y = 0; y < app.h; ++y)
            for (int x = 0; x < app.w; ++x)
                if (app.depth[0][size_t(y) * app.w + x] != 0xFFFF)
                    box[0] = std::min(box[0], x), box[1] = std::min(box[1], y), box[2] = std::max(box[2], x), box[3] = std::max(box[3], y);
        ASSERT_GE(box[2], box[0]) << "the model covers pixels";
        // Pixel x is sampled at x + 0.5: every covered pixel's centre lies within the projected
        // bounds (to the rasterizer's 1/16-pixel rounding), and the bounds are tight (to the
        // few pixels a sharp corner leaves uncovered); bounds clipped to the screen.
        const float clo[2] = {std::max(lo[0], 0.5f), std::max(lo[1], 0.5f)};
        const float chi[2] = {std::min(hi[0], app.w - 0.5f), std::min(hi[1], app.h - 0.5f)};
        for (int k = 0; k < 2; ++k) {
            EXPECT_GE(box[k] + 0.5f, clo[k] - 0.125f) << "axis " << k;
            EXPECT_LE(box[k + 2] + 0.5f, chi[k] + 0.125f) << "axis " << k;
            EXPECT_NEAR(box[k] + 0.5f, clo[k], 3.0f) << "axis " << k;
            EXPECT_NEAR(box[k + 2] + 0.5f, chi[k], 3.0f) << "axis " << k;
        }
        // The small triangle's middle is on it.
        float x, y;
        project({126.7f, 6.7f, 0}, x, y);
        EXPECT_NE(app.depth[0][size_t(y) * app.w + size_t(x)], 0xFFFF);
    };
    check("fitted");
    app.v->act(Action::TurnLeft), app.v->act(Action::TiltUp), app.v->act(Action::ZoomIn), app.v->act(Action::PanLeft);
    app.run();
    check("turned, zoomed and panned");
    app.v->act(Action::Projection);
    app.run();
    EXPECT_TRUE(app.v->camera().parallel);
    check("parallel");
}

// FIT with a section on frames what is drawn: the side the plane keeps, centred in the free
// area and filling it as the whole model would (the framer leaves out the points the section
// cuts away); before, the whole model was framed and the kept block sat off to one side.
TEST(Viewer, FitWithASectionFramesTheSideItKeeps) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = Interface::Full;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7'); // from the front: the blocks side by side along x
    app.run();
    app.v->key('c'); // no face picked: across x through the middle, the second block cut away
    app.run();
    ASSERT_TRUE(app.v->section().on);
    app.v->fit();
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const auto kept = box_of(core, 0, app.w, app.h); // the first block: pixels left, top, right, bottom
    const module::FreeArea taken = core.overlay().taken();
    const double aw = app.w - taken.left - taken.right, ah = app.h - taken.top - taken.bottom;
    EXPECT_NEAR((kept[0] + kept[2]) / 2.0, taken.left + aw / 2, 1.5);
    EXPECT_NEAR((kept[1] + kept[3]) / 2.0, taken.top + ah / 2, 1.5);
    EXPECT_NEAR(std::max((kept[2] - kept[0]) / aw, (kept[3] - kept[1]) / ah), module::Framer::kFill, 0.02);
}

// The camera at its extremes (issue 49): whatever the API takes, the view arithmetic stays in
// range on every display size (this suite runs under UBSan too, where an overflow aborts). A
// value past the range is refused (OutOfRange) and changes nothing; one within it, however far
// (an angle of 1e30 degrees, a pan to the edge of the range, keys and drags repeated past it),
// draws.
TEST(Viewer, TheCameraAtItsExtremesKeepsItsArithmeticInRange) {
    const std::pair<uint16_t, uint16_t> sizes[] = {{1, 1}, {2, 600}, {600, 2}, {160, 120}, {480, 272}, {640, 480}, {1024, 600}};
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float big = std::numeric_limits<float>::max();
    for (auto [w, h] : sizes) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
        App app;
        app.w = w, app.h = app.lines = h;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
        app.run();
        const float most = module::Camera::kPanRadii * static_cast<const Core*>(app.v)->scene().radius();
        // Refused, nothing changed.
        for (const Orbit& o : {Orbit{nan, 0, 1, {0, 0}, false}, Orbit{0, inf, 1, {0, 0}, false}, Orbit{0, 0, 0.01f, {0, 0}, false},
                               Orbit{0, 0, 1e30f, {0, 0}, false}, Orbit{0, 0, 1, {1e30f, 0}, false}, Orbit{0, 0, 1, {0, -big}, false},
                               Orbit{0, 0, 1, {2 * most, 0}, false}, Orbit{0, 0, 1, {0, -inf}, false}}) {
            const Orbit before = app.v->orbit();
            EXPECT_EQ(app.v->set_orbit(o).status, Status::OutOfRange);
            const Orbit after = app.v->orbit();
            EXPECT_TRUE(before.yaw_deg == after.yaw_deg && before.pitch_deg == after.pitch_deg && before.dolly == after.dolly &&
                        before.pan_mm[0] == after.pan_mm[0] && before.pan_mm[1] == after.pan_mm[1] && before.parallel == after.parallel)
                << "a refused orbit changes nothing";
        }
        // Taken and drawn: every corner of the range.
        for (float angle : {1e30f, -1e30f, big, -big, 8191.9f, 1e-30f})
            for (float dolly : {module::Camera::kNearest, module::Camera::kFarthest})
                for (float pan : {most, -most, 0.0f})
                    for (bool parallel : {false, true}) {
                        ASSERT_TRUE(app.v->set_orbit({angle, -angle, dolly, {pan, -pan}, parallel}).ok());
                        for (int k = 0; k < 3; ++k) app.v->step(100000);
                    }
        app.run();
        // Keys and drags past the range: the pan stops at its edge, the dolly at its ends.
        ASSERT_TRUE(app.v->set_orbit({0, 0, 1, {0, 0}, false}).ok());
        for (int k = 0; k < 2000; ++k) app.v->act(k % 2 ? Action::PanRight : Action::PanUp), app.v->act(Action::ZoomOut);
        app.v->step(100000);
        for (uint8_t buttons : {1, 2, 4}) { // relative motion at its largest, each button held
            app.v->pointer(0, 0, buttons);
            for (int k = 0; k < 200; ++k) app.v->pointer(INT16_MAX, INT16_MIN, buttons);
            app.v->pointer(0, 0, 0);
            app.v->step(100000);
        }
        app.run();
        const Orbit o = app.v->orbit();
        EXPECT_LE(std::fabs(o.pan_mm[0]), most);
        EXPECT_LE(std::fabs(o.pan_mm[1]), most);
        EXPECT_LE(o.dolly, module::Camera::kFarthest);
    }
}
