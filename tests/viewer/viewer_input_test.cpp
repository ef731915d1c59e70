// The module through its public API (facet/viewer.h), as an application uses it: bad packs,
// faces over capacity, the display contract (full frames and bands, copy and scan-out, a DMA's
// late flush_done), time slicing, input and the events out.
#include "core.h"
#include "facet/viewer.h"
#include "geom/pack.h"
#include "core/format.h"
#include "pack_io.h"
#include "pack_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <memory>
#include <cstddef>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

using Bytes = std::vector<uint8_t>;

// Two planar faces in one open shell: a polygon of `sides` straight edges around the origin
// (radius 100) and a small triangle beside it.
Bytes polygon_and_triangle(uint32_t sides) {
    PackWriter w;
    const uint32_t plane = w.add_surface(pack::SurfaceType::Plane, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    std::vector<uint32_t> v(sides);
    for (uint32_t i = 0; i < sides; ++i) {
        const double a = 2 * M_PI * i / sides;
        v[i] = w.add_vertex(float(100 * std::cos(a)), float(100 * std::sin(a)), 0);
    }
    const float side = float(2 * 100 * std::sin(M_PI / sides));
    std::vector<uint32_t> e(sides);
    for (uint32_t i = 0; i < sides; ++i) e[i] = w.add_edge({pack::kStraight, 0, side, v[i], v[(i + 1) % sides], 1e-7f, 0});
    uint32_t first = w.coedge_count();
    for (uint32_t i = 0; i < sides; ++i) w.add_coedge(pack::Coedge::make(e[i], false, pack::Seam::None));
    uint32_t loop = w.add_loop({first, sides});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {-100, -100}, {100, 100}});

    const uint32_t a = w.add_vertex(120, 0, 0), b = w.add_vertex(140, 0, 0), c = w.add_vertex(120, 20, 0);
    const uint32_t ab = w.add_edge({pack::kStraight, 0, 20, a, b, 1e-7f, 0}), bc = w.add_edge({pack::kStraight, 0, 28.28f, b, c, 1e-7f, 0}),
                   ca = w.add_edge({pack::kStraight, 0, 20, c, a, 1e-7f, 0});
    first = w.coedge_count();
    for (uint32_t x : {ab, bc, ca}) w.add_coedge(pack::Coedge::make(x, false, pack::Seam::None));
    loop = w.add_loop({first, 3});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {120, 0}, {140, 20}});
    const uint32_t shell = w.add_shell({0, 2, pack::kNoIndex, 0});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

std::string text(const Result& r) {
    char buf[200];
    describe(r, buf, sizeof buf);
    return buf;
}

// An application: its buffers, its display (a panel it copies bands or frames into, or one it
// shows full frames on), its event log.
struct App {
    uint16_t w = 160, h = 120;
    uint16_t lines = 120;
    int buffers = 2;
    Flush mode = Flush::Copy;
    bool late_done = false; // a DMA: flush_done() comes later (call done())
    std::vector<Rgb565> buf[2];
    std::vector<uint16_t> depth[2];
    std::vector<Rgb565> panel;
    const Rgb565* shown = nullptr;
    std::vector<uint64_t> workspace;
    std::vector<uint32_t> file, memory;
    Viewer* v = nullptr;
    std::vector<Event> events;
    uint32_t flushes = 0, pending = 0;
    uint32_t clock_us = 0, tick_us = 0; // a fake clock: each read advances it
    bool use_clock = false;
    bool interface = false; // the model alone (the on-screen interface has tests of its own)

    Capacity capacity;

