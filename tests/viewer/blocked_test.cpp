// Blocked packs in the viewer (pack_format.h: an index, then blocks of a few parts each): an
// assembly of shapes built in code, loaded whole and blocked, shows the same faces, triangles and
// pixels; the blocks are decoded into the pack memory (or from a file loaded into it), and a pack
// memory too small, a corrupt block or a misplaced file gets a clear refusal.
#include "../geom/shapes.h"
#include "app.h"
#include "assembly.h"
#include "loader.h"
#include "pack_blocks.h"
#include "watertight.h"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

namespace {

struct Shown {
    Stats stats;
    std::vector<Rgb565> screen;
    std::vector<std::string> names;
};

// Every part at the model's one tolerance (no coarser level for a far block: a whole pack is one
// block), so the two forms make the same mesh.
Shown show(const Bytes& file) {
    App app;
    app.w = 320, app.h = 240;
    app.screen_error_px = 0;
    EXPECT_TRUE(app.create().ok());
    const Result r = app.load(file);
    EXPECT_TRUE(r.ok()) << text(r);
    app.run();
    Shown s{app.v->stats(), app.screen(), {}};
    for (uint32_t i = 0; i < app.v->part_count(); ++i) s.names.push_back(app.v->part(i).name);
    return s;
}

uint32_t triangles_of(const module::Scene& scene, uint32_t s) {
    const module::Part part = scene.part(s);
    uint32_t n = 0;
    for (uint32_t f = part.first_face; f < part.first_face + part.face_count; ++f) n += scene.face(f).triangle_count;
    return n;
}

} // namespace

TEST(Blocked, AnAssemblyShowsWhatItsWholePackShows) {
    const Bytes whole = assembly();
    const Bytes file = blocked(whole);
    ASSERT_EQ(pack_file_kind(file.data(), uint32_t(file.size())), PackFileKind::Blocked);
    const Shown a = show(whole), b = show(file);
    EXPECT_EQ(b.stats.faces, a.stats.faces);
    EXPECT_EQ(b.stats.failed, 0u);
    EXPECT_EQ(b.stats.triangles, a.stats.triangles);
    EXPECT_EQ(b.stats.vertices, a.stats.vertices);
    EXPECT_EQ(b.stats.tolerance_mm, a.stats.tolerance_mm);
    EXPECT_EQ(b.names, a.names);
    EXPECT_GT(b.stats.pack_bytes, whole.size()) << "four blocks decoded, and their table";
    EXPECT_EQ(b.stats.pack_file_bytes, file.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.screen.size(); ++i) differ += a.screen[i] != b.screen[i];
    EXPECT_EQ(differ, 0u) << "pixels that differ between the whole and the blocked pack";
}

TEST(Blocked, EveryStoreOfABlockReads) {
    const Bytes whole = assembly();
    const Shown a = show(whole);
    for (const BlockStore store : {BlockStore::Deflated, BlockStore::Plain}) {
        const Bytes file = blocked(whole, store);
        const Shown b = show(file);
        EXPECT_EQ(b.stats.triangles, a.stats.triangles);
        EXPECT_EQ(b.screen, a.screen);
        // Plain blocks are read in place: the pack memory holds only the table of blocks (and
        // room for an LZMA decoder's state).
        std::vector<uint32_t> aligned(file.size() / 4 + 1);
        std::memcpy(aligned.data(), file.data(), file.size());
        const uint32_t need = pack_memory_bytes(aligned.data(), uint32_t(file.size()));
        if (store == BlockStore::Plain) {
            EXPECT_LT(need, 12000u);
            EXPECT_EQ(b.stats.pack_bytes, (4 * sizeof(module::Block) + 3) / 4 * 4) << "the table of four blocks, and nothing else";
        } else {
            EXPECT_GT(need, whole.size());
        }
    }
}

