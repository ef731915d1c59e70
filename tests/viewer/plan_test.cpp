// The workspace planned for the model (issue 25): load() lays out the model's arrays for its
// own faces and edges in the room the workspace has, so a model larger than the old fixed
// capacities (8,192 faces) opens when the memory is there; model_needs() says what a pack needs
// from its head or index alone, and a workspace under that is refused with the bytes missing.
// Given no pack memory, a compressed pack is decoded at the workspace's end, and a file the
// board loaded into the workspace is decoded where it lies.
#include "app.h"
#include "assembly.h"

#include <vector>

using namespace facet;
using namespace facet::test;
using geom::deflate_pack;

namespace {

struct Aligned {
    std::vector<uint64_t> words;
    uint32_t bytes;
    explicit Aligned(const Bytes& b) : words(b.size() / 8 + 1), bytes(uint32_t(b.size())) { std::memcpy(words.data(), b.data(), b.size()); }
    const void* data() const { return words.data(); }
};

} // namespace

TEST(Plan, AModelOverTheOldCapacitiesOpensInTheWorkspaceItNeeds) {
    const uint32_t kFaces = 8400; // over the 8,192 faces a default workspace held before
    const Aligned file(squares(kFaces, 100, {{0, 0, 0}}, 1.1f)); // (1.1 mm apart: each over kFacePixels below)
    ModelNeeds needs{};
    ASSERT_TRUE(model_needs(file.data(), file.bytes, needs).ok());
    EXPECT_EQ(needs.faces, kFaces);
    EXPECT_EQ(needs.edges, 4 * kFaces);
    EXPECT_EQ(needs.parts, 1u);
    EXPECT_EQ(needs.pack_memory_bytes, 0u) << "a plain pack is read in place";
    EXPECT_GT(needs.least_workspace_bytes, workspace_bytes());
    EXPECT_GE(needs.workspace_bytes, needs.least_workspace_bytes);

    // The workspace it needs: every face shaded (a screen where each square is over the
    // size a face is tessellated for, module::kFacePixels, so none is left to its edges).
    App app;
    app.w = 800, app.h = 600;
    app.workspace_size = needs.workspace_bytes;
    ASSERT_TRUE(app.create().ok());
    Result r = app.v->load(file.data(), file.bytes);
    ASSERT_TRUE(r.ok()) << text(r);
    app.run();
    EXPECT_EQ(app.v->stats().faces, kFaces);
    EXPECT_EQ(app.v->stats().done, kFaces);
    EXPECT_EQ(app.v->stats().failed, 0u);
    EXPECT_EQ(app.v->stats().triangles, 2 * kFaces);

    // The least: it opens; a kilobyte less (more than the alignment the least allows for) is
    // refused with the bytes missing, and nothing is shown.
    App least;
    least.workspace_size = needs.least_workspace_bytes;
    ASSERT_TRUE(least.create().ok());
    r = least.v->load(file.data(), file.bytes);
    EXPECT_TRUE(r.ok()) << text(r);
    least.run();
    EXPECT_EQ(least.v->stats().faces, kFaces);
    App short_of;
    short_of.workspace_size = needs.least_workspace_bytes - 1024;
    ASSERT_TRUE(short_of.create().ok());
    r = short_of.v->load(file.data(), file.bytes);
    EXPECT_EQ(r.status, Status::Full);
    EXPECT_NE(text(r).find("bytes needed"), std::string::npos) << text(r);
    EXPECT_EQ(short_of.v->step(1000), Activity::Idle);
    // A model that fits loads after the refusal.
    r = short_of.load(polygon_and_triangle(12));
    EXPECT_TRUE(r.ok()) << text(r);
}

