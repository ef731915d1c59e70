// Culling by parts (issue 25: a frame's cost follows the screen): a part off the view is skipped
// whole, one inside it spares its faces their own tests, and one a few pixels across is drawn as
// its box, all by the part's sphere (its box in the index); a part off the view or too small has
// none of its faces tessellated, judged once.
#include "app.h"
#include "assembly.h"

#include <cmath>
#include <random>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

namespace {

// The assembly blocked, a part a block, each part its own box (its vertices' and control
// points', as make_blocked takes them); empty when it cannot be made.
Bytes own_boxes() {
    const Bytes whole = assembly();
    Pack p;
    Bytes file;
    std::string error;
    if (!p.open(whole.data(), uint32_t(whole.size())).ok() || !make_blocked(p, {}, {1, BlockStore::Plain}, file, error)) return {};
    return file;
}

} // namespace

// A frame skips a part whose sphere (its box in the index) lies off the view and tests no face
// of one wholly inside it (Presenter, Transform::sight: its geometry in camera_test.cpp). That
// changes no pixel when the part's sphere holds everything drawn of it: checked here with each
// part its own box (its vertices' and control points', as make_blocked takes them), every mesh
// vertex and edge sample, at the model's one tolerance and refined.
TEST(Culling, APartsSphereHoldsEverythingDrawnOfIt) {
    const Bytes file = own_boxes();
    ASSERT_FALSE(file.empty());
    for (const float screen_error : {0.0f, 0.5f}) {
        App app;
        app.w = 320, app.h = 240, app.screen_error_px = screen_error;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(file).ok());
        app.run();
        for (int zoom = 0; zoom < 4; ++zoom) app.v->act(Action::ZoomIn); // (some blocks refined)
        app.run();
        const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
        uint32_t checked = 0;
        for (uint32_t s = 0; s < scene.part_count(); ++s) {
            int32_t c[3], r = 0;
            ASSERT_TRUE(scene.part_sphere(s, c, r)) << "part " << s;
            const auto inside = [&](const int32_t* q) {
                double d2 = 0;
                for (int k = 0; k < 3; ++k) d2 += double(q[k] - c[k]) * double(q[k] - c[k]);
                ++checked;
                return std::sqrt(d2) <= double(r);
            };
            const module::Part part = scene.part(s);
            for (uint32_t f = part.first_face; f < part.first_face + part.face_count; ++f) {
                const module::FaceInfo& F = scene.face(f);
                for (uint32_t v = 0; v < F.vertex_count; ++v) EXPECT_TRUE(inside(scene.vertices()[F.first_vertex + v].p)) << "part " << s << " face " << f;
            }
            uint32_t first = 0, count = 0;
            ASSERT_TRUE(scene.part_edges(s, first, count));
            for (uint32_t e = first; e < first + count; ++e)
                for (uint32_t k = 0; k < scene.samples().count[e]; ++k) EXPECT_TRUE(inside(scene.sample_q(scene.samples().first[e] + k))) << "part " << s << " edge " << e;
        }
        EXPECT_GT(checked, 100u);
    }
}

// A part under a few pixels across is drawn as its box (twelve lines) until it grows: none of
// its faces or edges is projected (issue 25: a frame's cost follows the screen).
TEST(Culling, APartAFewPixelsAcrossIsDrawnAsItsBox) {
    App app;
    app.w = 320, app.h = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(blocked(assembly())).ok());
    app.run();
    auto last_full = [&] { return app.last_full_frame() ? app.last_full_frame()->frame : Event{}.frame; };
    auto box_pixels = [&] {
        uint32_t n = 0;
        for (Rgb565 p : app.screen()) n += p == rgb565(96, 104, 128);
        return n;
    };
    ASSERT_GT(last_full().triangles, 100u);
    const uint32_t at_fit = box_pixels();
    for (int k = 0; k < 16; ++k) app.v->act(Action::ZoomOut); // the four parts a few pixels each
    app.run();
    EXPECT_EQ(last_full().triangles, 0u) << "no face drawn";
    EXPECT_GT(box_pixels(), at_fit + 8) << "the parts' boxes";
    app.v->act(Action::Fit); // grown again: faces, no boxes
    app.run();
    EXPECT_GT(last_full().triangles, 100u);
    EXPECT_EQ(box_pixels(), at_fit);
}


// The faces a pass or a sweep tessellates (FaceJudge): a part whose sphere, wide enough to hold
// its faces' spheres, is off the screen or under the faces' least size in every instance is
// judged once for all its faces. The same verdicts as each face judged alone, for views from
// afar, close up (the eye among and inside the parts, parts behind it), turned and panned, in
// perspective and parallel.
TEST(Culling, APartJudgedWholeGivesItsFacesTheVerdictsEachWouldHaveAlone) {
    const Bytes file = own_boxes();
    ASSERT_FALSE(file.empty());
    App app;
    app.w = 320, app.h = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(file).ok());
    app.run();
    Core& core = *static_cast<Core*>(app.v);
    const module::Scene& scene = core.scene();
    module::FaceJudge by_parts(scene, core.camera(), core.scheduler(), core.config());
    module::FaceJudge alone(scene, core.camera(), core.scheduler(), core.config());
    alone.judge_parts(false);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> yaw(-180, 180), pitch(-80, 80), pan(-300, 300);
    const float dollies[] = {0.05f, 0.2f, 0.5f, 1, 3, 20};
    uint32_t wanted = 0, left = 0;
    for (int view = 0; view < 60; ++view) {
        Orbit o;
        o.yaw_deg = yaw(rng), o.pitch_deg = pitch(rng), o.dolly = dollies[view % 6], o.parallel = view % 7 == 3;
        if (view % 3) o.pan_mm[0] = pan(rng), o.pan_mm[1] = pan(rng);
        ASSERT_TRUE(core.set_orbit(o).ok());
        for (uint32_t f = 0; f < scene.face_count(); ++f) {
            if (!(scene.face(f).radius > 0)) continue;
            const bool a = module::FaceJudge::wants(&alone, f);
            ASSERT_EQ(module::FaceJudge::wants(&by_parts, f), a) << "view " << view << " face " << f;
            (a ? wanted : left) += 1;
        }
    }
    EXPECT_GT(wanted, 200u);
    EXPECT_GT(left, 200u);
}
