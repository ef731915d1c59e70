// Models on the product's storage (facet/storage.h, issue 51): a folder's pack files listed with
// their sizes and face counts; a blocked pack opened from its index with its blocks read as the
// view needs them, never the whole file, with the same pixels as from memory, whether reads end
// at once or later (a DMA's interrupt); bad files said while the others open; a card pulled
// mid-read and put back.
#include "../geom/shapes.h"
#include "app.h"
#include "fake_storage.h"
#include "pack_blocks.h"
#include "pack_io.h"
#include "packs.h"

#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

namespace {

// Copies of the four shapes, a part a block: blocked (LZMA or DEFLATE), or one whole pack.
Bytes parts(uint32_t count, BlockStore store, bool blocked = true) {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<Pack> packs(count);
    for (uint32_t k = 0; k < count; ++k) EXPECT_TRUE(packs[k].open(shapes[k % 4].data(), uint32_t(shapes[k % 4].size())).ok());
    const Bytes combined = combine_packs(packs, 150.0f);
    if (!blocked) return store == BlockStore::Lzma ? lzma_pack(combined) : deflate_pack(combined);
    Pack whole;
    EXPECT_TRUE(whole.open(combined.data(), uint32_t(combined.size())).ok());
    Bytes file;
    std::string error;
    EXPECT_TRUE(make_blocked(whole, {}, {1, store}, file, error)) << error;
    return file;
}

ModelNeeds needs_of(const Bytes& file) {
    std::vector<uint64_t> aligned(file.size() / 8 + 1);
    std::memcpy(aligned.data(), file.data(), file.size());
    ModelNeeds needs{};
    EXPECT_TRUE(model_needs(aligned.data(), uint32_t(file.size()), needs).ok());
    return needs;
}
uint32_t faces_of(const Bytes& file) { return needs_of(file).faces; }

// An app with a clock that makes the storage's deferred reads end, in `workspace` bytes (0: the default).
void start(App& app, FakeStorage& card, size_t workspace = 0) {
    app.w = 320, app.h = 240;
    app.use_clock = true, app.tick_us = 1000;
    app.on_clock = [](void* c) { static_cast<FakeStorage*>(c)->tick(); };
    app.clock_user = &card;
    app.workspace_size = workspace;
    ASSERT_TRUE(app.create().ok());
    card.viewer = app.v;
}

// `file` (the card's /twelve.fpk) opened in the largest workspace that leaves 4 to 11 of its 12
// parts out: how many it left out (0: no such workspace).
uint32_t open_in_part(App& sd, FakeStorage& card, const Bytes& file) {
    const ModelNeeds needs = needs_of(file);
    for (size_t room = needs.least_workspace_bytes + needs.pack_memory_bytes; room > workspace_bytes() + 4096; room = room * 31 / 32) {
        sd = App{};
        start(sd, card, room);
        if (!sd.v->set_storage(card.storage(), "/").ok() || !sd.v->open_model(0).ok()) continue;
        const uint32_t boxed = sd.last(Event::Kind::Loaded)->loaded.boxed_parts;
        if (boxed >= 4 && boxed < 12) return boxed;
    }
    return 0;
}

// The same steps of input on two apps: a turn, zooms toward the middle, a pan, fit.
template <typename F>
void each_view(App& app, F&& after) {
    after("opened");
    app.v->act(Action::TurnLeft);
    app.run();
    after("turned");
    for (int k = 0; k < 6; ++k) app.v->wheel(1);
    app.run();
    after("zoomed");
    app.v->pointer(0, 0, 2), app.v->pointer(40, 10, 2), app.v->pointer(0, 0, 0);
    app.run();
    after("panned");
    app.v->act(Action::Fit);
    app.run();
    after("fitted");
}

} // namespace

