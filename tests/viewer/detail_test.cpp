// The level of detail the view asks for (issue 25): a face under module::kFacePixels across on
// the screen, or off it, is left untessellated (deferred: a speck, or its edges); when the view
// changes, the deferred faces are judged again and those it makes large enough come in, in the
// background. Checked against the projection the frames use: at rest, no deferred face shows
// kFacePixels across anywhere on the screen, every face is either in or deferred, and the work
// ends. The test screens are sized from kFacePixels: their grids of 1 mm squares 2 mm apart put
// each square about that size (a square's sphere is 1.4 times its side).
#include "../geom/shapes.h"
#include "app.h"

using namespace facet;
using namespace facet::test;

namespace {

struct Extent {
    bool on_screen = false;
    int32_t width16 = 0, height16 = 0; // sub-pixels
};

// A face's boundary as the frames project it (its edges' samples, with the integer transform),
// if the frames' culling of its sphere (bounded by those samples) does not leave it out.
Extent boundary_extent(const Core& core, uint32_t face, uint16_t w, uint16_t h) {
    const module::Scene& scene = core.scene();
    const module::Transform t = core.camera().transform(scene, 0, w, h);
    const module::FaceInfo& info = scene.face(face);
    if (info.radius > 0 && !t.visible(info.centre, info.radius, {t.cy16, t.cy16})) return {};
    const module::Block& block = scene.block_of_face(face);
    const pack::Face& F = block.pack.faces()[face - block.first_face];
    int32_t l = INT32_MAX, r = INT32_MIN, top = INT32_MAX, bottom = INT32_MIN;
    uint32_t in = 0, out = 0; // points projected; out: behind the eye or far past the screen's sides
    for (uint32_t li = F.first_loop; li < F.first_loop + F.loop_count; ++li) {
        const pack::Loop& L = block.pack.loops()[li];
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const uint32_t e = block.first_edge + block.pack.coedges()[c].edge();
            for (uint32_t k = 0; k < scene.samples().count[e]; ++k) {
                module::Projected p{};
                t.project(scene.sample_q(scene.samples().first[e] + k), p);
                if (p.out) {
                    ++out;
                    continue;
                }
                ++in;
                l = std::min(l, p.s.x), r = std::max(r, p.s.x), top = std::min(top, p.s.y), bottom = std::max(bottom, p.s.y);
            }
        }
    }
    if (in == 0) return {}; // all of it off the screen
    if (out > 0) return {true, INT32_MAX, INT32_MAX}; // not culled, and from near the screen to far off it: large
    Extent x;
    x.on_screen = r >= 0 && l < w * 16 && bottom >= 0 && top < h * 16;
    x.width16 = r - l, x.height16 = bottom - top;
    return x;
}

// Whether the frames leave the face out whole in every instance of its part: a closed part's
// plane turned away from the eye (Transform::hides_plane, at a point of its boundary).
bool hidden_plane(const Core& core, uint32_t face, uint16_t w, uint16_t h) {
    const module::Scene& scene = core.scene();
    float point[3], normal[3];
    const uint32_t part = scene.shell_of(face);
    if (!scene.part(part).closed || !scene.face_plane(face, point, normal)) return false;
    int16_t n[3];
    for (int k = 0; k < 3; ++k) n[k] = int16_t(std::lround(normal[k] * 16384));
    const module::Block& block = scene.block_of_face(face);
    const pack::Face& F = block.pack.faces()[face - block.first_face];
    const uint32_t e = block.first_edge + block.pack.coedges()[block.pack.loops()[F.first_loop].first_coedge].edge();
    const int32_t* p = scene.sample_q(scene.samples().first[e]);
    for (uint32_t i = 0; i < scene.instances().size(); ++i) {
        if (scene.instances()[i].shell != part) continue;
        if (!core.camera().transform(scene, i, w, h).hides_plane(p, n)) return false;
    }
    return true;
}

