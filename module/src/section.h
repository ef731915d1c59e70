#pragma once
// The section plane as a tool: what cuts the model (the camera's Section), the kind the
// toolbar's cycle is at, the slider that shows where the plane lies in its range (the placed
// model's sphere along its normal), and the moves of the plane within that range.
#include "camera.h"
#include "presenter.h"
#include "scene.h"

#include <cstdint>

namespace facet::module {

class Sectioning {
public:
    // The toolbar's cycle: off -> the picked planar face's plane -> x -> y -> z -> off. A plane
    // the application sets counts as Z (the next step turns it off).
    enum class Kind : uint8_t { Off, Picked, X, Y, Z };
    static constexpr float kStep = 1.0f / 32; // SectionIn / SectionOut: of the model's diameter

    // `slider`: the full on-screen interface (the slider is shown while a section is on).
    Sectioning(const Scene& scene, Camera& camera, Presenter& presenter, bool slider)
        : scene_(scene), camera_(camera), presenter_(presenter), slider_(slider) {}

    // A new model (or none): no section, the slider hidden.
    void reset();
    Kind kind() const { return kind_; }
    // Section s (off: none), reached as `kind`.
    void set(const Section& s, Kind kind);
    // Across the placed model's middle, normal to axis 0 (x), 1 (y) or 2 (z).
    [[nodiscard]] Result across(uint8_t axis);
    // The plane moved to `at` of its range (0: the near end, 1: the far end; clamped), or by `at`
    // of it from where it is (relative).
    void at(float at, bool relative);
    // The plane moved by `by_mm` along its normal (within its range).
    [[nodiscard]] Result move(float by_mm);
    // The cycle's next kind that can be set: `picked()` sets the picked face's plane when there
    // is one (true then).
    template <typename Picked>
    void next(Picked picked) {
        for (uint8_t k = uint8_t((uint8_t(kind_) + 1) % 5);; k = uint8_t((k + 1) % 5)) {
            const Kind kind = Kind(k);
            if (kind == Kind::Off) return set(Section{}, Kind::Off);
            if (kind == Kind::Picked ? picked() : across(uint8_t(k - uint8_t(Kind::X))).ok()) return;
        }
    }

private:
    void range(const Section& s, float& lo, float& hi) const;
    void changed(); // the slider and the frames follow the plane
    const Scene& scene_;
    Camera& camera_;
    Presenter& presenter_;
    bool slider_;
    Kind kind_ = Kind::Off;
};

} // namespace facet::module