TEST(Blocked, AFileLoadedIntoThePackMemoryIsDecodedThere) {
    const Bytes file = blocked(assembly());
    App app;
    ASSERT_TRUE(app.create().ok());
    std::vector<uint64_t> words(file.size() / 8 + 1);
    std::memcpy(words.data(), file.data(), file.size());
    const uint32_t blocks_need = pack_memory_bytes(words.data(), uint32_t(file.size()));
    ASSERT_GT(blocks_need, file.size());
    // The file at the start of a memory of the blocks' size plus its own: moved to the end,
    // decoded to the front.
    std::vector<uint64_t> memory((blocks_need + file.size()) / 8 + 2, 0);
    std::memcpy(memory.data(), file.data(), file.size());
    const Result r = app.v->load(memory.data(), uint32_t(file.size()), memory.data(), uint32_t(memory.size() * 8));
    ASSERT_TRUE(r.ok()) << text(r);
    app.run();
    EXPECT_EQ(app.v->stats().failed, 0u);
    EXPECT_EQ(app.v->stats().done + app.v->stats().deferred, app.v->stats().faces) << "(a solid's planes turned away wait)";
}

TEST(Blocked, AFileTheBoardLoadedIntoTheWorkspaceIsDecodedWhereverItLies) {
    // The boards hand the module all free RAM, the file loaded somewhere in it: with no pack
    // memory, the blocks are decoded in front of the file (moved to the end first), whatever
    // the file's size modulo the alignment.
    const Bytes whole = assembly();
    const Shown reference = show(blocked(whole));
    for (BlockStore store : {BlockStore::Lzma, BlockStore::Deflated, BlockStore::Plain}) {
        const Bytes file = blocked(whole, store);
        App app;
        app.w = 320, app.h = 240;
        app.screen_error_px = 0;
        ASSERT_TRUE(app.create().ok());
        uint8_t* at = reinterpret_cast<uint8_t*>(app.workspace.data()) + app.workspace.size() / 2 * 8; // mid-workspace
        std::memcpy(at, file.data(), file.size());
        const Result r = app.v->load(at, uint32_t(file.size()));
        ASSERT_TRUE(r.ok()) << text(r) << " (store " << int(store) << ", " << file.size() % 8 << " bytes over 8)";
        app.run();
        EXPECT_EQ(app.screen(), reference.screen) << "store " << int(store);
    }
}

TEST(Blocked, TooLittleMemoryACorruptBlockAndAnUnalignedFileAreRefused) {
    const Bytes file = blocked(assembly());
    App app;
    ASSERT_TRUE(app.create().ok());
    std::vector<uint64_t> in(file.size() / 8 + 2);
    std::memcpy(in.data(), file.data(), file.size());
    const uint32_t need = pack_memory_bytes(in.data(), uint32_t(file.size()));
    std::vector<uint64_t> memory(need / 8 + 1);
    {
        const Result r = app.v->load(in.data(), uint32_t(file.size()), memory.data(), need / 2);
        EXPECT_EQ(r.status, Status::Full) << text(r);
        EXPECT_NE(text(r).find("do not fit the pack memory"), std::string::npos) << text(r);
    }
    {
        Bytes bad = file;
        bad[bad.size() - 40] ^= 0x5A; // inside the last block's compressed stream
        std::vector<uint64_t> b(bad.size() / 8 + 2);
        std::memcpy(b.data(), bad.data(), bad.size());
        const Result r = app.v->load(b.data(), uint32_t(bad.size()), memory.data(), uint32_t(memory.size() * 8));
        EXPECT_EQ(r.status, Status::Corrupt) << text(r);
        EXPECT_NE(text(r).find("block 3"), std::string::npos) << text(r);
    }
    {
        std::vector<uint8_t> shifted(file.size() + 1);
        std::memcpy(shifted.data() + 1, file.data(), file.size());
        const Result r = app.v->load(shifted.data() + 1, uint32_t(file.size()), memory.data(), uint32_t(memory.size() * 8));
        EXPECT_FALSE(r.ok());
        EXPECT_NE(text(r).find("4-byte aligned"), std::string::npos) << text(r);
    }
    // And a good load after all of them.
    const Result r = app.v->load(in.data(), uint32_t(file.size()), memory.data(), uint32_t(memory.size() * 8));
    EXPECT_TRUE(r.ok()) << text(r);
    app.run();
    EXPECT_EQ(app.v->stats().failed, 0u);
}

