// The module through its public API (facet/viewer.h), as an application uses it (app.h).
// The display contract and time slicing: bands and full frames give the same pixels, a step
// without a clock is one piece of work, a step stops at its budget, a DMA's late flush_done().
#include "app.h"

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include <sys/time.h>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

TEST(Viewer, BandsGiveTheSamePixelsAsFullFrames) {
    // The same model and view through every display configuration: full frames (two buffers
    // with a depth buffer each, or one shared depth buffer; scan-out or copy; with a faces
    // layer or without) and bands of several heights with one or two band buffers. The final
    // pictures are identical.
    const Bytes pack = deflate_pack(polygon_and_triangle(40));
    struct Setup {
        uint16_t lines;
        int buffers;
        Flush mode;
        bool depth_each;
        bool layer = false;
    };
    const Setup setups[] = {{120, 2, Flush::Scanout, true}, {120, 2, Flush::Copy, false}, {120, 1, Flush::Copy, true},
                            {16, 2, Flush::Copy, false},    {7, 1, Flush::Copy, false},   {1, 2, Flush::Copy, false},
                            {50, 2, Flush::Copy, false},    {120, 2, Flush::Scanout, true, true}, {120, 1, Flush::Copy, true, true},
                            {120, 2, Flush::Copy, false, true}};
    std::vector<Rgb565> reference;
    for (const Setup& s : setups) {
        App app;
        app.lines = s.lines, app.buffers = s.buffers, app.mode = s.mode, app.faces_layer = s.layer;
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
        EXPECT_EQ(got, reference) << "bands of " << s.lines << ", " << s.buffers << " buffers" << (s.layer ? ", a faces layer" : "");
    }
}

TEST(Viewer, AFrameAtRestDrawsItsEdgesOverTheFacesKeptForTheView) {
    // With a faces layer, a whole frame that changes no face (tangent edges hidden and shown,
    // the end of a drag) sets up no triangle: the layer is copied and the edges drawn over it;
    // a face picked is drawn again over it in its highlight, no other. Its pictures are those
    // of a viewer without the layer, which draws every face again; a change of view or of
    // display mode draws the faces again (into the layer).
    for (const auto& [name, bytes] : {std::pair<const char*, Bytes>{"two blocks", two_blocks()}, {"tube", tube()}}) {
        SCOPED_TRACE(name);
        std::vector<std::vector<Rgb565>> screens[2];
        std::vector<uint32_t> triangles; // the layered viewer's last whole frame, at each look
        for (int layered = 0; layered < 2; ++layered) {
            App app;
            app.faces_layer = layered == 1;
            ASSERT_TRUE(app.create().ok());
            ASSERT_TRUE(app.load(bytes).ok());
            app.run();
            auto look = [&]() {
                app.events.clear();
                app.run();
                screens[layered].push_back(app.screen());
                if (!layered) return;
                const Event* frame = app.last_full_frame();
                triangles.push_back(frame ? frame->frame.triangles + frame->frame.culled : ~0u);
            };
            app.v->key('d'), look();                              // a view change: the faces drawn
            app.v->set_tangent_edges(false), look();              // at rest: edges alone
            app.v->set_tangent_edges(true), look();
            const FaceFacts at = app.v->pick(int16_t(app.w / 2), int16_t(app.h / 2)); // the face at the middle
            ASSERT_TRUE(at.hit);
            ASSERT_TRUE(app.v->select(at.part, at.face).ok());    // picked: it alone drawn again, highlighted
            look();
            app.v->clear_selection(), look();                     // and let go: none
            app.v->key('m'), look();                              // another display mode: the faces drawn
        }
        ASSERT_EQ(screens[0].size(), screens[1].size());
        for (size_t k = 0; k < screens[0].size(); ++k) EXPECT_TRUE(screens[0][k] == screens[1][k]) << "picture " << k;
        EXPECT_FALSE(screens[1][3] == screens[1][4]) << "the pick shows";
        ASSERT_EQ(triangles.size(), 6u);
        EXPECT_GT(triangles[0], 0u) << "a view change draws the faces";
        EXPECT_EQ(triangles[1], 0u) << "tangent edges hidden: the faces kept";
        EXPECT_EQ(triangles[2], 0u) << "and shown again";
        EXPECT_GT(triangles[3], 0u) << "the picked face drawn again";
        EXPECT_LE(triangles[3], triangles[0]);
        if (std::string(name) == "two blocks") {
            EXPECT_LT(triangles[3], triangles[0]) << "and no other";
        }
        EXPECT_EQ(triangles[4], 0u) << "no face highlighted";
        EXPECT_GT(triangles[5], 0u) << "a display mode draws the faces";
    }
}

