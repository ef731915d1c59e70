// Triangles bounded by the screen (issue 52, module/src/detail.cpp): an assembly of several
// blocks holds what its view's pixels bound it to, each part watertight at any level.
#include "../geom/shapes.h"
#include "app.h"
#include "assembly.h"
#include "detail.h"
#include "pack_blocks.h"
#include "watertight.h"

#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

// Triangles bounded by the screen (issue 52): an assembly of several blocks holding more
// triangles than one per DetailScale::kPixelsPerTriangle pixels of the view (at least
// kLeastTriangleBound) takes its screen error coarser, block by block, until it holds fewer or
// its error is DetailScale::kCrowdMeshCoarsest times the view's (a pack without proxies);
// every part stays watertight, and the same assembly with the bound out of reach (a larger
// screen) keeps its finer level.
TEST(Blocked, AnAssemblyHoldsTheTrianglesTheScreenBoundsItTo) {
    const Bytes shapes[] = {sphere(), torus(), sphere(), torus(), trimmed_bspline(), plate_with_holes()};
    std::vector<Pack> packs(6);
    for (int k = 0; k < 6; ++k) ASSERT_TRUE(packs[k].open(shapes[k].data(), uint32_t(shapes[k].size())).ok());
    const Bytes file = blocked(combine_packs(packs, 150.0f));
    std::vector<uint32_t> held;
    for (const uint16_t w : {320, 1280}) {
        App app;
        app.w = w, app.h = uint16_t(w * 3 / 4), app.lines = app.h;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(file).ok());
        app.run();
        ASSERT_TRUE(app.v->set_detail(0.125f).ok()); // finer: more triangles than the small screen takes
        app.run();
        const Core& core = *static_cast<const Core*>(app.v);
        const module::Scene& scene = core.scene();
        ASSERT_GT(scene.block_count(), 1u);
        const module::Detail& detail = core.detail_level();
        const uint32_t bound = detail.triangle_bound();
        held.push_back(app.v->stats().triangles);
        if (w == 320) {
            EXPECT_EQ(bound, module::DetailScale::kLeastTriangleBound);
            EXPECT_GT(detail.crowd(), 1.0f) << "the bound was reached";
            EXPECT_TRUE(held.back() <= bound || detail.crowd() == module::DetailScale::kCrowdMeshCoarsest) << held.back() << " triangles";
        } else {
            EXPECT_EQ(bound, uint32_t(1280 * 960) / module::DetailScale::kPixelsPerTriangle);
            EXPECT_EQ(detail.crowd(), 1.0f) << "under the bound";
        }
        EXPECT_EQ(app.v->stats().failed, 0u);
        for (uint32_t s = 0; s < scene.part_count(); ++s) {
            if (whole(scene, s)) {
                EXPECT_EQ(open_sides(scene, s), 0u) << "part " << s;
            }
        }
    }
    EXPECT_LT(held[0], held[1]) << "the small screen holds fewer";
}