// An index that lies (issue 49): its counts, offsets, sizes, sections, instances or blocks'
// order changed, its CRC made right again. Each is Corrupt with its reason, from load() or, for
// what only the block shows, when the block is decoded (a PassFailed event; the rest still
// shows); never Full, whatever memory is given (pack_memory_bytes() of the file, or ample).
TEST(Blocked, AnIndexThatLiesIsCorrupt) {
    const Bytes good = blocked(assembly());
    auto section = [](Bytes& f, pack::IndexSectionId id) -> uint8_t* {
        const auto* h = reinterpret_cast<const pack::IndexHeader*>(f.data());
        const auto* t = reinterpret_cast<const pack::SectionEntry*>(f.data() + sizeof(pack::IndexHeader));
        for (uint32_t i = 0; i < h->section_count; ++i)
            if (t[i].id == uint32_t(id)) return f.data() + t[i].offset;
        return nullptr;
    };
    auto reseal = [](Bytes& f) {
        auto* h = reinterpret_cast<pack::IndexHeader*>(f.data());
        h->crc32 = pack::crc32(f.data() + pack::kIndexCrcFrom, h->index_bytes - pack::kIndexCrcFrom);
    };
    struct Lie {
        const char* what;
        void (*change)(Bytes&, uint8_t* blocks, uint8_t* parts, uint8_t* instances);
    };
    const Lie lies[] = {
        {"a part claims 100,000 faces", [](Bytes&, uint8_t*, uint8_t* parts, uint8_t*) { reinterpret_cast<pack::Part*>(parts)[0].face_count = 100000; }},
        {"a part claims 100,000 edges", [](Bytes&, uint8_t*, uint8_t* parts, uint8_t*) { reinterpret_cast<pack::Part*>(parts)[1].edge_count = 100000; }},
        {"a block's offset moved", [](Bytes&, uint8_t* blocks, uint8_t*, uint8_t*) { reinterpret_cast<pack::Block*>(blocks)[1].offset += 4; }},
        {"a block's stored size", [](Bytes&, uint8_t* blocks, uint8_t*, uint8_t*) { reinterpret_cast<pack::Block*>(blocks)[0].stored_bytes -= 4; }},
        {"a block's decoded size", [](Bytes&, uint8_t* blocks, uint8_t*, uint8_t*) { reinterpret_cast<pack::Block*>(blocks)[0].pack_bytes += 8; }},
        {"two blocks swapped", [](Bytes&, uint8_t* blocks, uint8_t*, uint8_t*) { std::swap(reinterpret_cast<pack::Block*>(blocks)[0], reinterpret_cast<pack::Block*>(blocks)[1]); }},
        {"an instance's part", [](Bytes&, uint8_t*, uint8_t*, uint8_t* instances) { reinterpret_cast<pack::Instance*>(instances)[0].shell = 1000; }},
        {"a section more", [](Bytes& f, uint8_t*, uint8_t*, uint8_t*) { ++reinterpret_cast<pack::IndexHeader*>(f.data())->section_count; }},
        {"a zeroed placement row", [](Bytes&, uint8_t*, uint8_t*, uint8_t* instances) {
             float* m = reinterpret_cast<pack::Instance*>(instances)[0].m;
             m[4] = m[5] = m[6] = m[7] = 0;
         }},
    };
    std::vector<uint64_t> ample(2 * pack_memory_bytes(good.data(), uint32_t(good.size())) / 8 + 64);
    for (const Lie& lie : lies) {
        SCOPED_TRACE(lie.what);
        Bytes file = good;
        lie.change(file, section(file, pack::IndexSectionId::Blocks), section(file, pack::IndexSectionId::Parts), section(file, pack::IndexSectionId::Instances));
        reseal(file);
        std::vector<uint64_t> in(file.size() / 8 + 2);
        std::memcpy(in.data(), file.data(), file.size());
        const uint32_t need = pack_memory_bytes(in.data(), uint32_t(file.size()));
        std::vector<uint64_t> sized(need / 8 + 1);
        for (int k = 0; k < 2; ++k) {
            App app;
            ASSERT_TRUE(app.create().ok());
            void* memory = k ? ample.data() : sized.data();
            const uint32_t bytes = k ? uint32_t(ample.size() * 8) : need;
            const Result r = app.v->load(in.data(), uint32_t(file.size()), memory, bytes);
            if (!r.ok()) {
                EXPECT_EQ(r.status, Status::Corrupt) << text(r);
                continue;
            }
            app.run();
            bool corrupt = false;
            for (const Event& e : app.events) corrupt = corrupt || (e.kind == Event::Kind::PassFailed && e.why.status == Status::Corrupt);
            EXPECT_TRUE(corrupt) << "loaded: a block found corrupt when decoded, said by PassFailed";
        }
    }
}

