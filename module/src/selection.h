#pragma once
// The selection: the faces picked (a tap's, or Viewer::select()'s), at most two; measuring,
// the second joins the first. Its own state and rules; the Core turns it into the painter's
// highlight and the measurement panel (pick.cpp).
#include "facet/types.h"

#include <cstdint>

namespace facet::module {

class Selection {
public:
    struct Face {
        uint32_t face, instance;
    };

    uint32_t count() const { return count_; }
    const Face& operator[](uint32_t i) const { return faces_[i]; }
    // Face i's, or kNone past the selection.
    uint32_t face(uint32_t i) const { return i < count_ ? faces_[i].face : kNone; }
    uint32_t instance(uint32_t i) const { return i < count_ ? faces_[i].instance : kNone; }

    void clear() { count_ = 0; }
    // A face picked: it replaces the selection, or, when measuring and one face is selected,
    // becomes the second.
    void pick(Face f, bool measuring) {
        if (measuring && count_ == 1) {
            faces_[1] = f, count_ = 2;
        } else {
            faces_[0] = f, count_ = 1;
        }
    }
    // Measuring starts from the face picked, if any.
    void keep_first() {
        if (count_ > 1) count_ = 1;
    }
    // Whether `test` holds for a face of the selection.
    template <typename Test>
    bool any(Test test) const {
        for (uint32_t i = 0; i < count_; ++i)
            if (test(faces_[i])) return true;
        return false;
    }
    // The faces `gone` says are gone (hidden, or their block left out) leave the selection,
    // the others keep their order. True when some went.
    template <typename Gone>
    bool forget(Gone gone) {
        uint32_t kept = 0;
        for (uint32_t i = 0; i < count_; ++i)
            if (!gone(faces_[i])) faces_[kept++] = faces_[i];
        const bool changed = kept != count_;
        count_ = kept;
        return changed;
    }

private:
    Face faces_[2] = {};
    uint32_t count_ = 0;
};

} // namespace facet::module
