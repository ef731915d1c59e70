// The controls on their own: one table from keys to actions, and the gestures of a mouse and
// of fingers.
#include "controls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

using namespace facet;
using namespace facet::module;
using Kind = Command::Kind;

// The keys as docs/viewer.md and the help panel state them: what a user presses, written out
// here apart from the table (module/src/controls.cpp) so that a change of either shows.
struct Spec {
    uint32_t key;
    Action action;
};
constexpr Spec kSpec[] = {
    {'a', Action::TurnLeft}, {'d', Action::TurnRight}, {'w', Action::TiltUp}, {'s', Action::TiltDown},
    {'+', Action::ZoomIn}, {'=', Action::ZoomIn}, {'-', Action::ZoomOut}, {'j', Action::PanLeft}, {'l', Action::PanRight},
    {'i', Action::PanUp}, {'k', Action::PanDown}, {'f', Action::Fit}, {'[', Action::Coarser}, {']', Action::Finer},
    {'g', Action::NextDetail}, {'1', Action::ViewFront}, {'2', Action::ViewBack}, {'3', Action::ViewRight},
    {'4', Action::ViewLeft}, {'7', Action::ViewTop}, {'8', Action::ViewBottom}, {'0', Action::ViewIso},
    {'5', Action::Projection}, {'m', Action::NextDisplayMode}, {'t', Action::TangentEdges}, {'r', Action::Annotations}, {'e', Action::Explode}, {'c', Action::Section}, {',', Action::SectionIn},
    {'.', Action::SectionOut}, {'p', Action::Parts}, {'n', Action::NextPart}, {'x', Action::HidePart},
    {'o', Action::IsolatePart}, {'u', Action::ShowAllParts}, {'b', Action::Models}, {'h', Action::Help}, {'?', Action::Help},
    {KeyLeft, Action::TurnLeft}, {KeyRight, Action::TurnRight}, {KeyUp, Action::TiltUp}, {KeyDown, Action::TiltDown},
    {KeyPageUp, Action::ZoomIn}, {KeyPageDown, Action::ZoomOut}, {KeyHome, Action::Fit},
};
// Actions only the toolbar has (no key).
constexpr Action kToolbarOnly[] = {Action::NextView, Action::Measure};

TEST(Controls, EachKeyDoesWhatTheDocsSayAndEveryActionIsReachable) {
    Controls c;
    c.set_screen(640, 480);
    for (const Spec& s : kSpec) {
        const Command k = c.key(s.key);
        EXPECT_EQ(k.kind, Kind::Act) << "key " << s.key;
        EXPECT_EQ(int(k.action), int(s.action)) << "key " << s.key;
    }
    // The table has no key the spec leaves out, none twice, and says what each does.
    const KeyBindings keys = key_bindings();
    std::set<uint32_t> seen;
    std::set<int> reachable;
    for (uint32_t i = 0; i < keys.count; ++i) {
        const KeyBinding& b = keys.table[i];
        EXPECT_TRUE(seen.insert(b.key).second) << "key " << b.key << " bound twice";
        EXPECT_TRUE(std::any_of(std::begin(kSpec), std::end(kSpec), [&](const Spec& s) { return s.key == b.key; }))
            << "key " << b.key << " is bound but not in the spec";
        EXPECT_TRUE(b.help && b.help[0]) << "key " << b.key << " has no help text";
        reachable.insert(int(b.action));
    }
    for (Action a : kToolbarOnly) reachable.insert(int(a));
    for (int a = int(Action::None) + 1; a <= int(Action::Explode); ++a) {
        EXPECT_TRUE(reachable.count(a)) << "action " << a << " has neither a key nor a toolbar button";
    }
    EXPECT_EQ(c.key('%').kind, Kind::None);
    EXPECT_EQ(c.key('q').kind, Kind::None) << "quitting is the application's";
}

