#include "camera.h"

#include "geom/fmath.h"
#include "scene.h"

#include <algorithm>
#include <cmath>

namespace facet::module {
namespace {

constexpr float kViewPerDiagonal = 65536.0f; // 2^16: camera-space unit = diagonal / 2^16
constexpr int32_t kRadiusV = 32768;          // the bounding sphere's radius in view units
constexpr float kAwayMargin = 0.02f;          // about a degree: a plane nearer edge-on is not judged away

inline int32_t round_to_int(float v) { return int32_t(v + (v >= 0 ? 0.5f : -0.5f)); }

// The eye's distance from the centre in view units, and the focal length in sub-pixels: the
// bounding sphere fills 80% of the short side when fitted.
int32_t eye_distance(float zoom) { return round_to_int(3.0f * kRadiusV * zoom); }
int32_t focal16(uint16_t width, uint16_t height) {
    const float half = 0.5f * float(width < height ? width : height);
    return round_to_int(float(render::subpixel::kPerPixel) * 2.5f * half);
}

} // namespace

View standard_view(Standard s, const View& from) {
    constexpr float kPi = 3.14159265358979f, kHalf = kPi / 2;
    View v = from;
    switch (s) {
    case Standard::Front: v.yaw = 0, v.pitch = -kHalf; break;
    case Standard::Back: v.yaw = kPi, v.pitch = -kHalf; break;
    case Standard::Right: v.yaw = -kHalf, v.pitch = -kHalf; break;
    case Standard::Left: v.yaw = kHalf, v.pitch = -kHalf; break;
    case Standard::Top: v.yaw = 0, v.pitch = 0; break;
    case Standard::Bottom: v.yaw = 0, v.pitch = -kPi; break;
    case Standard::Iso: v.yaw = -kPi / 4, v.pitch = -0.9553166181f; break; // atan(sqrt 2)
    }
    return v;
}

View Camera::in_range(View v, float radius) {
    const View def{};
    // (Any finite angle turns the same way: geom::sincos_f reduces it exactly.)
    if (!std::isfinite(v.yaw)) v.yaw = def.yaw;
    if (!std::isfinite(v.pitch)) v.pitch = def.pitch;
    v.zoom = std::isfinite(v.zoom) ? std::clamp(v.zoom, kNearest, kFarthest) : def.zoom;
    const float most = kPanRadii * (radius > 0 && std::isfinite(radius) ? radius : 1);
    v.pan_x = std::isfinite(v.pan_x) ? std::clamp(v.pan_x, -most, most) : 0;
    v.pan_y = std::isfinite(v.pan_y) ? std::clamp(v.pan_y, -most, most) : 0;
    return v;
}

void Camera::orbit(float d_yaw, float d_pitch) {
    view_.yaw += d_yaw;
    view_.pitch += d_pitch;
}

void Camera::dolly(float factor) {
    view_.zoom *= factor;
    if (view_.zoom < kNearest) view_.zoom = kNearest;
    if (view_.zoom > kFarthest) view_.zoom = kFarthest;
}

void Camera::pan(float dx_mm, float dy_mm) {
    view_.pan_x += dx_mm;
    view_.pan_y += dy_mm;
}

void Camera::pan_pixels(int32_t dx, int32_t dy, float radius, uint16_t width, uint16_t height) {
    // Millimetres per pixel at the model's centre (its bounding sphere fills 80% of the short side).
    const float px = 2 * radius * 3 * view_.zoom / (2.5f * 0.5f * float(width < height ? width : height));
    view_.pan_x += float(dx) * px / 2;
    view_.pan_y -= float(dy) * px / 2;
}

void Camera::rotation(float R[9]) const { rotation(in_range(view_, 1), R); }

void Camera::rotation(const View& v, float R[9]) {
    float sy, cy, sp, cp;
    geom::sincos_f(v.yaw, sy, cy);
    geom::sincos_f(v.pitch, sp, cp);
    // Rotate about z (yaw), then tilt about x (pitch): CAD models are usually z-up.
    const float r[9] = {cy, -sy, 0, sy * cp, cy * cp, -sp, sy * sp, cy * sp, cp};
    for (int i = 0; i < 9; ++i) R[i] = r[i];
}

// The transform's dist over its view units per mm (the sphere's radius is kRadiusV units).
float Camera::distance_mm(const Scene& scene) const {
    return float(eye_distance(in_range(view_, scene.radius()).zoom)) * (2 * scene.radius()) / kViewPerDiagonal;
}

float Camera::focal_px(uint16_t width, uint16_t height) {
    return float(focal16(width, height)) / 16;
}

ViewBasis Camera::basis(const Scene& scene, uint16_t width, uint16_t height) const {
    const View v = in_range(view_, scene.radius()); // (in range by construction, whatever the view holds)
    ViewBasis basis{};
    float* R = basis.R;
    rotation(v, R);
    const float radius = scene.radius();
    const float* centre = basis.centre = scene.centre();
    const float v_per_mm = basis.v_per_mm = kViewPerDiagonal / (2 * radius);
    float* pan = basis.pan;
    pan[0] = v.pan_x, pan[1] = v.pan_y, pan[2] = 0;
    // View units per mesh unit: 1/16 when the placed model is its shells' own box (the view's
    // diagonal is 2^16 units, the mesh's 2^20); at most 1 (Scene::fit_bounds keeps it so).
    basis.k = scene.unit() * v_per_mm;
    basis.k30 = basis.k * 1073741824.0f; // a's scale, 2^30 (a power of two: A k 2^30 rounds as A k)
    Transform& in = basis.shared;
    in.k16 = round_to_int(basis.k * 65536.0f) + 1;
    in.dist = eye_distance(v.zoom);
    in.near = kRadiusV / 64;
    in.f16 = focal16(width, height);
    in.cx16 = int32_t(width) * (render::subpixel::kPerPixel / 2); // the screen's centre
    in.cy16 = int32_t(height) * (render::subpixel::kPerPixel / 2);
    in.guard = render::kGuardBand - (in.cx16 > in.cy16 ? in.cx16 : in.cy16) - 64;
    const int32_t far = in.dist + kRadiusV;
    in.zk = (int64_t(65535) << 16) / (far - in.near > 1 ? far - in.near : 1);
    in.ortho = v.ortho;
    if (in.ortho) in.ortho_r = render::reciprocal(uint32_t(in.dist));
    if (section_.on) {
        // View space is v = v_per_mm (R (W - centre) + pan), depth d = dist - v_z; the plane
        // n . W = offset in it: (R n) . v / v_per_mm - (R n) . pan + n . centre - offset.
        const float* n = section_.n;
        float r[3];
        for (int i = 0; i < 3; ++i) r[i] = R[3 * i] * n[0] + R[3 * i + 1] * n[1] + R[3 * i + 2] * n[2];
        constexpr float Q = 16384.0f;
        const float at = n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] - section_.offset - r[0] * pan[0] - r[1] * pan[1];
        in.cut.on = true;
        in.cut.nx = round_to_int(Q * r[0]), in.cut.ny = round_to_int(Q * r[1]), in.cut.nd = round_to_int(-Q * r[2]);
        const double c = double(Q) * (double(r[2]) * in.dist + double(v_per_mm) * at);
        in.cut.c = int64_t(c + (c >= 0 ? 0.5 : -0.5));
        in.cut.c_float = float(in.cut.c);
    }
    return basis;
}

