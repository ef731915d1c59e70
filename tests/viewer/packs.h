#pragma once
// Packs the viewer tests build in code (no OCCT): planar faces of straight edges, a disc of four
// arcs, two named blocks placed twice, an open tube with a seam, a grid of squares.
#include "geom/pack.h"
#include "pack_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace facet::test {

using Bytes = std::vector<uint8_t>;
using geom::PackWriter;

// Two planar faces in one open shell: a polygon of `sides` straight edges around the origin
// (radius 100) and a small triangle beside it.
inline Bytes polygon_and_triangle(uint32_t sides) {
    PackWriter w;
    const uint32_t plane = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
    std::vector<uint32_t> v(sides);
    for (uint32_t i = 0; i < sides; ++i) {
        const double a = 2 * M_PI * i / sides;
        v[i] = w.add_vertex(float(100 * std::cos(a)), float(100 * std::sin(a)), 0);
    }
    const float side = float(2 * 100 * std::sin(M_PI / sides));
    std::vector<uint32_t> e(sides);
    for (uint32_t i = 0; i < sides; ++i) e[i] = w.add_edge({pack::kStraight, 0, side, v[i], v[(i + 1) % sides], 1e-7f, 0});
    uint32_t first = w.coedge_count();
    for (uint32_t i = 0; i < sides; ++i) w.add_coedge(pack::Coedge::make(e[i], false, pack::Seam::None));
    uint32_t loop = w.add_loop({first, sides});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {-100, -100}, {100, 100}});

    const uint32_t a = w.add_vertex(120, 0, 0), b = w.add_vertex(140, 0, 0), c = w.add_vertex(120, 20, 0);
    const uint32_t ab = w.add_edge({pack::kStraight, 0, 20, a, b, 1e-7f, 0}), bc = w.add_edge({pack::kStraight, 0, 28.28f, b, c, 1e-7f, 0}),
                   ca = w.add_edge({pack::kStraight, 0, 20, c, a, 1e-7f, 0});
    first = w.coedge_count();
    for (uint32_t x : {ab, bc, ca}) w.add_coedge(pack::Coedge::make(x, false, pack::Seam::None));
    loop = w.add_loop({first, 3});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {120, 0}, {140, 20}});
    const uint32_t shell = w.add_shell({0, 2, pack::kNoIndex, 0});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

// A disc of radius 100 in z = 0 bounded by four quarter circles; those numbered in `smooth`
// marked as tangent edges (pack::SectionId::SmoothEdges), as if the disc were a blend's.
inline Bytes disc(std::initializer_list<int> smooth = {}) {
    PackWriter w;
    const uint32_t plane = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
    const uint32_t circle = w.add_curve(pack::Circle3Params{.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, 1, 0}, .radius = 100});
    const uint32_t v[4] = {w.add_vertex(100, 0, 0), w.add_vertex(0, 100, 0), w.add_vertex(-100, 0, 0), w.add_vertex(0, -100, 0)};
    const uint32_t first = w.coedge_count();
    for (int i = 0; i < 4; ++i) {
        const uint32_t e = w.add_edge({circle, float(M_PI / 2 * i), float(M_PI / 2 * (i + 1)), v[i], v[(i + 1) % 4], 1e-7f, 0});
        if (std::find(smooth.begin(), smooth.end(), i) != smooth.end()) w.set_smooth_edge(e);
        w.add_coedge(pack::Coedge::make(e, false, pack::Seam::None));
    }
    const uint32_t loop = w.add_loop({first, 4});
    w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {-100, -100}, {100, 100}});
    const uint32_t shell = w.add_shell({0, 1, pack::kNoIndex, 0});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

// Two closed blocks (100 mm cubes, one solid placed twice: at the origin and 150 mm along x),
// named as a STEP file would name them.
inline Bytes two_blocks() {
    PackWriter w;
    auto corner = [](int i) { return std::array<float, 3>{float(i & 1) * 100, float((i >> 1) & 1) * 100, float((i >> 2) & 1) * 100}; };
    uint32_t v[8];
    for (int i = 0; i < 8; ++i) v[i] = w.add_vertex(corner(i)[0], corner(i)[1], corner(i)[2]);
    std::map<std::pair<int, int>, uint32_t> edges;
    const uint32_t first_face = w.face_count();
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            float n[3] = {0, 0, 0}, x[3] = {0, 0, 0}, y[3];
            n[axis] = side ? 1.0f : -1.0f;
            x[(axis + 1) % 3] = 1;
            y[0] = n[1] * x[2] - n[2] * x[1], y[1] = n[2] * x[0] - n[0] * x[2], y[2] = n[0] * x[1] - n[1] * x[0];
            float o[3] = {0, 0, 0};
            o[axis] = side ? 100.0f : 0.0f;
            const uint32_t plane = w.add_surface(pack::PlaneParams{{.origin = {o[0], o[1], o[2]}, .x = {x[0], x[1], x[2]}, .y = {y[0], y[1], y[2]}, .z = {n[0], n[1], n[2]}}});
            // The face's corners counter-clockwise about its outward normal.
            std::vector<std::pair<double, int>> around;
            for (int i = 0; i < 8; ++i) {
                if (((i >> axis) & 1) != side) continue;
                const auto c = corner(i);
                const double u = (c[0] - 50) * x[0] + (c[1] - 50) * x[1] + (c[2] - 50) * x[2];
                const double t = (c[0] - 50) * y[0] + (c[1] - 50) * y[1] + (c[2] - 50) * y[2];
                around.push_back({std::atan2(t, u), i});
            }
            std::sort(around.begin(), around.end());
            const uint32_t first = w.coedge_count();
            float lo[2] = {1e9f, 1e9f}, hi[2] = {-1e9f, -1e9f};
            for (int k = 0; k < 4; ++k) {
                const int a = around[k].second, b = around[(k + 1) % 4].second;
                const auto key = std::make_pair(std::min(a, b), std::max(a, b));
                if (!edges.count(key)) edges[key] = w.add_edge({pack::kStraight, 0, 100, v[key.first], v[key.second], 1e-7f, 0});
                w.add_coedge(pack::Coedge::make(edges[key], a != key.first, pack::Seam::None));
                const auto c = corner(a);
                const float uv[2] = {(c[0] - o[0]) * x[0] + (c[1] - o[1]) * x[1] + (c[2] - o[2]) * x[2],
                                     (c[0] - o[0]) * y[0] + (c[1] - o[1]) * y[1] + (c[2] - o[2]) * y[2]};
                for (int j = 0; j < 2; ++j) lo[j] = std::min(lo[j], uv[j]), hi[j] = std::max(hi[j], uv[j]);
            }
            const uint32_t loop = w.add_loop({first, 4});
            w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {lo[0], lo[1]}, {hi[0], hi[1]}});
        }
    }
    const uint32_t shell = w.add_shell({first_face, 6, pack::kNoIndex, 1});
    w.name_shell(shell, "block");
    w.name_instance(w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}), "block_a");
    w.name_instance(w.add_instance({shell, {1, 0, 0, 150, 0, 1, 0, 0, 0, 0, 1, 0}}), "");
    w.set_model_name("two blocks");
    return w.finish();
}