// Level of detail per block (issue 25): a block's parts take a tolerance from how far they lie
// (half a pixel at their nearest point, never finer than the model's), and every edge of a part
// is sampled once at its block's level for both its faces: each closed part is watertight
// whatever mix of levels the model shows.
TEST(Blocked, PartsAtMixedLevelsOfDetailAreEachWatertight) {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<Pack> packs(4);
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(packs[k].open(shapes[k].data(), uint32_t(shapes[k].size())).ok());
    const Bytes file = blocked(combine_packs(packs, 600.0f)); // far apart: the far blocks coarser
    App app;
    app.w = 320, app.h = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(file).ok());
    app.run();
    // Looking along the row (the left view looks along +x: the plate nearest, then the sphere
    // and the torus) from nearer, a new pass: the far blocks coarser than the near one.
    app.v->act(Action::ViewLeft);
    app.run();
    for (int zoom = 0; zoom < 4; ++zoom) app.v->act(Action::ZoomIn);
    app.run();
    app.v->act(Action::Finer);
    app.run();
    app.v->act(Action::Fit); // the whole model again: the faces the zoom left out come in, each at its block's level
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    float finest = INFINITY, coarsest = 0;
    for (uint32_t b = 0; b < scene.block_count(); ++b) {
        finest = std::min(finest, scene.block(b).tolerance), coarsest = std::max(coarsest, scene.block(b).tolerance);
    }
    EXPECT_GE(finest, app.v->stats().tolerance_mm) << "no block finer than the model's tolerance";
    EXPECT_GT(coarsest, 1.5f * finest) << "the blocks are at different levels";
    EXPECT_EQ(app.v->stats().failed, 0u);
    float checked_finest = INFINITY, checked_coarsest = 0; // the levels of the parts checked
    for (uint32_t s = 0; s < scene.part_count(); ++s) {
        if (!whole(scene, s)) continue;
        const float level = scene.block(scene.part(s).block).tolerance;
        checked_finest = std::min(checked_finest, level), checked_coarsest = std::max(checked_coarsest, level);
        EXPECT_EQ(open_sides(scene, s), 0u) << "part " << s << " (block tolerance " << level
                                             << " mm): sides not shared by exactly two triangles";
    }
    EXPECT_GT(checked_coarsest, 1.5f * checked_finest) << "closed parts at different levels were checked";
}

