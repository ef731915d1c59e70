#include "geom/elementary.h"

#include "face_internal.h"
#include "geom/fmath.h"

#include <algorithm>

namespace facet::geom {

using detail::kTwoPi;
using detail::max_arc_angle;

namespace {

using pack::SurfaceType;

// a into [lo, lo + 2 pi).
float wrap(float a, float lo) {
    if (a < lo) a += kTwoPi; // atan2 is within pi of 0: one turn does it for most faces
    else if (a >= lo + kTwoPi) a -= kTwoPi;
    if (a >= lo && a < lo + kTwoPi) return a;
    float r = std::fmod(a - lo, kTwoPi);
    if (r < 0) r += kTwoPi;
    return lo + r;
}

// a, by whole turns, within pi of mid.
float near(float a, float mid) {
    float r = std::fmod(a - (mid - kTwoPi / 2), kTwoPi);
    if (r < 0) r += kTwoPi;
    return mid - kTwoPi / 2 + r;
}

// How far (u,v) lies outside the bounds (0 inside).
float outside(Vec2 p, const float lo[2], const float hi[2]) {
    const float du = p.x < lo[0] ? lo[0] - p.x : (p.x > hi[0] ? p.x - hi[0] : 0);
    const float dv = p.y < lo[1] ? lo[1] - p.y : (p.y > hi[1] ? p.y - hi[1] : 0);
    return du + dv;
}

} // namespace

Vec2 Elementary::torus_candidate(float x, float y, float z, const float uv_min[2], const float uv_max[2], int which) const {
    const float R = radius_, rho = sqrt_f(x * x + y * y), u1 = atan2_f(y, x);
    const float um = 0.5f * (uv_min[0] + uv_max[0]), vm = 0.5f * (uv_min[1] + uv_max[1]);
    return which == 0 ? Vec2{near(u1, um), near(atan2_f(z, rho - R), vm)}
                      : Vec2{near(u1 + kTwoPi / 2, um), near(atan2_f(z, -rho - R), vm)};
}

Vec2 Elementary::inverse(Vec3 P, const float uv_min[2], const float uv_max[2]) const {
    const Vec3 d = P - O_;
    const float x = dot(d, X_), y = dot(d, Y_), z = dot(d, Z_);
    switch (type_) {
    case SurfaceType::Plane: return {x, y};
    case SurfaceType::Cylinder: return {wrap(atan2_f(y, x), uv_min[0]), z};
    case SurfaceType::Cone: {
        // v from the height alone; past the apex the radius R + v sin a is negative and the
        // point lies opposite its direction from the axis.
        const float v = z / cos_a_;
        const float turn = radius_ + v * sin_a_ < 0 ? kTwoPi / 2 : 0;
        return {wrap(atan2_f(y, x) + turn, uv_min[0]), v};
    }
    case SurfaceType::Sphere: return {wrap(atan2_f(y, x), uv_min[0]), atan2_f(z, sqrt_f(x * x + y * y))};
    case SurfaceType::Torus: {
        const Vec2 c[2] = {torus_candidate(x, y, z, uv_min, uv_max, 0), torus_candidate(x, y, z, uv_min, uv_max, 1)};
        // The candidate inside the face's bounds (or nearer its middle).
        return outside(c[0], uv_min, uv_max) <= outside(c[1], uv_min, uv_max) ? c[0] : c[1];
    }
    default: return {};
    }
}

int Elementary::preimages(Vec3 P, const float uv_min[2], const float uv_max[2], Vec2 out[2]) const {
    if (type_ != SurfaceType::Torus) {
        out[0] = inverse(P, uv_min, uv_max);
        return 1;
    }
    const Vec3 d = P - O_;
    const float x = dot(d, X_), y = dot(d, Y_), z = dot(d, Z_);
    out[0] = torus_candidate(x, y, z, uv_min, uv_max, 0);
    out[1] = torus_candidate(x, y, z, uv_min, uv_max, 1);
    return minor_ > radius_ ? 2 : 1; // only a self-intersecting torus has a second preimage
}

void Elementary::bending(float v, float& ku, float& kv) const {
    ku = kv = 0;
    switch (type_) {
    case SurfaceType::Cylinder: ku = 1 / radius_; return;
    case SurfaceType::Cone: {
        const float r = std::fabs(radius_ + v * sin_a_);
        ku = r > 0 ? std::fabs(cos_a_) / r : 0;
        return;
    }
    case SurfaceType::Sphere: ku = kv = 1 / radius_; return;
    case SurfaceType::Torus: {
        float sv, cv;
        sincos_f(v, sv, cv);
        const float rho = std::fabs(radius_ + minor_ * cv);
        kv = 1 / minor_;
        ku = rho > 0 ? std::fabs(cv) / rho : 0;
        return;
    }
    default: return; // a plane
    }
}

Elementary::FlatBound Elementary::flat_bound(float tol, float v_min, float v_max) const {
    using Kind = FlatBound::Kind;
    switch (type_) {
    case SurfaceType::Plane: return {Kind::Everywhere, 0};
    case SurfaceType::Cylinder: return {Kind::USpan, max_arc_angle(radius_, tol)};
    case SurfaceType::Cone: { // the widest circle of the face's part of the cone
        const float r0 = std::fabs(radius_ + v_min * sin_a_), r1 = std::fabs(radius_ + v_max * sin_a_);
        return {Kind::USpan, max_arc_angle(std::max(r0, r1), tol)};
    }
    case SurfaceType::Sphere: return {Kind::Circumradius, std::max(0.0f, 2 * radius_ * tol - tol * tol)};
    default: return {};
    }
}

} // namespace facet::geom