// At rest: every face in or deferred, and no deferred face kFacePixels across on the screen
// unless the frames leave it out whole (a solid's plane turned away).
void expect_deferred_only_small(const App& app, const char* when) {
    const Core& core = *static_cast<const Core*>(app.v);
    const Stats s = app.v->stats();
    EXPECT_EQ(s.done + s.deferred + s.failed, s.faces) << when;
    uint32_t deferred = 0;
    for (uint32_t f = 0; f < core.scene().face_count(); ++f) {
        const module::FaceState state = core.scene().face(f).state;
        EXPECT_NE(state, module::FaceState::Pending) << when << ": face " << f;
        if (state != module::FaceState::Deferred) continue;
        ++deferred;
        const Extent x = boundary_extent(core, f, app.w, app.h);
        if (!x.on_screen || hidden_plane(core, f, app.w, app.h)) continue;
        // kFacePixels, and the rounding of its two ends to sub-pixels by the projection.
        EXPECT_LE(x.width16, 16 * module::kFacePixels + 2) << when << ": face " << f << " deferred";
        EXPECT_LE(x.height16, 16 * module::kFacePixels + 2) << when << ": face " << f << " deferred";
    }
    EXPECT_EQ(deferred, s.deferred) << when;
}

constexpr Rgb565 kEdge = rgb565(28, 30, 38); // the edges' colour, and the specks'

// For each face in `state` whose sphere's centre projects onto the screen (the first instance's
// view), visit(face, its info, the transform, the screen's pixel there); returns how many.
template <typename Visit>
uint32_t at_face_centres(const App& app, module::FaceState state, Visit visit) {
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    const module::Transform t = static_cast<const Core*>(app.v)->camera().transform(scene, 0, app.w, app.h);
    const std::vector<Rgb565> screen = app.screen();
    uint32_t n = 0;
    for (uint32_t f = 0; f < scene.face_count(); ++f) {
        const module::FaceInfo& info = scene.face(f);
        if (info.state != state) continue;
        module::Projected p{};
        t.project(info.centre, p);
        const int32_t x = p.s.x >> 4, y = p.s.y >> 4;
        if (p.out || x < 0 || x >= app.w || y < 0 || y >= app.h) continue;
        visit(f, info, t, screen[size_t(y) * app.w + x]);
        ++n;
    }
    return n;
}

// Each deferred face on the screen shows as its speck (painter.cpp): the pixel of its sphere's
// centre in the edges' colour, not the knot of edges a pixel long it was drawn as before.
uint32_t expect_specks(const App& app) {
    return at_face_centres(app, module::FaceState::Deferred, [](uint32_t f, const module::FaceInfo&, const module::Transform&, Rgb565 at) {
        EXPECT_EQ(at, kEdge) << "face " << f;
    });
}

// A section turned on (the viewer's cycle from off: across x) and the work done, then off
// again and the same view drawn anew: the stats with the section on.
Stats with_a_section_and_without(App& app) {
    const Core& core = *static_cast<const Core*>(app.v);
    app.v->act(Action::Section);
    app.run();
    EXPECT_TRUE(core.camera().section().on);
    const Stats on = app.v->stats();
    for (int k = 0; k < 8 && core.camera().section().on; ++k) app.v->act(Action::Section);
    EXPECT_FALSE(core.camera().section().on);
    app.run();
    return on;
}

} // namespace

// A screen of w x h at two pixels a face's threshold, scaled to kFacePixels (each way).
constexpr uint16_t scaled(int pixels) { return uint16_t(pixels * module::kFacePixels / 2); }