int32_t Transform::across(const int32_t sphere_centre[3], int32_t radius, int32_t most, Projected& centre) const {
    render::Reciprocal r;
    project(sphere_centre, centre, r);
    if (centre.out) return -1;
    const int64_t size = 2 * ((int64_t(radius) * k16) >> 16) * f16; // sub-pixels times the depth
    if (size >= int64_t(most) * (ortho ? dist : centre.d)) return most;
    return render::divide(size, r); // (over's reciprocal: the projection's)
}

Transform Camera::transform(const ViewBasis& basis, const Scene& scene, uint32_t index) {
    pack::Instance scratch;
    const pack::Instance& inst = scene.placed(index, scratch); // (exploded, where the view is)
    return transform(basis, inst.m, scene.part(inst.shell).closed);
}

Transform Camera::transform(const ViewBasis& basis, const float m[12], bool closed) {
    Transform in = basis.shared;
    const float* R = basis.R;
    float A[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[3 * i + j] = R[3 * i] * m[j] + R[3 * i + 1] * m[4 + j] + R[3 * i + 2] * m[8 + j];
    const float* centre = basis.centre;
    const float t[3] = {m[3] - centre[0], m[7] - centre[1], m[11] - centre[2]};
    const float* pan = basis.pan;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) in.a[3 * i + j] = round_to_int(A[3 * i + j] * basis.k30);
        in.b[i] = round_to_int((R[3 * i] * t[0] + R[3 * i + 1] * t[1] + R[3 * i + 2] * t[2] + pan[i]) * basis.v_per_mm);
    }
    // The light, fixed in view space (upper left, toward the viewer), into shell coordinates,
    // Q14 (scaled by a power of two before the products: the same floats as after them).
    constexpr float Q = 16384.0f, L[3] = {-0.38f * Q, 0.5f * Q, 0.78f * Q};
    for (int j = 0; j < 3; ++j) in.light[j] = round_to_int(A[j] * L[0] + A[3 + j] * L[1] + A[6 + j] * L[2]);
    const float det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
    in.mirrored = det < 0;
    in.closed = closed;
    return in;
}

