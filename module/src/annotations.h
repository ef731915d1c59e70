#pragma once
// A model's annotations (PMI: geom/pmi.h) over the view: each presentation's polylines (its
// leaders, frames and the CAD system's stroked text) drawn as lines over the model, in its
// kind's colour, faded where its plane turns its back to the eye; and the text of each in
// facet's font on a label at its anchor, where the stroked text is too small to read (or the
// file gives no presentation), labels that would cover one already placed left out. Shown all,
// by kind, or none; one chosen (its faces lit, its label and lines in the highlight colour).
// The faces an annotation applies to are a pick's facts (face_line()).
#include "camera.h"
#include "geom/pmi.h"
#include "render/raster.h"

#include <cstdint>

namespace facet::module {

class Annotating {
public:
    static constexpr uint32_t kNone = 0xFFFFFFFFu;
    // Labels placed in a frame at most (a 480 x 272 screen holds some 60 apart): those past it
    // are left out as covered ones are, and counted (labels_left_out()).
    static constexpr uint32_t kMaxLabels = 96;
    // A presentation whose strokes (pack::Annotation::stroke, about its text's height) draw
    // under this many pixels has its outline drawn alone and its text on a label.
    static constexpr int32_t kReadablePixels = 9;

    void set(const geom::Annotations* pmi) {
        pmi_ = pmi, chosen_ = kNone, placed_ = 0, candidates_ = 0, left_out_ = 0, listed_ = 0;
        for (uint32_t i = 0; i < count(); ++i) listed_ += listed(i);
    }
    const geom::Annotations* annotations() const { return pmi_ && pmi_->count() ? pmi_ : nullptr; }
    uint32_t count() const { return pmi_ ? pmi_->count() : 0; }
    // The kinds shown (pack::kind_bit of each; 0: none).
    void show(uint32_t kinds) { shown_ = kinds & pack::kAllKinds; }
    uint32_t shown() const { return shown_; }
    bool drawing() const { return count() && shown_; }
    void choose(uint32_t i) { chosen_ = i < count() ? i : kNone; }
    uint32_t chosen() const { return chosen_; }

    // A piece of a frame's annotations into the rasterizer's target (one band): the polylines
    // of annotations [from, ...) until about `units` are spent (a unit: 64 points or 8 labels),
    // `spent` what was; then the labels. Returns where to go on; count() + 1 when done.
    // `t`: the view's transform of the placed model (mesh units of `unit` mm).
    // `rows`: the band's (Painter::rows), `screen`: the whole screen's (labels are placed on it
    // whole, in every band alike); `diagonal_mm`: the pack's box diagonal (kCoarsePolylines).
    uint32_t draw(render::Rasterizer& raster, const Transform& t, Rows rows, Rows screen, float unit, float diagonal_mm, uint32_t from,
                  uint32_t units, uint32_t& spent);
    // The annotation whose label (as the last frame placed it) is under a screen pixel, or kNone.
    uint32_t label_at(int16_t x, int16_t y) const;
    uint32_t labels_left_out() const { return left_out_; }
    // The annotations of face f (a pack face), each once (the first of those with its text),
    // up to `max` into out; how many there are in all.
    uint32_t of_face(uint32_t f, uint32_t* out, uint32_t max) const;
    // "PMI: ⌀52 ±0.15 · ⏥ 0.05" for face f (empty: none), cut to `bytes` on a character.
    void face_line(uint32_t f, char* line, uint32_t bytes) const;
    // Whether annotation i's text stands for it in a list (not the same as an earlier one's:
    // the file gives a datum once per tolerance that refers to it).
    bool listed(uint32_t i) const;
    uint32_t listed_count() const { return listed_; }
    uint32_t next_listed(uint32_t from) const { // the first listed at or after `from` (count(): none)
        while (from < count() && !listed(from)) ++from;
        return from < count() ? from : count();
    }
    uint32_t nth_listed(uint32_t n) const { // the list's row n (count(): past the last)
        uint32_t i = next_listed(0);
        for (; n > 0 && i < count(); --n) i = next_listed(i + 1);
        return i;
    }

    // Millimetres to mesh units (Scene::unit) from a float's bits, no soft float: 1/unit as
    // m 2^e. False for a coordinate of 2^30 units or more (left out: it would overflow).
    struct UnitScale {
        uint32_t m;
        int32_t e;
    };
    static UnitScale unit_scale(float unit);
    static bool to_units(float mm, const UnitScale& s, int32_t& q);

private:
    struct Label {
        int16_t x, y, w, h; // placed: its box; a candidate: its anchor on the screen (pixels)
        uint32_t annotation;
    };
    bool kind_shown(uint32_t i) const { return (shown_ >> (*pmi_)[i].kind) & 1u; }
    struct Frame {
        const Transform& t;
        Rows rows, screen;
        UnitScale unit;
        float coarse_below; // sub-pixels across a millimetre of radius under which the coarse polylines do
    };
    uint32_t polylines(render::Rasterizer& raster, const Frame& f, uint32_t i);
    // A sphere's size across on the screen (sub-pixels; -1: behind the eye or too far off).
    static int32_t across_screen(const Frame& f, const float centre_mm[3], float radius_mm);
    // Whether its strokes draw under kReadablePixels: too small to read (its label stands for
    // its text, its outline alone is drawn).
    bool too_small(const Frame& f, uint32_t i) const;
    void candidate(const Transform& t, const UnitScale& unit, uint32_t i); // its label wanted at its anchor
    void labels(render::Rasterizer& raster);                              // the candidates placed and drawn
    static bool quantize(const float p_mm[3], const UnitScale& s, int32_t q[3]);
    static bool project(const float p_mm[3], const Transform& t, const UnitScale& unit, Projected& out);
    bool faces_away(uint32_t i, const Transform& t, const UnitScale& unit) const;

    const geom::Annotations* pmi_ = nullptr;
    uint32_t shown_ = pack::kAllKinds;
    uint32_t chosen_ = kNone;
    Label candidates_list_[kMaxLabels] = {}, placed_labels_[kMaxLabels] = {};
    uint32_t candidates_ = 0, placed_ = 0, left_out_ = 0, wanted_ = 0;
    uint32_t listed_ = 0;
};

} // namespace facet::module