    Result create(bool depth_per_buffer = true) {
        for (int b = 0; b < 2; ++b) {
            buf[b].assign(size_t(w) * lines, 0);
            depth[b].assign(size_t(w) * lines, 0);
        }
        panel.assign(size_t(w) * h, 0);
        Config cfg;
        cfg.display.width = w, cfg.display.height = h, cfg.display.band_lines = lines;
        cfg.display.buffers[0] = buf[0].data();
        cfg.display.buffers[1] = buffers == 2 ? buf[1].data() : nullptr;
        cfg.display.depth[0] = depth[0].data();
        cfg.display.depth[1] = depth_per_buffer && buffers == 2 ? depth[1].data() : nullptr;
        cfg.display.mode = mode;
        cfg.display.flush = [](void* self, const Area& a, const Rgb565* px) { static_cast<App*>(self)->flushed(a, px); };
        cfg.display.user = this;
        cfg.on_event = [](void* self, const Event& e) { static_cast<App*>(self)->events.push_back(e); };
        cfg.event_user = this;
        if (use_clock) {
            cfg.now_us = [](void* self) {
                App& a = *static_cast<App*>(self);
                return a.clock_us += a.tick_us;
            };
            cfg.clock_user = this;
        }
        cfg.capacity = capacity;
        cfg.interface = interface;
        workspace.assign(workspace_bytes() / 8 + 1, 0);
        Result why;
        v = Viewer::create(cfg, workspace.data(), workspace.size() * 8, &why);
        return why;
    }
    void flushed(const Area& a, const Rgb565* px) {
        ++flushes;
        if (mode == Flush::Scanout) {
            shown = px;
        } else {
            for (uint16_t y = 0; y < a.height; ++y)
                std::memcpy(&panel[size_t(a.y + y) * w + a.x], px + size_t(y) * a.width, size_t(a.width) * 2);
        }
        if (late_done) ++pending;
        else v->flush_done();
    }
    void done() {
        for (; pending; --pending) v->flush_done();
    }
    // A finger down and up at (x, y), and what follows.
    void tap(int x, int y) {
        v->touch(0, int16_t(x), int16_t(y), true);
        v->touch(0, int16_t(x), int16_t(y), false);
        run();
    }
    // A row inside the toolbar button of `a` (-1: none).
    int button_row(const module::Overlay& o, Action a) const {
        for (int y = 0; y < h; ++y)
            if (o.button_at(int16_t(w - 5), int16_t(y)) == a) return y + 5;
        return -1;
    }
    std::vector<Rgb565> screen() const { return mode == Flush::Scanout ? std::vector<Rgb565>(shown, shown + size_t(w) * h) : panel; }
    Result load(const Bytes& pack_file) {
        file.assign(pack_file.size() / 4 + 1, 0);
        std::memcpy(file.data(), pack_file.data(), pack_file.size());
        memory.assign(pack_memory_bytes(file.data(), uint32_t(pack_file.size())) / 4 + 1, 0);
        return v->load(file.data(), uint32_t(pack_file.size()), memory.data(), uint32_t(memory.size() * 4));
    }
    void run() {
        for (int i = 0; i < 100000 && v->step(100000) != Activity::Idle; ++i) done();
        EXPECT_EQ(v->stats().refused, 0u) << "everything drawn was clipped into the rasterizer's range first";
    }
    int count(Event::Kind k) const {
        int n = 0;
        for (const Event& e : events) n += e.kind == k;
        return n;
    }
    const Event* last(Event::Kind k) const {
        for (auto it = events.rbegin(); it != events.rend(); ++it)
            if (it->kind == k) return &*it;
        return nullptr;
    }
};

} // namespace

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
        {"not a pack at all", Bytes(300, 'x'), "no pack here (neither FPK1, FPX1 nor FPZ1)"},
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
    EXPECT_EQ(app.v->load(file.data(), uint32_t(deflated.size()), nullptr, 0).status, Status::Full);
    EXPECT_EQ(app.v->load(file.data(), uint32_t(deflated.size()), small.data(), 64).status, Status::Full);
    EXPECT_GT(pack_memory_bytes(file.data(), uint32_t(deflated.size())), deflated.size());
    // In place, as a board loads it: the file at the start of its pack memory.
    std::vector<uint32_t> region((deflated.size() + pack_memory_bytes(file.data(), uint32_t(deflated.size()))) / 4 + 1);
    std::memcpy(region.data(), deflated.data(), deflated.size());
    EXPECT_TRUE(app.v->load(region.data(), uint32_t(region.size() * 4), region.data(), uint32_t(region.size() * 4)).ok());
}

TEST(Viewer, CreateRefusesMissingOrSmallBuffers) {
    std::vector<uint64_t> ws(workspace_bytes() / 8 + 1);
    std::vector<Rgb565> px(160 * 120);
    std::vector<uint16_t> z(160 * 120);
    auto config = [&]() {
        Config c;
        c.display = {160, 120, 120, {px.data(), nullptr}, {z.data(), nullptr}, Flush::Copy, [](void*, const Area&, const Rgb565*) {}, nullptr};
        return c;
    };
    Result why;
    Config c = config();
    ASSERT_NE(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << text(why);
    EXPECT_EQ(Viewer::create(c, ws.data(), workspace_bytes() / 2, &why), nullptr);
    EXPECT_EQ(why.status, Status::Full);
    EXPECT_EQ(Viewer::create(c, reinterpret_cast<uint8_t*>(ws.data()) + 4, ws.size() * 8 - 8, &why), nullptr);
    EXPECT_NE(text(why).find("aligned"), std::string::npos);
    c = config(), c.display.buffers[0] = nullptr;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr);
    c = config(), c.display.band_lines = 121;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr);
    c = config(), c.display.mode = Flush::Scanout, c.display.band_lines = 16;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "scan-out takes full frames";
    c = config(), c.capacity.face_points = 40000;
    EXPECT_EQ(Viewer::create(c, ws.data(), ws.size() * 8, &why), nullptr) << "a 16-bit arena";
}

TEST(Viewer, BandsGiveTheSamePixelsAsFullFrames) {
    // The same model and view through every display configuration: full frames (two buffers
    // with a depth buffer each, or one shared depth buffer; scan-out or copy) and bands of
    // several heights with one or two band buffers. The final pictures are identical.
    const Bytes pack = deflate_pack(polygon_and_triangle(40));
    struct Setup {
        uint16_t lines;
        int buffers;
        Flush mode;
        bool depth_each;
    };
    const Setup setups[] = {{120, 2, Flush::Scanout, true}, {120, 2, Flush::Copy, false}, {120, 1, Flush::Copy, true},
                            {16, 2, Flush::Copy, false},    {7, 1, Flush::Copy, false},   {1, 2, Flush::Copy, false},
                            {50, 2, Flush::Copy, false}};
    std::vector<Rgb565> reference;
    for (const Setup& s : setups) {
        App app;
        app.lines = s.lines, app.buffers = s.buffers, app.mode = s.mode;
        ASSERT_TRUE(app.create(s.depth_each).ok());
        ASSERT_TRUE(app.load(pack).ok());
        app.run();
        app.v->key('d'); // a view change: every configuration draws it whole
        app.v->key('w');
        app.run();
        const std::vector<Rgb565> got = app.screen();
        if (reference.empty()) {
            reference = got;
            size_t lit = 0;
            for (size_t i = 0; i < got.size(); ++i) lit += got[i] != got[0];
            EXPECT_GT(lit, got.size() / 20) << "the picture shows something";
        }
        EXPECT_EQ(got, reference) << "bands of " << s.lines << ", " << s.buffers << " buffers";
    }
}

