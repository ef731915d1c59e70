#include "overlay.h"

#include "hal/print.h"
#include "render/text.h"

namespace facet::module {
namespace {

constexpr hal::Rgb565 kBar = hal::rgb565(36, 40, 48), kText = hal::rgb565(236, 238, 242), kDim = hal::rgb565(150, 156, 168);
constexpr hal::Rgb565 kButton = hal::rgb565(58, 64, 76), kButtonOn = hal::rgb565(40, 110, 220), kEdge = hal::rgb565(20, 22, 28);

const char* mode_name(DisplayMode m) {
    switch (m) {
    case DisplayMode::ShadedEdges: return "shaded+edges";
    case DisplayMode::Shaded: return "shaded";
    case DisplayMode::Wireframe: return "wireframe";
    case DisplayMode::HiddenLine: return "hidden line";
    }
    return "";
}

} // namespace

void Overlay::layout(uint16_t width, uint16_t height) {
    width_ = width, height_ = height;
    button_count_ = 0;
    status_rows_ = 0, toolbar_x_ = int16_t(width);
    if (width < 160 || height < 96) return; // too small for a toolbar: the progress bar only
    status_rows_ = int16_t(render::kLineHeight + 2);
    // Buttons down the right side, as tall as a finger needs (at least 28 pixels).
    const int16_t w = int16_t(width >= 600 ? 56 : 44);
    toolbar_x_ = int16_t(width - w);
    static constexpr struct {
        Action action;
        const char* label;
    } kAll[kButtons] = {{Action::Fit, "FIT"},        {Action::NextView, "VIEW"}, {Action::NextDisplayMode, "MODE"},
                        {Action::Projection, "PROJ"}, {Action::Measure, "MEAS"},  {Action::Finer, "LOD+"},
                        {Action::Coarser, "LOD-"},    {Action::Help, "HELP"}};
    const int16_t room = int16_t(height - status_rows_);
    uint32_t n = kButtons;
    while (n > 1 && room / int16_t(n) < 28) --n; // a short screen keeps the first ones
    const int16_t h = int16_t(room / int16_t(n));
    for (uint32_t i = 0; i < n; ++i) buttons_[i] = {toolbar_x_, int16_t(status_rows_ + int16_t(i) * h), w, h, kAll[i].action, kAll[i].label};
    button_count_ = n;
}

Overlay::TimeField Overlay::time_field() const {
    const int16_t x1 = int16_t(toolbar_x_ - 3);
    return {int16_t(x1 - (kTimeChars * render::kCellWidth - 1)), x1, status_rows_};
}

FreeArea Overlay::taken() const {
    FreeArea a;
    a.top = status_rows_;
    a.right = int16_t(width_ - toolbar_x_);
    a.bottom = int16_t(line_count_ ? line_count_ * render::kLineHeight + 4 : 0);
    return a;
}

Action Overlay::button_at(int16_t x, int16_t y) const {
    for (uint32_t i = 0; i < button_count_; ++i) {
        const Button& b = buttons_[i];
        if (x >= b.x && x < b.x + b.w && y >= b.y && y < b.y + b.h) return b.action;
    }
    return Action::None;
}

void Overlay::set_lines(const char* const* lines, uint32_t count) {
    line_count_ = count < kLines ? count : kLines;
    for (uint32_t i = 0; i < line_count_; ++i) {
        uint32_t k = 0;
        for (; lines[i][k] && k + 1 < kLineChars; ++k) lines_[i][k] = lines[i][k];
        lines_[i][k] = 0;
    }
}

void Overlay::draw(const render::Target& t, const StatusInfo& info) const {
    if (button_count_) {
        status(t, info);
        toolbar(t);
        if (line_count_) panel(t);
        if (help_) help_panel(t);
    }
    progress(t, info.finished, info.total);
}

void Overlay::status(const render::Target& t, const StatusInfo& s) const {
    render::fill_rect(t, 0, 0, width_, status_rows_, kBar);
    char text[96];
    // "faces 87/87  1594 tri  lod 0.504 mm  shaded+edges  persp", and the frame's cost in its
    // own field at the right end (the one value that differs between a board and the host).
    const int64_t tol = int64_t(s.tolerance_mm * 1000 + 0.5f);
    format(text, sizeof text, "faces {}/{}  {} tri  lod {} mm  {}  {}", s.finished, s.total, s.triangles, fixed(tol, 3),
           mode_name(s.mode), s.ortho ? "parallel" : "persp");
    const TimeField f = time_field();
    const int32_t room = (f.x0 - 6 - 3) / render::kCellWidth; // characters before the field
    if (room < int32_t(sizeof text)) text[room > 0 ? room : 0] = 0;
    render::draw_text(t, 3, 2, text, s.finished < s.total ? kDim : kText);
    if (s.frame_us) {
        format(text, sizeof text, "{} ms", fixed((s.frame_us + 50) / 100, 1));
        render::draw_text(t, f.x1 - render::text_width(text), 2, text, kText);
    }
}

void Overlay::toolbar(const render::Target& t) const {
    for (uint32_t i = 0; i < button_count_; ++i) {
        const Button& b = buttons_[i];
        const bool on = (b.action == Action::Measure && measuring_) || (b.action == Action::Help && help_);
        render::fill_rect(t, b.x, b.y, b.w, b.h, kEdge);
        render::fill_rect(t, b.x + 1, b.y + 1, b.w - 2, b.h - 2, on ? kButtonOn : kButton);
        const int32_t tw = render::text_width(b.label);
        render::draw_text(t, b.x + (b.w - tw) / 2, b.y + (b.h - render::kGlyphHeight) / 2, b.label, kText);
    }
}

void Overlay::panel(const render::Target& t) const {
    const int32_t h = int32_t(line_count_) * render::kLineHeight + 4, y = height_ - h;
    render::fill_rect(t, 0, y, toolbar_x_, h, kBar);
    for (uint32_t i = 0; i < line_count_; ++i) render::draw_text(t, 3, y + 3 + int32_t(i) * render::kLineHeight, lines_[i], kText);
}

void Overlay::help_panel(const render::Target& t) const {
    static constexpr const char* kHelp[] = {
        "drag: turn      two fingers: pinch to zoom, drag to pan",
        "tap: pick a face (MEAS: two faces, distance and angle)",
        "double tap: frame the face   FIT: the whole model",
        "VIEW: front, right, top, iso...   PROJ: perspective/parallel",
        "MODE: shaded+edges, shaded, wireframe, hidden line",
        "LOD+ / LOD-: finer / coarser triangles",
        "keys: 1 2 3 4 7 8 0 views, 5 projection, m mode, f fit",
    };
    constexpr int32_t n = sizeof kHelp / sizeof kHelp[0];
    const int32_t w = toolbar_x_ - 16, h = n * render::kLineHeight + 8, x = 8, y = status_rows_ + 8;
    render::fill_rect(t, x, y, w, h, kEdge);
    render::fill_rect(t, x + 1, y + 1, w - 2, h - 2, kBar);
    for (int32_t i = 0; i < n; ++i) render::draw_text(t, x + 5, y + 5 + i * render::kLineHeight, kHelp[i], kText);
}

void Overlay::progress(const render::Target& t, uint32_t finished, uint32_t total) const {
    if (finished >= total) return;
    const uint32_t w = t.width * finished / total;
    for (int32_t y = t.height - kBarRows; y < t.height; ++y) {
        if (y < t.y0 || y >= t.y0 + t.rows) continue;
        render::fill_pixels(t.row(y), w, kDone);
        render::fill_pixels(t.row(y) + w, t.width - w, kLeft);
    }
}

} // namespace facet::module
