#pragma once
// The camera: an orbit (yaw about the model's z, then pitch), a dolly and a pan, and for each
// instance of the model one fixed-point transform from mesh units to the view and the screen.
// Everything per vertex is integer (host and targets compute the same pixels): a 3x3 product
// in 64 bits, and one reciprocal per vertex for the perspective.
#include "render/fixed.h"
#include "render/raster.h"

#include <cstdint>

namespace facet::module {

class Scene;

// A vertex in camera space (x right, y up, d = depth in front of the eye; units of the
// diagonal / 2^16) and on the screen.
struct Projected {
    int32_t x, y, d;
    render::ScreenVertex s;
    uint8_t out;   // bit 0: behind the near plane; bit 1: beyond the guard band
    uint8_t front; // hidden line, curved faces: the vertex normal looks at the eye (silhouettes)
};
constexpr uint8_t kOutNear = 1, kOutGuard = 2, kOutCut = 4; // kOutCut: on the side a section cuts away (drawing only)

// Rows of the screen being drawn, as distances from the screen's centre (sub-pixels,
// render/subpixel.h):
// the view volume's top and bottom sides for culling. The whole screen: both cy16.
struct Rows {
    int32_t top16, bottom16;
};

// The section plane in camera space: side() > 0 on the side cut away. Q14 normal, values in
// units of a view unit / 2^14 (exact integers per vertex; the same plane for every instance).
struct CutPlane {
    bool on = false;
    int32_t nx = 0, ny = 0, nd = 0;
    int64_t c = 0;
    float c_float = 0; // float(c), once (a 64-bit integer to float is some 550 instructions of soft float)
    int64_t side(int32_t x, int32_t y, int32_t d) const { return int64_t(nx) * x + int64_t(ny) * y + int64_t(nd) * d + c; }
};

// A section: the plane n . p = offset (mm, placed model), the side n points to cut away.
struct Section {
    bool on = false;
    float n[3] = {1, 0, 0};
    float offset = 0;
};

// One instance under the camera: view = (a P >> 30) + b (a: rotation x scale; 2^26 when the
// placed model is as big as its shells' own box: a mesh unit is then 1/16 of a view unit).
struct Transform {
    int32_t a[9];
    int32_t b[3];
    int32_t k16; // view units per mesh unit, 2^16 = 1, rounded up (sizes of spheres)
    int32_t light[3]; // Q14, in shell coordinates
    int64_t eye[3];     // the eye in shell coordinates (mesh units): place_eye()
    int32_t toward[3];  // parallel: the way to the eye in shell coordinates (Q14): place_eye()
    bool eye_placed;    // eye and toward hold (facing() and what uses it need them)
    bool mirrored;
    bool closed;
    bool ortho; // parallel projection: x and y over the centre's depth (dist), not each point's
    int32_t dist, near, f16, cx16, cy16, guard;
    int64_t zk; // depth scale: z16 = (d - near) * zk >> 16
    render::Reciprocal ortho_r; // of dist (ortho)
    CutPlane cut;

