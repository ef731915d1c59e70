// The camera on its own: the fitted view, the one transform path (projection, culling of
// spheres against the screen and against bands, facing), dolly limits and pixel pans.
#include "camera.h"
#include "pack_writer.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace facet;
using namespace facet::module;

namespace {

// A 100 mm square in z = 0 around (10, 20, 0): the model's box centre and radius are known.
struct Model {
    std::vector<uint8_t> bytes;
    std::vector<uint32_t> words;
    geom::Pack pack;
    std::vector<FaceInfo> faces = std::vector<FaceInfo>(4);
    std::vector<uint32_t> done = std::vector<uint32_t>(4), first = std::vector<uint32_t>(8);
    std::vector<uint16_t> count = std::vector<uint16_t>(8);
    Scene scene;
    Model() {
        geom::PackWriter w;
        const uint32_t plane = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
        const float x0 = -40, x1 = 60, y0 = -30, y1 = 70;
        const uint32_t v[4] = {w.add_vertex(x0, y0, 0), w.add_vertex(x1, y0, 0), w.add_vertex(x1, y1, 0), w.add_vertex(x0, y1, 0)};
        const uint32_t first_coedge = w.coedge_count();
        for (int i = 0; i < 4; ++i) {
            const uint32_t e = w.add_edge({pack::kStraight, 0, 100, v[i], v[(i + 1) % 4], 1e-7f, 0});
            w.add_coedge(pack::Coedge::make(e, false, pack::Seam::None));
        }
        const uint32_t loop = w.add_loop({first_coedge, 4});
        w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {x0, y0}, {x1, y1}});
        const uint32_t shell = w.add_shell({0, 1, pack::kNoIndex, 0});
        w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
        bytes = w.finish();
        words.assign(bytes.size() / 4 + 1, 0);
        std::memcpy(words.data(), bytes.data(), bytes.size());
        EXPECT_TRUE(pack.open(words.data(), uint32_t(bytes.size())).ok());
        EXPECT_TRUE(scene.open(pack).ok());
        EXPECT_TRUE(scene.attach({geom::EdgeSamples{first, count, {}, {}}, {}, {}, {}, faces, done}).ok());
    }
};

// A point in mm of the model as mesh units (diag / 2^20).
void quantize(const Scene& s, float x, float y, float z, int32_t p[3]) {
    const float q[3] = {x / s.unit(), y / s.unit(), z / s.unit()};
    for (int k = 0; k < 3; ++k) p[k] = int32_t(std::lround(q[k]));
}

} // namespace

TEST(Camera, TheFittedViewCentresTheModelAndHoldsItsSphere) {
    Model m;
    EXPECT_NEAR(m.scene.centre()[0], 10, 1e-4);
    EXPECT_NEAR(m.scene.centre()[1], 20, 1e-4);
    EXPECT_NEAR(m.scene.radius(), 50 * std::sqrt(2.0f), 1e-3);
    Camera cam;
    for (const auto& [w, h] : {std::pair<uint16_t, uint16_t>{640, 480}, {480, 272}}) {
        const Transform t = cam.transform(m.scene, 0, w, h);
        int32_t c[3];
        quantize(m.scene, 10, 20, 0, c);
        Projected p;
        t.project(c, p);
        ASSERT_EQ(p.out, 0);
        EXPECT_NEAR(p.s.x / 16.0, w / 2.0, 0.5) << w << "x" << h;
        EXPECT_NEAR(p.s.y / 16.0, h / 2.0, 0.5);
        // The corners of the square are on the bounding sphere: on the screen, within its short side.
        for (const auto& [x, y] : {std::pair<float, float>{-40, -30}, {60, -30}, {60, 70}, {-40, 70}}) {
            int32_t q[3];
            quantize(m.scene, x, y, 0, q);
            t.project(q, p);
            ASSERT_EQ(p.out, 0);
            EXPECT_LT(std::abs(p.s.x / 16.0 - w / 2.0), std::min(w, h) / 2.0);
            EXPECT_LT(std::abs(p.s.y / 16.0 - h / 2.0), std::min(w, h) / 2.0);
        }
    }
}

