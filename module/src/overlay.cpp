#include "overlay.h"

#include "overlay_style.h"

#include "core/format.h"
#include "render/text.h"

namespace facet::module {
namespace {

using namespace overlay_style;
constexpr int32_t kKnob = 10;    // half the section slider's knob

const char* mode_name(DisplayMode m) {
    switch (m) {
    case DisplayMode::ShadedEdges: return "shaded+edges";
    case DisplayMode::Shaded: return "shaded";
    case DisplayMode::Wireframe: return "wireframe";
    case DisplayMode::HiddenLine: return "hidden line";
    case DisplayMode::SeeThrough: return "see-through";
    }
    return "";
}

} // namespace

void Overlay::layout(uint16_t width, uint16_t height, bool status_only) {
    width_ = width, height_ = height;
    button_count_ = 0;
    status_rows_ = 0, toolbar_x_ = int16_t(width);
    if (width < 160 || height < 96) return; // too small for a toolbar: the progress bar only
    status_rows_ = int16_t(render::kLineHeight + 2);
    if (status_only) return;
    // Buttons down the right side, as tall as a finger needs (at least 28 pixels).
    const int16_t w = int16_t(width >= 600 ? 56 : 44);
    toolbar_x_ = int16_t(width - w);
    static constexpr struct {
        Action action;
        const char* label;
    } kAll[kButtons] = {{Action::Fit, "FIT"},        {Action::NextView, "VIEW"},    {Action::NextDisplayMode, "MODE"},
                        {Action::Projection, "PROJ"}, {Action::Section, "SECT"},  {Action::Measure, "MEAS"},
                        {Action::Parts, "PART"},      {Action::NextDetail, "LOD"}, {Action::Help, "HELP"}};
    const int16_t room = int16_t(height - status_rows_);
    uint32_t n = kButtons;
    while (n > 1 && room / int16_t(n) < 28) --n; // a short screen keeps the first ones
    const int16_t h = int16_t(room / int16_t(n));
    for (uint32_t i = 0; i < n; ++i) {
        const int16_t bh = i + 1 < n ? h : int16_t(room - int16_t(n - 1) * h); // the last one takes the rest
        buttons_[i] = {toolbar_x_, int16_t(status_rows_ + int16_t(i) * h), w, bh, kAll[i].action, kAll[i].label};
    }
    button_count_ = n;
}

Overlay::TimeField Overlay::time_field() const {
    const int16_t x1 = int16_t(toolbar_x_ - 3);
    return {int16_t(x1 - (kTimeChars * render::kCellWidth - 1)), x1, status_rows_};
}

FreeArea Overlay::taken() const {
    FreeArea a;
    a.top = status_rows_;
    a.right = int16_t(width_ - toolbar_x_ + (slider_on() && button_count_ ? kSliderWidth : 0));
    a.left = parts_open() || pmi_open() ? parts_panel().width : 0;
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

// An area from signed corners: nothing (0 wide or high) where they cross.
static Area area(int32_t x, int32_t y, int32_t width, int32_t height) {
    return {uint16_t(x > 0 ? x : 0), uint16_t(y > 0 ? y : 0), uint16_t(width > 0 ? width : 0), uint16_t(height > 0 ? height : 0)};
}

Area Overlay::slider() const {
    if (!slider_on() || !button_count_) return {0, 0, 0, 0};
    const int32_t bottom = height_ - (line_count_ ? line_count_ * render::kLineHeight + 4 : 0) - kBarRows;
    return area(toolbar_x_ - kSliderWidth, status_rows_, kSliderWidth, bottom - status_rows_);
}

float Overlay::slider_at(int16_t y) const {
    const Area r = slider();
    const int32_t track = r.height - 2 * kKnob; // the knob's centre runs from kKnob to height - kKnob
    if (track <= 0) return 0.5f;
    const float v = float(r.y + r.height - kKnob - y) / float(track);
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

Area Overlay::parts_panel() const {
    // (the models chooser wider: a file's name, size and faces)
    const int32_t w = models_open_ ? (toolbar_x_ - 4 < 360 ? toolbar_x_ - 4 : 360) : toolbar_x_ / 2 < 200 ? toolbar_x_ / 2 : 200;
    const int32_t bottom = height_ - (line_count_ ? line_count_ * render::kLineHeight + 4 : 0);
    return area(0, status_rows_, w, bottom - status_rows_);
}

uint32_t Overlay::part_rows() const {
    const int32_t rows = (parts_panel().height - kRow - kPartsFooter) / kRow;
    return rows > 0 ? uint32_t(rows) : 0;
}

// A tap on a list panel (the parts list's or the chooser's) as far as the panel alone says:
// outside it (None), on its header (Up, Down: its scroll buttons; Panel: the rest). True when
// that decides it; else the tap is in the rows below the header, Panel so far.
bool Overlay::list_hit(int16_t x, int16_t y, PartsHit& h) const {
    const Area p = parts_panel();
    if (!p.contains(x, y)) return true;
    h.kind = PartsHit::Kind::Panel;
    if (y - p.y >= kRow) return false;
    if (x >= p.width - 2 * kScrollW) h.kind = x >= p.width - kScrollW ? PartsHit::Kind::Down : PartsHit::Kind::Up;
    return true;
}

void Overlay::draw(const render::Target& t, const StatusInfo& info) const {
    if (status_rows_) status(t, info);
    if (button_count_) {
        toolbar(t);
        if (line_count_) panel(t);
        if (slider_on()) slider_bar(t);
        if (parts_open()) parts_list(t);
        if (pmi_open()) pmi_list(t);
        if (models_open()) models_list(t);
        if (help_) help_panel(t, info.tangent_edges);
    }
    progress(t, info.finished, info.total);
}

void Overlay::status(const render::Target& t, const StatusInfo& s) const {
    render::fill_rect(t, 0, 0, width_, status_rows_, kBar);
    char text[160];
    // "faces 87/87  1594 tri  lod 0.504 mm  shaded+edges  persp", and the frame's cost in its
    // own field at the right end (the one value that differs between a board and the host).
    const int64_t tol = int64_t(s.tolerance_mm * 1000 + 0.5f);
    // The model's name first: its first kNameCells characters (UTF-8, up to 4 bytes each); with
    // a library, on a button that opens the chooser.
    char name[kNameCells * 4 + 1];
    format(name, sizeof name, "{}", s.name);
    render::cut_text(name, kNameCells);
    if (has_models() && button_count_ > 0) {
        render::fill_rect(t, 0, 0, render::text_width(name) + 6, status_rows_, models_open_ ? kButtonOn : kButton);
    }
    // A model larger than the memory: "faces 900/900 +4100 left out" (the faces of the parts left
    // out, drawn as their proxies, or boxes from a pack without them).
    char boxed[24] = "";
    if (s.boxed_faces) format(boxed, sizeof boxed, " +{} left out", s.boxed_faces);
    format(text, sizeof text, "{}{}faces {}/{}{}  {} tri  lod {} mm  {}  {}", name, name[0] ? "  " : "", s.finished, s.total, boxed,
           s.triangles, fixed(tol, 3), mode_name(s.mode), s.ortho ? "parallel" : "persp");
    const TimeField f = time_field();
    render::cut_text(text, (f.x0 - 6 - 3) / render::kCellWidth); // the characters before the field
    render::draw_text(t, 3, 2, text, s.finished < s.total ? kDim : kText);
    if (s.frame_us) {
        format(text, sizeof text, "{} ms", fixed((s.frame_us + 50) / 100, 1));
        render::draw_text(t, f.x1 - render::text_width(text), 2, text, kText);
    }
}

void Overlay::toolbar(const render::Target& t) const {
    for (uint32_t i = 0; i < button_count_; ++i) {
        const Button& b = buttons_[i];
        const bool on = (b.action == Action::Measure && measuring_) || (b.action == Action::Help && help_) ||
                        (b.action == Action::Section && slider_on_) || (b.action == Action::Parts && parts_open_);
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

namespace {
// The help panel: its lines, then its button (a finger's height).
constexpr const char* kHelp[] = {
    "drag: turn      two fingers: pinch to zoom, drag to pan",
    "tap: pick a face (MEAS: two faces, distance and angle)",
    "double tap: frame the face   FIT: the whole model",
    "VIEW: front, right, top, iso...   PROJ: perspective/parallel",
    "MODE: shaded+edges, shaded, wireframe, hidden line, see-through",
    "SECT: a section (picked plane, x, y, z); drag its slider",
    "PART: the parts: tap a name, its box hides it; ISOL, ALL; PMI",
    "LOD: finer, finest, coarser triangles, and back",
    "keys: 1 2 3 4 7 8 0 views, 5 projection, m mode, f fit",
    "c section , . move it  p parts n next x hide o isolate u all",
    "g detail  t tangent edges  r PMI shown/hidden  h or ? help",
};
constexpr int32_t kHelpLines = int32_t(sizeof kHelp / sizeof kHelp[0]);
constexpr int32_t kHelpButtonRows = 28;
} // namespace

Area Overlay::help_area() const {
    if (toolbar_x_ < 32) return {}; // (a screen too narrow for it)
    return {8, uint16_t(status_rows_ + 8), uint16_t(toolbar_x_ - 16), uint16_t(kHelpLines * render::kLineHeight + 8 + kHelpButtonRows + 4)};
}

void Overlay::help_panel(const render::Target& t, bool tangent_edges) const {
    const Area p = help_area();
    if (p.width == 0) return;
    render::fill_rect(t, p.x, p.y, p.width, p.height, kEdge);
    render::fill_rect(t, p.x + 1, p.y + 1, p.width - 2, p.height - 2, kBar);
    for (int32_t i = 0; i < kHelpLines; ++i) render::draw_text(t, p.x + 5, p.y + 5 + i * render::kLineHeight, kHelp[i], kText);
    const Area b = help_button();
    render::fill_rect(t, b.x, b.y, b.width, b.height, tangent_edges ? kButtonOn : kButton);
    render::draw_text(t, b.x + 6, b.y + (b.height - render::kLineHeight) / 2 + 1,
                      tangent_edges ? "TANGENT EDGES: SHOWN (tap, or key t)" : "TANGENT EDGES: LEFT OUT (tap, or key t)", kText);
}

Area Overlay::help_button() const {
    const Area p = help_area();
    if (!help_ || p.width == 0) return {};
    return {uint16_t(p.x + 4), uint16_t(p.y + kHelpLines * render::kLineHeight + 8), uint16_t(p.width - 8), uint16_t(kHelpButtonRows)};
}

void Overlay::slider_bar(const render::Target& t) const {
    const Area r = slider();
    if (r.width <= 0 || r.height <= 2 * kKnob) return;
    render::fill_rect(t, r.x, r.y, r.width, r.height, kBar);
    render::fill_rect(t, r.x + r.width / 2 - 1, r.y + kKnob, 3, r.height - 2 * kKnob, kDim); // the track
    const float value = explode_on_ ? explode_value_ : slider_value_;
    const int32_t y = r.y + r.height - kKnob - int32_t(value * float(r.height - 2 * kKnob) + 0.5f);
    render::fill_rect(t, r.x + 2, y - kKnob + 2, r.width - 4, 2 * kKnob - 4, kEdge);
    render::fill_rect(t, r.x + 3, y - kKnob + 3, r.width - 6, 2 * kKnob - 6, kButtonOn);
}

// A list panel's background and its header: the title, the scroll buttons at its right end.
void Overlay::list_head(const render::Target& t, const Area& p, const char* title) const {
    render::fill_rect(t, p.x, p.y, p.width, p.height, kEdge);
    render::fill_rect(t, p.x, p.y, p.width - 1, p.height, kBar);
    render::draw_text(t, p.x + 4, p.y + (kRow - render::kGlyphHeight) / 2, title, kText);
    for (int i = 0; i < 2; ++i) { // scroll up, down
        const int32_t x = p.width - (2 - i) * kScrollW;
        render::fill_rect(t, x + 1, p.y + 1, kScrollW - 2, kRow - 2, kButton);
        render::draw_text(t, x + (kScrollW - render::kCellWidth) / 2, p.y + (kRow - render::kGlyphHeight) / 2, i ? "v" : "^", kText);
    }
}

// The models chooser: "MODELS n", then a row per model (its number and name; one that could not
// be opened says so, dimmed), the open one lit, scrolled by the header's buttons.
void Overlay::models_list(const render::Target& t) const {
    const Area p = parts_panel();
    if (p.height < 2 * kRow) return;
    char text[128];
    if (!library_->on_storage()) {
        format(text, sizeof text, "MODELS {}", library_->count());
    } else if (storage_gone_) {
        format(text, sizeof text, "MODELS: the card is gone");
    } else if (library_->unlisted()) {
        format(text, sizeof text, "MODELS {} in {} (+{} not listed)", library_->count(), library_->folder(), library_->unlisted());
    } else {
        format(text, sizeof text, "MODELS {} in {}", library_->count(), library_->folder());
    }
    list_head(t, p, text);
    for (uint32_t r = 0; r < model_rows() && first_model_ + r < library_->count(); ++r) {
        const uint32_t m = first_model_ + r;
        const int32_t y = p.y + kRow + int32_t(r) * kRow;
        if (m == current_model_) render::fill_rect(t, p.x, y, p.width - 1, kRow, kButtonOn);
        if (library_->on_storage()) { // "2 PUMP.FPK  812 KB  3656 faces", "3 Pump (LINE.FLB)  812 KB ..."
            const Models::Listed& f = library_->listed(m);
            char faces[24] = "", name[Models::kFolderBytes + pack::kLibraryNameBytes + 4];
            if (f.faces != kNone) format(faces, sizeof faces, "  {} faces", f.faces);
            if (f.unreadable) format(name, sizeof name, "{} (library)", f.name);
            else if (f.library) format(name, sizeof name, "{} ({})", f.model[0] ? f.model : "model", f.name);
            else format(name, sizeof name, "{}", f.name);
            format(text, sizeof text, broken(m) ? "{} cannot open: {}" : "{} {}  {} KB{}", m + 1, name, (f.bytes + 1023) / 1024, faces);
        } else {
            format(text, sizeof text, broken(m) ? "{} cannot open: {}" : "{} {}", m + 1, library_->name(m));
        }
        render::cut_text(text, (p.width - 8) / render::kCellWidth);
        render::draw_text(t, p.x + 4, y + (kRow - render::kGlyphHeight) / 2, text, broken(m) ? kDim : kText);
    }
}

bool Overlay::name_at(int16_t x, int16_t y) const {
    return has_models() && button_count_ > 0 && y >= 0 && y < status_rows_ && x >= 0 &&
           x < kNameCells * render::kCellWidth + 6;
}

uint32_t Overlay::model_rows() const {
    const int32_t rows = parts_panel().height / kRow - 1;
    return rows > 0 ? uint32_t(rows) : 0;
}

void Overlay::scroll_models(int32_t rows) { first_model_ = scrolled(first_model_, rows, library_ ? library_->count() : 0, model_rows()); }

Overlay::PartsHit Overlay::models_at(int16_t x, int16_t y) const {
    PartsHit h;
    if (!models_open() || list_hit(x, y, h)) return h;
    const uint32_t row = uint32_t(y - parts_panel().y - kRow) / uint32_t(kRow);
    if (row < model_rows() && first_model_ + row < library_->count()) h.kind = PartsHit::Kind::Row, h.part = first_model_ + row;
    return h;
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
