#pragma once
// What the viewer draws over the model, for the person holding the handheld: a status bar
// along the top (faces done of all, triangles, the last frame's cost, the level of detail,
// the display mode), a toolbar of touch targets down the right side, the measurement panel
// along the bottom (the picked faces' exact values), the help panel, and the progress bar
// while the faces fill in. Text in facet's own bitmap font (render/text.h). Everything is
// opaque (an incremental frame draws over the last one) and clipped to the target's band.
#include "facet/viewer.h"
#include "geom/tree_format.h"
#include "models.h"
#include "render/raster.h"
#include "scene.h"

#include <cstdint>

namespace facet::module {

class Annotating;

// Pixels the overlay takes at each side of the screen (the model is framed in the rest).
struct FreeArea {
    int16_t left = 0, top = 0, right = 0, bottom = 0;
};

struct StatusInfo {
    const char* name = ""; // the model's
    uint32_t finished = 0, total = 0, triangles = 0;
    uint32_t boxed_faces = 0; // a model larger than the memory: the faces of the parts it left out, drawn as their proxies
    uint32_t frame_us = 0; // the last full frame's cost (0: no clock)
    float tolerance_mm = 0;
    DisplayMode mode = DisplayMode::ShadedEdges;
    bool ortho = false;
    bool tangent_edges = true; // drawn (the help panel's button says which)
};

class Overlay {
public:
    static constexpr uint16_t kBarRows = 4;
    static constexpr Rgb565 kDone = rgb565(40, 110, 220), kLeft = rgb565(70, 74, 84);
    static constexpr uint32_t kButtons = 9;
    static constexpr int16_t kSliderWidth = 28; // the section slider, left of the toolbar
    static constexpr int16_t kRow = 20, kPartsFooter = 26; // the parts list's rows and buttons
    static constexpr uint32_t kLines = 3, kLineChars = 80; // the measurement panel

    // The screen's size: where the bars and the buttons go (480 x 272 and larger; a screen
    // under 160 x 96 gets no toolbar, only the progress bar). `status_only`: the status bar
    // and the progress bar, no toolbar (the application's own buttons drive the viewer).
    void layout(uint16_t width, uint16_t height, bool status_only = false);
    FreeArea taken() const;
    // The status bar's frame-time field: pixels [x0, x1) of rows [0, rows) (tools/img.py's
    // frame_time_field() says the same, for comparing a board's screenshots with the host's).
    static constexpr int32_t kTimeChars = 9; // "1234.5 ms"
    struct TimeField {
        int16_t x0, x1, rows;
    };
    TimeField time_field() const;
    // The toolbar button under a screen pixel, or None.
    Action button_at(int16_t x, int16_t y) const;

    // The section slider: shown or not, and where its knob is (0: the bottom, 1: the top).
    void set_slider(bool on, float value) { slider_on_ = on, slider_value_ = value; }
    // The same slider for the exploded view while it is on (it then moves the parts, not the plane).
    void set_explode_slider(bool on, float value) { explode_on_ = on, explode_value_ = value; }
    bool slider_explodes() const { return explode_on_; }
    bool slider_on() const { return slider_on_ || explode_on_; }
    Area slider() const; // the track (width 0: none)
    float slider_at(int16_t y) const; // the value at a row of the track, 0..1

    // The parts list: a panel down the left side: the assembly tree (overlay_tree.cpp), a row
    // per sub-assembly (its box opens or closes it, its name chooses it: all its parts) with
    // its sub-assemblies and parts under it when open (one open child a level: the rows a path
    // down the tree), and a row per part (instance) with its box (shown or hidden) and name; a
    // flat list of the parts for a model without a tree. Scroll buttons; HIDE, ISOL, ALL, FIT
    // and EXPL (the exploded view) for the chosen part or sub-assembly.
    void set_scene(const Scene* scene) { scene_ = scene; }
    void set_parts(bool open) {
        parts_open_ = open, first_row_ = 0, models_open_ = models_open_ && !open, pmi_open_ = pmi_open_ && !open;
        if (open) open_depth_ = 0; // (the tree's top level)
    }
    bool parts_open() const { return parts_open_ && button_count_ > 0; }
    void set_chosen(uint32_t part); // highlighted row (its sub-assemblies opened, scrolled into the list); kNone: none
    void set_chosen_node(uint32_t node); // a sub-assembly's row (likewise)
    void toggle_open(uint32_t node);     // a sub-assembly opened (its siblings' closed) or closed
    struct PartsHit {
        // (Tab: the header's other list; KindToggle: a kind of annotation shown or not, `part`
        // its kind; ShowAll, HideAll: every kind.)
        enum class Kind : uint8_t {
            None, Panel, Row, Box, Up, Down, Hide, Isolate, All, Tab, KindToggle, ShowAll, HideAll,
            NodeRow, NodeBox, Fit, Explode, // (a sub-assembly's row, its box; the footer's last two)
        } kind = Kind::None;
        uint32_t part = 0;
    };
    PartsHit parts_at(int16_t x, int16_t y) const;
    void scroll(int32_t rows);
    Area parts_panel() const;
    uint32_t part_rows() const; // rows the list shows at once
    // A row of the parts list: a sub-assembly (node) or a part (instance), at its depth.
    struct TreeRow {
        bool node;
        uint32_t index, depth;
        bool open;
    };
    uint32_t tree_row_count() const;
    bool tree_row(uint32_t row, TreeRow& out) const; // (false: past the last)

