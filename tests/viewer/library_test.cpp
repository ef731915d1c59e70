// Several models on the device: a library read in place, its models opened in turn in the
// same memory, a corrupt one reported while the others still open, the chooser of facet's
// interface, and unloading.
#include "app.h"
#include "assembly.h"
#include "geom/library.h"

namespace facet::test {
namespace {

// A library of these model files, 8-byte aligned, and the pack memory the largest needs.
struct Lib {
    std::vector<uint64_t> words;
    uint32_t bytes = 0;
    std::vector<uint32_t> memory;
    explicit Lib(const std::vector<Bytes>& files) {
        Bytes out;
        std::string error;
        EXPECT_TRUE(geom::make_library(files, out, error)) << error;
        words.assign(out.size() / 8 + 1, 0);
        std::memcpy(words.data(), out.data(), out.size());
        bytes = uint32_t(out.size());
        uint32_t most = 0;
        for (const Bytes& f : files) most = std::max(most, pack_memory_bytes(f.data(), uint32_t(f.size())));
        memory.assign(most / 4 + 1, 0);
    }
    uint8_t* data() { return reinterpret_cast<uint8_t*>(words.data()); }
    // The first byte of model i's file, inside the library.
    uint8_t* file(uint32_t i) {
        LibraryModel m;
        EXPECT_TRUE(library_model(data(), bytes, i, m).ok());
        return data() + (static_cast<const uint8_t*>(m.file) - data());
    }
};

TEST(Library, ModelsOpenInTurnInTheSameMemoryAndACorruptOneIsReportedWhileTheOthersOpen) {
    const std::vector<Bytes> files = {disc(), squares(6, 3), geom::lzma_pack(polygon_and_triangle(7)), blocked(assembly())};
    Lib lib(files);
    ASSERT_EQ(library_count(lib.data(), lib.bytes), 4u);
    // The third model's stream damaged in the middle: the table still reads, that model does not.
    lib.file(2)[files[2].size() / 2] ^= 0x5A;
    App a;
    ASSERT_TRUE(a.create().ok());
    ASSERT_EQ(text(a.v->set_library(lib.data(), lib.bytes, lib.memory.data(), uint32_t(lib.memory.size() * 4))), "ok");
    const uint32_t faces[] = {1, 6, 2, 0};
    uint32_t assembly_faces = 0;
    {
        geom::LoadedPack p;
        std::string error;
        ASSERT_TRUE(geom::load_pack_bytes(files[3], p, error)) << error;
        geom::Pack pack;
        ASSERT_TRUE(pack.open(p.data(), p.bytes).ok());
        assembly_faces = uint32_t(pack.faces().size());
    }
    size_t peak = 0;
    for (uint32_t round = 0; round < 2; ++round) { // each model twice: the same memory each time
        for (uint32_t i : {0u, 1u, 3u}) {
            ASSERT_EQ(text(a.v->open_model(i)), "ok") << "model " << i;
            a.run();
            EXPECT_EQ(a.v->model_index(), i);
            EXPECT_EQ(a.v->stats().faces, i == 3 ? assembly_faces : faces[i]);
            EXPECT_EQ(a.v->stats().failed, 0u);
            if (i == 3 && round == 0) {
                peak = a.v->stats().workspace_peak_bytes;
            } else if (i == 3) {
                EXPECT_EQ(a.v->stats().workspace_peak_bytes, peak) << "the same model takes the same memory again";
            }
        }
    }
    // The corrupt model: said, and the one open before opens again.
    const size_t events = a.events.size();
    const Result r = a.v->open_model(2);
    EXPECT_EQ(r.status, Status::Corrupt) << text(r);
    const Event* failed = a.last(Event::Kind::ModelFailed);
    ASSERT_NE(failed, nullptr);
    EXPECT_GT(size_t(failed - a.events.data()), events - 1);
    EXPECT_EQ(failed->model.index, 2u);
    EXPECT_EQ(failed->why.status, Status::Corrupt);
    EXPECT_TRUE(static_cast<Core*>(a.v)->overlay().broken(2)) << "the chooser says it cannot be opened";
    EXPECT_FALSE(static_cast<Core*>(a.v)->overlay().broken(1));
    a.run();
    EXPECT_EQ(a.v->model_index(), 3u);
    EXPECT_EQ(a.v->stats().faces, assembly_faces);
    EXPECT_GT(a.v->stats().triangles, 0u);
    // And the others still open after it.
    ASSERT_EQ(text(a.v->open_model(1)), "ok");
    a.run();
    EXPECT_EQ(a.v->stats().faces, 6u);
    EXPECT_EQ(a.v->open_model(4).status, Status::OutOfRange);
    EXPECT_EQ(a.v->model_index(), 1u);
}

TEST(Library, ABadTableIsRefusedWhole) {
    Lib lib({disc(), squares(4, 2)});
    App a;
    ASSERT_TRUE(a.create().ok());
    EXPECT_EQ(a.v->open_model(0).status, Status::NotFound); // no library set
    EXPECT_EQ(a.v->set_library(lib.data() + 4, lib.bytes - 4).status, Status::Corrupt);
    EXPECT_EQ(a.v->set_library(lib.data(), 12).status, Status::Corrupt);           // shorter than its head
    EXPECT_EQ(a.v->set_library(lib.data(), lib.bytes - 1).status, Status::Corrupt); // shorter than it says
    {
        // A total of 20 bytes, under its own table: said so (it read as larger than the bytes given).
        Lib small({disc(), squares(4, 2)});
        uint32_t total = 20;
        std::memcpy(small.data() + offsetof(pack::LibraryHeader, total_bytes), &total, 4);
        const Result r = a.v->set_library(small.data(), small.bytes);
        EXPECT_EQ(r.status, Status::Corrupt);
        EXPECT_STREQ(r.what, "the library's total is smaller than its table of entries");
    }
    lib.data()[16 + 4] ^= 1;                                                         // an entry's size: the table's CRC
    EXPECT_EQ(a.v->set_library(lib.data(), lib.bytes).status, Status::Corrupt);
    EXPECT_EQ(library_count(lib.data(), lib.bytes), 0u);
    LibraryModel m;
    EXPECT_EQ(library_model(lib.data(), lib.bytes, 0, m).status, Status::Corrupt);
    EXPECT_EQ(m.file, nullptr);
    // A pack is no library, and a library is no pack: load() says so.
    Lib good({disc()});
    EXPECT_EQ(library_count(disc().data(), uint32_t(disc().size())), 0u);
    EXPECT_NE(a.v->load(good.data(), good.bytes).status, Status::Ok);
}

// The EVKB's screen with facet's own interface (its chooser), the library set, its first model in.
void open_first(App& a, Lib& lib) {
    a.w = 480, a.h = 272, a.lines = 272;
    a.interface = Interface::Full;
    ASSERT_TRUE(a.create().ok());
    ASSERT_TRUE(a.v->set_library(lib.data(), lib.bytes, lib.memory.data(), uint32_t(lib.memory.size() * 4)).ok());
    ASSERT_TRUE(a.v->open_model(0).ok());
    a.run();
}

TEST(Library, TheChooserListsTheModelsAndATapOpensOne) {
    Lib lib({disc(), squares(6, 3), squares(2, 2)});
    App a;
    open_first(a, lib);
    Core& core = *static_cast<Core*>(a.v);
    const module::Overlay& o = core.overlay();
    // The model's name in the status bar opens the chooser (for a person with only the screen).
    ASSERT_TRUE(o.name_at(10, 5));
    a.tap(10, 5);
    ASSERT_TRUE(o.models_open());
    EXPECT_EQ(a.count(Event::Kind::Picked), 0);
    a.tap(10, 5);
    EXPECT_FALSE(o.models_open());
    a.v->act(Action::Models);
    ASSERT_TRUE(o.models_open());
    a.run();
    const auto before = a.screen();
    // The second row: model 2.
    const Area panel = o.parts_panel();
    const int x = panel.x + 30, y = panel.y + module::Overlay::kRow * 2 + module::Overlay::kRow / 2;
    EXPECT_EQ(o.models_at(int16_t(x), int16_t(y)).kind, module::Overlay::PartsHit::Kind::Row);
    EXPECT_EQ(o.models_at(int16_t(x), int16_t(y)).part, 1u);
    EXPECT_EQ(o.models_at(int16_t(x), int16_t(panel.y + 2)).kind, module::Overlay::PartsHit::Kind::Panel); // the header
    a.tap(x, y);
    EXPECT_EQ(a.v->model_index(), 1u);
    EXPECT_EQ(a.v->stats().faces, 6u);
    EXPECT_FALSE(o.models_open()) << "the chooser closes on the model it opened";
    EXPECT_EQ(a.count(Event::Kind::Picked), 0) << "a tap on the chooser picks nothing";
    EXPECT_NE(a.screen(), before);
    EXPECT_FALSE(o.broken(1));
    // A tap on the open model's row leaves it be.
    a.v->act(Action::Models);
    a.tap(x, y);
    EXPECT_EQ(a.v->model_index(), 1u);
}

TEST(Library, AChooserOfMoreModelsThanRowsScrollsToEach) {
    std::vector<Bytes> files;
    for (uint32_t k = 1; k <= 30; ++k) files.push_back(squares(k, 10)); // model k: k faces
    Lib lib(files);
    App a;
    open_first(a, lib);
    const module::Overlay& o = static_cast<Core*>(a.v)->overlay();
    a.v->act(Action::Models);
    const uint32_t rows = o.model_rows();
    ASSERT_GT(rows, 2u);
    ASSERT_LT(rows, 30u) << "the test wants more models than rows";
    const Area panel = o.parts_panel();
    const int down_x = panel.width - 5, header_y = panel.y + 5;
    // Down until the last model shows in the last row, then open it.
    for (int i = 0; i < 30 && o.models_at(30, int16_t(panel.y + module::Overlay::kRow * int(rows) + 5)).part != 29; ++i) a.tap(down_x, header_y);
    const int last_row_y = panel.y + module::Overlay::kRow * int(rows) + 5;
    ASSERT_EQ(o.models_at(30, int16_t(last_row_y)).part, 29u);
    a.tap(30, last_row_y);
    EXPECT_EQ(a.v->model_index(), 29u);
    EXPECT_EQ(a.v->stats().faces, 30u);
    // Opened again, the chooser shows the open model.
    a.v->act(Action::Models);
    bool shown = false;
    for (uint32_t r = 0; r < rows; ++r) shown |= o.models_at(30, int16_t(panel.y + module::Overlay::kRow * int(r + 1) + 5)).part == 29;
    EXPECT_TRUE(shown);
}

TEST(Library, UnloadDropsTheModelAndALoadAfterItTakesTheSameMemory) {
    App a;
    ASSERT_TRUE(a.create().ok());
    ASSERT_TRUE(a.load(blocked(assembly())).ok());
    a.run();
    const Stats first = a.v->stats();
    a.v->unload();
    EXPECT_EQ(a.v->stats().faces, 0u);
    EXPECT_EQ(a.v->part_count(), 0u);
    EXPECT_EQ(a.v->step(1000), Activity::Idle);
    a.v->act(Action::Fit); // nothing to do, nothing broken
    EXPECT_EQ(a.v->select(0, 0).status, Status::NotFound);
    ASSERT_TRUE(a.load(blocked(assembly())).ok());
    a.run();
    EXPECT_EQ(a.v->stats().faces, first.faces);
    EXPECT_EQ(a.v->stats().triangles, first.triangles);
    EXPECT_EQ(a.v->stats().workspace_peak_bytes, first.workspace_peak_bytes);
}

} // namespace
} // namespace facet::test