// While the faces fill in, a draw buffer that lags the other by many faces, or was drawn for
// an earlier state than the other, takes a copy of it (Presenter::catch_up) instead of drawing
// those faces again or a whole frame: the pictures flushed are the ones drawing them gives,
// with far fewer triangles drawn and one whole frame fewer.
TEST(Viewer, ABufferLaggingTheOtherCatchesUpByACopy) {
    // Two layers of squares, the second behind and a little aside (depth decides what shows of
    // each square's two copies), close enough together that each square is over the size a
    // face is tessellated for; a progress frame every 21 faces (42 triangles, over the copy's
    // worth at 160 x 120). (Where faces of different progress frames overlap, a two-buffer
    // display's pictures differed by a pixel or so before the copy: a buffer's first whole
    // frame shows the model at its own moment, and its updates build on it.)
    const Bytes pack = squares(700, 25, {{0, 0, 0}, {0.6f, 0.6f, -1}}, 1.1f);
    std::vector<std::vector<Rgb565>> pictures[2];
    uint32_t updated[2] = {}; // triangles the updates drew
    uint32_t whole[2] = {};   // whole frames
    for (int copy = 0; copy < 2; ++copy) {
        App app;
        app.mode = Flush::Scanout;
        ASSERT_TRUE(app.create(true).ok()); // (two buffers, a depth buffer each)
        static_cast<Core*>(app.v)->presenter().set_catch_up(copy == 1);
        ASSERT_TRUE(app.load(pack).ok());
        size_t seen = 0;
        for (int i = 0; i < 100000 && app.v->step(100000) != Activity::Idle; ++i) {
            for (; seen < app.events.size(); ++seen) {
                const Event& e = app.events[seen];
                if (e.kind != Event::Kind::FrameDone) continue;
                pictures[copy].push_back(app.screen());
                if (!e.frame.full) updated[copy] += e.frame.triangles;
                whole[copy] += e.frame.full;
            }
        }
    }
    ASSERT_GT(pictures[0].size(), 8u) << "frames while the faces fill in";
    ASSERT_EQ(pictures[0].size(), pictures[1].size());
    for (size_t k = 0; k < pictures[0].size(); ++k) EXPECT_TRUE(pictures[0][k] == pictures[1][k]) << "picture " << k;
    EXPECT_GT(updated[0], 1400u) << "the faces came in as updates";
    EXPECT_LT(updated[1] * 3, updated[0] * 2) << "the lagging buffer's faces not drawn again";
    EXPECT_EQ(whole[1] + 1, whole[0]) << "the second buffer's first frame a copy of the first's wireframe, then its faces";
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
        std::map<std::string, int> pieces; // each piece of work by its name
        for (const Event& e : app.events)
            if (e.kind == Event::Kind::WorkBegin) ++pieces[work_name(e.work.what)];
        std::string s;
        for (const auto& [name, n] : pieces) s += std::to_string(n) + " " + name + ", ";
        return s + "pieces; ";
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

// flush_done() from an interrupt (a DMA's completion) and from the application's loop at once,
// as the API allows: a signal handler calls it while the loop steps and calls it too. No call
// is lost nor taken for a later flush: every flush is freed, the viewer comes to rest with the
// picture of a viewer whose flushes complete at once (issue 49: a volatile increment could lose
// one).
namespace {
Viewer* g_interrupted = nullptr;
volatile sig_atomic_t g_pending = 0;
void on_alarm(int) {
    if (g_interrupted && g_pending) g_interrupted->flush_done(); // (the interrupt's completion)
}
} // namespace

TEST(Viewer, FlushDoneFromAnInterruptAndTheLoopAlike) {
    App app;
    app.lines = 30, app.buffers = 2, app.late_done = true;
    ASSERT_TRUE(app.create(false).ok());
    ASSERT_TRUE(app.load(polygon_and_triangle(400)).ok());
    g_interrupted = app.v;
    struct sigaction sa {};
    sa.sa_handler = on_alarm;
    ASSERT_EQ(sigaction(SIGALRM, &sa, nullptr), 0);
    itimerval every{{0, 50}, {0, 50}}; // every 50 us
    ASSERT_EQ(setitimer(ITIMER_REAL, &every, nullptr), 0);
    Activity a = Activity::Busy;
    for (int i = 0; i < 2000000 && a != Activity::Idle; ++i) {
        const uint32_t before = app.flushes;
        a = app.v->step(0);
        if (app.flushes > before) g_pending = 1; // a flush in flight: the interrupt may complete it
        if (a == Activity::Waiting) { // (the loop completes it too)
            app.v->flush_done();
            g_pending = 0;
        }
    }
    const itimerval off{};
    setitimer(ITIMER_REAL, &off, nullptr);
    g_interrupted = nullptr;
    EXPECT_EQ(a, Activity::Idle) << "every flush freed: the viewer comes to rest";
    EXPECT_EQ(app.v->stats().done, 2u);
    App ref;
    ASSERT_TRUE(ref.create().ok());
    ASSERT_TRUE(ref.load(polygon_and_triangle(400)).ok());
    ref.run();
    EXPECT_EQ(app.screen(), ref.screen());
}

// facet in a rectangle of the product's screen (Display::x, y): the same pixels as on a screen
// of the rectangle's size, in full frames and in bands, and nothing outside it; touch in the
// screen's coordinates (a tap on a face picks it, a finger landing outside is the product's).
TEST(Viewer, AViewportInTheProductsScreenDrawsWhatItsOwnScreenWould) {
    constexpr uint16_t W = 200, H = 150, kScreenW = 320, kScreenH = 240, kX = 90, kY = 60;
    constexpr Rgb565 kProduct = 0x1234; // what the product drew around it
    for (const uint16_t lines : {H, uint16_t(40)}) {
        App own, inside;
        own.w = inside.w = W, own.h = inside.h = H, own.lines = inside.lines = lines;
        inside.screen_w = kScreenW, inside.screen_h = kScreenH, inside.at_x = kX, inside.at_y = kY;
        ASSERT_TRUE(own.create().ok());
        ASSERT_TRUE(inside.create().ok());
        std::fill(inside.panel.begin(), inside.panel.end(), kProduct);
        ASSERT_TRUE(own.load(polygon_and_triangle(40)).ok());
        ASSERT_TRUE(inside.load(polygon_and_triangle(40)).ok());
        own.run(), inside.run();
        const std::vector<Rgb565> a = own.screen(), b = inside.screen();
        ASSERT_EQ(b.size(), size_t(kScreenW) * kScreenH);
        uint32_t outside_changed = 0;
        for (uint32_t y = 0; y < kScreenH; ++y) {
            for (uint32_t x = 0; x < kScreenW; ++x) {
                const Rgb565 p = b[size_t(y) * kScreenW + x];
                const bool in = x >= kX && x < kX + W && y >= kY && y < kY + H;
                if (in) ASSERT_EQ(p, a[size_t(y - kY) * W + (x - kX)]) << x << "," << y << " (bands of " << lines << ")";
                else outside_changed += p != kProduct;
            }
        }
        EXPECT_EQ(outside_changed, 0u) << "bands of " << lines;
        // A tap at the middle of the rectangle picks what the middle of its own screen does.
        own.tap(W / 2, H / 2);
        inside.tap(kX + W / 2, kY + H / 2);
        ASSERT_NE(own.last(Event::Kind::Picked), nullptr);
        ASSERT_NE(inside.last(Event::Kind::Picked), nullptr);
        EXPECT_TRUE(own.last(Event::Kind::Picked)->pick.hit) << "the model fills the middle";
        EXPECT_EQ(inside.last(Event::Kind::Picked)->pick.hit, own.last(Event::Kind::Picked)->pick.hit);
        EXPECT_EQ(inside.last(Event::Kind::Picked)->pick.face, own.last(Event::Kind::Picked)->pick.face);
        const int picks = inside.count(Event::Kind::Picked);
        inside.tap(10, 10); // the product's part of the screen
        EXPECT_EQ(inside.count(Event::Kind::Picked), picks);
    }
    // A scan-out display is the whole screen.
    App scanout;
    scanout.mode = Flush::Scanout, scanout.at_x = 8;
    EXPECT_EQ(scanout.create().status, Status::OutOfRange);
}