    // The annotations list (the model's PMI: annotations.h), in the parts list's panel, its
    // header's PMI tab opens it (its PARTS tab goes back): a row of the kinds (DIM, TOL, DAT,
    // NOTE), each lit when shown; a row per annotation listed, its text in its kind's colour,
    // the chosen one lit (a tap chooses it, a second lets go); SHOW and HIDE every kind.
    void set_annotating(const Annotating* a) { annotating_ = a, pmi_first_row_ = 0; }
    bool has_pmi() const; // the model has annotations to list
    void set_pmi(bool open);
    bool pmi_open() const { return pmi_open_ && button_count_ > 0 && has_pmi(); }
    PartsHit pmi_at(int16_t x, int16_t y) const; // (Row: `part` the annotation)
    void scroll_pmi(int32_t rows);
    uint32_t pmi_rows() const; // annotations the list shows at once

    // The models chooser (a library's): the parts list's panel, a row per model, the one open
    // highlighted; a tap on a row opens it. (Opening it closes the parts list.)
    void set_library(const Models* library) {
        library_ = library;
        for (uint32_t& w : broken_) w = 0;
    }
    void mark_broken(uint32_t model) { // it could not be opened: its row says so
        if (model < pack::kMaxLibraryEntries) broken_[model / 32] |= 1u << (model % 32);
    }
    bool broken(uint32_t model) const { return model < pack::kMaxLibraryEntries && (broken_[model / 32] >> (model % 32)) & 1u; }
    void set_models(bool open, uint32_t current) {
        models_open_ = open && has_models(), current_model_ = current, first_model_ = 0;
        pmi_open_ = pmi_open_ && !models_open_;
        if (current != kNone && current >= model_rows()) first_model_ = current - model_rows() + 1; // (the open one in view)
        parts_open_ = parts_open_ && !models_open_;
    }
    bool models_open() const { return models_open_ && button_count_ > 0; }
    // A chooser to show: a library's models, or a storage folder's (listed even when empty: it says so).
    bool has_models() const { return library_ && (library_->count() > 0 || library_->on_storage()); }
    void set_storage_gone(bool gone) { storage_gone_ = gone; }
    // With a library, the model's name at the status bar's left end is a button (drawn as one):
    // a tap on it opens the chooser, for a person with only the screen.
    bool name_at(int16_t x, int16_t y) const;
    static constexpr int32_t kNameCells = 16; // the name's characters in the status bar
    // What a tap on the chooser is: None (not the panel), Panel, Row (a model: `part`), Up, Down.
    PartsHit models_at(int16_t x, int16_t y) const;
    void scroll_models(int32_t rows);
    uint32_t model_rows() const; // rows the chooser shows at once

    void set_help(bool on) { help_ = on; }
    bool help() const { return help_; }
    void toggle_help() { help_ = !help_; }
    // The help panel's own button, at its foot: tangent edges shown or left out (what a finger
    // has for key t). Its area while the panel is open (empty otherwise).
    Area help_button() const;
    void set_measuring(bool on) { measuring_ = on; }
    bool measuring() const { return measuring_; }
    // The measurement panel's lines (copied; empty: no panel).
    void set_lines(const char* const* lines, uint32_t count);
    uint32_t line_count() const { return line_count_; }
    const char* line(uint32_t i) const { return i < line_count_ ? lines_[i] : ""; }

    // Everything, into the target's rows.
    void draw(const render::Target& target, const StatusInfo& info) const;
    // The bottom kBarRows rows: `finished` of `total` faces in blue, the rest grey; nothing
    // once every face is in.
    void progress(const render::Target& target, uint32_t finished, uint32_t total) const;

private:
    struct Button {
        int16_t x, y, w, h;
        Action action;
        const char* label;
    };
    void status(const render::Target& t, const StatusInfo& info) const;
    void toolbar(const render::Target& t) const;
    void panel(const render::Target& t) const;
    void help_panel(const render::Target& t, bool tangent_edges) const;
    Area help_area() const; // the help panel: its lines, then its button
    void slider_bar(const render::Target& t) const;
    void parts_list(const render::Target& t) const;
    void models_list(const render::Target& t) const;
    void list_head(const render::Target& t, const Area& p, const char* title) const;
    void list_tab(const render::Target& t, const Area& p, const char* label) const; // the header's other list
    bool tab_hit(int16_t x, int16_t y) const;
    bool list_hit(int16_t x, int16_t y, PartsHit& h) const;
    void pmi_list(const render::Target& t) const;

    uint16_t width_ = 0, height_ = 0;
    int16_t status_rows_ = 0, toolbar_x_ = 0;
    Button buttons_[kButtons] = {};
    uint32_t button_count_ = 0;
    bool help_ = false, measuring_ = false;
    char lines_[kLines][kLineChars] = {};
    uint32_t line_count_ = 0;
    bool slider_on_ = false, explode_on_ = false;
    float slider_value_ = 0.5f, explode_value_ = 0;
    const Scene* scene_ = nullptr;
    bool parts_open_ = false;
    uint32_t first_row_ = 0, chosen_ = kNone, chosen_node_ = kNone;
    uint32_t open_[pack::kMaxTreeDepth + 1] = {}; // the path of open sub-assemblies: open_[d] at depth d (open_[0]: the root)
    uint32_t open_depth_ = 0;                     // how many below the root
    template <typename Each>
    void walk_rows(Each each) const; // each row in order (each returns false: stop)
    void scroll_to(uint32_t row);
    const Models* library_ = nullptr;
    bool storage_gone_ = false;
    bool models_open_ = false;
    uint32_t current_model_ = kNone, first_model_ = 0;
    uint32_t broken_[pack::kMaxLibraryEntries / 32] = {};
    const Annotating* annotating_ = nullptr;
    bool pmi_open_ = false;
    uint32_t pmi_first_row_ = 0; // the annotations list's first row shown
};

} // namespace facet::module