TEST(Camera, SpheresOffTheScreenOrOutOfABandAreCulled) {
    Model m;
    Camera cam;
    const Transform t = cam.transform(m.scene, 0, 640, 480);
    const Rows whole{t.cy16, t.cy16};
    int32_t c[3];
    quantize(m.scene, 10, 20, 0, c);
    const int32_t r = int32_t(5 / m.scene.unit()); // 5 mm
    EXPECT_TRUE(t.visible(c, r, whole));
    int32_t far[3];
    quantize(m.scene, 10 + 5000, 20, 0, far);
    EXPECT_FALSE(t.visible(far, r, whole)) << "far to the side";
    // A small sphere at the centre: in the band through the middle, not in the top rows.
    const Rows middle{t.cy16 - 230 * 16, 250 * 16 - t.cy16}, top{t.cy16, 16 * 16 - t.cy16};
    EXPECT_TRUE(t.visible(c, r, middle));
    EXPECT_FALSE(t.visible(c, r, top));
    EXPECT_TRUE(t.visible(c, 0, top)) << "no radius known: never culled";
}

// A part's sphere wholly inside the view spares its faces their own tests: In must hold every
// point of the sphere on the screen (and in the rows), Out exactly what visible() culls.
TEST(Camera, ASphereIsInOnlyWhenAllOfItProjectsOntoTheRows) {
    Model m;
    Camera cam;
    const Transform t = cam.transform(m.scene, 0, 640, 480);
    const Rows whole{t.cy16, t.cy16}, middle{t.cy16 - 200 * 16, 280 * 16 - t.cy16};
    int32_t c[3];
    quantize(m.scene, 10, 20, 0, c);
    EXPECT_EQ(t.sight(c, int32_t(5 / m.scene.unit()), whole), Transform::Sight::In);
    EXPECT_EQ(t.sight(c, int32_t(5000 / m.scene.unit()), whole), Transform::Sight::Across) << "larger than the view";
    int32_t far[3];
    quantize(m.scene, 10 + 5000, 20, 0, far);
    EXPECT_EQ(t.sight(far, int32_t(5 / m.scene.unit()), whole), Transform::Sight::Out);
    uint32_t in = 0, across = 0;
    for (const Rows rows : {whole, middle})
        for (int x = -400; x <= 400; x += 40)
            for (int y = -400; y <= 400; y += 40)
                for (const float radius : {2.0f, 20.0f, 80.0f}) {
                    int32_t centre[3];
                    quantize(m.scene, float(x), float(y), 10, centre);
                    const int32_t r = int32_t(radius / m.scene.unit());
                    const Transform::Sight s = t.sight(centre, r, rows);
                    EXPECT_EQ(s == Transform::Sight::Out, !t.visible(centre, r, rows));
                    if (s != Transform::Sight::In) {
                        across += s == Transform::Sight::Across;
                        continue;
                    }
                    ++in;
                    for (int k = 0; k < 26; ++k) { // the sphere's points along the axes and diagonals
                        const int dx = k % 3 - 1, dy = (k / 3) % 3 - 1, dz = k / 9 - 1;
                        const float n = std::sqrt(float(dx * dx + dy * dy + dz * dz));
                        if (n == 0) continue;
                        int32_t p[3];
                        quantize(m.scene, x + radius * dx / n, y + radius * dy / n, 10 + radius * dz / n, p);
                        Projected q;
                        t.project(p, q);
                        ASSERT_EQ(q.out, 0);
                        EXPECT_TRUE(q.s.x >= 0 && q.s.x < 640 * 16) << x << " " << y << " " << radius;
                        EXPECT_TRUE(q.s.y - t.cy16 >= -rows.top16 && q.s.y - t.cy16 < rows.bottom16) << x << " " << y << " " << radius;
                    }
                }
    EXPECT_GT(in, 20u);
    EXPECT_GT(across, 20u);
}

TEST(Camera, ThePlaneFacesTheEyeFromAboveAndAwayFromBelow) {
    Model m;
    Camera cam;
    int32_t p[3];
    quantize(m.scene, 10, 20, 0, p);
    const int16_t up[3] = {0, 0, 16384}, down[3] = {0, 0, -16384};
    const Transform t = cam.transform(m.scene, 0, 640, 480); // the default view looks down on z
    EXPECT_FALSE(t.faces_away(p, up));
    EXPECT_TRUE(t.faces_away(p, down));
}