Transform Camera::transform(const Scene& scene, uint32_t index, uint16_t width, uint16_t height) const {
    Transform in = transform(basis(scene, width, height), scene, index);
    in.place_eye();
    return in;
}

void Transform::place_eye() {
    // The eye (view (0, 0, dist)) and the way to it (view +z) back in shell coordinates:
    // P = a^-1 (view - b) 2^30, with a's inverse from its cofactors.
    double m3[9], inv[9];
    for (int i = 0; i < 9; ++i) m3[i] = double(a[i]) / 1073741824.0;
    inv[0] = m3[4] * m3[8] - m3[5] * m3[7], inv[1] = m3[2] * m3[7] - m3[1] * m3[8], inv[2] = m3[1] * m3[5] - m3[2] * m3[4];
    inv[3] = m3[5] * m3[6] - m3[3] * m3[8], inv[4] = m3[0] * m3[8] - m3[2] * m3[6], inv[5] = m3[2] * m3[3] - m3[0] * m3[5];
    inv[6] = m3[3] * m3[7] - m3[4] * m3[6], inv[7] = m3[1] * m3[6] - m3[0] * m3[7], inv[8] = m3[0] * m3[4] - m3[1] * m3[3];
    const double det3 = m3[0] * inv[0] + m3[1] * inv[3] + m3[2] * inv[6];
    const double v[3] = {-double(b[0]), -double(b[1]), double(dist) - double(b[2])};
    double most = 0; // the way to the eye: only its direction counts (largest component 2^14)
    for (int i = 0; i < 3; ++i) {
        const double e = (inv[3 * i] * v[0] + inv[3 * i + 1] * v[1] + inv[3 * i + 2] * v[2]) / det3;
        eye[i] = int64_t(e + (e >= 0 ? 0.5 : -0.5));
        most = std::max(most, inv[3 * i + 2] < 0 ? -inv[3 * i + 2] : inv[3 * i + 2]);
    }
    const double q = (det3 < 0 ? -16384.0 : 16384.0) / most;
    for (int i = 0; i < 3; ++i) {
        const double w = inv[3 * i + 2] * q;
        toward[i] = int32_t(w + (w >= 0 ? 0.5 : -0.5));
    }
    eye_placed = true;
}

