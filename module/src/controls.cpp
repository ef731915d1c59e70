#include "controls.h"

#include <cmath>

namespace facet::module {
namespace {

constexpr KeyBinding kKeys[] = {
    {'a', Action::TurnLeft, "turn left"},    {'d', Action::TurnRight, "turn right"},
    {'w', Action::TiltUp, "tilt up"},        {'s', Action::TiltDown, "tilt down"},
    {'+', Action::ZoomIn, "zoom in"},        {'=', Action::ZoomIn, "zoom in"},
    {'-', Action::ZoomOut, "zoom out"},      {'j', Action::PanLeft, "pan left"},
    {'l', Action::PanRight, "pan right"},    {'i', Action::PanUp, "pan up"},
    {'k', Action::PanDown, "pan down"},      {'f', Action::Fit, "fit the model"},
    {'[', Action::Coarser, "coarser detail"}, {']', Action::Finer, "finer detail"},
    {KeyLeft, Action::TurnLeft, "turn left"}, {KeyRight, Action::TurnRight, "turn right"},
    {KeyUp, Action::TiltUp, "tilt up"},      {KeyDown, Action::TiltDown, "tilt down"},
    {KeyPageUp, Action::ZoomIn, "zoom in"},  {KeyPageDown, Action::ZoomOut, "zoom out"},
    {KeyHome, Action::Fit, "fit the model"},
    {'1', Action::ViewFront, "front view"},  {'2', Action::ViewBack, "back view"},
    {'3', Action::ViewRight, "right view"},  {'4', Action::ViewLeft, "left view"},
    {'7', Action::ViewTop, "top view"},      {'8', Action::ViewBottom, "bottom view"},
    {'0', Action::ViewIso, "isometric view"}, {'5', Action::Projection, "perspective / parallel"},
    {'m', Action::NextDisplayMode, "display mode: shaded + edges, shaded, wireframe, hidden line, see-through"},
    {'t', Action::TangentEdges, "tangent edges (a fillet's sides) shown / hidden"},
    {'r', Action::Annotations, "annotations (PMI: dimensions, tolerances, datums) shown / hidden"},
    {'e', Action::Explode, "exploded view (an assembly's parts apart; its slider) / back"},
    {'c', Action::Section, "section: picked plane, x, y, z, off"},
    {',', Action::SectionIn, "move the section back"}, {'.', Action::SectionOut, "move the section forward"},
    {'p', Action::Parts, "the parts list"},  {'n', Action::NextPart, "choose the next part"},
    {'x', Action::HidePart, "hide the chosen part"}, {'o', Action::IsolatePart, "show the chosen part alone"},
    {'u', Action::ShowAllParts, "show every part"}, {'g', Action::NextDetail, "level of detail: finer, finest, coarser"},
    {'b', Action::Models, "the models on the device (a library): tap one to open it"},
    {'h', Action::Help, "help: the keys and gestures"}, {'?', Action::Help, "help: the keys and gestures"},
};

// (Squares in 64 bits: two touches 65,535 pixels apart square past 32.)
int32_t distance(int32_t dx, int32_t dy) { return int32_t(std::sqrt(float(int64_t(dx) * dx + int64_t(dy) * dy)) + 0.5f); }

} // namespace

} // namespace facet::module

namespace facet {
KeyBindings key_bindings() { return {module::kKeys, uint32_t(sizeof module::kKeys / sizeof module::kKeys[0])}; }
} // namespace facet

