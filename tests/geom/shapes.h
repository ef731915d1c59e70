#pragma once
// B-rep shapes built in code for the tessellation's unit tests (no Open CASCADE): each a pack as
// a STEP file's would be, loops counter-clockwise in their face's (u,v) (holes clockwise), faces
// reversed where their surface's normal points into the solid.
#include "geom/pack_format.h"
#include "pack_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace facet::test {

using Bytes = std::vector<uint8_t>;
using geom::PackWriter;
using pack::Coedge;
using pack::Seam;
constexpr float kPi = 3.14159265358979f, kTwoPi = 2 * kPi;

inline uint32_t straight(PackWriter& w, uint32_t a, uint32_t b, float length) {
    return w.add_edge({pack::kStraight, 0, length, a, b, 1e-7f, 0});
}

// A plate [0,100] x [0,60] x [0,10] mm with two round through holes (centres (30, 30) and
// (70, 30), radii 10 and 8): eight planar faces' worth of loops with holes, two cylinders with
// seams. Closed. Volume 100 * 60 * 10 - pi (10^2 + 8^2) 10.
struct Hole {
    float cx, cy, r;
    float seam = 0; // the angle of its seam (and its circles' vertex) about its axis, from +x
};
constexpr std::array<Hole, 2> kPlateHoles = {{{30, 30, 10}, {70, 30, 8}}};
// The same plate with its holes 0.1 micron apart, each one's seam vertex facing the other: a wall
// far thinner than the CDT's grid unit on the top and bottom faces (100 mm / 2^15 = 3 microns),
// where the two holes' loops meet on one grid point at every tolerance (tangles.cpp).
constexpr std::array<Hole, 2> kHolesAMicronApart = {{{30, 30, 10, 0}, {48.0001f, 30, 8, kPi}}};
inline double plate_volume(const std::array<Hole, 2>& holes = kPlateHoles) {
    return 100.0 * 60 * 10 - M_PI * (double(holes[0].r) * holes[0].r + double(holes[1].r) * holes[1].r) * 10;
}