TEST(Viewer, WithoutAClockEachStepIsOnePieceOfWork) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(3000)).ok());
    int steps = 0;
    size_t seen = 0;
    while (app.v->step(0) != Activity::Idle && steps < 10000) {
        ++steps;
        int begun = 0;
        for (; seen < app.events.size(); ++seen) begun += app.events[seen].kind == Event::Kind::WorkBegin;
        ASSERT_EQ(begun, 1) << "step " << steps;
    }
    EXPECT_GT(steps, 5) << "sampling, the faces in pieces, frames";
    EXPECT_EQ(app.v->stats().done, 2u) << steps << " steps (" << [&] {
        int k[5] = {};
        for (const Event& e : app.events)
            if (e.kind == Event::Kind::WorkBegin) ++k[int(e.work.what)];
        return std::to_string(k[0]) + " unpack, " + std::to_string(k[1]) + " sampling, " + std::to_string(k[2]) + " face, " +
               std::to_string(k[3]) + " frame, " + std::to_string(k[4]) + " update pieces); ";
    }() << (app.last(Event::Kind::FaceFailed) ? text(app.last(Event::Kind::FaceFailed)->why) : "no face failed");
}

TEST(Viewer, AStepStopsWhenItsBudgetIsSpent) {
    // A clock that advances 50 us at every read: a step goes on with pieces of work while its
    // budget lasts (the step reads the clock once a piece at least: at most budget / 50 + 1
    // pieces), and always does one.
    for (uint32_t budget : {1u, 400u, 2000u}) {
        App a;
        a.use_clock = true, a.tick_us = 50;
        ASSERT_TRUE(a.create().ok());
        ASSERT_TRUE(a.load(polygon_and_triangle(3000)).ok());
        size_t seen = 0;
        int steps = 0, most = 0;
        while (a.v->step(budget) != Activity::Idle && steps < 10000) {
            ++steps;
            int begun = 0;
            for (; seen < a.events.size(); ++seen) begun += a.events[seen].kind == Event::Kind::WorkBegin;
            ASSERT_GE(begun, 1) << "budget " << budget;
            ASSERT_LE(begun, int(budget / 50 + 1)) << "budget " << budget;
            most = std::max(most, begun);
        }
        EXPECT_EQ(a.v->stats().done, 2u);
        if (budget == 1) {
            EXPECT_EQ(most, 1);
        }
        if (budget == 2000) {
            EXPECT_GT(most, 3);
        }
    }
    App b;
    b.use_clock = true, b.tick_us = 50;
    ASSERT_TRUE(b.create().ok());
    ASSERT_TRUE(b.load(polygon_and_triangle(3000)).ok());
    EXPECT_EQ(b.v->step(1'000'000'000), Activity::Idle) << "all of it in one step";
    EXPECT_EQ(b.v->stats().done, 2u);
    App c;
    ASSERT_TRUE(c.create().ok());
    ASSERT_TRUE(c.load(polygon_and_triangle(3000)).ok());
    c.run();
    EXPECT_EQ(b.screen(), c.screen()) << "however the work is cut, the same picture";
}

TEST(Viewer, ADmaDisplayGetsNoDrawingIntoABufferInFlight) {
    // flush_done() comes only when step() says it waits for it (a slow DMA): meanwhile the
    // module draws into no buffer that is being copied, hands over one flush at a time, and
    // the picture comes out whole.
    for (int buffers : {1, 2}) {
        App app;
        app.lines = 30, app.buffers = buffers, app.late_done = true;
        ASSERT_TRUE(app.create(false).ok());
        ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
        int waits = 0;
        Activity a = Activity::Busy;
        for (int i = 0; i < 100000; ++i) {
            const uint32_t before = app.flushes;
            a = app.v->step(0);
            ASSERT_LE(app.pending, 1u) << "one flush in flight at most";
            if (app.flushes > before) {
                // The pixels just handed over: they must stay until flush_done().
                const Rgb565* px = app.buffers == 2 ? app.buf[(app.flushes - 1) % 2].data() : app.buf[0].data();
                const std::vector<Rgb565> copy(px, px + size_t(app.w) * app.lines);
                while ((a = app.v->step(0)) == Activity::Busy) {
                    ASSERT_TRUE(std::equal(copy.begin(), copy.end(), px)) << "drawn into while in flight";
                }
                ASSERT_TRUE(std::equal(copy.begin(), copy.end(), px));
            }
            if (a == Activity::Waiting) ++waits;
            app.done();
            if (a == Activity::Idle) break;
        }
        EXPECT_GT(waits, 0) << buffers << " buffers";
        EXPECT_EQ(a, Activity::Idle);
        EXPECT_EQ(app.v->stats().done, 2u);
        App ref; // the same, copied at once
        ASSERT_TRUE(ref.create().ok());
        ASSERT_TRUE(ref.load(polygon_and_triangle(40)).ok());
        ref.run();
        EXPECT_EQ(app.screen(), ref.screen()) << buffers << " buffers";
    }
}

// Parts placed far from their own origins (an assembly's instances): the view frames the
// placed model, centred and filling the screen, not the parts where their files put them.
TEST(Viewer, AnAssemblyIsFramedWhereItsInstancesPlaceItsParts) {
    PackWriter w;
    const uint32_t plane = w.add_surface(pack::SurfaceType::Plane, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
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

// The display modes, told apart by their pixels: the B-rep edges' colour, the faces' shading,
// the white of hidden-line faces, the background through a wireframe.
TEST(Viewer, DisplayModesDrawFacesAndEdgesAsNamed) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const Rgb565 edge = rgb565(28, 30, 38), white = rgb565(255, 255, 255);
    auto look = [&]() {
        const std::vector<Rgb565> s = app.screen();
        struct {
            int edges = 0, white = 0;
            Rgb565 centre, row_start;
        } r;
        for (Rgb565 p : s) r.edges += p == edge, r.white += p == white;
        // The polygon's middle (a tap there picks it), and the same row at the screen's left edge (background).
        r.centre = s[size_t(app.h / 2) * app.w + app.w / 2 - 10];
        r.row_start = s[size_t(app.h / 2) * app.w];
        return r;
    };
    EXPECT_EQ(app.v->display_mode(), DisplayMode::ShadedEdges);
    const auto shaded_edges = look();
    EXPECT_GT(shaded_edges.edges, 100);
    EXPECT_NE(shaded_edges.centre, shaded_edges.row_start) << "a face over the background";
    app.v->key('m');
    app.run();
    EXPECT_EQ(app.v->display_mode(), DisplayMode::Shaded);
    const auto shaded = look();
    EXPECT_EQ(shaded.edges, 0);
    EXPECT_EQ(shaded.centre, shaded_edges.centre) << "the same shaded face";
    app.v->key('m');
    app.run();
    EXPECT_EQ(app.v->display_mode(), DisplayMode::Wireframe);
    const auto wire = look();
    EXPECT_GT(wire.edges, 100);
    EXPECT_EQ(wire.centre, wire.row_start) << "no face: the background through the polygon";
    app.v->key('m');
    app.run();
    EXPECT_EQ(app.v->display_mode(), DisplayMode::HiddenLine);
    const auto hidden = look();
    EXPECT_GT(hidden.edges, 100);
    const uint32_t r = hidden.centre >> 11, g = (hidden.centre >> 5) & 63, b = hidden.centre & 31;
    EXPECT_TRUE(r >= 24 && g >= 48 && b >= 24) << "paper-white faces, lightly shaded: " << hidden.centre;
    app.v->set_display_mode(DisplayMode::ShadedEdges);
    app.run();
    EXPECT_EQ(app.screen()[size_t(app.h / 2) * app.w + app.w / 2 - 10], shaded_edges.centre);
}

// The on-screen interface through touch: toolbar buttons act (and pick nothing), a tapped face
// is described with its exact values, and with MEAS on a second one gives the relation.
TEST(Viewer, TheToolbarAndTheMeasurementPanelWorkByTouch) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = true;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Overlay& o = core.overlay();
    auto tap = [&](int x, int y) { app.tap(x, y); };
    auto button = [&](Action a) { return app.button_row(o, a); };
    // MODE: the display mode changes, nothing is picked.
    const int picks = app.count(Event::Kind::Picked);
    tap(app.w - 20, button(Action::NextDisplayMode));
    EXPECT_EQ(app.v->display_mode(), DisplayMode::Shaded);
    EXPECT_EQ(app.count(Event::Kind::Picked), picks);
    // The polygon (a plane face) from the top view: described exactly.
    app.v->key('7');
    app.run();
    const module::Transform t = core.camera().transform(core.scene(), 0, app.w, app.h);
    auto screen_of = [&](float x, float y) {
        int32_t p[3] = {int32_t(std::lround(x / core.scene().unit())), int32_t(std::lround(y / core.scene().unit())), 0};
        module::Projected q;
        t.project(p, q);
        return std::pair<int, int>{q.s.x / 16, q.s.y / 16};
    };
    const auto [px, py] = screen_of(-50, 0);
    tap(px, py);
    ASSERT_EQ(app.last(Event::Kind::Picked)->pick.face, 0u);
    ASSERT_EQ(o.line_count(), 1u);
    EXPECT_STREQ(o.line(0), "#0 plane  normal (0.000, 0.000, 1.000)  offset 0.000 mm");
    // MEAS on, then the triangle: the two faces' relation (one plane: parallel, 0 apart).
    tap(app.w - 20, button(Action::Measure));
    EXPECT_TRUE(o.measuring());
    EXPECT_STREQ(o.line(1), "MEAS: tap a second face");
    const auto [tx, ty] = screen_of(125, 5);
    tap(tx, ty);
    ASSERT_EQ(app.last(Event::Kind::Picked)->pick.face, 1u);
    ASSERT_EQ(o.line_count(), 3u);
    EXPECT_STREQ(o.line(2), "parallel planes: distance 0.000 mm");
    // HELP on and off; a tap on nothing clears the selection.
    tap(app.w - 20, button(Action::Help));
    EXPECT_TRUE(o.help());
    tap(app.w - 20, button(Action::Help));
    EXPECT_FALSE(o.help());
    tap(5, app.h - 5);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit);
    EXPECT_EQ(o.line_count(), 0u);
}

TEST(Viewer, KeysGesturesAndPicks) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    auto view = [&]() { return app.last(Event::Kind::ViewChanged)->view; };
    app.v->key('d');
    ASSERT_NE(app.last(Event::Kind::ViewChanged), nullptr);
    const float yaw = view().yaw_deg, fitted = view().zoom; // the dolly the framing chose
    app.v->key(KeyLeft);
    EXPECT_NEAR(view().yaw_deg, yaw - 15, 0.01f);
    app.v->key('+');
    EXPECT_NEAR(view().zoom, 0.8f * fitted, 1e-5f);
    app.v->wheel(-1);
    EXPECT_NEAR(view().zoom, fitted, 1e-5f);
    const int changes = app.count(Event::Kind::ViewChanged);
    app.v->key('%'); // no key of the table
    EXPECT_EQ(app.count(Event::Kind::ViewChanged), changes);
    // One finger: small motions are a tap's; a drag orbits.
    app.v->touch(0, 80, 60, true);
    app.v->touch(0, 83, 60, true);
    EXPECT_EQ(app.count(Event::Kind::ViewChanged), changes) << "within the tap slop";
    app.v->touch(0, 100, 60, true);
    EXPECT_NEAR(view().yaw_deg, yaw - 15 + 20 * 0.5f, 0.01f) << "half a degree a pixel, from where it landed";
    app.v->touch(0, 100, 60, false);
    EXPECT_EQ(app.count(Event::Kind::Picked), 0) << "a drag is no tap";
    // Two fingers apart: zoom in.
    app.v->touch(0, 60, 60, true);
    app.v->touch(1, 100, 60, true);
    const float zoom = view().zoom;
    app.v->touch(1, 140, 60, true);
    EXPECT_LT(view().zoom, zoom);
    app.v->touch(1, 140, 60, false);
    app.v->touch(0, 60, 60, false);
    EXPECT_EQ(app.count(Event::Kind::Picked), 0) << "a pinch is no tap";
    // Back to the fitted view: a tap in the middle picks the polygon, one in a corner nothing.
    app.v->key('f');
    app.run();
    app.v->touch(0, 60, 60, true);
    app.v->touch(0, 60, 60, false);
    ASSERT_EQ(app.count(Event::Kind::Picked), 1);
    EXPECT_TRUE(app.last(Event::Kind::Picked)->pick.hit);
    EXPECT_EQ(app.last(Event::Kind::Picked)->pick.face, 0u);
    app.v->touch(0, 1, 1, true);
    app.v->touch(0, 1, 1, false);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit);
    // A mouse click picks where the pointer is (it starts in the middle).
    app.v->pointer(0, 0, 1);
    app.v->pointer(0, 0, 0);
    EXPECT_EQ(app.count(Event::Kind::Picked), 3);
    EXPECT_TRUE(app.last(Event::Kind::Picked)->pick.hit);
}

