#pragma once
// What the user has picked, shown: the selection (one face, or two when measuring) and the part
// chosen in the parts list, drawn by the painter (the picked faces in the highlight colour, the
// chosen part in focus) and described on the panel (each face's exact facts, and between two
// faces their distance and angle).
#include "painter.h"
#include "presenter.h"
#include "scene.h"
#include "selection.h"

#include <cstdint>

namespace facet::module {

class Picks {
public:
    using Face = Selection::Face;

    // `panel`: the full on-screen interface (the panel's lines are shown).
    Picks(const Scene& scene, Painter& painter, Presenter& presenter, bool panel)
        : scene_(scene), painter_(painter), presenter_(presenter), panel_(panel) {}

    const Selection& selection() const { return selection_; }
    uint32_t chosen() const { return chosen_; }
    bool measuring() const { return presenter_.overlay().measuring(); }

    // A new model (or none): nothing picked or chosen.
    void reset();
    // A face picked (or, hit false, nothing: the selection clears).
    void picked(bool hit, const Face& f);
    // Measuring on or off: it starts from the face picked, if any.
    void set_measuring(bool on);
    // The part chosen (kNone: none; the caller's to check it is one).
    void choose(uint32_t part);
    // A node of the assembly tree chosen (its parts lit; kNone: none), instead of a part.
    void choose_node(uint32_t node);
    uint32_t chosen_node() const { return chosen_node_; }
    // An annotation chosen (a tap on its label, or the call; kNone: none): its faces lit, its
    // text and what it applies to on the panel. A face picked ends it.
    void choose_annotation(uint32_t annotation);
    uint32_t chosen_annotation() const { return presenter_.annotating().chosen(); }
    // A part hidden: a selection with a face of it goes whole.
    void hidden(uint32_t part);
    // The faces `gone` says are gone (their block left out) leave the selection.
    template <typename Gone>
    void forget(Gone gone) {
        if (selection_.forget(gone)) shown();
    }
private:
    void shown();       // the painter's highlight and focus, the panel's lines
    void highlight();   // the painter's highlight from the selection (and the focus)
    void focus();       // the painter's chosen part and see-through focus
    void panel();       // the panel's lines: the faces' facts, their measurement (or the annotation chosen)
    bool annotation_panel(); // the annotation chosen's lines (false: none chosen)
    void redraw();      // a whole frame (the faces kept, but in see-through mode)
    const Scene& scene_;
    Painter& painter_;
    Presenter& presenter_;
    bool panel_;
    Selection selection_;
    uint32_t chosen_ = kNone, chosen_node_ = kNone;
};

} // namespace facet::module