TEST(Storage, ABlockedPackFromStorageDrawsWhatItDrawsFromMemoryReadingOneBlockAtATime) {
    for (const bool deferred : {false, true}) {
        for (const BlockStore store : {BlockStore::Lzma, BlockStore::Deflated}) {
            const Bytes file = parts(8, store);
            App mem, sd;
            FakeStorage card;
            card.files["/models/eight.fpk"] = file;
            card.deferred = deferred;
            start(mem, card);
            start(sd, card);
            ASSERT_TRUE(mem.load(file).ok());
            mem.run();
            ASSERT_TRUE(sd.v->set_storage(card.storage(), "/models").ok());
            const Result r = sd.v->open_model(0);
            ASSERT_TRUE(r.ok()) << text(r);
            sd.run();
            std::vector<std::vector<Rgb565>> shots;
            each_view(mem, [&](const char*) { shots.push_back(mem.screen()); });
            size_t k = 0;
            each_view(sd, [&](const char* view) {
                EXPECT_TRUE(sd.screen() == shots[k++]) << view << (deferred ? ", deferred reads" : ", reads at once");
            });
            // Never the whole file at once: the index, then a block a read.
            PackIndex index;
            ASSERT_TRUE(index.open(file.data(), uint32_t(file.size())).ok());
            uint32_t largest = index.header().index_bytes;
            for (const pack::Block& b : index.blocks()) largest = std::max(largest, b.stored_bytes);
            EXPECT_LE(card.largest_read, largest);
            EXPECT_LE(card.largest_read, module::Reader::kChunkBytes) << "a transfer at a time (a piece of work each)";
            EXPECT_LT(card.largest_read, file.size() / 2);
            EXPECT_EQ(sd.v->stats().pack_file_bytes, file.size());
            EXPECT_EQ(sd.count(Event::Kind::PassFailed), 0);
        }
    }
}

// A model larger than the memory from storage: its blocks left out are read in as the view nears
// them (swapped, as from memory), with the same pixels.
TEST(Storage, BlocksLeftOutAreReadFromStorageAsTheViewNearsThem) {
    for (const bool deferred : {false, true}) {
        const Bytes file = parts(12, BlockStore::Lzma);
        // A workspace that leaves parts out from storage (its index takes room there too).
        FakeStorage card;
        card.files["/twelve.fpk"] = file;
        card.deferred = deferred;
        App sd;
        ASSERT_GT(open_in_part(sd, card, file), 0u) << "a workspace that leaves some parts out";
        sd.run();
        const uint32_t reads_at_open = card.reads;
        const module::Scene& scene = static_cast<const Core*>(sd.v)->scene();
        const uint32_t left_at_open = scene.left_out().parts;
        for (int k = 0; k < 10; ++k) sd.v->wheel(1);
        sd.run();
        EXPECT_GT(card.reads, reads_at_open) << "blocks read as the view neared them";
        EXPECT_NE(scene.left_out().parts, left_at_open);
        for (const Event& e : sd.events) { // (a level short of room is no storage's fault)
            if (e.kind == Event::Kind::PassFailed) {
                EXPECT_EQ(e.why.status, Status::Full) << text(e.why);
            }
        }
        EXPECT_EQ(card.open_files, 1u) << "the model's file alone stays open";
    }
}