TEST(Viewer, LevelsOfDetailRetessellateWithinTheirLimits) {
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(40)).ok());
    app.run();
    const float t0 = app.v->stats().tolerance_mm;
    app.v->key(']');
    app.run();
    EXPECT_NEAR(app.v->stats().tolerance_mm, t0 / 2, t0 * 1e-6f);
    EXPECT_EQ(app.v->stats().pass, 1u);
    EXPECT_EQ(app.count(Event::Kind::Tessellated), 2);
    for (int i = 0; i < 10; ++i) app.v->key(']');
    app.run();
    EXPECT_NEAR(app.v->stats().tolerance_mm, t0 / 8, t0 * 1e-6f) << "no finer than an eighth";
}

// A disc of radius 100 in z = 0 bounded by four quarter circles.
Bytes disc() {
    PackWriter w;
    const uint32_t plane = w.add_surface(pack::SurfaceType::Plane, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    const uint32_t circle = w.add_curve(pack::CurveType::Circle, 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 100});
    const uint32_t v[4] = {w.add_vertex(100, 0, 0), w.add_vertex(0, 100, 0), w.add_vertex(-100, 0, 0), w.add_vertex(0, -100, 0)};
    const uint32_t first = w.coedge_count();
    for (int i = 0; i < 4; ++i) {
        const uint32_t e = w.add_edge({circle, float(M_PI / 2 * i), float(M_PI / 2 * (i + 1)), v[i], v[(i + 1) % 4], 1e-7f, 0});
        w.add_coedge(pack::Coedge::make(e, false, pack::Seam::None));
    }
    const uint32_t loop = w.add_loop({first, 4});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {-100, -100}, {100, 100}});
    const uint32_t shell = w.add_shell({0, 1, pack::kNoIndex, 0});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