inline Bytes plate_with_holes(const std::array<Hole, 2>& kPlateHoles = test::kPlateHoles) {
    PackWriter w;
    constexpr float X = 100, Y = 60, Z = 10;
    uint32_t c[8]; // corners: bit 0 x, bit 1 y, bit 2 z
    for (int i = 0; i < 8; ++i) c[i] = w.add_vertex(i & 1 ? X : 0, i & 2 ? Y : 0, i & 4 ? Z : 0);
    auto box_edge = [&](int a, int b) {
        const float len = (a ^ b) == 1 ? X : (a ^ b) == 2 ? Y : Z;
        return straight(w, c[a], c[b], len);
    };
    // The 12 box edges, each from its lower corner to its upper one.
    const uint32_t x00 = box_edge(0, 1), x10 = box_edge(2, 3), x01 = box_edge(4, 5), x11 = box_edge(6, 7);
    const uint32_t y00 = box_edge(0, 2), y10 = box_edge(1, 3), y01 = box_edge(4, 6), y11 = box_edge(5, 7);
    const uint32_t z00 = box_edge(0, 4), z10 = box_edge(1, 5), z01 = box_edge(2, 6), z11 = box_edge(3, 7);
    // Each hole: a circle at the bottom and the top, a seam between them at angle 0.
    struct HoleEdges {
        uint32_t bottom, top, seam;
    } h[2];
    for (int k = 0; k < 2; ++k) {
        const Hole& o = kPlateHoles[k];
        const float cs = std::cos(o.seam), sn = std::sin(o.seam);
        const uint32_t vb = w.add_vertex(o.cx + o.r * cs, o.cy + o.r * sn, 0), vt = w.add_vertex(o.cx + o.r * cs, o.cy + o.r * sn, Z);
        const uint32_t cb = w.add_curve(pack::Circle3Params{.origin = {o.cx, o.cy, 0}, .x = {cs, sn, 0}, .y = {-sn, cs, 0}, .radius = o.r});
        const uint32_t ct = w.add_curve(pack::Circle3Params{.origin = {o.cx, o.cy, Z}, .x = {cs, sn, 0}, .y = {-sn, cs, 0}, .radius = o.r});
        h[k] = {w.add_edge({cb, 0, kTwoPi, vb, vb, 1e-7f, 0}), w.add_edge({ct, 0, kTwoPi, vt, vt, 1e-7f, 0}),
                straight(w, vb, vt, Z)};
    }
    std::vector<uint32_t> faces;
    auto loop = [&](std::initializer_list<std::pair<uint32_t, bool>> coedges) {
        const uint32_t first = w.coedge_count();
        for (auto [e, reversed] : coedges) w.add_coedge(Coedge::make(e, reversed, Seam::None));
        return w.add_loop({first, uint32_t(coedges.size())});
    };
    auto plane = [&](const pack::Frame& frame, uint32_t first_loop, uint32_t loops, std::array<float, 4> bounds) {
        const uint32_t s = w.add_surface(pack::PlaneParams{frame});
        faces.push_back(w.add_face({s, first_loop, loops, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0},
                                    {bounds[0], bounds[1]}, {bounds[2], bounds[3]}}));
    };
    // Top (z = 10, normal +z, (u,v) = (x, y)): the outline counter-clockwise, the holes clockwise.
    uint32_t first = loop({{x01, false}, {y11, false}, {x11, true}, {y01, true}});
    loop({{h[0].top, true}});
    loop({{h[1].top, true}});
    plane({.origin = {0, 0, Z}, .x = {1, 0, 0}, .y = {0, 1, 0}, .z = {0, 0, 1}}, first, 3, {0, 0, X, Y});
    // Bottom (z = 0, normal -z: x = (1,0,0), y = (0,-1,0), (u,v) = (x, -y)).
    first = loop({{y00, false}, {x10, false}, {y10, true}, {x00, true}});
    loop({{h[0].bottom, false}});
    loop({{h[1].bottom, false}});
    plane({.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, -1, 0}, .z = {0, 0, -1}}, first, 3, {0, -Y, X, 0});
    // The sides, outward: -y (x, z), +x (y, z), +y (-x, z), -x (-y, z).
    plane({.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, 0, 1}, .z = {0, -1, 0}}, loop({{x00, false}, {z10, false}, {x01, true}, {z00, true}}), 1, {0, 0, X, Z});
    plane({.origin = {X, 0, 0}, .x = {0, 1, 0}, .y = {0, 0, 1}, .z = {1, 0, 0}}, loop({{y10, false}, {z11, false}, {y11, true}, {z10, true}}), 1, {0, 0, Y, Z});
    plane({.origin = {X, Y, 0}, .x = {-1, 0, 0}, .y = {0, 0, 1}, .z = {0, 1, 0}}, loop({{x10, true}, {z01, false}, {x11, false}, {z11, true}}), 1, {0, 0, X, Z});
    plane({.origin = {0, Y, 0}, .x = {0, -1, 0}, .y = {0, 0, 1}, .z = {-1, 0, 0}}, loop({{y00, true}, {z00, false}, {y01, false}, {z01, true}}), 1, {0, 0, Y, Z});
    // The holes' walls: cylinders about z, reversed (the solid is outside them). Counter-
    // clockwise in (u, v) = (angle, z): the bottom circle, up the seam at u = 2 pi, the top
    // circle back, down the seam at u = 0.
    for (int k = 0; k < 2; ++k) {
        const Hole& o = kPlateHoles[k];
        const float cs = std::cos(o.seam), sn = std::sin(o.seam);
        const uint32_t s = w.add_surface(pack::CylinderParams{{.origin = {o.cx, o.cy, 0}, .x = {cs, sn, 0}, .y = {-sn, cs, 0}, .z = {0, 0, 1}}, o.r});
        const uint32_t fc = w.coedge_count();
        w.add_coedge(Coedge::make(h[k].bottom, false, Seam::None));
        w.add_coedge(Coedge::make(h[k].seam, false, Seam::UHigh));
        w.add_coedge(Coedge::make(h[k].top, true, Seam::None));
        w.add_coedge(Coedge::make(h[k].seam, true, Seam::ULow));
        faces.push_back(w.add_face({s, w.add_loop({fc, 4}), 1, pack::kNoIndex, pack::kNoIndex, 1, {0, 0, 0}, {0, 0}, {kTwoPi, Z}}));
    }
    w.add_instance({w.add_shell({faces.front(), uint32_t(faces.size()), pack::kNoIndex, 1}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

// A square sheet, 10 x 10 mm in z = 0 (one planar face, open), whose left side starts with a
// hook: from the top-left corner it runs up past the top side and back down across it, then
// down to the bottom. The loop crosses itself 0.055 mm from the corner, as a translator's curve
// that overshoots its vertex does (usb4110_spatial_ap242.stp's face 188, on a B-spline there).
// Counter-clockwise: the top from right to left, the hook and the left side down, the bottom, the
// right side up. Every side straight: its samples are its vertices at every tolerance.
constexpr std::array<std::array<float, 2>, 7> kHookedSheet = {
    {{10, 10}, {0, 10}, {0.04f, 10.05f}, {0.07f, 9.95f}, {0.1f, 0}, {10, 0}, {10, 10}}};
inline Bytes hooked_sheet() {
    PackWriter w;
    std::vector<uint32_t> v;
    for (size_t k = 0; k + 1 < kHookedSheet.size(); ++k) v.push_back(w.add_vertex(kHookedSheet[k][0], kHookedSheet[k][1], 0));
    const uint32_t first = w.coedge_count();
    for (size_t k = 0; k < v.size(); ++k) {
        const auto a = kHookedSheet[k], b = kHookedSheet[k + 1];
        const uint32_t e = straight(w, v[k], v[(k + 1) % v.size()], std::hypot(b[0] - a[0], b[1] - a[1]));
        w.add_coedge(Coedge::make(e, false, Seam::None));
    }
    const uint32_t s = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
    const uint32_t face = w.add_face({s, w.add_loop({first, uint32_t(v.size())}), 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0},
                                      {0, 0}, {10, 10.05f}});
    w.add_instance({w.add_shell({face, 1, pack::kNoIndex, 0}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

// A half-round bar: half a cylinder of radius 10 about z (u in [0, pi]: y >= 0), z in [0, 40],
// closed by its flat side in y = 0 and two half discs. Closed, every frame right-handed. Its
// round face turns wholly away from an eye far toward -y.
inline Bytes half_round_bar() {
    PackWriter w;
    const uint32_t va = w.add_vertex(10, 0, 0), vb = w.add_vertex(-10, 0, 0), vc = w.add_vertex(10, 0, 40), vd = w.add_vertex(-10, 0, 40);
    const uint32_t low = w.add_curve(pack::Circle3Params{.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, 1, 0}, .radius = 10});
    const uint32_t high = w.add_curve(pack::Circle3Params{.origin = {0, 0, 40}, .x = {1, 0, 0}, .y = {0, 1, 0}, .radius = 10});
    const uint32_t A = w.add_edge({low, 0, kPi, va, vb, 1e-7f, 0}), B = w.add_edge({high, 0, kPi, vc, vd, 1e-7f, 0});
    const uint32_t L1 = straight(w, va, vc, 40), L2 = straight(w, vb, vd, 40), D0 = straight(w, vb, va, 20), D1 = straight(w, vd, vc, 20);
    auto loop = [&](std::initializer_list<std::pair<uint32_t, bool>> coedges) {
        const uint32_t first = w.coedge_count();
        for (auto [e, reversed] : coedges) w.add_coedge(Coedge::make(e, reversed, Seam::None));
        return w.add_loop({first, uint32_t(coedges.size())});
    };
    auto face = [&](uint32_t s, uint32_t l, std::array<float, 4> bounds) {
        return w.add_face({s, l, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {bounds[0], bounds[1]}, {bounds[2], bounds[3]}});
    };
    // Counter-clockwise in each face's (u, v): the round face in (angle, z); the flat side in
    // (x, z), normal -y; the bottom in (x, -y), normal -z; the top in (x, y), normal +z.
    const uint32_t first = face(w.add_surface(pack::CylinderParams{geom::axes_at(0, 0, 0), 10}),
                                loop({{A, false}, {L2, false}, {B, true}, {L1, true}}), {0, 0, kPi, 40});
    face(w.add_surface(pack::PlaneParams{{.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, 0, 1}, .z = {0, -1, 0}}}), loop({{D0, false}, {L1, false}, {D1, true}, {L2, true}}), {-10, 0, 10, 40});
    face(w.add_surface(pack::PlaneParams{{.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, -1, 0}, .z = {0, 0, -1}}}), loop({{D0, true}, {A, true}}), {-10, -10, 10, 0});
    face(w.add_surface(pack::PlaneParams{{.origin = {0, 0, 40}, .x = {1, 0, 0}, .y = {0, 1, 0}, .z = {0, 0, 1}}}), loop({{B, false}, {D1, false}}), {-10, 0, 10, 10});
    w.add_instance({w.add_shell({first, 4, pack::kNoIndex, 1}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

// A sphere of radius R about the origin: one face, a seam from pole to pole (a half circle at
// u = 0) and a degenerate edge at each pole. Closed.
constexpr float kSphereRadius = 20;
inline Bytes sphere() {
    PackWriter w;
    const float R = kSphereRadius;
    const uint32_t s = w.add_surface(pack::SphereParams{geom::axes_at(0, 0, 0), R});
    const uint32_t south = w.add_vertex(0, 0, -R), north = w.add_vertex(0, 0, R);
    // The seam: R (cos t (0,0,-1) + sin t (1,0,0)), t from 0 (south) to pi (north).
    const uint32_t meridian = w.add_curve(pack::Circle3Params{.origin = {0, 0, 0}, .x = {0, 0, -1}, .y = {1, 0, 0}, .radius = R});
    const uint32_t seam = w.add_edge({meridian, 0, kPi, south, north, 1e-7f, 0});
    const uint32_t south_pole = w.add_edge({pack::kNoIndex, 0, kTwoPi, south, south, 1e-7f, 0});
    const uint32_t north_pole = w.add_edge({pack::kNoIndex, 0, kTwoPi, north, north, 1e-7f, 0});
    const uint32_t fc = w.coedge_count();
    w.add_coedge(Coedge::make(south_pole, false, Seam::None)); // v = -pi/2, u 0 -> 2 pi
    w.add_coedge(Coedge::make(seam, false, Seam::UHigh));      // up at u = 2 pi
    w.add_coedge(Coedge::make(north_pole, true, Seam::None));  // v = pi/2, back
    w.add_coedge(Coedge::make(seam, true, Seam::ULow));        // down at u = 0
    const uint32_t face = w.add_face({s, w.add_loop({fc, 4}), 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0},
                                      {0, -kPi / 2}, {kTwoPi, kPi / 2}});
    w.add_instance({w.add_shell({face, 1, pack::kNoIndex, 1}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}
inline double sphere_volume() { return 4.0 / 3.0 * M_PI * kSphereRadius * kSphereRadius * kSphereRadius; }

// A torus about z, major radius 30, minor 10 unless told: one face bounded by its two seams
// (the tube's circle at u = 0, the outer equator at v = 0), each used twice. Closed.
constexpr float kTorusMajor = 30, kTorusMinor = 10;
inline Bytes torus(float R = kTorusMajor, float r = kTorusMinor) {
    PackWriter w;
    const uint32_t s = w.add_surface(pack::TorusParams{geom::axes_at(0, 0, 0), R, r});
    const uint32_t v = w.add_vertex(R + r, 0, 0);
    const uint32_t tube = w.add_curve(pack::Circle3Params{.origin = {R, 0, 0}, .x = {1, 0, 0}, .y = {0, 0, 1}, .radius = r});       // u = 0, t = v
    const uint32_t equator = w.add_curve(pack::Circle3Params{.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, 1, 0}, .radius = R + r}); // v = 0, t = u
    const uint32_t e_tube = w.add_edge({tube, 0, kTwoPi, v, v, 1e-7f, 0});
    const uint32_t e_equator = w.add_edge({equator, 0, kTwoPi, v, v, 1e-7f, 0});
    const uint32_t fc = w.coedge_count();
    w.add_coedge(Coedge::make(e_equator, false, Seam::VLow)); // v = 0, u 0 -> 2 pi
    w.add_coedge(Coedge::make(e_tube, false, Seam::UHigh));   // u = 2 pi, v 0 -> 2 pi
    w.add_coedge(Coedge::make(e_equator, true, Seam::VHigh)); // v = 2 pi, back
    w.add_coedge(Coedge::make(e_tube, true, Seam::ULow));     // u = 0, back
    const uint32_t face = w.add_face({s, w.add_loop({fc, 4}), 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {0, 0},
                                      {kTwoPi, kTwoPi}});
    w.add_instance({w.add_shell({face, 1, pack::kNoIndex, 1}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}
inline double torus_volume(double R = kTorusMajor, double r = kTorusMinor) { return 2.0 * M_PI * M_PI * R * r * r; }

// A trimmed B-spline sheet: S(u, v) = (100 u, 100 v, 40 v (1 - v)) mm over [0,1]^2 (degree 1 in
// u, 2 in v: a bent plate, curvature 0.008/mm), trimmed to a quadrilateral inside its
// parameter square with a triangular hole. Each trimming edge is a line in (u, v) (its pcurve)
// and, on the surface, a quadratic: its 3D curve is that Bezier exactly. Open.
inline std::array<float, 3> bent_plate(float u, float v) { return {100 * u, 100 * v, 40 * v * (1 - v)}; }
constexpr float kBentPlateCurvature = 0.008f; // the most the surface bends (1/mm)
constexpr std::array<float, 2> kTrim[4] = {{0.10f, 0.10f}, {0.90f, 0.15f}, {0.85f, 0.90f}, {0.15f, 0.80f}}; // ccw
constexpr std::array<float, 2> kTrimHole[3] = {{0.40f, 0.40f}, {0.50f, 0.60f}, {0.60f, 0.45f}};               // cw

inline Bytes trimmed_bspline() {
    PackWriter w;
    // Head, knots, poles (row after row in u, 3 in v), no weights.
    std::vector<float> p = {1, 2, 2, 3, 4, 6, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 1, 1};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j) p.insert(p.end(), {100.0f * float(i), 50.0f * float(j), j == 1 ? 20.0f : 0.0f});
    const uint32_t surface = w.add_bspline_surface(p);
    std::vector<uint32_t> coedge_edges, pcurves;
    auto polygon = [&](const std::array<float, 2>* uv, int n) {
        std::vector<uint32_t> vs;
        for (int k = 0; k < n; ++k) {
            const auto q = bent_plate(uv[k][0], uv[k][1]);
            vs.push_back(w.add_vertex(q[0], q[1], q[2]));
        }
        const uint32_t first = w.coedge_count();
        for (int k = 0; k < n; ++k) {
            const auto a = uv[k], b = uv[(k + 1) % n];
            const auto q0 = bent_plate(a[0], a[1]), q2 = bent_plate(b[0], b[1]);
            const auto qm = bent_plate(0.5f * (a[0] + b[0]), 0.5f * (a[1] + b[1]));
            std::vector<float> curve = {2, 3, 6, 0, 0, 0, 0, 0, 1, 1, 1};
            for (int d = 0; d < 3; ++d) curve.push_back(q0[d]);
            for (int d = 0; d < 3; ++d) curve.push_back(2 * qm[d] - 0.5f * (q0[d] + q2[d])); // the middle pole
            for (int d = 0; d < 3; ++d) curve.push_back(q2[d]);
            const uint32_t c3 = w.add_bspline_curve(3, curve);
            const uint32_t e = w.add_edge({c3, 0, 1, vs[k], vs[(k + 1) % n], 1e-6f, 0});
            pcurves.push_back(w.add_curve(pack::Line2Params{.origin = {a[0], a[1]}, .direction = {b[0] - a[0], b[1] - a[1]}}));
            w.add_coedge(Coedge::make(e, false, Seam::None));
        }
        return w.add_loop({first, uint32_t(n)});
    };
    const uint32_t outer = polygon(kTrim, 4);
    polygon(kTrimHole, 3);
    const uint32_t face = w.add_face({surface, outer, 2, pcurves.front(), pack::kNoIndex, 0, {0, 0, 0}, {0, 0}, {1, 1}});
    w.add_instance({w.add_shell({face, 1, pack::kNoIndex, 0}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

} // namespace facet::test