TEST(Storage, TheChooserListsTheFoldersPackFilesWithSizesAndFaces) {
    FakeStorage card;
    const Bytes blocked = parts(4, BlockStore::Lzma), lzma = parts(3, BlockStore::Lzma, false), deflated = parts(2, BlockStore::Deflated, false);
    card.files["/MODELS/PUMP.FPK"] = blocked;
    card.files["/MODELS/valve body.fpk"] = lzma;
    card.files["/MODELS/Flange.Fpk"] = deflated;
    card.files["/MODELS/readme.txt"] = {1, 2, 3};
    card.files["/MODELS/old/gear.fpk"] = blocked; // (a subfolder: not listed here)
    card.files["/other.fpk"] = blocked;
    App app;
    app.interface = Interface::Full;
    start(app, card);
    ASSERT_TRUE(app.v->set_storage(card.storage(), "MODELS").ok());
    const module::Models& m = static_cast<const Core*>(app.v)->models();
    ASSERT_EQ(m.count(), 3u);
    std::map<std::string, std::pair<uint32_t, uint32_t>> seen;
    for (uint32_t i = 0; i < m.count(); ++i) seen[m.listed(i).name] = {m.listed(i).bytes, m.listed(i).faces};
    EXPECT_EQ(seen["PUMP.FPK"], std::make_pair(uint32_t(blocked.size()), faces_of(blocked)));
    EXPECT_EQ(seen["valve body.fpk"], std::make_pair(uint32_t(lzma.size()), faces_of(lzma)));
    EXPECT_EQ(seen["Flange.Fpk"], std::make_pair(uint32_t(deflated.size()), faces_of(deflated)));
    EXPECT_EQ(card.open_files, 0u) << "every file listed is closed again";
    // Each opens by its row.
    for (uint32_t i = 0; i < m.count(); ++i) {
        const Result r = app.v->open_model(i);
        EXPECT_TRUE(r.ok()) << m.listed(i).name << ": " << text(r);
        app.run();
        EXPECT_EQ(app.v->model_index(), i);
        EXPECT_EQ(app.v->stats().faces + app.last(Event::Kind::Loaded)->loaded.boxed_faces, m.listed(i).faces);
    }
    EXPECT_EQ(app.v->set_storage(card.storage(), "/nowhere").status, Status::NotFound);
}

// A library file (facet-pack --library) on the card: each of its models a row of the chooser,
// named, sized and counted, opened from inside the file; one whose table is damaged is a row
// that says so when opened, and the others still open.
TEST(Storage, ALibraryOnTheCardListsEachOfItsModels) {
    const Bytes a = parts(4, BlockStore::Lzma), b = parts(3, BlockStore::Lzma, false);
    Bytes lib;
    std::string error;
    ASSERT_TRUE(make_library({a, b}, lib, error)) << error;
    Bytes damaged = lib;
    damaged[16 + 8] ^= 0x5A; // (its first entry's name: the table's CRC fails)
    FakeStorage card;
    card.files["/line.flb"] = lib;
    card.files["/old.flb"] = damaged;
    App app;
    start(app, card);
    ASSERT_TRUE(app.v->set_storage(card.storage(), "/").ok());
    ASSERT_EQ(app.v->model_count(), 3u);
    Viewer::ListedModel m[3];
    for (uint32_t i = 0; i < 3; ++i) ASSERT_TRUE(app.v->listed_model(i, m[i]).ok());
    EXPECT_EQ(m[0].bytes, a.size());
    EXPECT_EQ(m[0].faces, faces_of(a));
    EXPECT_EQ(m[1].bytes, b.size());
    EXPECT_EQ(m[1].faces, faces_of(b));
    EXPECT_STREQ(m[2].name, "old.flb");
    for (uint32_t i = 0; i < 2; ++i) {
        const Result r = app.v->open_model(i);
        ASSERT_TRUE(r.ok()) << text(r);
        app.run();
        EXPECT_EQ(app.v->stats().faces + app.last(Event::Kind::Loaded)->loaded.boxed_faces, m[i].faces);
    }
    EXPECT_EQ(app.v->open_model(2).status, Status::Corrupt);
    EXPECT_EQ(app.v->model_index(), 1u) << "the model before is back";
    EXPECT_EQ(app.v->open_file("/line.flb").status, Status::Unsupported) << "a library opens by its rows";
}