TEST(Viewer, ALevelOfDetailWhoseEdgesDoNotFitGoesBackToThePreviousOne) {
    // The pool of edge samples holds the disc's circle at the default level of detail (48
    // samples) but not at a finer one (64): that pass fails and says why, the previous level's
    // samples come back, and the picture stays the previous level's; a coarser one then works.
    App app;
    app.capacity.samples = 60;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(disc()).ok());
    app.run();
    ASSERT_EQ(app.v->stats().done, 1u) << (app.last(Event::Kind::FaceFailed) ? text(app.last(Event::Kind::FaceFailed)->why) : "")
                                       << (app.last(Event::Kind::PassFailed) ? text(app.last(Event::Kind::PassFailed)->why) : "");
    ASSERT_EQ(app.count(Event::Kind::PassFailed), 0);
    const std::vector<Rgb565> before = app.screen();
    const float t0 = app.v->stats().tolerance_mm;
    app.v->key(']');
    app.run();
    ASSERT_EQ(app.count(Event::Kind::PassFailed), 1);
    EXPECT_EQ(app.last(Event::Kind::PassFailed)->why.status, Status::Full);
    EXPECT_NE(text(app.last(Event::Kind::PassFailed)->why).find("edge "), std::string::npos);
    EXPECT_FLOAT_EQ(app.v->stats().tolerance_mm, t0) << "back to the previous level";
    EXPECT_EQ(app.v->stats().done, 1u);
    EXPECT_EQ(app.screen(), before);
    app.v->key('d');
    app.run();
    app.v->key('a');
    app.run();
    EXPECT_EQ(app.screen(), before) << "the previous level's samples and mesh, intact";
    app.v->key('[');
    app.run();
    EXPECT_EQ(app.count(Event::Kind::PassFailed), 1);
    EXPECT_FLOAT_EQ(app.v->stats().tolerance_mm, t0 * 2);
    EXPECT_EQ(app.v->stats().done, 1u);
}

