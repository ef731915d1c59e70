// The module through its public API (facet/viewer.h), as an application uses it (app.h).
// Loading: faces over capacity stay wireframe while the rest fills in, bad and deflated pack
// files, buffers create() refuses, names from the pack.
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

TEST(Viewer, AFaceTooBigForTheArenaStaysWireframeAndTheRestFillsIn) {
    const uint32_t sides = FACET_DEFAULT_FACE_POINTS + 500;
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(deflate_pack(polygon_and_triangle(sides))).ok());
    app.run();
    const Stats s = app.v->stats();
    EXPECT_EQ(s.faces, 2u);
    EXPECT_EQ(s.failed, 1u);
    EXPECT_EQ(s.done, 1u);
    EXPECT_EQ(s.triangles, 1u) << "the triangle face";
    ASSERT_EQ(app.count(Event::Kind::FaceFailed), 1);
    const Event& f = *app.last(Event::Kind::FaceFailed);
    EXPECT_EQ(f.failed.face, 0u);
    EXPECT_EQ(f.why.status, Status::Full);
    EXPECT_EQ(text(f.why).rfind("face 0", 0), 0u) << text(f.why);
    const Event& t = *app.last(Event::Kind::Tessellated);
    EXPECT_EQ(t.tessellated.faces, 2u);
    EXPECT_EQ(t.tessellated.failed, 1u);
    EXPECT_EQ(t.tessellated.triangles, 1u);
}

TEST(Viewer, APolygonWithinTheArenaFillsIn) {
    // The same model with a face the arena holds: both faces tessellated (the test above
    // fails for the reason it names, not for the model).
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(deflate_pack(polygon_and_triangle(2000))).ok());
    app.run();
    EXPECT_EQ(app.v->stats().failed, 0u);
    EXPECT_EQ(app.v->stats().triangles, 1998u + 1u);
}

TEST(Viewer, BadPackFilesAreRefusedWithTheirReason) {
    const Bytes plain = polygon_and_triangle(12);
    const Bytes deflated = deflate_pack(plain);
    struct Case {
        const char* name;
        Bytes file;
        const char* reason;
    };
    Bytes flipped = plain;
    flipped[flipped.size() - 10] ^= 0x04;
    Bytes truncated_stream = deflated;
    truncated_stream.resize(deflated.size() / 2);
    Bytes bad_stream = deflated;
    bad_stream[sizeof(pack::DeflatedHead)] = 0xFF; // a final block of the reserved type
    Bytes bad_record = plain;
    const Case cases[] = {
        {"a bit flipped in a plain pack", flipped, "header: CRC mismatch"},
        {"a deflated pack cut in half", truncated_stream, "pack file: "},
        {"a damaged DEFLATE stream", bad_stream, "pack file: "},
        {"not a pack at all", Bytes(300, 'x'), "no pack here (neither FPK1, FPX1, FPZ1 nor FPB1)"},
        {"nothing loaded", Bytes(64, 0), "no pack here"},
    };
    for (const Case& c : cases) {
        App app;
        ASSERT_TRUE(app.create().ok());
        const Result r = app.load(c.file);
        EXPECT_FALSE(r.ok()) << c.name;
        EXPECT_NE(text(r).find(c.reason), std::string::npos) << c.name << ": " << text(r);
        EXPECT_EQ(app.v->step(1000), Activity::Idle) << c.name << ": nothing to show";
        EXPECT_EQ(app.flushes, 0u) << c.name;
    }
}

TEST(Viewer, ADeflatedPackNeedsItsMemory) {
    App app;
    ASSERT_TRUE(app.create().ok());
    const Bytes deflated = deflate_pack(polygon_and_triangle(12));
    std::vector<uint32_t> file(deflated.size() / 4 + 1), small(16);
    std::memcpy(file.data(), deflated.data(), deflated.size());
    EXPECT_TRUE(app.v->load(file.data(), uint32_t(deflated.size()), nullptr, 0).ok()) << "none given: the workspace's end";
    EXPECT_EQ(app.v->load(file.data(), uint32_t(deflated.size()), small.data(), 64).status, Status::Full);
    EXPECT_GT(pack_memory_bytes(file.data(), uint32_t(deflated.size())), deflated.size());
    // In place, as a board loads it: the file at the start of its pack memory.
    std::vector<uint32_t> region((deflated.size() + pack_memory_bytes(file.data(), uint32_t(deflated.size()))) / 4 + 1);
    std::memcpy(region.data(), deflated.data(), deflated.size());
    EXPECT_TRUE(app.v->load(region.data(), uint32_t(region.size() * 4), region.data(), uint32_t(region.size() * 4)).ok());
}

