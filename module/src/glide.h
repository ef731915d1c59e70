#pragma once
// A glide to a new view: the end view framed first (on a camera of its own: the Core runs the
// framer on target()), then the camera moved there over kUs (or kFrames frames without a
// clock), eased in and out, the short way round in yaw, a frame at each step.
#include "camera.h"

#include <cstdint>

namespace facet::module {

class Glide {
public:
    enum class Phase : uint8_t { None, Framing, Moving };
    static constexpr uint32_t kUs = 400000, kFrames = 10;

    bool idle() const { return phase_ == Phase::None; }
    bool framing() const { return phase_ == Phase::Framing; }
    bool moving() const { return phase_ == Phase::Moving; }
    Camera& target() { return target_; }
    const Camera& target() const { return target_; }
    // The view the glide is going to, or `now` when there is none.
    const View& going_to(const View& now) const { return idle() ? now : target_.view(); }

    // A glide to view v begins: its end framed first (the target camera reframed for it).
    void begin(const View& v) {
        target_.set_view(v);
        target_.reframe();
        phase_ = Phase::Framing;
    }
    // The end view is framed: the move from `from` begins at `t0` (us).
    void framed(const View& from, uint32_t t0) {
        phase_ = Phase::Moving;
        from_ = from, t0_ = t0, frames_ = 0;
    }
    void stop() { phase_ = Phase::None; }

    // The next view of the move at `now_us` (with a clock), or a frame further (without one);
    // at the end, the target's, and the glide is over.
    View next(bool clocked, uint32_t now_us) {
        const View &a = from_, &b = target_.view();
        float s = clocked ? float(now_us - t0_) / float(kUs) : float(++frames_) / float(kFrames);
        if (s >= 1) {
            phase_ = Phase::None;
            return b;
        }
        s = s * s * (3 - 2 * s); // eased in and out
        constexpr float kPi = 3.14159265358979f;
        float dyaw = b.yaw - a.yaw; // the short way round
        while (dyaw > kPi) dyaw -= 2 * kPi;
        while (dyaw < -kPi) dyaw += 2 * kPi;
        View v = b;
        v.yaw = a.yaw + dyaw * s;
        v.pitch = a.pitch + (b.pitch - a.pitch) * s;
        v.zoom = a.zoom + (b.zoom - a.zoom) * s;
        v.pan_x = a.pan_x + (b.pan_x - a.pan_x) * s;
        v.pan_y = a.pan_y + (b.pan_y - a.pan_y) * s;
        return v;
    }

private:
    Phase phase_ = Phase::None;
    Camera target_;
    View from_{};
    uint32_t t0_ = 0, frames_ = 0;
};

} // namespace facet::module