namespace {

// Two closed blocks (100 mm cubes, one solid placed twice: at the origin and 150 mm along x),
// named as a STEP file would name them.
Bytes two_blocks() {
    PackWriter w;
    auto corner = [](int i) { return std::array<float, 3>{float(i & 1) * 100, float((i >> 1) & 1) * 100, float((i >> 2) & 1) * 100}; };
    uint32_t v[8];
    for (int i = 0; i < 8; ++i) v[i] = w.add_vertex(corner(i)[0], corner(i)[1], corner(i)[2]);
    std::map<std::pair<int, int>, uint32_t> edges;
    const uint32_t first_face = w.face_count();
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            float n[3] = {0, 0, 0}, x[3] = {0, 0, 0}, y[3];
            n[axis] = side ? 1.0f : -1.0f;
            x[(axis + 1) % 3] = 1;
            y[0] = n[1] * x[2] - n[2] * x[1], y[1] = n[2] * x[0] - n[0] * x[2], y[2] = n[0] * x[1] - n[1] * x[0];
            float o[3] = {0, 0, 0};
            o[axis] = side ? 100.0f : 0.0f;
            const uint32_t plane = w.add_surface(pack::SurfaceType::Plane, {o[0], o[1], o[2], x[0], x[1], x[2], y[0], y[1], y[2], n[0], n[1], n[2]});
            // The face's corners counter-clockwise about its outward normal.
            std::vector<std::pair<double, int>> around;
            for (int i = 0; i < 8; ++i) {
                if (((i >> axis) & 1) != side) continue;
                const auto c = corner(i);
                const double u = (c[0] - 50) * x[0] + (c[1] - 50) * x[1] + (c[2] - 50) * x[2];
                const double t = (c[0] - 50) * y[0] + (c[1] - 50) * y[1] + (c[2] - 50) * y[2];
                around.push_back({std::atan2(t, u), i});
            }
            std::sort(around.begin(), around.end());
            const uint32_t first = w.coedge_count();
            float lo[2] = {1e9f, 1e9f}, hi[2] = {-1e9f, -1e9f};
            for (int k = 0; k < 4; ++k) {
                const int a = around[k].second, b = around[(k + 1) % 4].second;
                const auto key = std::make_pair(std::min(a, b), std::max(a, b));
                if (!edges.count(key)) edges[key] = w.add_edge({pack::kStraight, 0, 100, v[key.first], v[key.second], 1e-7f, 0});
                w.add_coedge(pack::Coedge::make(edges[key], a != key.first, pack::Seam::None));
                const auto c = corner(a);
                const float uv[2] = {(c[0] - o[0]) * x[0] + (c[1] - o[1]) * x[1] + (c[2] - o[2]) * x[2],
                                     (c[0] - o[0]) * y[0] + (c[1] - o[1]) * y[1] + (c[2] - o[2]) * y[2]};
                for (int j = 0; j < 2; ++j) lo[j] = std::min(lo[j], uv[j]), hi[j] = std::max(hi[j], uv[j]);
            }
            const uint32_t loop = w.add_loop({first, 4});
            w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {lo[0], lo[1]}, {hi[0], hi[1]}});
        }
    }
    const uint32_t shell = w.add_shell({first_face, 6, pack::kNoIndex, 1});
    w.name_shell(shell, "block");
    w.name_instance(w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}), "block_a");
    w.name_instance(w.add_instance({shell, {1, 0, 0, 150, 0, 1, 0, 0, 0, 0, 1, 0}}), "");
    w.set_model_name("two blocks");
    return w.finish();
}

// The screen box of one instance's faces (pixels), from the camera; face: one of them only.
std::array<int, 4> box_of(const Core& core, uint32_t instance, uint16_t w, uint16_t h, uint32_t face = ~0u) {
    const module::Transform t = core.camera().transform(core.scene(), instance, w, h);
    int l = INT32_MAX, top = INT32_MAX, r = INT32_MIN, b = INT32_MIN;
    for (uint32_t f = 0; f < 6; ++f) {
        if (face != ~0u && f != face) continue;
        const module::FaceInfo& F = core.scene().face(f);
        for (uint32_t k = 0; k < F.vertex_count; ++k) {
            module::Projected p;
            t.project(core.scene().vertices()[F.first_vertex + k].p, p);
            l = std::min(l, p.s.x / 16), r = std::max(r, p.s.x / 16), top = std::min(top, p.s.y / 16), b = std::max(b, p.s.y / 16);
        }
    }
    return {l, top, r, b};
}

} // namespace

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

// The parts list by touch: PART opens it, a tap on a name chooses the part (highlighted), a tap
// on its box hides it (gone from the screen, not pickable), ISOL shows it alone, ALL shows all.
TEST(Viewer, ThePartsListHidesShowsAndIsolatesByTouch) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = true;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7'); // from the top: the blocks side by side
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Overlay& o = core.overlay();
    auto tap = [&](int x, int y) { app.tap(x, y); };
    auto button = [&](Action a) { return app.button_row(o, a); };
    const std::vector<Rgb565> both = app.screen();
    const auto second = box_of(core, 1, app.w, app.h);
    const int cx = (second[0] + second[2]) / 2, cy = (second[1] + second[3]) / 2;
    tap(app.w - 20, button(Action::Parts));
    ASSERT_TRUE(o.parts_open());
    const Area panel = o.parts_panel();
    EXPECT_LT(panel.x + panel.width, second[0]) << "the list leaves the second block in view";
    const int row1 = panel.y + module::Overlay::kRow + module::Overlay::kRow + module::Overlay::kRow / 2; // the second row
    tap(60, row1);
    EXPECT_EQ(app.v->chosen_part(), 1u);
    const Rgb565 magenta = app.screen()[size_t(cy) * app.w + cx];
    EXPECT_NE(magenta, both[size_t(cy) * app.w + cx]) << "the chosen part is highlighted";
    tap(10, row1); // its box: hidden
    EXPECT_FALSE(app.v->part(1).shown);
    const std::vector<Rgb565> hidden = app.screen();
    EXPECT_NE(hidden[size_t(cy) * app.w + cx], magenta);
    app.v->touch(0, int16_t(cx), int16_t(cy), true);
    app.v->touch(0, int16_t(cx), int16_t(cy), false);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit) << "a hidden part is not picked";
    // ISOL with the first part chosen: the second stays hidden, ALL brings it back.
    tap(60, row1 - module::Overlay::kRow);
    EXPECT_EQ(app.v->chosen_part(), 0u);
    tap(panel.width / 2, panel.y + panel.height - 5);
    EXPECT_TRUE(app.v->part(0).shown);
    EXPECT_FALSE(app.v->part(1).shown);
    tap(panel.width - 5, panel.y + panel.height - 5);
    EXPECT_TRUE(app.v->part(1).shown);
    tap(60, row1 - module::Overlay::kRow); // a second tap on the chosen name lets it go
    EXPECT_EQ(app.v->chosen_part(), ~0u);
    tap(app.w - 20, button(Action::Parts));
    EXPECT_FALSE(o.parts_open());
    EXPECT_EQ(app.screen(), both) << "everything as it was";
}