    // eye and toward from a, b and dist: a part drawn from its own faces needs them (facing),
    // one drawn as its proxy or box does not (some 5 k instructions of soft double on the
    // ARM926, the most of a transform's cost).
    void place_eye();
    // The rotation part applied to v, before the shift (the one place the 3x3 product is written).
    void rotate(const int32_t v[3], int64_t out[3]) const {
        out[0] = int64_t(a[0]) * v[0] + int64_t(a[1]) * v[1] + int64_t(a[2]) * v[2];
        out[1] = int64_t(a[3]) * v[0] + int64_t(a[4]) * v[1] + int64_t(a[5]) * v[2];
        out[2] = int64_t(a[6]) * v[0] + int64_t(a[7]) * v[1] + int64_t(a[8]) * v[2];
    }
    // Mesh point -> camera space: x, y and depth d in front of the eye.
    void to_view(const int32_t p[3], int32_t& x, int32_t& y, int32_t& d) const {
        int64_t r[3];
        rotate(p, r);
        x = int32_t(r[0] >> 30) + b[0];
        y = int32_t(r[1] >> 30) + b[1];
        d = dist - (int32_t(r[2] >> 30) + b[2]);
    }
    void project(const int32_t p[3], Projected& o) const {
        render::Reciprocal r;
        project(p, o, r);
    }
    // And the reciprocal of what x and y were divided by (the depth, or the orthographic
    // distance), for other quantities over the same depth (a sphere's size on the screen).
    void project(const int32_t p[3], Projected& o, render::Reciprocal& r) const {
        to_view(p, o.x, o.y, o.d);
        o.out = 0;
        if (o.d < near) {
            o.out = kOutNear;
            return;
        }
        const int32_t over = ortho ? dist : o.d; // what x and y are divided by
        const int64_t X = int64_t(o.x) * f16, Y = int64_t(o.y) * f16, G = int64_t(guard) * over;
        if (X > G || -X > G || Y > G || -Y > G) {
            o.out = kOutGuard;
            return;
        }
        r = ortho ? ortho_r : render::reciprocal(uint32_t(over)); // x and y over one depth
        o.s.x = cx16 + render::divide(X, r);
        o.s.y = cy16 - render::divide(Y, r);
        const int64_t zz = (int64_t(o.d - near) * zk) >> 16;
        o.s.z = uint16_t(zz > 65535 ? 65535 : zz);
    }
    // A sphere (mesh units) across on the screen: sub-pixels, at most `most`; its centre
    // projected into `centre`; -1 when the centre is off (near the eye, or past the guard band).
    int32_t across(const int32_t sphere_centre[3], int32_t radius, int32_t most, Projected& centre) const;
    // Whether a sphere (mesh units) may touch the rows: false only when it lies wholly behind
    // the near plane or beyond one side of the view volume (conservative).
    bool visible(const int32_t centre[3], int32_t radius, Rows rows) const;
    // Where a sphere lies: wholly outside the view volume or the rows (as !visible), wholly
    // inside them (in front of the near plane and within every side: what it holds needs no
    // test of its own), or across a side. Conservative both ways: Across when unsure.
    enum class Sight : uint8_t { Out, Across, In };
    Sight sight(const int32_t centre[3], int32_t radius, Rows rows) const;
    // Whether the section's plane may cross a sphere (mesh units): what it holds is then drawn
    // cut, each of its own (a proxy has no cap). False without a section.
    bool cut_may_cross(const int32_t centre[3], int32_t radius) const {
        if (!cut.on) return false;
        int32_t x, y, d;
        to_view(centre, x, y, d);
        const int64_t rv = (int64_t(radius) * k16) >> 16, side = cut.side(x, y, d), r = (rv + rv / 8 + 2) * 16384;
        return side >= -r && side <= r;
    }
    // n . (eye - p) for a normal n (Q14) at the mesh point p, in shell coordinates: > 0 where
    // the surface looks at the eye, < 0 where it turns away (parallel: n . the way to the eye).
    int64_t facing(const int32_t p[3], const int16_t n[3]) const {
        if (ortho) return int64_t(n[0]) * toward[0] + int64_t(n[1]) * toward[1] + int64_t(n[2]) * toward[2];
        return n[0] * (eye[0] - p[0]) + n[1] * (eye[1] - p[1]) + n[2] * (eye[2] - p[2]);
    }
    bool faces_away(const int32_t p[3], const int16_t n[3]) const { return facing(p, n) < 0; }
    // Whether a closed solid's inside may show: a section is on and the eye is on the side it
    // cuts away (the eye at view (0, 0, 0); parallel: far toward -d). From the kept side, a ray
    // reaches the cut only through the solid's own front faces, which hide every back face.
    bool inside_shows() const { return cut.on && (ortho ? cut.nd < 0 : cut.c > 0); }
    // Whether a closed solid's plane through p with normal n cannot show, faces nor edges: it
    // turns its back to the eye and no inside shows. (One normal: the face is skipped whole.)
    bool hides_plane(const int32_t p[3], const int16_t n[3]) const { return closed && !inside_shows() && faces_away(p, n); }
    // The Gouraud shade (palette index) of a unit normal (Q14); open sheets are lit both sides.
    uint8_t shade(const int16_t n[3]) const {
        int32_t lit = (int32_t(n[0]) * light[0] + int32_t(n[1]) * light[1] + int32_t(n[2]) * light[2]) >> 14;
        if (lit < 0) lit = closed ? 0 : (-lit * 154) >> 8; // the back of an open sheet, a little darker
        if (lit > 16384) lit = 16384;
        return uint8_t(77 + ((178 * lit) >> 14)); // ambient 0.3 + diffuse 0.7, of 255
    }
};

// A point (or, point false, a direction) of a part where an instance's 3x4 placement m puts it.
inline void place(const float m[12], const float q[3], float out[3], bool point = true) {
    for (int k = 0; k < 3; ++k) {
        out[k] = m[4 * k] * q[0] + m[4 * k + 1] * q[1] + m[4 * k + 2] * q[2];
        if (point) out[k] += m[4 * k + 3];
    }
}

// A cylinder's or a cone's face as far as which way it faces goes (its part's coordinates, mm):
// the surface's frame, its radius at v = 0 and semi-angle (a cylinder: 0), +1 when the face's
// normal points away from the axis (-1: toward it, a hole), and the ends of its range of u as
// cos, sin, and its span (a full turn or more: every way round).
struct RoundFace {
    float o[3], x[3], y[3], z[3];
    float radius, sin_a, cos_a, sign;
    float c0, s0, c1, s1, span;
};

// Spheres of the placed model on the screen, for the level of detail: a few dozen float
// operations a sphere, no fixed-point transform per instance. Sides as Transform::visible.
struct SphereView {
    float R[9], centre[3], pan[2];
    float dist, near, focal, half_w, half_h; // mm, pixels
    bool ortho;
    // A sphere's size across on the screen (placed model, mm, radius r), in pixels at its
    // nearest point: 0 when it lies wholly off the screen or behind the eye.
    float pixels(const float p[3], float r) const;
    // Millimetres a pixel spans at the sphere's nearest point (the eye's plane at its depth).
    float mm_per_pixel(const float p[3], float r) const;
    // A placed point (mm) in view space: x right, y up, d its depth in front of the eye.
    void to_view(const float p[3], float& x, float& y, float& d) const;
    // A placed direction in view space (x, y, d: as to_view's axes).
    void turn(const float n[3], float v[3]) const {
        v[0] = R[0] * n[0] + R[1] * n[1] + R[2] * n[2], v[1] = R[3] * n[0] + R[4] * n[1] + R[5] * n[2];
        v[2] = -(R[6] * n[0] + R[7] * n[1] + R[8] * n[2]);
    }
    // Whether the plane through the placed point p with the placed unit normal n turns its
    // back to the eye by more than about a degree (n . (eye - p) < 0, as Transform::facing).
    bool faces_away(const float p[3], const float n[3]) const;
    // Whether the round face, placed by the 3x4 matrix m, turns its back to the eye at every u
    // of its range (its normal turns with u alone) by more than about a degree and `sag` (mm:
    // how far its mesh's chords may lie inside it).
    bool faces_away(const RoundFace& f, const float m[12], float sag) const;
};

// The view: orbit angles (rad), dolly factor (1 = the sphere fitted), pan (mm, in view x/y),
// and the projection (perspective, or parallel: the sizes at the model's centre everywhere).
struct View {
    float yaw = 0.6f, pitch = -0.95f, zoom = 1, pan_x = 0, pan_y = 0;
    bool ortho = false;
};

inline bool same_view(const View& a, const View& b) {
    return a.yaw == b.yaw && a.pitch == b.pitch && a.zoom == b.zoom && a.pan_x == b.pan_x && a.pan_y == b.pan_y && a.ortho == b.ortho;
}

// The standard views of a z-up model (yaw, pitch): front looks along +y, right along -x, top
// down -z; isometric from (+1, -1, +1).
enum class Standard : uint8_t { Front, Back, Right, Left, Top, Bottom, Iso };
View standard_view(Standard s, const View& from); // the angles of s, the rest of `from`

// What every instance's transform shares under one view, screen and section (Camera::basis):
// made once for them all, each instance's transform from it (Camera::transform).
struct ViewBasis {
    float R[9];        // Camera::rotation
    float v_per_mm;    // view units per mm
    float k;           // view units per mesh unit
    float k30;         // k 2^30 (Transform::a's scale)
    float pan[3];      // mm, in view x and y
    const float* centre; // the scene's (mm)
    Transform shared;  // the fields that do not depend on the instance: k16, dist and on
};

class Camera {
public:
    static constexpr float kTurn = 0.2617993878f; // a key turns by 15 degrees
    static constexpr float kNearest = 0.05f, kFarthest = 20.0f; // the dolly's range
    // How far a pan may take the model's centre from the view's: this many radii of its
    // bounding sphere (the view units it gives, 2^21, keep every transform's sums in 32 bits).
    static constexpr float kPanRadii = 64;
    // v with its dolly within kNearest and kFarthest and its pan within kPanRadii of `radius`
    // (mm): what every view drawn is made of, however the view was reached (a value not
    // finite: the default's).
    static View in_range(View v, float radius);
    void keep_in_range(float radius) { view_ = in_range(view_, radius); }

