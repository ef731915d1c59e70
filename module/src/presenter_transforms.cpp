// Each instance's transform in a frame (presenter.h): the view's basis made once a view, and
// the first kKeptPlacements instances' own parts of it and kKeptEyes eyes kept from frame to frame.
#include "presenter.h"

#include <cstring> // (std::memcpy)

namespace facet::module {

const Transform& Presenter::transform_of(uint32_t instance) {
    (void)view_basis();
    if (!keep_ || instance >= kKeptPlacements) return made_ = Camera::transform(basis_, scene_, instance);
    KeptPlacement& kept = kept_[instance];
    if (kept.stamp != kept_stamp_) {
        made_ = Camera::transform(basis_, scene_, instance);
        kept.keep(made_);
        kept.stamp = kept_stamp_;
        return made_;
    }
    made_ = basis_.shared;
    kept.into(made_);
    return made_;
}

const ViewBasis& Presenter::view_basis() {
    const View& v = camera_.view();
    const Section& s = camera_.section();
    const float* c = scene_.centre();
    KeptFor& k = kept_for_;
    const bool same_section = k.section.on == s.on && k.section.n[0] == s.n[0] && k.section.n[1] == s.n[1] &&
                              k.section.n[2] == s.n[2] && k.section.offset == s.offset;
    const bool same_placing = same_view(k.view, v) && k.width == display_.width && k.height == display_.height &&
                              k.radius == scene_.radius() && k.unit == scene_.unit() && k.centre[0] == c[0] &&
                              k.centre[1] == c[1] && k.centre[2] == c[2] && k.explode == scene_.explode();
    if (!same_section || !same_placing) {
        k = {v, s, display_.width, display_.height, scene_.radius(), {c[0], c[1], c[2]}, scene_.unit(), scene_.explode()};
        basis_ = camera_.basis(scene_, display_.width, display_.height);
        if (!same_placing) ++kept_stamp_; // (a section alone changes the cut, which the basis holds)
    }
    return basis_;
}

Transform Presenter::model_transform(bool closed) {
    static constexpr float kIdentity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    return Camera::transform(view_basis(), kIdentity, closed);
}

void Presenter::place_eye() {
    Transform& t = job_.transform;
    if (t.eye_placed) return;
    const uint32_t id = job_.id;
    KeptEye& kept = eyes_[id % kKeptEyes];
    if (keep_ && id < kKeptPlacements && kept.instance == id && kept.stamp == kept_stamp_) {
        std::memcpy(t.eye, kept.eye, sizeof t.eye), std::memcpy(t.toward, kept.toward, sizeof t.toward);
        t.eye_placed = true;
        return;
    }
    t.place_eye();
    if (id >= kKeptPlacements) return;
    kept.instance = id, kept.stamp = kept_stamp_;
    std::memcpy(kept.eye, t.eye, sizeof t.eye), std::memcpy(kept.toward, t.toward, sizeof t.toward);
}

} // namespace facet::module