// Right after load, while the first pass samples the edges, a blocked pack's parts show as
// their boxes (the index's), each instance's in its place: the model's layout at once. A whole
// pack has no boxes before its edges: nothing is drawn until its wireframe.
TEST(Blocked, ThePartsShowAsBoxesWhileTheirEdgesAreSampled) {
    const Bytes whole = assembly();
    for (const Bytes* file : {&whole, static_cast<const Bytes*>(nullptr)}) {
        const Bytes pack = file ? *file : blocked(whole);
        App app;
        app.w = 320, app.h = 240;
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(pack).ok());
        uint32_t box_pixels = 0;
        for (int i = 0; i < 100000 && app.count(Event::Kind::Sampled) == 0; ++i) {
            (void)app.v->step(1000);
            app.done();
        }
        ASSERT_EQ(app.count(Event::Kind::Sampled), 1);
        bool boxes = false;
        for (const Event& e : app.events) {
            if (e.kind == Event::Kind::FrameDone) boxes = boxes || e.frame.boxes;
            if (e.kind == Event::Kind::Sampled) break;
        }
        for (Rgb565 p : app.screen()) box_pixels += p == rgb565(96, 104, 128);
        if (file) {
            EXPECT_FALSE(boxes) << "a whole pack: no frame before its edges";
        } else {
            EXPECT_TRUE(boxes) << "a blocked pack: its boxes while its edges are sampled";
            EXPECT_GT(box_pixels, 200u) << "four boxes' lines";
        }
        app.run();
        EXPECT_EQ(app.v->stats().done + app.v->stats().deferred, app.v->stats().faces);
    }
}

// Zoomed in along a row of four parts, the blocks the view brings near are tessellated again
// at the level it asks for, finer than the model's tolerance where a part fills the screen;
// every part stays watertight. Back at the first view each block is coarsened to its first
// level: the same mesh and the same picture as before. In a mesh of fixed bytes, the meshes
// left behind are moved out of the way (compacted) rather than refused.
TEST(Blocked, ZoomingInRefinesTheBlocksItBringsNearAndZoomingOutCoarsensThem) {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<Pack> packs(4);
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(packs[k].open(shapes[k].data(), uint32_t(shapes[k].size())).ok());
    const Bytes file = blocked(combine_packs(packs, 600.0f));
    std::vector<uint32_t> at_model_tolerance; // each part's triangles with every part at the model's tolerance
    {
        App whole_model;
        whole_model.w = 320, whole_model.h = 240, whole_model.screen_error_px = 0;
        ASSERT_TRUE(whole_model.create().ok());
        ASSERT_TRUE(whole_model.load(file).ok());
        whole_model.run();
        const module::Scene& scene = static_cast<const Core*>(whole_model.v)->scene();
        for (uint32_t s = 0; s < scene.part_count(); ++s) at_model_tolerance.push_back(triangles_of(scene, s));
    }
    for (const bool tight : {false, true}) {
        App app;
        app.w = 320, app.h = 240;
        if (tight) app.capacity.mesh_vertices = 2000, app.capacity.mesh_triangles = 3600, app.capacity.samples = 360; // (the most in use: 1,246, 2,240, 271)
        ASSERT_TRUE(app.create().ok());
        ASSERT_TRUE(app.load(file).ok());
        app.run();
        app.v->act(Action::ViewLeft); // along the row
        app.run();
        const Core& core = *static_cast<const Core*>(app.v);
        const module::Scene& scene = core.scene();
        const float model = app.v->stats().tolerance_mm;
        std::vector<float> levels;
        for (uint32_t b = 0; b < scene.block_count(); ++b) levels.push_back(scene.block(b).tolerance);
        const std::vector<Rgb565> before = app.screen();
        const uint32_t triangles = app.v->stats().triangles;
        for (int cycle = 0; cycle < 3; ++cycle) {
            for (int zoom = 0; zoom < 4; ++zoom) app.v->act(Action::ZoomIn);
            app.run();
            uint32_t finest = 0;
            for (uint32_t b = 1; b < scene.block_count(); ++b)
                if (scene.block(b).tolerance < scene.block(finest).tolerance) finest = b;
            EXPECT_LT(scene.block(finest).tolerance, model) << "a part filling the screen, finer than the model's tolerance";
            // Its mesh too: more triangles than the same part takes at the model's tolerance.
            EXPECT_GT(triangles_of(scene, finest), at_model_tolerance[finest]) << "block " << finest;
            EXPECT_EQ(app.v->stats().failed, 0u);
            uint32_t checked = 0;
            for (uint32_t s = 0; s < scene.part_count(); ++s) {
                if (!whole(scene, s)) continue;
                EXPECT_EQ(open_sides(scene, s), 0u) << "part " << s << " at " << scene.block(scene.part(s).block).tolerance << " mm, cycle " << cycle;
                ++checked;
            }
            EXPECT_GT(checked, 0u);
            for (int zoom = 0; zoom < 4; ++zoom) app.v->act(Action::ZoomOut);
            app.run();
            for (uint32_t b = 0; b < scene.block_count(); ++b) EXPECT_EQ(scene.block(b).tolerance, levels[b]) << "block " << b << ": its first level again";
            EXPECT_EQ(app.v->stats().triangles, triangles);
            EXPECT_EQ(app.screen(), before) << "the same mesh, the same picture";
        }
        EXPECT_EQ(app.count(Event::Kind::PassFailed), 0);
        if (tight) {
            EXPECT_GT(scene.moves(), 0u) << "the meshes left behind were compacted";
        }
    }
}