TEST(Detail, FacesUnderAFewPixelsAreLeftToTheirEdgesUntilTheViewMakesThemLarger) {
    // 1,600 squares of 1 mm, 2 mm apart, on a 160 x 120 screen at a threshold of two pixels
    // (scaled): about the threshold each, those further from the eye under.
    App app;
    app.w = scaled(160), app.h = app.lines = scaled(120);
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(squares(1600, 40)).ok());
    app.run();
    ASSERT_EQ(app.v->step(1000), Activity::Idle) << "the work ends";
    EXPECT_EQ(app.count(Event::Kind::Tessellated), 1);
    const Stats fitted = app.v->stats();
    EXPECT_EQ(fitted.faces, 1600u);
    EXPECT_GT(fitted.deferred, 0u);
    EXPECT_EQ(fitted.triangles, 2 * fitted.done);
    expect_deferred_only_small(app, "fitted");
    EXPECT_GT(expect_specks(app), 100u);

    // Zoomed in (each step 0.8 of the distance): the squares grow over the threshold and come in
    // (each while it is still on the screen).
    uint32_t done = fitted.done;
    for (int zoom = 1; zoom <= 12; ++zoom) {
        app.v->act(Action::ZoomIn);
        app.run();
        ASSERT_EQ(app.v->step(1000), Activity::Idle) << "the work ends";
        const std::string when = "zoom " + std::to_string(zoom);
        expect_deferred_only_small(app, when.c_str());
        EXPECT_GE(app.v->stats().done, done) << when;
        done = app.v->stats().done;
    }
    EXPECT_GT(done, fitted.done);
    EXPECT_EQ(app.v->stats().triangles, 2 * done);
    EXPECT_EQ(app.count(Event::Kind::Tessellated), 1) << "a pass says it is done once";

    // Turned and zoomed out again: nothing already in is lost (the turn may bring in a few
    // that come nearer the eye), and the rest stay deferred.
    app.v->act(Action::TurnLeft);
    for (int zoom = 0; zoom < 12; ++zoom) app.v->act(Action::ZoomOut);
    app.run();
    EXPECT_GE(app.v->stats().done, done);
    expect_deferred_only_small(app, "zoomed out");
}

TEST(Detail, ANewLevelOfDetailJudgesEveryFaceAgain) {
    App app;
    app.w = scaled(320), app.h = app.lines = scaled(240);
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(squares(400, 20)).ok());
    app.run();
    EXPECT_EQ(app.v->stats().deferred, 0u) << "a square is about twice the threshold across";
    EXPECT_EQ(app.v->stats().done, 400u);
    for (int zoom = 0; zoom < 8; ++zoom) app.v->act(Action::ZoomOut);
    app.run();
    // Zoomed out, the model is judged again at a coarser level (Core::refine_for_view): the
    // squares now under the threshold are left to their edges.
    const Stats out = app.v->stats();
    EXPECT_GT(out.deferred, 0u) << "zoomed out, the squares under the threshold are evicted";
    EXPECT_EQ(out.done + out.deferred, 400u);
    expect_deferred_only_small(app, "zoomed out");
    app.v->act(Action::Coarser); // a new pass, at this view
    app.run();
    const Stats s = app.v->stats();
    EXPECT_GT(s.deferred, 0u) << "zoomed out, the new pass leaves the small squares to their edges";
    EXPECT_EQ(s.done + s.deferred, 400u);
    expect_deferred_only_small(app, "new pass");

    // Zoomed in on a corner: the squares there come in, those off the screen stay deferred.
    for (int zoom = 0; zoom < 16; ++zoom) app.v->act(Action::ZoomIn);
    for (int pan = 0; pan < 4; ++pan) app.v->act(Action::PanLeft);
    app.run();
    expect_deferred_only_small(app, "a corner");
    EXPECT_GT(app.v->stats().done, s.done);
    EXPECT_GT(app.v->stats().deferred, 0u) << "the squares off the screen are not tessellated";
}