TEST(Controls, MouseDragsOrbitPanAndDollyAndAClickPicksWhereThePointerIs) {
    Controls c;
    c.set_screen(640, 480);
    EXPECT_EQ(c.pointer(0, 0, 1).kind, Kind::None); // press
    Command m = c.pointer(20, -10, 1);
    EXPECT_EQ(m.kind, Kind::Orbit);
    EXPECT_FLOAT_EQ(m.yaw, 20 * Controls::kRadPerPixel);
    EXPECT_FLOAT_EQ(m.pitch, -10 * Controls::kRadPerPixel);
    EXPECT_EQ(c.pointer(0, 0, 0).kind, Kind::None) << "a drag's release picks nothing";
    c.pointer(0, 0, 2);
    m = c.pointer(7, 3, 2);
    EXPECT_EQ(m.kind, Kind::Pan);
    EXPECT_EQ(m.dx, 7);
    c.pointer(0, 0, 0);
    c.pointer(0, 0, 4);
    m = c.pointer(0, 10, 4);
    EXPECT_EQ(m.kind, Kind::Dolly);
    EXPECT_FLOAT_EQ(m.factor, 1.1f);
    c.pointer(0, 0, 0);
    c.pointer(0, 0, 1);
    m = c.pointer(0, 0, 0);
    EXPECT_EQ(m.kind, Kind::Pick);
    EXPECT_EQ(m.x, 320 + 20 + 7);
    EXPECT_EQ(m.y, 240 - 10 + 3 + 10);
    EXPECT_EQ(c.pointer(5000, 5000, 0).kind, Kind::None); // moves without buttons
    c.pointer(0, 0, 1);
    m = c.pointer(0, 0, 0);
    EXPECT_EQ(m.x, 639) << "the pointer stays on the screen";
    EXPECT_EQ(m.y, 479);
}

TEST(Controls, WheelClicksDolly) {
    Controls c;
    EXPECT_FLOAT_EQ(c.wheel(1).factor, 0.8f);
    EXPECT_NEAR(c.wheel(-2).factor, 1.5625f, 1e-5);
    EXPECT_EQ(c.wheel(0).kind, Kind::None);
}

TEST(Controls, FingersTapDragAndPinch) {
    Controls c;
    c.set_screen(480, 272);
    Command out[2];
    // A tap: down and up without leaving the slop.
    EXPECT_EQ(c.touch(0, 100, 50, true, out), 0u);
    EXPECT_EQ(c.touch(0, 103, 52, true, out), 0u);
    ASSERT_EQ(c.touch(0, 103, 52, false, out), 1u);
    EXPECT_EQ(out[0].kind, Kind::Pick);
    EXPECT_EQ(out[0].x, 100);
    EXPECT_EQ(out[0].y, 50);
    // A drag: past the slop, every move orbits by what it moved since the last (or the landing).
    c.touch(0, 100, 50, true, out);
    ASSERT_EQ(c.touch(0, 110, 50, true, out), 1u);
    EXPECT_EQ(out[0].kind, Kind::Orbit);
    EXPECT_FLOAT_EQ(out[0].yaw, 10 * Controls::kRadPerPixel);
    ASSERT_EQ(c.touch(0, 115, 48, true, out), 1u);
    EXPECT_FLOAT_EQ(out[0].yaw, 5 * Controls::kRadPerPixel);
    EXPECT_EQ(c.touch(0, 115, 48, false, out), 0u) << "no tap after a drag";
    // A pinch: two fingers spreading dolly closer (factor under 1) and pan by half the motion.
    c.touch(0, 200, 100, true, out);
    c.touch(1, 240, 100, true, out);
    const uint32_t n = c.touch(1, 280, 100, true, out);
    ASSERT_EQ(n, 2u);
    EXPECT_EQ(out[0].kind, Kind::Pan);
    EXPECT_EQ(out[0].dx, 20);
    EXPECT_EQ(out[1].kind, Kind::Dolly);
    EXPECT_FLOAT_EQ(out[1].factor, 40.0f / 80.0f);
    EXPECT_EQ(c.touch(1, 280, 100, false, out), 0u);
    EXPECT_EQ(c.touch(0, 200, 100, false, out), 0u) << "no tap after a pinch";
    EXPECT_EQ(c.touch(2, 10, 10, true, out), 0u) << "a third finger is no gesture's";
}