// A mesh too small for a refined part and everything else: the meshes of the parts the view
// no longer shows (off the screen) make room, and the part zoomed into comes in whole at its
// finer level; zoomed back out, the evicted faces come back.
TEST(Blocked, AFullMeshEvictsWhatTheViewNoLongerShowsToRefineWhatItDoes) {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<Pack> packs(4);
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(packs[k].open(shapes[k].data(), uint32_t(shapes[k].size())).ok());
    const Bytes file = blocked(combine_packs(packs, 600.0f));
    App app;
    app.w = 320, app.h = 240;
    // (Fitted along the row: 725 vertices and 1,206 triangles. Zoomed onto the sphere: its new
    // mesh 1,086 and 2,132 beside its old one, 186 and 352, the torus and the patch 397 and 718:
    // room for those, not for the plate's 142 and 136 as well.)
    app.capacity.mesh_vertices = 1730, app.capacity.mesh_triangles = 3260;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(file).ok());
    app.run();
    app.v->act(Action::ViewLeft); // along the row: the plate nearest, then the sphere
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    const Stats first = app.v->stats();
    const float sphere_level = scene.block(1).tolerance;
    const module::Part plate = scene.part(0);
    std::vector<module::FaceState> first_states;
    for (uint32_t f = plate.first_face; f < plate.first_face + plate.face_count; ++f) first_states.push_back(scene.face(f).state);
    for (int zoom = 0; zoom < 4; ++zoom) app.v->act(Action::ZoomIn); // past the plate, onto the sphere
    app.run();
    EXPECT_LT(scene.block(1).tolerance, first.tolerance_mm) << "the sphere refined";
    EXPECT_EQ(scene.face(scene.part(1).first_face).state, module::FaceState::Done);
    for (uint32_t f = plate.first_face; f < plate.first_face + plate.face_count; ++f) {
        EXPECT_EQ(scene.face(f).state, module::FaceState::Deferred) << "the plate, off the screen, evicted: face " << f;
    }
    EXPECT_EQ(app.v->stats().failed, 0u);
    EXPECT_EQ(app.count(Event::Kind::FaceFailed), 0);
    for (uint32_t s = 0; s < scene.part_count(); ++s) {
        if (!whole(scene, s)) continue;
        EXPECT_EQ(open_sides(scene, s), 0u) << "part " << s;
    }
    for (int zoom = 0; zoom < 4; ++zoom) app.v->act(Action::ZoomOut);
    app.run();
    // Zoomed back out: the sphere coarsened to its first level, and the faces the plate's
    // eviction left to their edges back (the plate at the level the view asks of it now: the
    // pass's floor held it coarser at first), every part whole and watertight.
    EXPECT_EQ(scene.block(1).tolerance, sphere_level);
    EXPECT_EQ(app.v->stats().done, first.done);
    EXPECT_EQ(app.v->stats().failed, 0u);
    for (uint32_t f = plate.first_face; f < plate.first_face + plate.face_count; ++f) {
        EXPECT_EQ(scene.face(f).state, first_states[f - plate.first_face]) << "the plate's face " << f;
    }
    for (uint32_t s = 0; s < scene.part_count(); ++s) {
        if (!whole(scene, s)) continue;
        EXPECT_EQ(open_sides(scene, s), 0u) << "part " << s << ", back";
    }
}

