// Blocks and the view (issue 25): a pass takes the blocks largest on the screen first; a model
// larger than the memory opens with its largest blocks and the rest as boxes, and zooming into a
// part left out brings its block in (decoded into the pack memory in place of blocks the view
// no longer shows), watertight at the view's level, and zooming into another swaps again, the
// decoded blocks never overlapping nor leaving the workspace.
#include "../geom/shapes.h"
#include "app.h"
#include "loader.h"
#include "pack_blocks.h"
#include "watertight.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

namespace {

constexpr Rgb565 kBoxColour = rgb565(96, 104, 128); // (painter.cpp)

// Three copies of the four shapes, a part a block (LZMA).
struct Model {
    std::vector<uint64_t> file;
    uint32_t bytes = 0;
};
Model twelve_parts() {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<Pack> packs(12);
    for (uint32_t k = 0; k < 12; ++k) EXPECT_TRUE(packs[k].open(shapes[k % 4].data(), uint32_t(shapes[k % 4].size())).ok());
    Pack whole_pack;
    const Bytes combined = combine_packs(packs, 150.0f);
    EXPECT_TRUE(whole_pack.open(combined.data(), uint32_t(combined.size())).ok());
    Bytes file;
    std::string error;
    EXPECT_TRUE(make_blocked(whole_pack, {}, {1, BlockStore::Lzma}, file, error)) << error;
    Model m;
    m.file.assign(file.size() / 8 + 1, 0);
    std::memcpy(m.file.data(), file.data(), file.size());
    m.bytes = uint32_t(file.size());
    return m;
}

// Part s's box centre on the screen (pixels) in its first instance, and how far across the
// screen its box's corners reach (pixels, the larger of width and height; corners behind the
// eye left out); false when the centre is off the screen.
bool on_screen(const App& app, uint32_t s, int32_t& x, int32_t& y, int32_t& across) {
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    int32_t lo[3], hi[3];
    if (!scene.part_box(s, lo, hi)) return false;
    for (uint32_t i = 0; i < scene.instances().size(); ++i) {
        if (scene.instances()[i].shell != s) continue;
        const module::Transform t = core.camera().transform(scene, i, app.w, app.h);
        const int32_t centre[3] = {int32_t((int64_t(lo[0]) + hi[0]) / 2), int32_t((int64_t(lo[1]) + hi[1]) / 2),
                                   int32_t((int64_t(lo[2]) + hi[2]) / 2)};
        module::Projected p;
        t.project(centre, p);
        if (p.out) return false;
        x = render::subpixel::pixel_of(p.s.x), y = render::subpixel::pixel_of(p.s.y);
        int32_t x0 = x, x1 = x, y0 = y, y1 = y;
        for (int c = 0; c < 8; ++c) {
            const int32_t corner[3] = {(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]};
            module::Projected q;
            t.project(corner, q);
            if (q.out & module::kOutNear) continue;
            const int32_t qx = render::subpixel::pixel_of(q.s.x), qy = render::subpixel::pixel_of(q.s.y);
            x0 = std::min(x0, qx), x1 = std::max(x1, qx), y0 = std::min(y0, qy), y1 = std::max(y1, qy);
        }
        across = std::max(x1 - x0, y1 - y0);
        return true;
    }
    return false;
}
bool on_screen(const App& app, uint32_t s, int32_t& x, int32_t& y) {
    int32_t across = 0;
    return on_screen(app, s, x, y, across);
}

// The view brought onto part s and zoomed in (a drag with the second button, the wheel) until
// its block is in, its faces done and its box spans the view or the wheel brings it no nearer
// (the others have left the view, so the full mesh has room for its faces); or the tries run out.
bool zoom_into(App& app, uint32_t s) {
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    float gain = 1; // pixels the part moves for a pixel dragged (more as the view nears it)
    int32_t last_across = -1;
    bool wheeled = false; // the last step was a turn of the wheel
    for (int k = 0; k < 60; ++k) {
        int32_t x = 0, y = 0, across = 0;
        if (!on_screen(app, s, x, y, across)) return false;
        const int32_t ox = app.w / 2 - x, oy = app.h / 2 - y;
        const int32_t dx = std::clamp<int32_t>(int32_t(float(ox) / gain), -40, 40), dy = std::clamp<int32_t>(int32_t(float(oy) / gain), -40, 40);
        const bool centred = std::abs(ox) < 8 && std::abs(oy) < 8;
        // Near: across the view, or as near as the wheel goes (its last turn brought it no nearer).
        const bool near = across >= std::min(app.w, app.h) || (wheeled && across <= last_across);
        last_across = across;
        if (centred && near && !scene.part_left_out(s) && whole(scene, s)) return true;
        if (!centred) {
            app.v->pointer(0, 0, 2);
            app.v->pointer(int16_t(dx), int16_t(dy), 2);
            app.v->pointer(0, 0, 0);
        } else {
            app.v->wheel(1);
        }
        wheeled = centred;
        app.run();
        int32_t nx = 0, ny = 0;
        if ((dx || dy) && on_screen(app, s, nx, ny) && std::abs(dx) + std::abs(dy) > 0) {
            const float moved = float(std::abs(nx - x) + std::abs(ny - y)), dragged = float(std::abs(dx) + std::abs(dy));
            if (moved > 0) gain = moved / dragged;
        }
    }
    return false;
}

std::vector<uint32_t> parts_left_out(const module::Scene& scene) {
    std::vector<uint32_t> left;
    for (uint32_t p = 0; p < scene.part_count(); ++p)
        if (scene.part_left_out(p)) left.push_back(p);
    return left;
}

// The decoded blocks held: each inside the workspace, none overlapping another.
void expect_blocks_apart(const App& app, const PackIndex& index) {
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    const auto* lo = reinterpret_cast<const uint8_t*>(app.workspace.data());
    const auto* hi = lo + app.workspace.size() * 8;
    std::vector<std::pair<const uint8_t*, const uint8_t*>> held;
    for (uint32_t b = 0; b < scene.block_count(); ++b) {
        const module::Block& block = scene.block(b);
        if (block.left_out) {
            EXPECT_EQ(block.pack.faces().size(), 0u) << "block " << b;
            continue;
        }
        ASSERT_NE(block.data, nullptr);
        EXPECT_GE(block.data, lo) << "block " << b;
        const uint32_t bytes = index.blocks()[b].pack_bytes;
        EXPECT_LE(block.data + bytes, hi) << "block " << b;
        held.push_back({block.data, block.data + bytes});
    }
    std::sort(held.begin(), held.end());
    for (size_t k = 1; k < held.size(); ++k) EXPECT_LE(held[k - 1].second, held[k].first) << "decoded blocks overlap";
}

void expect_counts(const App& app) {
    const Stats s = app.v->stats();
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    EXPECT_EQ(s.done + s.deferred + s.failed, s.faces);
    EXPECT_EQ(s.faces + scene.left_out().faces, scene.face_count());
    for (uint32_t p = 0; p < scene.part_count(); ++p) {
        if (!scene.part_left_out(p) && whole(scene, p)) {
            EXPECT_EQ(open_sides(scene, p), 0u) << "part " << p;
        }
    }
}

// The model in the largest workspace under the whole model's that leaves at least four of its
// twelve parts out, run until idle; false when none does.
bool open_in_part(App& app, const Model& m, Interface ui = Interface::Off) {
    ModelNeeds needs;
    if (!model_needs(m.file.data(), m.bytes, needs).ok()) return false;
    const size_t base = workspace_bytes();
    for (size_t room = needs.least_workspace_bytes + needs.pack_memory_bytes - base; room > 4096; room = room * 31 / 32) {
        app = App{};
        app.w = 320, app.h = 240;
        app.interface = ui;
        app.workspace_size = base + room;
        if (!app.create().ok() || !app.v->load(m.file.data(), m.bytes).ok()) return false;
        const uint32_t boxed = app.last(Event::Kind::Loaded)->loaded.boxed_parts;
        if (boxed >= 4 && boxed < 12) {
            app.run();
            return true;
        }
    }
    return false;
}

} // namespace

