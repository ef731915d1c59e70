// The viewer's views: framing the model (or a part, or a face), the standard views and the
// glide to them, the orbit set at once, the projection, the display mode.
#include "core.h"

#include <cmath>

namespace facet {

// The placed model bounded again before it is framed: from its samples and mesh in pieces of
// work (step() runs them before the framer's), or at once from its edges' ends while the edges
// are being sampled (no framing then).
void Core::bound(bool sampled) {
    if (sampled) scene_.start_bounds(true);
    else scene_.fit_bounds(false);
}

void Core::glide_to(const module::View& v, uint32_t instance, uint32_t face, uint32_t instances) {
    if (!scene_.loaded()) return;
    framer_.stop(); // a glide frames its own end view
    glide_.begin(v);
    const bool sampled = !scheduler_.sampling();
    bound(sampled);
    if (sampled) {
        // A face is framed to fill less: it is seen among its neighbours.
        framer_.start(config_.display.width, config_.display.height, presenter_.overlay().taken(), instance, face,
                      face == kNone ? module::Framer::kFill : 0.6f, instances);
    }
}

bool Core::glide_step() {
    camera_.set_view(glide_.next(config_.now_us != nullptr, now()));
    view_changed();
    return true;
}

void Core::fit_view(bool keep_direction, bool from_here) {
    const bool sampled = !scheduler_.sampling();
    framed_from_ = camera_.view();
    bound(sampled);
    if (from_here) {
        // (the view framed already, from a nearly equal outline: fewer rounds from it)
    } else if (keep_direction) {
        camera_.reframe();
    } else {
        camera_.fit();
    }
    if (sampled) framer_.start(config_.display.width, config_.display.height, presenter_.overlay().taken());
}

namespace {
constexpr float kDegrees = 57.2957795f;
static_assert(uint8_t(StandardView::Iso) == uint8_t(module::Standard::Iso) && uint8_t(StandardView::Top) == uint8_t(module::Standard::Top),
              "StandardView is module::Standard");
} // namespace

Orbit Core::orbit() const {
    const module::View& v = camera_.view();
    return {v.yaw * kDegrees, v.pitch * kDegrees, v.zoom, {v.pan_x, v.pan_y}, v.ortho};
}

Result Core::set_orbit(const Orbit& o) {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    const float values[] = {o.yaw_deg, o.pitch_deg, o.dolly, o.pan_mm[0], o.pan_mm[1]};
    for (const float x : values) {
        if (!std::isfinite(x)) return Result::fail(Status::OutOfRange, "an orbit's values must be finite");
    }
    if (!(o.dolly >= module::Camera::kNearest && o.dolly <= module::Camera::kFarthest)) {
        return Result::fail(Status::OutOfRange, "the orbit's dolly is outside 0.05 to 20");
    }
    const float most = module::Camera::kPanRadii * scene_.radius();
    if (!(std::fabs(o.pan_mm[0]) <= most && std::fabs(o.pan_mm[1]) <= most)) {
        return Result::fail(Status::OutOfRange, "the orbit's pan takes the model further than 64 of its radii away");
    }
    glide_.stop();
    framer_.stop();
    camera_.set_view({o.yaw_deg / kDegrees, o.pitch_deg / kDegrees, o.dolly, o.pan_mm[0], o.pan_mm[1], o.parallel});
    view_changed();
    return {};
}

void Core::show_view(StandardView v) { glide_to(module::standard_view(module::Standard(uint8_t(v)), camera_.view())); }

void Core::fit() {
    if (!scene_.loaded()) return;
    fit_view(true);
    view_changed();
    user_moved_ = false; // framed again once the faces are in
}

Result Core::fit_part(uint32_t part, uint32_t face) {
    if (const Result r = face == kNone ? check_part(part) : check_face(part, face); !r.ok()) return r;
    glide_to(camera_.view(), part, face);
    return {};
}

void Core::set_parallel(bool parallel) {
    // From the view under way if a glide is (a standard view asked for just before stays asked for).
    module::View v = glide_.going_to(camera_.view());
    if (v.ortho == parallel) return;
    v.ortho = parallel;
    glide_to(v); // framed again: a parallel view of the same zoom is not the same size
}

void Core::set_mode(DisplayMode m) {
    if (m == painter_.mode()) return;
    painter_.set_mode(m);
    presenter_.invalidate(); // a whole frame in the new style
}

void Core::set_tangent_edges(bool shown) {
    if (shown == painter_.tangent_edges()) return;
    painter_.set_tangent_edges(shown);
    presenter_.redraw(); // (edges alone)
}

} // namespace facet