SphereView Camera::sphere_view(const Scene& scene, uint16_t width, uint16_t height) const {
    const View v = in_range(view_, scene.radius());
    SphereView s{};
    rotation(v, s.R);
    for (int k = 0; k < 3; ++k) s.centre[k] = scene.centre()[k];
    s.pan[0] = v.pan_x, s.pan[1] = v.pan_y;
    s.dist = float(eye_distance(v.zoom)) * (2 * scene.radius()) / kViewPerDiagonal; // (distance_mm, in range)
    s.near = float(kRadiusV / 64) * (2 * scene.radius()) / kViewPerDiagonal; // as Transform::near
    s.focal = focal_px(width, height);
    s.half_w = 0.5f * float(width), s.half_h = 0.5f * float(height);
    s.ortho = v.ortho;
    return s;
}

void SphereView::to_view(const float p[3], float& x, float& y, float& d) const {
    const float w[3] = {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
    float v[3];
    turn(w, v);
    x = v[0] + pan[0], y = v[1] + pan[1], d = dist + v[2];
}

float SphereView::pixels(const float p[3], float r) const {
    float x, y, d;
    to_view(p, x, y, d);
    if (d + r < near) return 0;
    const float D = ortho ? dist : d, ax = x < 0 ? -x : x, ay = y < 0 ? -y : y;
    if (ax * focal - half_w * D > r * (focal + half_w) || ay * focal - half_h * D > r * (focal + half_h)) return 0;
    const float over = ortho ? dist : d - r;
    if (over < near) return 1e9f; // at the eye
    return 2 * r * focal / over;
}

bool SphereView::faces_away(const float p[3], const float n[3]) const {
    float x, y, d, v[3];
    to_view(p, x, y, d);
    turn(n, v);
    if (ortho) return v[2] > kAwayMargin; // the eye far toward -d
    const float reach = (x < 0 ? -x : x) + (y < 0 ? -y : y) + (d < 0 ? -d : d); // >= |eye - p|
    return x * v[0] + y * v[1] + d * v[2] > kAwayMargin * reach;               // the eye at view (0, 0, 0)
}

// In view space (the eye at the origin; parallel: far toward -d), with w the way from the
// frame's origin to the eye, the face's normal at u is sign (cos a (X cos u + Y sin u) - sin a Z)
// and n . w = sign (cos a (A cos u + B sin u) - R cos a - C sin a), A = X . w, B = Y . w,
// C = Z . w: the same along v (a cone's normal tilts as its radius grows). Its largest value
// over [u0, u1]: where (A, B) points, if that lies in the range, else at an end.
bool SphereView::faces_away(const RoundFace& f, const float m[12], float sag) const {
    auto axis = [&](const float a[3], float out[3]) { // the part's direction in view space
        float placed[3];
        place(m, a, placed, false);
        turn(placed, out);
    };
    float X[3], Y[3], Z[3], w[3];
    axis(f.x, X), axis(f.y, Y), axis(f.z, Z);
    float margin = kAwayMargin;
    if (ortho) {
        w[0] = 0, w[1] = 0, w[2] = -1;
    } else {
        float placed[3];
        place(m, f.o, placed);
        to_view(placed, w[0], w[1], w[2]);
        for (float& k : w) k = -k;
        margin = kAwayMargin * ((w[0] < 0 ? -w[0] : w[0]) + (w[1] < 0 ? -w[1] : w[1]) + (w[2] < 0 ? -w[2] : w[2]) + f.radius) + sag;
    }
    const float A = X[0] * w[0] + X[1] * w[1] + X[2] * w[2], B = Y[0] * w[0] + Y[1] * w[1] + Y[2] * w[2];
    const float C = Z[0] * w[0] + Z[1] * w[1] + Z[2] * w[2];
    const float k = f.sign * f.cos_a, rest = -f.sign * ((ortho ? 0 : f.radius * f.cos_a) + C * f.sin_a);
    // The largest of k (A cos u + B sin u): toward (A, B) when k > 0, away from it when not.
    const float pa = k > 0 ? A : -A, pb = k > 0 ? B : -B;
    auto cross = [](float ax, float ay, float bx, float by) { return ax * by - ay * bx; };
    bool inside;
    if (f.span >= 6.2831853f) {
        inside = true;
    } else if (f.span <= 3.14159265f) {
        inside = cross(f.c0, f.s0, pa, pb) >= 0 && cross(pa, pb, f.c1, f.s1) >= 0;
    } else { // more than a half turn: not strictly inside the rest of the circle
        inside = !(cross(f.c1, f.s1, pa, pb) > 0 && cross(pa, pb, f.c0, f.s0) > 0);
    }
    const float k_abs = k < 0 ? -k : k;
    const float most = inside ? k_abs * geom::sqrt_f(A * A + B * B)
                              : std::max(k * (A * f.c0 + B * f.s0), k * (A * f.c1 + B * f.s1));
    return most + rest < -margin;
}

float SphereView::mm_per_pixel(const float p[3], float r) const {
    if (ortho) return dist / focal;
    float x, y, d;
    to_view(p, x, y, d);
    return (d - r > near ? d - r : near) / focal;
}

// Each side test is conservative: the sphere's distance to a side plane is compared with its
// radius times a bound on the plane normal's length.
bool Transform::visible(const int32_t centre[3], int32_t radius, Rows rows) const {
    if (radius <= 0) return true;
    int32_t cx, cy, d;
    to_view(centre, cx, cy, d);
    // Mesh units to view units (k16 / 2^16, rounded up); an eighth more for the rounding of
    // the fixed-point rotation.
    const int64_t rv = (int64_t(radius) * k16) >> 16;
    const int64_t r = rv + rv / 8 + 2;
    if (d + r < near) return false;
    const int64_t f = f16, w = cx16, X = cx, Y = cy, D = ortho ? dist : d; // parallel sides: the centre's depth
    if (X * f - w * D > r * (f + w) || -X * f - w * D > r * (f + w)) return false;
    const int64_t top = rows.top16, bottom = rows.bottom16;
    const int64_t top_n = top < 0 ? -top : top, bottom_n = bottom < 0 ? -bottom : bottom;
    if (Y * f - top * D > r * (f + top_n) || -Y * f - bottom * D > r * (f + bottom_n)) return false;
    return true;
}

// The same sides as visible(), each now asking whether the sphere lies wholly on its inner side.
Transform::Sight Transform::sight(const int32_t centre[3], int32_t radius, Rows rows) const {
    if (!visible(centre, radius, rows)) return Sight::Out;
    int32_t cx, cy, d;
    to_view(centre, cx, cy, d);
    const int64_t rv = (int64_t(radius) * k16) >> 16;
    const int64_t r = rv + rv / 8 + 2;
    if (d - r <= near) return Sight::Across;
    // Each side as visible() writes it, the sphere now wholly on the inner side (by r times a
    // bound of the side's normal: f + w over sqrt(f^2 + w^2)).
    const int64_t f = f16, w = cx16, X = cx, Y = cy, D = ortho ? dist : d;
    if (X * f - w * D >= -r * (f + w) || -X * f - w * D >= -r * (f + w)) return Sight::Across;
    const int64_t top = rows.top16, bottom = rows.bottom16;
    const int64_t top_n = top < 0 ? -top : top, bottom_n = bottom < 0 ? -bottom : bottom;
    if (Y * f - top * D >= -r * (f + top_n) || -Y * f - bottom * D >= -r * (f + bottom_n)) return Sight::Across;
    return Sight::In;
}

} // namespace facet::module