TEST(Swap, ZoomingIntoAPartLeftOutBringsItsBlockInInPlaceOfWhatTheViewLeaves) {
    Model m = twelve_parts();
    PackIndex index;
    ASSERT_TRUE(index.open(m.file.data(), m.bytes).ok());
    App app;
    ASSERT_TRUE(open_in_part(app, m));
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    expect_blocks_apart(app, index);
    expect_counts(app);
    const std::vector<uint32_t> left = parts_left_out(scene);
    ASSERT_GE(left.size(), 2u);

    // Into the first part left out: its block comes in, others go out to make room.
    const uint32_t first = left[0];
    ASSERT_TRUE(zoom_into(app, first)) << "part " << first << " brought in";
    EXPECT_GT(scene.left_out().parts, 0u) << "room made by leaving others out";
    EXPECT_EQ(app.count(Event::Kind::PassFailed), 0);
    expect_blocks_apart(app, index);
    expect_counts(app);
    size_t shaded = 0; // pixels neither the background (a row's colour at its left end) nor a box
    const std::vector<Rgb565> screen = app.screen();
    for (size_t i = 0; i < screen.size(); ++i) shaded += screen[i] != screen[i - i % app.w] && screen[i] != kBoxColour;
    EXPECT_GT(shaded, size_t(app.w) * app.h / 8) << "the part drawn shaded, filling the view";

    // Back out and into another: swapped again.
    app.v->act(Action::Fit);
    app.run();
    uint32_t second = ~0u;
    for (uint32_t p : left)
        if (p != first && scene.part_left_out(p)) second = p;
    if (second == ~0u) {
        for (uint32_t p = 0; p < scene.part_count(); ++p)
            if (scene.part_left_out(p)) second = p;
    }
    ASSERT_NE(second, ~0u);
    ASSERT_TRUE(zoom_into(app, second)) << "part " << second << " brought in";
    EXPECT_EQ(app.count(Event::Kind::PassFailed), 0);
    expect_blocks_apart(app, index);
    expect_counts(app);
    // And back to the whole model: every part held or a box, the counts whole.
    app.v->act(Action::Fit);
    app.run();
    expect_blocks_apart(app, index);
    expect_counts(app);
}