// Bad files on a card: each is said (ModelFailed, its row marked), the model open before comes
// back, and the good ones still open.
TEST(Storage, ABadFileIsSaidAndTheOtherModelsStillOpen) {
    FakeStorage card;
    const Bytes good = parts(4, BlockStore::Lzma);
    Bytes truncated = good;
    truncated.resize(good.size() * 2 / 3);
    Bytes corrupt_block = good;
    for (size_t k = corrupt_block.size() - 200; k < corrupt_block.size(); k += 3) corrupt_block[k] ^= 0x5A;
    Bytes whole_cut = parts(3, BlockStore::Lzma, false);
    whole_cut.resize(whole_cut.size() / 2);
    card.files["/a_good.fpk"] = good;
    card.files["/b_truncated.fpk"] = truncated;
    card.files["/c_notapack.fpk"] = Bytes(5000, 0x41);
    card.files["/d_empty.fpk"] = {};
    card.files["/e_cut.fpk"] = whole_cut;
    card.files["/f_badblock.fpk"] = corrupt_block;
    App app;
    start(app, card);
    ASSERT_TRUE(app.v->set_storage(card.storage(), "/").ok());
    const module::Models& m = static_cast<const Core*>(app.v)->models();
    ASSERT_EQ(m.count(), 6u);
    ASSERT_TRUE(app.v->open_model(0).ok());
    app.run();
    for (uint32_t i = 1; i < 5; ++i) {
        const size_t failed = size_t(app.count(Event::Kind::ModelFailed));
        const Result r = app.v->open_model(i);
        EXPECT_FALSE(r.ok()) << m.listed(i).name;
        EXPECT_TRUE(r.status == Status::Corrupt) << m.listed(i).name << ": " << text(r);
        EXPECT_EQ(size_t(app.count(Event::Kind::ModelFailed)), failed + 1);
        EXPECT_EQ(app.v->model_index(), 0u) << "the model open before is back";
        app.run();
        EXPECT_GT(app.v->stats().done, 0u);
    }
    // A corrupt block: found as it is read (the model opens; the block is said and stays a box).
    const Result r = app.v->open_model(5);
    if (r.ok()) {
        app.run();
        EXPECT_GT(app.count(Event::Kind::PassFailed), 0);
    } else {
        EXPECT_EQ(r.status, Status::Corrupt) << text(r);
    }
    EXPECT_TRUE(app.v->open_model(0).ok());
    app.run();
    EXPECT_EQ(card.open_files, 1u);
}

// A card pulled while a block is being read: the read ends as Io (said, the block a box), the
// model on screen stays, nothing hangs; put back, the blocks come in.
TEST(Storage, ACardPulledMidReadLeavesTheModelOnScreenAndPutBackGoesOn) {
    for (const bool deferred : {false, true}) {
        const Bytes file = parts(12, BlockStore::Lzma);
        FakeStorage card;
        card.files["/twelve.fpk"] = file;
        card.deferred = deferred;
        App sd;
        ASSERT_GT(open_in_part(sd, card, file), 0u) << "a workspace that leaves some parts out";
        sd.run();
        const Stats before = sd.v->stats();
        card.pull_after_reads = 0; // the next read finds the card gone
        for (int k = 0; k < 10; ++k) sd.v->wheel(1);
        sd.run(); // (ends: no hang)
        ASSERT_LT(card.pull_after_reads, 0) << "a block was being read";
        EXPECT_TRUE(sd.v->storage_changed(false).ok());
        sd.run();
        const Event* failed = sd.last(Event::Kind::PassFailed);
        ASSERT_NE(failed, nullptr);
        EXPECT_EQ(failed->why.status, Status::Io) << text(failed->why);
        EXPECT_GE(sd.v->stats().done, before.done / 2) << "the model on screen stays";
        // The chooser is empty while the card is out; back, the blocks come in.
        EXPECT_EQ(static_cast<const Core*>(sd.v)->models().count(), 0u);
        card.present = true;
        const size_t failures = size_t(sd.count(Event::Kind::PassFailed));
        const Result back = sd.v->storage_changed(true);
        ASSERT_TRUE(back.ok()) << text(back);
        EXPECT_EQ(static_cast<const Core*>(sd.v)->models().count(), 1u);
        sd.v->act(Action::Fit);
        sd.run();
        for (int k = 0; k < 10; ++k) sd.v->wheel(1);
        sd.run();
        for (size_t k = 0, seen = 0; k < sd.events.size(); ++k) { // (a level short of room is no storage's fault)
            const Event& e = sd.events[k];
            if (e.kind == Event::Kind::PassFailed && ++seen > failures) {
                EXPECT_EQ(e.why.status, Status::Full) << text(e.why);
            }
        }
    }
}