// A pack that carries what the packer measured (pack::Needs): model_needs() sizes the
// workspace from it, alike from a plain, an LZMA, a deflated and a blocked file, the least from
// the coarse level and the roomy one from the default; without it, from estimates.
TEST(Plan, ThePacksMeasureSizesTheWorkspaceInEveryForm) {
    constexpr uint32_t kFaces = 400;
    const pack::Needs measured{90000, 120000, 60000, 20000, 30000, 15000};
    const Bytes plain = squares(kFaces, 20, {{0, 0, 0}}, 2, &measured);
    ModelNeeds estimated{};
    const Aligned without(squares(kFaces, 20, {{0, 0, 0}}, 2));
    ASSERT_TRUE(model_needs(without.data(), without.bytes, estimated).ok());
    ModelNeeds first{};
    const Bytes forms[] = {plain, geom::lzma_pack(plain), deflate_pack(plain), blocked(plain, geom::BlockStore::Deflated)};
    for (const Bytes& form : forms) {
        const Aligned file(form);
        ModelNeeds needs{};
        const Result r = model_needs(file.data(), file.bytes, needs);
        ASSERT_TRUE(r.ok()) << text(r);
        EXPECT_EQ(needs.faces, kFaces);
        if (&form == &forms[0]) {
            first = needs;
            // Each level's samples, the most of its three shares here (90,000 and 20,000 of
            // FACET_BYTES_PER_SAMPLE in the 30% of the room the samples take, each with its
            // margin of 1/64 and 16), beside the base and the faces' and edges' arrays.
            const size_t model = FACET_WORKSPACE_BASE_BYTES + kFaces * FACET_BYTES_PER_FACE + 4 * kFaces * FACET_BYTES_PER_EDGE;
            const size_t roomy = model + size_t(90000 + 90000 / 64 + 16) * FACET_BYTES_PER_SAMPLE * 100 / 30;
            EXPECT_GE(needs.workspace_bytes, roomy - 64);
            EXPECT_LT(needs.workspace_bytes, roomy + 1024);
            const size_t least = model + size_t(20000 + 20000 / 64 + 16) * FACET_BYTES_PER_SAMPLE * 100 / 30;
            EXPECT_GE(needs.least_workspace_bytes, least - 64);
            EXPECT_LT(needs.least_workspace_bytes, least + 1024);
            EXPECT_LT(needs.least_workspace_bytes, needs.workspace_bytes);
            EXPECT_GT(needs.workspace_bytes, estimated.workspace_bytes) << "the measure, not the estimate";
        } else {
            EXPECT_EQ(needs.least_workspace_bytes, first.least_workspace_bytes);
            EXPECT_EQ(needs.workspace_bytes, first.workspace_bytes);
        }
    }
}

TEST(Plan, WithoutPackMemoryTheWorkspaceEndHoldsTheDecodedPack) {
    const Bytes plain = polygon_and_triangle(24);
    const Bytes file = deflate_pack(plain);
    // With pack memory of its own (the reference), then with none.
    App given, none;
    ASSERT_TRUE(given.create().ok());
    ASSERT_TRUE(given.load(file).ok());
    given.run();
    ASSERT_TRUE(none.create().ok());
    const Aligned f(file);
    const Result r = none.v->load(f.data(), f.bytes);
    ASSERT_TRUE(r.ok()) << text(r);
    none.run();
    EXPECT_EQ(none.v->stats().triangles, given.v->stats().triangles);
    EXPECT_EQ(none.screen(), given.screen());

    // A file the board loaded into the workspace's free room (the boards hand the module all
    // free RAM, the loaded file included) is decoded where it lies.
    App inside;
    ASSERT_TRUE(inside.create().ok());
    const size_t at = inside.workspace.size() * 8 - (file.size() + 64) / 8 * 8;
    std::memcpy(reinterpret_cast<uint8_t*>(inside.workspace.data()) + at, file.data(), file.size());
    const Result in = inside.v->load(reinterpret_cast<uint8_t*>(inside.workspace.data()) + at, uint32_t(file.size()));
    ASSERT_TRUE(in.ok()) << text(in);
    inside.run();
    EXPECT_EQ(inside.screen(), given.screen());

    // Pack memory that overlaps the workspace is refused (the model's arrays would be laid over it).
    App overlap;
    ASSERT_TRUE(overlap.create().ok());
    uint8_t* tail = reinterpret_cast<uint8_t*>(overlap.workspace.data()) + overlap.workspace.size() * 8 - 65536;
    EXPECT_EQ(overlap.v->load(f.data(), f.bytes, tail, 65536).status, Status::OutOfRange);
}