TEST(Detail, ASolidsPlanesTurnedAwayWaitUntilTheViewTurnsThemRound) {
    // Two 100 mm cubes (one solid placed twice): from the fitted view, some of a cube's six
    // planes turn their backs to the eye in both places. The frames leave those out whole, so
    // they are not tessellated until the view turns them round, or a section opens the solid.
    App app;
    app.w = 320, app.h = 240, app.lines = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const Stats fitted = app.v->stats();
    EXPECT_GT(fitted.deferred, 0u) << "planes turned away wait";
    EXPECT_GE(fitted.done, 3u) << "a cube shows at least three of its faces at a time in a general view";
    EXPECT_EQ(fitted.done + fitted.deferred, 6u);
    for (uint32_t f = 0; f < 6; ++f) {
        if (core.scene().face(f).state != module::FaceState::Deferred) continue;
        EXPECT_TRUE(hidden_plane(core, f, app.w, app.h)) << "face " << f;
    }
    expect_deferred_only_small(app, "fitted");
    const std::vector<Rgb565> before = app.screen();

    // A section may show the solid's inside: every plane comes in. Off again, the same view
    // draws the same pixels with every face in as it drew with the back planes waiting.
    const Stats cut = with_a_section_and_without(app);
    EXPECT_EQ(cut.deferred, 0u) << "with a section on, no plane is judged hidden";
    EXPECT_EQ(cut.done, 6u);
    EXPECT_EQ(app.screen(), before) << "the planes that waited drew nothing";

    // Anew, turned round: the planes the first view left waiting come in as they face the eye.
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    std::vector<uint32_t> waiting;
    for (uint32_t f = 0; f < 6; ++f)
        if (core.scene().face(f).state == module::FaceState::Deferred) waiting.push_back(f);
    ASSERT_FALSE(waiting.empty());
    for (int k = 0; k < 24; ++k) {
        app.v->act(Action::TurnLeft);
        app.v->act(Action::TiltUp);
        app.run();
        expect_deferred_only_small(app, ("turn " + std::to_string(k)).c_str());
    }
    uint32_t came = 0;
    for (uint32_t f : waiting) came += core.scene().face(f).state == module::FaceState::Done;
    EXPECT_GT(came, 0u) << "turning brings the back planes round";
}

TEST(Detail, ASolidsRoundFaceTurnedAwayWaitsAndDrawsWhatEveryFaceIn) {
    // A half-round bar from each standard view: where its round face turns wholly away from the
    // eye it is left to its edges, and the picture is the one every face in gives (a section
    // brings every face in; off again, the same view is drawn anew).
    uint32_t waited = 0, shown = 0;
    for (const Action view : {Action::ViewFront, Action::ViewBack, Action::ViewRight, Action::ViewLeft, Action::ViewTop,
                              Action::ViewBottom, Action::ViewIso}) {
        App app;
        app.w = 320, app.h = 240, app.lines = 240;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(half_round_bar()).ok());
        app.v->act(view);
        app.run();
        const Core& core = *static_cast<const Core*>(app.v);
        ASSERT_EQ(app.v->stats().failed, 0u);
        const bool round_waits = core.scene().face(0).state == module::FaceState::Deferred;
        (round_waits ? waited : shown) += 1;
        const std::vector<Rgb565> before = app.screen();
        EXPECT_EQ(with_a_section_and_without(app).done, 4u) << "a section on: every face in";
        EXPECT_EQ(app.screen(), before) << "view " << int(view) << (round_waits ? ": the round face waited" : "");
    }
    EXPECT_GT(waited, 0u) << "some view turns the round face away";
    EXPECT_GT(shown, 0u);
}

// While the view is dragged, a face under module::kSplatPixels across is drawn as a splat of its colour
// (painter.cpp), not as its triangles (coarser detail while the view moves, issue 25): fewer
// triangles, and each such square still shows where its centre is.
// With a faces layer as without: a frame while the view is dragged is drawn into the buffer,
// lighter; the layer keeps full detail, drawn anew when the view rests.
class DragWithLayer : public ::testing::TestWithParam<bool> {};
INSTANTIATE_TEST_SUITE_P(Detail, DragWithLayer, ::testing::Values(false, true));