// A section: across x through the middle cuts the second block away; moved into the first, the
// inside of the cut solid shows in the cap colour; the slider moves the plane; the cut part is
// not picked.
TEST(Viewer, ASectionCutsTheModelAndShowsTheSolidsInside) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272, app.interface = true;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7');
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const std::vector<Rgb565> whole = app.screen();
    const auto second = box_of(core, 1, app.w, app.h);
    const int cx = (second[0] + second[2]) / 2, cy = (second[1] + second[3]) / 2;
    app.v->key('c'); // no face picked: across x, through the model's middle (x = 125)
    app.run();
    ASSERT_TRUE(app.v->section().on);
    EXPECT_FLOAT_EQ(app.v->section().normal[0], 1.0f);
    EXPECT_NEAR(app.v->section().offset_mm, 125.0f, 0.01f);
    const std::vector<Rgb565> cut = app.screen();
    EXPECT_NE(cut[size_t(cy) * app.w + cx], whole[size_t(cy) * app.w + cx]) << "the second block is cut away";
    app.v->touch(0, int16_t(cx), int16_t(cy), true);
    app.v->touch(0, int16_t(cx), int16_t(cy), false);
    EXPECT_FALSE(app.last(Event::Kind::Picked)->pick.hit) << "what is cut away is not picked";
    // Into the first block, seen from the isometric view: its inside in the cap colour.
    app.v->set_section({true, {1, 0, 0}, 50});
    app.v->key('0');
    app.run();
    const Rgb565 cap = rgb565(205, 70, 60); // painter.cpp's kCap, flat
    const std::vector<Rgb565> iso = app.screen();
    const long caps = std::count(iso.begin(), iso.end(), cap);
    EXPECT_GT(caps, 500) << "the inside of the cut block";
    // The other half kept (the plane x = 50 cutting away x < 50): the eye (isometric, at +x) is
    // on the kept side, where the block's own front faces hide all its back faces: they are
    // skipped as without a section (a clipped face: a triangle or two more).
    app.v->set_section({false, {1, 0, 0}, 0});
    app.run();
    const uint32_t front_only = app.last(Event::Kind::FrameDone)->frame.triangles;
    app.v->set_section({true, {-1, 0, 0}, -50});
    app.run();
    const std::vector<Rgb565> kept = app.screen();
    EXPECT_EQ(std::count(kept.begin(), kept.end(), cap), 0) << "no inside shows from the kept side";
    EXPECT_LE(app.last(Event::Kind::FrameDone)->frame.triangles, front_only + 4);
    app.v->set_section({true, {1, 0, 0}, 50});
    app.run();
    EXPECT_EQ(app.screen(), iso);
    // The slider: a finger on it at the top puts the plane at the model's far end, dragged to
    // the bottom at its near end.
    const Area s = core.overlay().slider();
    ASSERT_GT(s.width, 0);
    app.v->touch(0, int16_t(s.x + s.width / 2), int16_t(s.y + 2), true);
    const float hi = app.v->section().offset_mm;
    app.v->touch(0, int16_t(s.x + s.width / 2), int16_t(s.y + s.height - 2), true);
    app.v->touch(0, int16_t(s.x + s.width / 2), int16_t(s.y + s.height - 2), false);
    const float lo = app.v->section().offset_mm;
    const float radius = 0.5f * std::sqrt(250.0f * 250 + 100 * 100 + 100 * 100);
    EXPECT_NEAR(hi, 125 + radius, 0.5f);
    EXPECT_NEAR(lo, 125 - radius, 0.5f);
    EXPECT_EQ(app.count(Event::Kind::Picked), 1) << "a slide is no tap";
    // Off again (after a plane of the application's, c turns it off).
    app.v->key('c');
    app.run();
    EXPECT_FALSE(app.v->section().on);
    app.v->key('7');
    app.run();
    EXPECT_EQ(app.screen(), whole);
}

