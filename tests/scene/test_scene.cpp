#include "test_scene.h"

#include "render/fixed.h"

namespace facet::render {
namespace {

// Object units: 4096 = 1.0. The camera sits at +z looking toward -z, y up.
constexpr int32_t kOne = 4096;
constexpr int32_t kCameraDistance = 5 * kOne;
constexpr int32_t kNear = kCameraDistance - 2 * kOne, kFar = kCameraDistance + 2 * kOne;

struct Shader {
    Mat3 rot;
    int32_t cx16, cy16; // screen centre, 28.4
    int32_t focal;      // pixels per unit at unit depth
    Vec3 light;         // unit vector toward the light, Q14

    // Position (object units) and unit normal (Q14) to a lit screen vertex.
    ScreenVertex shade(Vec3 p, Vec3 n) const {
        const Vec3 q = rot.apply(p);
        const Vec3 m = rot.apply(n);
        const int32_t depth = kCameraDistance - q.z;
        ScreenVertex v;
        v.x = cx16 + static_cast<int32_t>(int64_t(q.x) * focal * 16 / depth);
        v.y = cy16 - static_cast<int32_t>(int64_t(q.y) * focal * 16 / depth);
        const int32_t zr = int32_t((int64_t(depth - kNear) * 65535) / (kFar - kNear));
        v.z = static_cast<uint16_t>(zr < 0 ? 0 : (zr > 65535 ? 65535 : zr));
        // Intensity in Q14: 0.25 ambient + 0.75 diffuse.
        int32_t dot = (m.x * light.x + m.y * light.y + m.z * light.z) >> 14;
        if (dot < 0) dot = 0;
        const int32_t k = 4096 + ((dot * 3) >> 2);
        v.shade = static_cast<uint8_t>((255 * k) >> 14);
        return v;
    }
};

Vec3 add(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 scale(Vec3 a, int32_t num, int32_t den) {
    return {a.x * num / den, a.y * num / den, a.z * num / den};
}

Status draw_cube(Rasterizer& raster, const Shader& s) {
    constexpr int32_t h = kOne * 3 / 4; // half edge
    struct Face {
        Vec3 n, u, v;
        uint8_t r, g, b;
    };
    // u x v = n, so corners -u-v, +u-v, +u+v, -u+v run counter-clockwise seen from outside.
    constexpr Face faces[6] = {
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 230, 90, 60},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, 60, 200, 90},
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 70, 110, 230},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, 230, 200, 60},
        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, 200, 200, 210}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, 160, 80, 200},
    };
    Palette palette;
    for (const Face& f : faces) {
        make_palette(palette, f.r, f.g, f.b);
        const Vec3 c = scale(f.n, h, 1), u = scale(f.u, h, 1), v = scale(f.v, h, 1);
        const Vec3 nq = scale(f.n, 16384, 1);
        const Vec3 corner[4] = {add(c, {-u.x - v.x, -u.y - v.y, -u.z - v.z}),
                                add(c, {u.x - v.x, u.y - v.y, u.z - v.z}), add(c, add(u, v)),
                                add(c, {v.x - u.x, v.y - u.y, v.z - u.z})};
        ScreenVertex sv[4];
        for (int i = 0; i < 4; ++i) sv[i] = s.shade(corner[i], nq);
        if (Status st = raster.draw(sv[0], sv[1], sv[2], palette); !ok(st)) return st;
        if (Status st = raster.draw(sv[0], sv[2], sv[3], palette); !ok(st)) return st;
    }
    return Status::Ok;
}

Status draw_sphere(Rasterizer& raster, const Shader& s) {
    constexpr int kRings = 14, kSegments = 24;
    constexpr int32_t radius = kOne * 3 / 4;
    constexpr Vec3 centre = {kOne / 2, kOne / 3, kOne / 2};
    auto vertex = [&](int ring, int seg) {
        const uint16_t lat = static_cast<uint16_t>(-16384 + ring * 32768 / kRings);
        const uint16_t lon = static_cast<uint16_t>(seg * 65536 / kSegments);
        const int32_t cl = cos_q15(lat);
        const Vec3 n = {int32_t((int64_t(cl) * cos_q15(lon)) >> 16), sin_q15(lat) >> 1,
                        int32_t((int64_t(cl) * sin_q15(lon)) >> 16)}; // Q14
        const Vec3 p = add(centre, scale(n, radius, 16384));
        return s.shade(p, n);
    };
    Palette palette;
    make_palette(palette, 240, 240, 245);
    for (int i = 0; i < kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            const ScreenVertex p00 = vertex(i, j), p01 = vertex(i, j + 1);
            const ScreenVertex p10 = vertex(i + 1, j), p11 = vertex(i + 1, j + 1);
            if (Status st = raster.draw(p00, p10, p11, palette); !ok(st)) return st;
            if (Status st = raster.draw(p00, p11, p01, palette); !ok(st)) return st;
        }
    }
    return Status::Ok;
}

} // namespace

Status draw_test_scene(Rasterizer& raster, const SceneView& view) {
    const Target& t = raster.target();
    const uint16_t w = t.width, h = t.height;
    // Background: a vertical gradient, dark blue-grey at the top to light grey at the bottom.
    for (int32_t y = t.y0; y < t.y0 + t.rows; ++y) {
        const uint32_t k = uint32_t(y) * 255 / (h > 1 ? h - 1 : 1);
        const Rgb565 c = rgb565(uint8_t(40 + k * 150 / 255), uint8_t(48 + k * 150 / 255),
                                          uint8_t(70 + k * 140 / 255));
        Rgb565* row = t.row(y);
        for (uint16_t x = 0; x < w; ++x) row[x] = c;
    }
    raster.clear_depth();

    Shader s;
    s.rot = Mat3::rotation(view.yaw, view.pitch);
    s.cx16 = w * 8;
    s.cy16 = h * 8;
    s.focal = (w < h ? w : h) * 17 / 10;
    s.light = {-6270, 8200, 12300}; // ~(-0.38, 0.5, 0.75) * 16384, unit length within 0.2%
    if (Status st = draw_cube(raster, s); !ok(st)) return st;
    return draw_sphere(raster, s);
}

} // namespace facet::render