    void fit() { view_ = View{}; } // the whole model's sphere, from the default direction
    // The sphere framed again from the current direction (before Framing adjusts it).
    void reframe() { view_.zoom = 1, view_.pan_x = 0, view_.pan_y = 0; }
    const View& view() const { return view_; }
    void set_view(const View& v) { view_ = v; }
    void toggle_projection() { view_.ortho = !view_.ortho; }
    const Section& section() const { return section_; }
    void set_section(const Section& s) { section_ = s; }
    // Orbit by angles (rad), dolly by a factor (< 1: closer; kept within kNearest and kFarthest), pan by
    // millimetres, or by screen pixels (the model's centre follows the pointer).
    void orbit(float d_yaw, float d_pitch);
    void dolly(float factor);
    void pan(float dx_mm, float dy_mm);
    void pan_pixels(int32_t dx, int32_t dy, float radius, uint16_t width, uint16_t height);

    // The orbit's rotation (row-major): world axes into the camera's (x right, y up, z to the eye).
    void rotation(float R[9]) const;
    static void rotation(const View& v, float R[9]);
    // The eye's distance from the model's centre (mm) and the focal length (pixels).
    float distance_mm(const Scene& scene) const;
    static float focal_px(uint16_t width, uint16_t height);

    SphereView sphere_view(const Scene& scene, uint16_t width, uint16_t height) const;
    // Instance `instance` of the scene under this camera on a width x height screen.
    Transform transform(const Scene& scene, uint32_t instance, uint16_t width, uint16_t height) const;
    // The same in two steps: the view's basis once, then each instance's transform from it,
    // without its eye (Transform::place_eye); equal, field for field, to transform()'s.
    ViewBasis basis(const Scene& scene, uint16_t width, uint16_t height) const;
    static Transform transform(const ViewBasis& basis, const Scene& scene, uint32_t instance);
    // A placement `m` (pack::Instance's: row-major 3x4, mm) from the view's basis: an instance's
    // is this with its part's closedness; the model's own coordinates (a group's) the identity.
    static Transform transform(const ViewBasis& basis, const float m[12], bool closed);

private:
    View view_;
    Section section_;
};

} // namespace facet::module