// A block left out whose bytes are corrupt is found so only when the view brings it in: said by
// a PassFailed event naming it, drawn as its box, and the other blocks still come in.
TEST(Swap, ACorruptBlockIsReportedWhenTheViewBringsItInAndTheOthersStillCome) {
    Model m = twelve_parts();
    PackIndex index;
    ASSERT_TRUE(index.open(m.file.data(), m.bytes).ok());
    App app;
    ASSERT_TRUE(open_in_part(app, m));
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    const std::vector<uint32_t> left = parts_left_out(scene);
    ASSERT_GE(left.size(), 2u);
    // The first one's compressed bytes garbled past its head (the file stays where it was loaded).
    const uint32_t bad = scene.part(left[0]).block;
    const auto file = index.block_file(bad);
    auto* bytes = const_cast<uint8_t*>(file.data());
    for (size_t k = 24; k < file.size(); k += 3) bytes[k] ^= 0x5A;
    EXPECT_FALSE(zoom_into(app, left[0]));
    bool said = false;
    for (const Event& e : app.events) {
        if (e.kind != Event::Kind::PassFailed) continue;
        said = said || text(e.why).find("block " + std::to_string(bad)) != std::string::npos;
    }
    EXPECT_TRUE(said) << "a PassFailed event names the corrupt block";
    EXPECT_TRUE(scene.part_left_out(left[0])) << "still a box";
    expect_counts(app);
    app.v->act(Action::Fit);
    app.run();
    ASSERT_TRUE(zoom_into(app, left[1])) << "another part left out still comes in";
    expect_blocks_apart(app, index);
    expect_counts(app);
}

// Work in screen order: a pass tessellates the blocks largest on the screen first, so what the
// view shows large is shaded first (the faces finished, in order). Seen
// here in a pass of finer detail begun from a view zoomed into the assembly's near end.
TEST(Swap, APassTakesTheBlocksLargestOnTheScreenFirst) {
    Model m = twelve_parts();
    App app;
    app.w = 320, app.h = 240;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.v->load(m.file.data(), m.bytes).ok());
    app.run();
    for (int k = 0; k < 3; ++k) app.v->act(Action::ZoomIn);
    app.run();
    app.v->act(Action::Finer); // a new pass, the view as it is
    app.run();
    const Core& core = *static_cast<const Core*>(app.v);
    const module::Scene& scene = core.scene();
    ASSERT_EQ(scene.left_out().blocks, 0u);
    const module::SphereView view = core.camera().sphere_view(scene, app.w, app.h);
    auto pixels = [&](uint32_t b) {
        float lo[3], hi[3], c[3], r2 = 0;
        scene.block_box(b, lo, hi);
        for (int k = 0; k < 3; ++k) c[k] = 0.5f * (lo[k] + hi[k]), r2 += 0.25f * (hi[k] - lo[k]) * (hi[k] - lo[k]);
        return view.pixels(c, std::sqrt(r2));
    };
    ASSERT_EQ(app.count(Event::Kind::Tessellated), 2) << "the pass done, no sweep after it";
    std::vector<uint32_t> order; // blocks as the pass finished their faces (the faces finished, in order)
    for (uint32_t k = 0; k < scene.totals().done; ++k) {
        const uint32_t b = scene.block_index(scene.block_of_face(scene.done_face(k)));
        if (std::find(order.begin(), order.end(), b) == order.end()) order.push_back(b);
    }
    ASSERT_GE(order.size(), 4u) << "blocks with faces to tessellate";
    float smallest = 1e30f, largest = 0;
    for (uint32_t b : order) smallest = std::min(smallest, pixels(b)), largest = std::max(largest, pixels(b));
    EXPECT_GT(largest, 1.5f * smallest) << "sizes that differ on the screen";
    for (size_t k = 1; k < order.size(); ++k) {
        EXPECT_LE(pixels(order[k]), pixels(order[k - 1])) << "block " << order[k] << " after block " << order[k - 1];
    }
}