// A read the storage never ends (a driver that lost its interrupt) is given up after 5 s on the
// clock, with Io: load() does not hang.
TEST(Storage, AReadThatNeverEndsIsGivenUp) {
    FakeStorage card;
    card.files["/a.fpk"] = parts(2, BlockStore::Lzma);
    card.deferred = true;
    card.delay = 0xFFFFFFFF;
    App app;
    start(app, card);
    ASSERT_TRUE(app.v->set_storage(card.storage(), "/").ok()); // (its listing's reads given up too)
    const Result r = app.v->open_model(0);
    EXPECT_EQ(r.status, Status::Io) << text(r);
}

TEST(Storage, CallsRefuseWhatTheyCannotTake) {
    FakeStorage card;
    App app;
    start(app, card);
    EXPECT_EQ(app.v->open_file("/a.fpk").status, Status::NotFound);
    EXPECT_EQ(app.v->storage_changed(true).status, Status::NotFound);
    Storage none;
    EXPECT_EQ(app.v->set_storage(none, "/").status, Status::OutOfRange);
    ASSERT_TRUE(app.v->set_storage(card.storage(), "/").ok());
    EXPECT_EQ(app.v->open_file("/missing.fpk").status, Status::NotFound);
    EXPECT_EQ(app.v->open_file(nullptr).status, Status::OutOfRange);
    EXPECT_EQ(app.v->set_storage(card.storage(), std::string(200, 'x').c_str()).status, Status::OutOfRange);
}

// A pack larger than the EVKB's 7 MiB flash region and than the workspace opens from storage:
// its index read, its largest blocks in, the rest boxes; zooming in reads more, a block at a time.
TEST(Storage, APackLargerThanTheFlashAndTheWorkspaceOpensFromStorage) {
    // Parts of long outlines (a 3,000-gon each): a large pack of few faces, as plain blocks.
    const Bytes part = polygon_and_triangle(3000);
    std::vector<Pack> packs(7u * 1024 * 1024 / part.size() + 8);
    for (Pack& p : packs) ASSERT_TRUE(p.open(part.data(), uint32_t(part.size())).ok());
    const Bytes combined = combine_packs(packs, 400.0f);
    Pack whole;
    ASSERT_TRUE(whole.open(combined.data(), uint32_t(combined.size())).ok());
    Bytes file;
    std::string error;
    ASSERT_TRUE(make_blocked(whole, {}, {64 * 1024, BlockStore::Plain}, file, error)) << error;
    ASSERT_GT(file.size(), 7u << 20) << "larger than the EVKB's pack region";
    FakeStorage card;
    card.files["/big.fpk"] = file;
    App app;
    start(app, card, 6u << 20); // (a workspace smaller than the file)
    ASSERT_TRUE(app.v->set_storage(card.storage(), "/").ok());
    const Result r = app.v->open_model(0);
    ASSERT_TRUE(r.ok()) << text(r);
    const Event* loaded = app.last(Event::Kind::Loaded);
    ASSERT_NE(loaded, nullptr);
    EXPECT_GT(loaded->loaded.boxed_parts, 0u) << "larger than the memory: some parts boxes";
    EXPECT_LT(loaded->loaded.boxed_parts, packs.size());
    app.run();
    EXPECT_GT(app.v->stats().done, 0u);
    EXPECT_LE(card.largest_read, module::Reader::kChunkBytes);
    EXPECT_LT(card.bytes_read, file.size()) << "never the whole file";
    const uint64_t read_at_open = card.bytes_read;
    for (int k = 0; k < 12; ++k) app.v->wheel(1);
    app.run();
    EXPECT_GT(card.bytes_read, read_at_open) << "blocks read as the view nears them";
    for (const Event& e : app.events) {
        if (e.kind == Event::Kind::PassFailed) {
            EXPECT_EQ(e.why.status, Status::Full) << text(e.why);
        }
    }
}