// An open tube: one cylinder face (radius 50 mm, 100 mm tall about z), its two circles and its
// seam; no B-rep edge runs along its sides.
inline Bytes tube() {
    PackWriter w;
    constexpr float kTwoPi = 6.28318530718f;
    const uint32_t cylinder = w.add_surface(pack::CylinderParams{geom::axes_at(0, 0, 0), 50});
    const uint32_t low = w.add_curve(pack::Circle3Params{.origin = {0, 0, 0}, .x = {1, 0, 0}, .y = {0, 1, 0}, .radius = 50});
    const uint32_t high = w.add_curve(pack::Circle3Params{.origin = {0, 0, 100}, .x = {1, 0, 0}, .y = {0, 1, 0}, .radius = 50});
    const uint32_t v0 = w.add_vertex(50, 0, 0), v1 = w.add_vertex(50, 0, 100);
    const uint32_t e_low = w.add_edge({low, 0, kTwoPi, v0, v0, 1e-7f, 0});
    const uint32_t e_high = w.add_edge({high, 0, kTwoPi, v1, v1, 1e-7f, 0});
    const uint32_t e_seam = w.add_edge({pack::kStraight, 0, 100, v0, v1, 1e-7f, 0});
    // Counter-clockwise in (u, v): along the bottom, up the seam at u = 2 pi, back along the
    // top, down the seam at u = 0.
    const uint32_t first = w.coedge_count();
    w.add_coedge(pack::Coedge::make(e_low, false, pack::Seam::None));
    w.add_coedge(pack::Coedge::make(e_seam, false, pack::Seam::UHigh));
    w.add_coedge(pack::Coedge::make(e_high, true, pack::Seam::None));
    w.add_coedge(pack::Coedge::make(e_seam, true, pack::Seam::ULow));
    const uint32_t loop = w.add_loop({first, 4});
    const uint32_t face = w.add_face({cylinder, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {0, 0}, {kTwoPi, 100}});
    w.add_instance({w.add_shell({face, 1, pack::kNoIndex, 0}), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    w.set_model_name("tube");
    return w.finish();
}

// A grid of `count` unit squares `pitch` mm apart (their corners) in z = 0, `columns` a row, one
// face each (their own four edges), in one shell, placed once at each offset (mm).
inline Bytes squares(uint32_t count, uint32_t columns = 100, std::initializer_list<std::array<float, 3>> offsets = {{0, 0, 0}},
                     float pitch = 2, const pack::Needs* needs = nullptr) {
    PackWriter w;
    if (needs) w.set_needs(*needs);
    const uint32_t plane = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
    for (uint32_t i = 0; i < count; ++i) {
        const float x = pitch * float(i % columns), y = pitch * float(i / columns);
        const uint32_t v[4] = {w.add_vertex(x, y, 0), w.add_vertex(x + 1, y, 0), w.add_vertex(x + 1, y + 1, 0), w.add_vertex(x, y + 1, 0)};
        uint32_t e[4];
        for (int k = 0; k < 4; ++k) e[k] = w.add_edge({pack::kStraight, 0, 1, v[k], v[(k + 1) % 4], 1e-7f, 0});
        const uint32_t first = w.coedge_count();
        for (int k = 0; k < 4; ++k) w.add_coedge(pack::Coedge::make(e[k], false, pack::Seam::None));
        const uint32_t loop = w.add_loop({first, 4});
        w.add_face({plane, loop, 1, pack::kNoIndex, pack::kNoIndex, 0, {0, 0, 0}, {x, y}, {x + 1, y + 1}});
    }
    const uint32_t shell = w.add_shell({0, count, pack::kNoIndex, 0});
    for (const std::array<float, 3>& o : offsets) w.add_instance({shell, {1, 0, 0, o[0], 0, 1, 0, o[1], 0, 0, 1, o[2]}});
    return w.finish();
}

} // namespace facet::test