TEST(Viewer, CreateRefusesMissingOrSmallBuffers) {
    std::vector<uint64_t> ws(FACET_WORKSPACE_BYTES_DEFAULT / 8 + 1);
    std::vector<Rgb565> px(160 * 120);
    std::vector<uint16_t> z(160 * 120);
    auto config = [&]() {
        Config c;
        c.display = {160, 120, 120, {px.data(), nullptr}, {z.data(), nullptr}, Flush::Copy, [](Viewer&, void*, const Area&, const Rgb565*) {}, nullptr};
        return c;
    };
    Result why;
    Config c = config();
    ASSERT_NE(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << text(why);
    EXPECT_EQ(Viewer::create(c, ws.data(), workspace_bytes() / 2, &why), nullptr); // under one face's working memory
    EXPECT_EQ(why.status, Status::Full);
    EXPECT_EQ(Viewer::create(c, ws.data(), workspace_bytes() - 1, &why), nullptr) << "a byte under facet/sizes.h's formula";
    EXPECT_EQ(why.status, Status::Full);
    EXPECT_NE(Viewer::create(c, ws.data(), workspace_bytes(), &why), nullptr) << "the formula's bytes: " << text(why);
    EXPECT_EQ(Viewer::create(c, reinterpret_cast<uint8_t*>(ws.data()) + 4, ws.size() * 8 - 8, &why), nullptr);
    EXPECT_NE(text(why).find("aligned"), std::string::npos);
    c = config(), c.display.buffers[0] = nullptr;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr);
    c = config(), c.display.band_lines = 121;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr);
    c = config(), c.display.mode = Flush::Scanout, c.display.band_lines = 16;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "scan-out takes full frames";
    std::vector<Rgb565> layer(160 * 120);
    std::vector<uint16_t> layer_depth(160 * 120);
    c = config(), c.display.faces = layer.data(), c.display.faces_depth = layer_depth.data();
    EXPECT_NE(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "a faces layer: " << text(why);
    c.display.band_lines = 16;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "a faces layer takes full frames";
    EXPECT_NE(text(why).find("full frames"), std::string::npos) << text(why);
    c = config(), c.display.faces = layer.data();
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "a faces layer without its depth";
    c = config(), c.capacity.face_points = 40000;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "a 16-bit arena";
}

// Names from the STEP file travel in the pack: the model's, each part's and occurrence's; a pack
// whose name tables point into the middle of a name is refused.
TEST(Viewer, PartsCarryTheirNamesFromThePack) {
    const Bytes bytes = two_blocks();
    Pack p;
    ASSERT_TRUE(p.open(bytes.data(), uint32_t(bytes.size())).ok());
    EXPECT_STREQ(p.model_name(), "two blocks");
    EXPECT_STREQ(p.shell_name(0), "block");
    EXPECT_STREQ(p.instance_name(0), "block_a");
    EXPECT_STREQ(p.instance_name(1), "");
    // A name table entry moved into the middle of a name (the CRC made right again): refused.
    Bytes bad = bytes;
    const auto* h = reinterpret_cast<const pack::Header*>(bad.data());
    const auto* table = reinterpret_cast<const pack::SectionEntry*>(bad.data() + sizeof(pack::Header));
    for (uint32_t i = 0; i < h->section_count; ++i) {
        if (table[i].id != uint32_t(pack::SectionId::ShellNames)) continue;
        uint32_t at;
        std::memcpy(&at, bad.data() + table[i].offset, 4);
        ++at;
        std::memcpy(bad.data() + table[i].offset, &at, 4);
    }
    const uint32_t crc = pack::crc32(bad.data() + sizeof(pack::Header), uint32_t(bad.size() - sizeof(pack::Header)));
    std::memcpy(bad.data() + offsetof(pack::Header, crc32), &crc, 4);
    Pack q;
    const Result r = q.open(bad.data(), uint32_t(bad.size()));
    EXPECT_EQ(text(r), "section ShellNames record 0: the name does not start a string of Names");

    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(bytes).ok());
    EXPECT_STREQ(app.v->model_name(), "two blocks");
    ASSERT_EQ(app.v->part_count(), 2u);
    EXPECT_STREQ(app.v->part(1).name, "block");
    EXPECT_STREQ(app.v->part(0).instance, "block_a");
    EXPECT_EQ(app.v->part(1).faces, 6u);
    EXPECT_TRUE(app.v->part(1).shown);
    EXPECT_EQ(app.v->show_part(2, false).status, Status::OutOfRange);
}

// Only public statuses leave the module (module/src/public_result.h, used where results leave:
// the Viewer's loading calls and every event): the layers' own kinds are said as what they mean
// to a caller, with the text and places kept.
TEST(Viewer, TheLayersOwnStatusesLeaveAsPublicOnes) {
    static_assert(module::public_status(Status::Degenerate) == Status::Corrupt);
    static_assert(module::public_status(Status::Crossing) == Status::Corrupt);
    for (Status s : {Status::Ok, Status::OutOfRange, Status::Full, Status::Corrupt, Status::Unsupported, Status::NotFound, Status::Busy,
                     Status::Io}) {
        EXPECT_EQ(module::public_status(s), s);
        EXPECT_TRUE(module::is_public(s));
    }
    const Result r = module::public_result(Result::fail(Status::Crossing, "loops cross", {"face", 12}, {"loop", 3}));
    EXPECT_EQ(r.status, Status::Corrupt);
    EXPECT_EQ(text(r), "face 12, loop 3: loops cross");
    // A model's whole life (load, faces, frames, a pick): every event's status a public one.
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(FACET_DEFAULT_FACE_POINTS + 500)).ok());
    app.run();
    app.v->touch(0, int16_t(app.w / 2), int16_t(app.h / 2), true);
    app.v->touch(0, int16_t(app.w / 2), int16_t(app.h / 2), false);
    app.run();
    ASSERT_EQ(app.count(Event::Kind::FaceFailed), 1);
    for (const Event& e : app.events) EXPECT_TRUE(module::is_public(e.why.status)) << int(e.kind);
}