// A model larger than the memory (issue 25): with no room for every block's decoded pack and
// arrays, the largest parts (by their boxes) are opened and the rest left out, drawn as their
// boxes; the Loaded event says what was left out, the parts shown are whole and watertight, and
// the view turns and zooms over both. With the room, nothing is left out.
TEST(Blocked, AModelLargerThanTheMemoryShowsItsLargestPartsAndTheRestAsBoxes) {
    // Three copies of the four shapes (copies have equal boxes: the first of them is opened first).
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    constexpr uint32_t kParts = 12;
    std::vector<Pack> packs(kParts);
    for (uint32_t k = 0; k < kParts; ++k) ASSERT_TRUE(packs[k].open(shapes[k % 4].data(), uint32_t(shapes[k % 4].size())).ok());
    Pack whole_pack;
    const Bytes combined = combine_packs(packs, 150.0f);
    ASSERT_TRUE(whole_pack.open(combined.data(), uint32_t(combined.size())).ok());
    Bytes file;
    std::string error;
    ASSERT_TRUE(make_blocked(whole_pack, {}, {1, BlockStore::Lzma}, file, error)) << error; // a part a block, its own box
    std::vector<uint64_t> in(file.size() / 8 + 1);
    std::memcpy(in.data(), file.data(), file.size());
    geom::PackIndex index;
    ASSERT_TRUE(index.open(in.data(), uint32_t(file.size())).ok());
    uint32_t largest = 0; // the first part with the largest box
    for (uint32_t b = 0; b < index.blocks().size(); ++b) {
        if (module::block_size(index.blocks()[b]) > module::block_size(index.blocks()[largest])) largest = b;
    }
    ASSERT_LT(largest, 4u);
    ModelNeeds needs;
    ASSERT_TRUE(model_needs(in.data(), uint32_t(file.size()), needs).ok());
    // Workspaces from what opens the whole model down, until none opens even the index: each
    // that leaves parts out (some or all of them) checked.
    const size_t base = workspace_bytes();
    bool some_opened = false, all_boxed = false;
    for (size_t room = needs.least_workspace_bytes + needs.pack_memory_bytes - base; room > 1024; room = room * 31 / 32) {
        App app;
        app.w = 320, app.h = 240;
        app.workspace_size = base + room;
        ASSERT_TRUE(app.create().ok());
        const Result r = app.v->load(in.data(), uint32_t(file.size())); // the pack memory at the workspace's end
        if (!r.ok()) {
            EXPECT_EQ(r.status, Status::Full) << text(r);
            EXPECT_NE(text(r).find("bytes needed"), std::string::npos) << text(r);
            break;
        }
        const Event* loaded = app.last(Event::Kind::Loaded);
        ASSERT_NE(loaded, nullptr);
        EXPECT_EQ(loaded->loaded.faces + loaded->loaded.boxed_faces, needs.faces) << "every face held or boxed";
        if (loaded->loaded.boxed_parts == 0) continue; // still the whole model
        const bool some = loaded->loaded.boxed_parts < kParts;
        some_opened = some_opened || some, all_boxed = all_boxed || !some;
        app.run();
        const Core& core = *static_cast<const Core*>(app.v);
        const module::Scene& scene = core.scene();
        if (some) {
            EXPECT_FALSE(scene.block(largest).left_out) << "the largest part is opened first";
        }
        // Each part opened has room for about 24 mesh vertices a face: these shapes' dense faces
        // (a torus or a patch of hundreds) may not all fit. A face that does not is said so and
        // keeps its edges; nothing else fails.
        uint32_t full = 0;
        for (const Event& e : app.events) {
            if (e.kind == Event::Kind::PassFailed) ADD_FAILURE() << text(e.why);
            if (e.kind != Event::Kind::FaceFailed) continue;
            EXPECT_EQ(e.why.status, Status::Full) << text(e.why);
            EXPECT_NE(text(e.why).find("mesh is full"), std::string::npos) << text(e.why);
            ++full;
        }
        EXPECT_EQ(app.v->stats().failed, full);
        EXPECT_EQ(app.v->stats().done + app.v->stats().deferred + app.v->stats().failed, app.v->stats().faces);
        for (uint32_t s = 0; s < scene.part_count(); ++s) {
            EXPECT_EQ(scene.part_left_out(s), scene.block(scene.part(s).block).left_out);
            if (scene.part_left_out(s)) {
                EXPECT_EQ(scene.part(s).face_count, 0u);
            } else if (whole(scene, s)) {
                EXPECT_EQ(open_sides(scene, s), 0u) << "part " << s;
            }
        }
        uint32_t box_pixels = 0;
        for (Rgb565 p : app.screen()) box_pixels += p == rgb565(96, 104, 128);
        EXPECT_GT(box_pixels, 100u) << "the parts left out drawn as boxes";
        for (Action a : {Action::TurnLeft, Action::TiltUp, Action::ZoomIn, Action::ZoomIn, Action::Fit}) {
            app.v->act(a);
            app.run();
        }
        EXPECT_EQ(app.v->stats().done + app.v->stats().deferred + app.v->stats().failed, app.v->stats().faces);
    }
    EXPECT_TRUE(some_opened) << "a workspace that opens the largest parts and leaves the rest out";
    EXPECT_TRUE(all_boxed) << "a workspace that opens only the index: every part a box";
    // With the room the whole model needs: nothing left out.
    App app;
    app.w = 320, app.h = 240;
    app.workspace_size = needs.workspace_bytes + needs.pack_memory_bytes;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.v->load(in.data(), uint32_t(file.size())).ok());
    EXPECT_EQ(app.last(Event::Kind::Loaded)->loaded.boxed_parts, 0u);
}