TEST_P(DragWithLayer, ADragDrawsFacesAFewPixelsAcrossAsSplats) {
    // The squares between kFacePixels and the splats' size across: those nearer the eye in,
    // the rest specks.
    App app;
    app.faces_layer = GetParam();
    app.w = uint16_t(160 * (module::kFacePixels + module::kSplatPixels) / 5);
    app.h = app.lines = uint16_t(120 * (module::kFacePixels + module::kSplatPixels) / 5);
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(squares(1600, 40)).ok());
    app.run();
    ASSERT_EQ(app.v->step(1000), Activity::Idle);
    auto full_frame = [&] { return app.last_full_frame() ? app.last_full_frame()->frame.triangles : 0u; };
    app.v->pointer(0, 0, 1); // the left button down, then moved past a tap's slop: an orbit
    for (int k = 0; k < 2; ++k) {
        app.v->pointer(6, 0, 1);
        app.run();
    }
    const uint32_t dragged = full_frame();
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    uint32_t splats = 0;
    at_face_centres(app, module::FaceState::Done, [&](uint32_t f, const module::FaceInfo& info, const module::Transform& t, Rgb565 at) {
        // Every square the same colour and normal: its splat's colour, or its triangles'.
        render::Palette palette;
        render::make_palette(palette, uint8_t(info.rgb & 255), uint8_t((info.rgb >> 8) & 255), uint8_t((info.rgb >> 16) & 255));
        const Rgb565 lit = Rgb565(palette.colour[t.shade(scene.vertices()[info.first_vertex].n)]);
        // (A square the drag brought over the threshold came in after the frame drew its speck:
        // over it, its splat (not pulled toward the eye as the speck is) leaves the speck.)
        EXPECT_TRUE(at == lit || at == kEdge) << "face " << f;
        splats += at == lit;
    });
    EXPECT_GT(splats, 100u);
    app.v->pointer(0, 0, 0); // released: at rest, the triangles again
    app.run();
    EXPECT_GT(full_frame(), 2 * dragged) << "most squares splats while dragging";
}

// A glide to a standard view draws its frames as a drag does (a face a few pixels across a
// splat, no B-rep edges): the frames between are the view moving; the one it ends on is whole.
TEST_P(DragWithLayer, AGlideDrawsItsFramesAsADragDoes) {
    App app;
    app.faces_layer = GetParam();
    app.w = uint16_t(160 * (module::kFacePixels + module::kSplatPixels) / 5);
    app.h = app.lines = uint16_t(120 * (module::kFacePixels + module::kSplatPixels) / 5);
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(squares(1600, 40)).ok());
    app.run();
    ASSERT_EQ(app.v->step(1000), Activity::Idle);
    const size_t from = app.events.size();
    app.v->key('0'); // the isometric view, in a glide
    app.run();
    std::vector<uint32_t> triangles; // of each whole frame the glide drew
    for (size_t i = from; i < app.events.size(); ++i) {
        const Event& e = app.events[i];
        if (e.kind == Event::Kind::FrameDone && e.frame.full) triangles.push_back(e.frame.triangles);
    }
    // The glide's frames, then the one it ends on (and, at rest, what the view brings in, or
    // over a faces layer a copy of it with the edges alone).
    ASSERT_FALSE(triangles.empty());
    const uint32_t whole = *std::max_element(triangles.begin(), triangles.end());
    size_t k = 0;
    while (k < triangles.size() && 2 * triangles[k] < whole) ++k;
    EXPECT_GE(k, 5u) << "a glide's frames, splats where the faces are a few pixels across";
}

// A part placed twice, one copy far below the other (the view looks down): its faces are
// tessellated for the nearer copy, and the farther one, where they are under kFacePixels, draws
// them as specks as the view draws a face it left out (issue 25: a frame follows the screen).
TEST(Detail, AFaceUnderAFewPixelsInAFartherInstanceIsDrawnAsASpeck) {
    App app;
    app.w = scaled(160), app.h = app.lines = scaled(120);
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(squares(100, 10, {{0, 0, 0}, {30, 0, -120}})).ok()); // the second beside the first and below
    app.run();
    ASSERT_EQ(app.v->step(1000), Activity::Idle);
    const Stats s = app.v->stats();
    const Event* frame = app.last_full_frame();
    ASSERT_NE(frame, nullptr);
    // Both copies on the screen (framed): the nearer draws the faces it has over the threshold,
    // the farther only specks (every square there under it: none would be in for it).
    ASSERT_GT(s.done, 0u);
    EXPECT_GT(frame->frame.triangles, 0u);
    EXPECT_LE(frame->frame.triangles + frame->frame.culled, s.triangles) << "the farther copy's faces drawn as specks";
}