// A face picked in a part whose block the view then leaves out is no longer there: the
// selection and the measurement go with it (its block's records are gone until it comes back).
TEST(Swap, AFacePickedInABlockLeftOutIsForgotten) {
    Model m = twelve_parts();
    App app;
    ASSERT_TRUE(open_in_part(app, m, Interface::Full));
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    std::vector<uint32_t> held, left;
    for (uint32_t p = 0; p < scene.part_count(); ++p) (scene.part_left_out(p) ? left : held).push_back(p);
    ASSERT_FALSE(left.empty());
    // Taps about a held part's box centre until one picks a face of it (a torus's centre is its hole).
    uint32_t picked = ~0u;
    for (uint32_t p : held) {
        int32_t x = 0, y = 0;
        if (!on_screen(app, p, x, y)) continue;
        for (int k = 0; k < 49 && picked == ~0u; ++k) {
            const int16_t tx = int16_t(x + 3 * (k % 7 - 3)), ty = int16_t(y + 3 * (k / 7 - 3));
            app.v->touch(0, 2, int16_t(app.h - 3), true); // (elsewhere first: two taps on one spot frame the face)
            app.v->touch(0, 2, int16_t(app.h - 3), false);
            app.v->touch(0, tx, ty, true);
            app.v->touch(0, tx, ty, false);
            app.run();
            const Event* e = app.last(Event::Kind::Picked);
            if (e && e->pick.hit && e->pick.shell == p) picked = p;
        }
        if (picked != ~0u) break;
    }
    ASSERT_NE(picked, ~0u) << "a tap picks a held part";
    const char* lines[3];
    ASSERT_GT(app.v->measurement(lines), 0u) << "the picked face described";
    // Into the part left out farthest from it on the screen, until the picked one is left out too.
    int32_t px = 0, py = 0;
    ASSERT_TRUE(on_screen(app, picked, px, py));
    uint32_t target = left[0];
    float far = -1;
    for (uint32_t p : left) {
        int32_t x = 0, y = 0;
        if (!on_screen(app, p, x, y)) continue;
        const float d = std::hypot(float(x - px), float(y - py));
        if (d > far) far = d, target = p;
    }
    (void)zoom_into(app, target);
    if (scene.part_left_out(picked)) {
        EXPECT_EQ(app.v->measurement(lines), 0u) << "the picked face went with its block";
    } else {
        EXPECT_GT(app.v->measurement(lines), 0u) << "still held: still described";
    }
    app.v->act(Action::Measure); // (describes the selection again: none of it left out)
    app.run();
    expect_counts(app);
}

// A walk of the view over a model larger than the memory (turns, zooms, pans, fits, levels of
// detail, display modes, picks; a fixed seed): after each step, the counts whole, every part
// held watertight, the decoded blocks apart inside the workspace, nothing refused by the
// rasterizer. (It found a block brought in whose samples then did not fit left pending.)
TEST(Swap, AWalkOfTheViewKeepsTheBlocksAndTheCountsWhole) {
    Model m = twelve_parts();
    PackIndex index;
    ASSERT_TRUE(index.open(m.file.data(), m.bytes).ok());
    App app;
    ASSERT_TRUE(open_in_part(app, m, Interface::Full));
    const module::Scene& scene = static_cast<const Core*>(app.v)->scene();
    constexpr Action kSteps[] = {Action::ZoomIn,  Action::ZoomIn,   Action::ZoomIn,    Action::ZoomOut, Action::PanLeft,
                                 Action::PanRight, Action::PanUp,   Action::PanDown,   Action::TurnLeft, Action::TiltUp,
                                 Action::Fit,     Action::NextDetail, Action::PanLeft, Action::Measure, Action::NextDisplayMode};
    uint32_t rng = 2026, swaps = 0, was_boxed = scene.left_out().parts;
    for (int step = 0; step < 150; ++step) {
        rng = rng * 1664525u + 1013904223u;
        const uint32_t pick = rng >> 24;
        if (pick % 7 == 0) { // a tap somewhere
            const int16_t x = int16_t((rng >> 8) % app.w), y = int16_t((rng >> 16) % app.h);
            app.v->touch(0, x, y, true);
            app.v->touch(0, x, y, false);
        } else {
            app.v->act(kSteps[pick % (sizeof kSteps / sizeof kSteps[0])]);
        }
        app.run();
        swaps += scene.left_out().parts != was_boxed;
        was_boxed = scene.left_out().parts;
        expect_blocks_apart(app, index);
        expect_counts(app);
        if (::testing::Test::HasFailure()) FAIL() << "after step " << step;
    }
    EXPECT_GT(swaps, 0u) << "the walk brought blocks in and left others out";
    for (const Event& e : app.events) {
        if (e.kind == Event::Kind::PassFailed) {
            EXPECT_EQ(e.why.status, Status::Full) << text(e.why);
        }
    }
}