// A frame makes the view's basis once and each instance's transform from it; the eye is
// placed only for an instance drawn from its own faces. Field for field the same transform,
// and the eye placed is where the transform puts the view's eye, (0, 0, dist).
TEST(Camera, ATransformFromTheViewsBasisIsTheWholeOneAndItsEyeMapsToTheViewsEye) {
    Model m;
    Camera cam;
    cam.orbit(0.4f, 0.3f), cam.dolly(0.7f), cam.pan(3, -2);
    cam.set_section({true, {0.6f, 0.0f, 0.8f}, 5.0f});
    for (const bool ortho : {false, true}) {
        if (ortho) cam.toggle_projection();
        const Transform whole = cam.transform(m.scene, 0, 480, 272);
        const ViewBasis basis = cam.basis(m.scene, 480, 272);
        Transform t = Camera::transform(basis, m.scene, 0);
        EXPECT_FALSE(t.eye_placed);
        t.place_eye();
        ASSERT_TRUE(t.eye_placed);
        EXPECT_EQ(0, std::memcmp(t.a, whole.a, sizeof t.a));
        EXPECT_EQ(0, std::memcmp(t.b, whole.b, sizeof t.b));
        EXPECT_EQ(0, std::memcmp(t.light, whole.light, sizeof t.light));
        EXPECT_EQ(0, std::memcmp(t.eye, whole.eye, sizeof t.eye));
        EXPECT_EQ(0, std::memcmp(t.toward, whole.toward, sizeof t.toward));
        EXPECT_EQ(t.k16, whole.k16);
        EXPECT_EQ(t.dist, whole.dist);
        EXPECT_EQ(t.zk, whole.zk);
        EXPECT_EQ(t.ortho, whole.ortho);
        EXPECT_TRUE(t.cut.on);
        EXPECT_EQ(t.cut.c, whole.cut.c);
        EXPECT_EQ(t.cut.nd, whole.cut.nd);
        // a eye 2^-30 + b = (0, 0, dist), to a view unit (the eye is rounded to mesh units,
        // a sixteenth of a view unit here).
        int64_t r[3];
        const int32_t e[3] = {int32_t(t.eye[0]), int32_t(t.eye[1]), int32_t(t.eye[2])};
        for (int k = 0; k < 3; ++k) ASSERT_EQ(e[k], t.eye[k]);
        t.rotate(e, r);
        EXPECT_NEAR(double(r[0]) / 1073741824.0 + t.b[0], 0, 1);
        EXPECT_NEAR(double(r[1]) / 1073741824.0 + t.b[1], 0, 1);
        EXPECT_NEAR(double(r[2]) / 1073741824.0 + t.b[2], t.dist, 1);
    }
}

TEST(Camera, DollyIsBoundedAndPixelPansFollowThePointer) {
    Model m;
    Camera cam;
    for (int i = 0; i < 100; ++i) cam.dolly(0.5f);
    EXPECT_FLOAT_EQ(cam.view().zoom, 0.05f);
    for (int i = 0; i < 100; ++i) cam.dolly(2.0f);
    EXPECT_FLOAT_EQ(cam.view().zoom, 20.0f);
    cam.fit();
    int32_t c[3];
    quantize(m.scene, 10, 20, 0, c);
    Projected before, after;
    cam.transform(m.scene, 0, 640, 480).project(c, before);
    cam.pan_pixels(40, -25, m.scene.radius(), 640, 480);
    cam.transform(m.scene, 0, 640, 480).project(c, after);
    EXPECT_NEAR((after.s.x - before.s.x) / 16.0, 40, 1.5);
    EXPECT_NEAR((after.s.y - before.s.y) / 16.0, -25, 1.5);
}