namespace facet::module {

void Controls::set_screen(uint16_t width, uint16_t height) {
    width_ = width, height_ = height;
    cursor_x_ = width / 2, cursor_y_ = height / 2;
}

Command Controls::key(uint32_t k) const {
    for (const KeyBinding& b : kKeys)
        if (b.key == k) return {Command::Kind::Act, b.action};
    return {};
}

Command Controls::pointer(int16_t dx, int16_t dy, uint8_t buttons) {
    Command c;
    const uint8_t pressed = buttons & ~buttons_, released = buttons_ & ~buttons;
    cursor_x_ += dx, cursor_y_ += dy;
    cursor_x_ = cursor_x_ < 0 ? 0 : (cursor_x_ >= width_ ? width_ - 1 : cursor_x_);
    cursor_y_ = cursor_y_ < 0 ? 0 : (cursor_y_ >= height_ ? height_ - 1 : cursor_y_);
    if (pressed) travel_ = 0;
    travel_ += (dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy);
    const uint8_t held = buttons & buttons_; // motion counts for the buttons held throughout
    buttons_ = buttons;
    if ((pressed & 1) && on_slider(cursor_x_, cursor_y_)) sliding_ = true;
    if (sliding_) { // the left button went down on the section slider: the plane follows
        if (!(buttons & 1)) sliding_ = false;
        if ((pressed & 1) || ((held & 1) && dy)) {
            c.kind = Command::Kind::Slide;
            c.y = int16_t(cursor_y_);
        }
        return c;
    }
    if ((released & 1) && travel_ <= kTapSlop && !(dx | dy)) {
        c.kind = Command::Kind::Pick;
        c.x = int16_t(cursor_x_), c.y = int16_t(cursor_y_);
        return c;
    }
    if (!(dx | dy) || !held) return c;
    if (held & 1) {
        c.kind = Command::Kind::Orbit;
        c.yaw = float(dx) * kRadPerPixel, c.pitch = float(dy) * kRadPerPixel;
    } else if (held & 2) {
        c.kind = Command::Kind::Pan;
        c.dx = dx, c.dy = dy;
    } else if (held & 4) {
        c.kind = Command::Kind::Dolly;
        c.factor = 1.0f + float(dy) * 0.01f;
    }
    return c;
}

Command Controls::wheel(int16_t clicks) const {
    Command c;
    if (!clicks) return c;
    c.kind = Command::Kind::Dolly;
    c.factor = std::pow(0.8f, float(clicks));
    return c;
}

uint32_t Controls::touch(uint8_t id, int16_t x, int16_t y, bool down, Command out[2]) {
    if (id > 1) return 0; // two fingers are all the gestures use
    Finger& f = fingers_[id];
    Finger& other = fingers_[id ^ 1];
    uint32_t n = 0;
    if (down && !f.down) { // a finger lands
        f = {true, x, y, x, y, false};
        if (other.down) pinched_ = true;
        else pinched_ = false;
        if (!other.down && on_slider(x, y)) { // on the section slider: the plane follows the finger
            sliding_ = true;
            out[n].kind = Command::Kind::Slide;
            out[n].y = y;
            return ++n;
        }
        return 0;
    }
    if (sliding_) {
        if (!down) sliding_ = false, f.down = false;
        else if (y != f.y) {
            f.x = x, f.y = y;
            out[n].kind = Command::Kind::Slide;
            out[n].y = y;
            ++n;
        }
        return n;
    }
    if (!down) { // lifted
        const bool tap = f.down && !f.moved && !pinched_ && !other.down;
        f.down = false;
        if (tap) {
            out[n].kind = Command::Kind::Pick;
            out[n].x = f.x0, out[n].y = f.y0;
            ++n;
        }
        return n;
    }
    // A finger moves.
    const int16_t px = f.x, py = f.y;
    f.x = x, f.y = y;
    if (!f.moved && distance(x - f.x0, y - f.y0) > kTapSlop) f.moved = true;
    if (!f.moved) {
        f.x = px, f.y = py; // within the slop: no motion yet
        return 0;
    }
    if (!other.down) {
        out[n].kind = Command::Kind::Orbit;
        out[n].yaw = float(x - px) * kRadPerPixel, out[n].pitch = float(y - py) * kRadPerPixel;
        return ++n;
    }
    // Two fingers: the midpoint's motion pans (half of this finger's), the distance's change dollies.
    const int32_t before = distance(px - other.x, py - other.y), after = distance(x - other.x, y - other.y);
    const int16_t mx = int16_t((x - px) / 2), my = int16_t((y - py) / 2);
    if (mx || my) {
        out[n].kind = Command::Kind::Pan;
        out[n].dx = mx, out[n].dy = my;
        ++n;
    }
    if (before > 0 && after > 0 && before != after) {
        out[n].kind = Command::Kind::Dolly;
        out[n].factor = float(before) / float(after);
        ++n;
    }
    return n;
}

} // namespace facet::module