namespace {

// An open tube: one cylinder face (radius 50 mm, 100 mm tall about z), its two circles and its
// seam; no B-rep edge runs along its sides.
Bytes tube() {
    PackWriter w;
    constexpr float kTwoPi = 6.28318530718f;
    const uint32_t cylinder = w.add_surface(pack::SurfaceType::Cylinder, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 50});
    const uint32_t low = w.add_curve(pack::CurveType::Circle, 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 50});
    const uint32_t high = w.add_curve(pack::CurveType::Circle, 3, {0, 0, 100, 1, 0, 0, 0, 1, 0, 50});
    const uint32_t v0 = w.add_vertex(50, 0, 0), v1 = w.add_vertex(50, 0, 100);
    const uint32_t e_low = w.add_edge({low, 0, kTwoPi, v0, v0, 1e-7f, 0});
    const uint32_t e_high = w.add_edge({high, 0, kTwoPi, v1, v1, 1e-7f, 0});
    const uint32_t e_seam = w.add_edge({pack::kStraight, 0, 100, v0, v1, 1e-7f, 0});
    // Counter-clockwise in (u, v): along the bottom, up the seam at u = 2 pi, back along the
    // top, down the seam at u = 0.
    const uint32_t first = w.coedge_count();
    w.add_coedge(pack::Coedge::make(e_low, false, pack::Seam::None));
    w.add_coedge(pack::Coedge::make(e_seam, false, pack::Seam::UHigh));
    w.add_coedge(pack::Coedge::make(e_high, true, pack::Seam::None));
    w.add_coedge(pack::Coedge::make(e_seam, true, pack::Seam::ULow));
    const uint32_t loop = w.add_loop({first, 4});
    const uint32_t face = w.add_face({cylinder, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {0, 0}, {kTwoPi, 100}});
    w.add_instance({w.add_shell({face, 1, pack::kNoIndex, 0}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    w.set_model_name("tube");
    return w.finish();
}

} // namespace

// Hidden line draws a curved face's outline, which no B-rep edge gives: the tube seen from the
// front in a parallel view has its two sides as lines, at its leftmost and rightmost points,
// all the way from its bottom to its top; shaded with edges, those columns have none.
TEST(Viewer, HiddenLineDrawsTheOutlinesOfCurvedFaces) {
    App app;
    app.w = 320, app.h = 240, app.lines = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(tube()).ok());
    app.run();
    app.v->key('1'); // the front: looking along +y, z up
    app.v->key('5'); // parallel (during the glide: the front view stays its end)
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    ASSERT_TRUE(core.camera().view().ortho);
    const module::FaceInfo& F = core.scene().face(0);
    ASSERT_GT(F.triangle_count, 20u);
    const auto [l, top, r, b] = box_of(core, 0, app.w, app.h, 0);
    ASSERT_TRUE(l >= 2 && top >= 0 && r < app.w - 2 && b < app.h) << "the tube on the screen";
    ASSERT_GT(r - l, 60);
    ASSERT_GT(b - top, 60);
    const Rgb565 ink = rgb565(28, 30, 38); // painter.cpp's kEdgeColour
    // Rows strictly between the circles (seen edge-on: the top and bottom lines): how many have
    // an outline pixel within two pixels of each side.
    auto sides = [&](const std::vector<Rgb565>& px) {
        int left = 0, right = 0;
        for (int y = top + 3; y <= b - 3; ++y) {
            bool at_l = false, at_r = false;
            for (int dx = -2; dx <= 2; ++dx) {
                at_l |= px[size_t(y) * app.w + size_t(l + dx)] == ink;
                at_r |= px[size_t(y) * app.w + size_t(r + dx)] == ink;
            }
            left += at_l, right += at_r;
        }
        return std::array<int, 2>{left, right};
    };
    const int rows = b - top - 5;
    const auto shaded = sides(app.screen());
    EXPECT_EQ(shaded[0], 0) << "shaded with edges: no outline";
    EXPECT_EQ(shaded[1], 0);
    app.v->key('m'), app.v->key('m'), app.v->key('m');
    app.run();
    ASSERT_EQ(app.v->display_mode(), DisplayMode::HiddenLine);
    const std::vector<Rgb565> hidden = app.screen();
    const auto outlined = sides(hidden);
    EXPECT_EQ(outlined[0], rows) << "the left side, every row";
    EXPECT_EQ(outlined[1], rows) << "the right side, every row";
    // And nowhere else between them: the middle columns hold no ink below the top circle.
    long inside = 0;
    for (int y = top + 3; y <= b - 3; ++y)
        for (int x = l + 4; x <= r - 4; ++x) inside += hidden[size_t(y) * app.w + size_t(x)] == ink;
    EXPECT_EQ(inside, 0);
}

// See-through: the chosen part solid, the others screen-door (every other pixel shows what is
// behind them).
TEST(Viewer, SeeThroughDrawsTheOtherPartsAsAScreenDoor) {
    App app;
    app.w = 480, app.h = 272, app.lines = 272;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(two_blocks()).ok());
    app.run();
    app.v->key('7');
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const std::vector<Rgb565> solid = app.screen();
    ASSERT_TRUE(app.v->show_part(1, false).ok());
    app.run();
    const std::vector<Rgb565> without = app.screen();
    ASSERT_TRUE(app.v->show_part(1, true).ok());
    app.v->choose_part(0);
    app.v->set_display_mode(DisplayMode::SeeThrough);
    app.run();
    const std::vector<Rgb565> door = app.screen();
    // Inside the top face and inside the bottom face's outline seen through it (the edges, lines,
    // are drawn whole).
    const auto top = box_of(core, 1, app.w, app.h, 5), bottom = box_of(core, 1, app.w, app.h, 4);
    const std::array<int, 4> b = {std::max(top[0], bottom[0]), std::max(top[1], bottom[1]), std::min(top[2], bottom[2]),
                                  std::min(top[3], bottom[3])};
    int face = 0, behind = 0, n = 0;
    for (int y = b[1] + 3; y < b[3] - 3; ++y) {
        for (int x = b[0] + 3; x < b[2] - 3; ++x, ++n) {
            const size_t i = size_t(y) * app.w + x;
            face += door[i] == solid[i];
            behind += door[i] == without[i];
            EXPECT_EQ(door[i], ((x ^ y) & 1) ? without[i] : solid[i]) << x << "," << y;
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(n, 1000);
    EXPECT_NEAR(double(face) / n, 0.5, 0.02);
    EXPECT_NEAR(double(behind) / n, 0.5, 0.02);
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
    app.v->set_display_mode(DisplayMode::Shaded); // faces only: their pixels are the model's
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