// The standard views of a z-up model: where +x, +y and +z of the model go on the screen, and
// which way the eye looks (a face toward it is not culled).
TEST(Camera, StandardViewsPutTheModelsAxesWhereCadUsersExpectThem) {
    Model m;
    struct Case {
        Standard s;
        int right[3], up[3], toward[3]; // model axes to screen right, screen up, toward the eye
    };
    const Case cases[] = {
        {Standard::Front, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}}, {Standard::Back, {-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {Standard::Right, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {Standard::Left, {0, -1, 0}, {0, 0, 1}, {-1, 0, 0}},
        {Standard::Top, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},    {Standard::Bottom, {1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
    };
    for (const Case& c : cases) {
        Camera cam;
        cam.set_view(standard_view(c.s, View{}));
        const Transform t = cam.transform(m.scene, 0, 640, 480);
        int32_t o[3], r[3], u[3];
        quantize(m.scene, 10, 20, 0, o);
        quantize(m.scene, 10 + 10 * c.right[0], 20 + 10 * c.right[1], 10 * c.right[2], r);
        quantize(m.scene, 10 + 10 * c.up[0], 20 + 10 * c.up[1], 10 * c.up[2], u);
        Projected po, pr, pu;
        t.project(o, po), t.project(r, pr), t.project(u, pu);
        ASSERT_EQ(po.out | pr.out | pu.out, 0) << int(c.s);
        EXPECT_GT(pr.s.x - po.s.x, 16 * 20) << "view " << int(c.s) << ": the model's right axis goes right";
        EXPECT_NEAR(pr.s.y, po.s.y, 16) << int(c.s);
        EXPECT_LT(pu.s.y - po.s.y, -16 * 20) << "view " << int(c.s) << ": the model's up axis goes up";
        EXPECT_NEAR(pu.s.x, po.s.x, 16) << int(c.s);
        const int16_t n[3] = {int16_t(16384 * c.toward[0]), int16_t(16384 * c.toward[1]), int16_t(16384 * c.toward[2])};
        const int16_t away[3] = {int16_t(-n[0]), int16_t(-n[1]), int16_t(-n[2])};
        EXPECT_FALSE(t.faces_away(o, n)) << int(c.s);
        EXPECT_TRUE(t.faces_away(o, away)) << int(c.s);
    }
    // Isometric: the three axes equally foreshortened (in a parallel view: perspective would
    // shorten the one pointing away).
    Camera iso;
    View v = standard_view(Standard::Iso, View{});
    v.ortho = true;
    iso.set_view(v);
    const Transform t = iso.transform(m.scene, 0, 640, 480);
    int32_t o[3];
    quantize(m.scene, 10, 20, 0, o);
    Projected po;
    t.project(o, po);
    double len[3];
    for (int k = 0; k < 3; ++k) {
        int32_t a[3];
        quantize(m.scene, 10 + (k == 0) * 20.0f, 20 + (k == 1) * 20.0f, (k == 2) * 20.0f, a);
        Projected pa;
        t.project(a, pa);
        len[k] = std::hypot(pa.s.x - po.s.x, pa.s.y - po.s.y);
    }
    EXPECT_NEAR(len[0], len[1], 0.005 * len[0]);
    EXPECT_NEAR(len[0], len[2], 0.005 * len[0]);
}

// Parallel projection: the same length at two depths has the same size on the screen; with
// perspective the nearer one is bigger.
TEST(Camera, AParallelViewDoesNotShrinkWhatIsFarther) {
    Model m;
    for (const bool ortho : {false, true}) {
        Camera cam;
        View v = standard_view(Standard::Front, View{});
        v.ortho = ortho;
        cam.set_view(v);
        const Transform t = cam.transform(m.scene, 0, 640, 480);
        double size[2];
        for (int k = 0; k < 2; ++k) {
            const float y = k == 0 ? -40.0f : 60.0f; // near the eye (front: the eye is at -y), then far
            int32_t a[3], b[3];
            quantize(m.scene, 0, y, 0, a);
            quantize(m.scene, 20, y, 0, b);
            Projected pa, pb;
            t.project(a, pa), t.project(b, pb);
            ASSERT_EQ(pa.out | pb.out, 0);
            size[k] = (pb.s.x - pa.s.x) / 16.0;
        }
        if (ortho) {
            EXPECT_NEAR(size[0], size[1], 0.05);
        } else {
            EXPECT_GT(size[0], size[1] * 1.1);
        }
    }
}