// The host's mesher (facet-mesh, the render bench's peer meshes) reads a blocked file at the
// tolerance the viewer takes for it: from its parts' exact boxes (the packer's, a little larger
// than the vertices' box the joined pack's header holds), not the joined pack's own box.
TEST(Blocked, TheHostTakesTheViewersDefaultToleranceForABlockedFile) {
    Pack whole;
    const Bytes shape = plate_with_holes();
    ASSERT_TRUE(whole.open(shape.data(), uint32_t(shape.size())).ok());
    PartBox box{};
    for (int k = 0; k < 3; ++k) box.min[k] = whole.header().bbox_min[k] - 3.0f, box.max[k] = whole.header().bbox_max[k] + 5.0f;
    Bytes file;
    std::string error;
    ASSERT_TRUE(make_blocked(whole, {box}, {}, file, error)) << error;
    LoadedPack loaded;
    ASSERT_TRUE(load_pack_bytes(file, loaded, error)) << error;
    Pack joined;
    ASSERT_TRUE(joined.open(loaded.data(), loaded.bytes).ok());
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(file).ok()) << "the blocked file";
    app.run();
    EXPECT_EQ(model_tolerance(loaded, joined), app.v->stats().tolerance_mm);
    EXPECT_NE(default_tolerance(joined), app.v->stats().tolerance_mm) << "the boxes differ, so the test tells";
    // A whole pack: its header's box, as the viewer's.
    LoadedPack plain;
    ASSERT_TRUE(load_pack_bytes(shape, plain, error)) << error;
    App other;
    ASSERT_TRUE(other.create().ok());
    ASSERT_TRUE(other.load(shape).ok());
    other.run();
    EXPECT_EQ(model_tolerance(plain, whole), other.v->stats().tolerance_mm);
}