TEST(Detail, APlanesNormalInWholeUnitsIsItsSurfacesRounded) {
    // Triangles on planes turned every way, in right- and left-handed frames, some faces
    // reversed: Scene::plane_normal (from the floats' bits, no soft float: the painter asks for
    // a waiting plane's every frame) gives face_plane's unit normal rounded to Q14.
    PackWriter w;
    const uint32_t first = w.face_count();
    constexpr int kPlanes = 96;
    for (int i = 0; i < kPlanes; ++i) {
        const double a = 0.37 * i, b = 0.23 * i + 0.1, c = 0.61 * i;
        const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b), cc = std::cos(c), sc = std::sin(c);
        // Rotation z(a) y(b) x(c): its columns the frame's x, y and z.
        const double R[3][3] = {{ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc},
                                {sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc},
                                {-sb, cb * sc, cb * cc}};
        const float o[3] = {float(200 * (i % 8)), float(200 * (i / 8)), 0};
        const float handed = i % 3 == 0 ? -1.0f : 1.0f; // a left-handed frame: y turned round
        float x[3], y[3], z[3];
        for (int k = 0; k < 3; ++k) x[k] = float(R[k][0]), y[k] = handed * float(R[k][1]), z[k] = float(R[k][2]);
        const uint32_t plane = w.add_surface(pack::PlaneParams{{.origin = {o[0], o[1], o[2]}, .x = {x[0], x[1], x[2]}, .y = {y[0], y[1], y[2]}, .z = {z[0], z[1], z[2]}}});
        const uint32_t v0 = w.add_vertex(o[0], o[1], o[2]);
        const uint32_t v1 = w.add_vertex(o[0] + 50 * x[0], o[1] + 50 * x[1], o[2] + 50 * x[2]);
        const uint32_t v2 = w.add_vertex(o[0] + 50 * y[0], o[1] + 50 * y[1], o[2] + 50 * y[2]);
        const uint32_t e0 = w.add_edge({pack::kStraight, 0, 50, v0, v1, 1e-7f, 0}), e1 = w.add_edge({pack::kStraight, 0, 70.71f, v1, v2, 1e-7f, 0}),
                       e2 = w.add_edge({pack::kStraight, 0, 50, v2, v0, 1e-7f, 0});
        const uint32_t coedge = w.coedge_count();
        for (uint32_t e : {e0, e1, e2}) w.add_coedge(pack::Coedge::make(e, false, pack::Seam::None));
        const uint32_t loop = w.add_loop({coedge, 3});
        const uint8_t reversed = i % 2;
        w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, reversed, {0, 0, 0}, {0, 0}, {50, 50}});
    }
    const uint32_t shell = w.add_shell({first, kPlanes, pack::kNoIndex, 0});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(w.finish()).ok());
    app.run();
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    uint32_t meshed = 0;
    for (uint32_t f = 0; f < kPlanes; ++f) {
        float point[3], normal[3];
        int16_t n[3];
        ASSERT_TRUE(scene.face_plane(f, point, normal));
        ASSERT_TRUE(scene.plane_normal(f, n));
        for (int k = 0; k < 3; ++k) EXPECT_EQ(n[k], std::lround(normal[k] * 16384)) << "face " << f << " component " << k;
        // A plane's mesh has one normal, that one (FaceInfo::planar: a closed solid's plane
        // turned away is skipped whole by its first vertex's).
        const module::FaceInfo& F = scene.face(f);
        if (F.state != module::FaceState::Done) continue; // (left out by the view: turned away)
        ++meshed;
        ASSERT_TRUE(F.planar);
        for (uint32_t v = 0; v < F.vertex_count; ++v) {
            const module::DrawVertex& vertex = scene.vertices()[F.first_vertex + v];
            for (int k = 0; k < 3; ++k) EXPECT_EQ(vertex.n[k], n[k]) << "face " << f << " vertex " << v;
        }
    }
    EXPECT_GT(meshed, kPlanes / 4u);
}
