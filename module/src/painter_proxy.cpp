// A part's proxy drawn where its box would be (painter.h: draws_proxy(), part_proxy()): the
// coarse mesh a blocked pack's index holds for it (geom/host/proxies.h), placed by the
// instance's transform, flat-shaded in its colour.
#include "painter.h"

#include <cmath>

namespace facet::module {
bool Painter::draws_proxy(uint32_t part) const {
    const auto proxies = scene_.index().proxy_parts();
    return mode_ != DisplayMode::Wireframe && scene_.blocked() && part < proxies.size() && proxies[part].triangle_count > 0 &&
           proxies[part].vertex_count <= mem_.projected.size();
}

uint32_t Painter::part_proxy(uint32_t part, const Transform& t) {
    if (!draws_proxy(part)) return 1;
    const geom::PackIndex& index = scene_.index();
    const pack::ProxyPart& x = index.proxy_parts()[part];
    const pack::Part& p = index.parts()[part];
    // A corner q (0-65535 over the part's box) in the mesh's units: base + q x step / 2^16.
    int32_t base[3], step[3];
    const float inv = 1.0f / scene_.unit();
    for (int k = 0; k < 3; ++k) {
        base[k] = int32_t(std::lround(p.box_min[k] * inv));
        step[k] = int32_t(std::lround((p.box_max[k] - p.box_min[k]) * inv * (65536.0f / 65535.0f)));
    }
    Projected* P = mem_.projected.data();
    const pack::ProxyVertex* corners = index.proxy_vertices().data() + x.first_vertex;
    for (uint32_t v = 0; v < x.vertex_count; ++v) {
        int32_t q[3];
        for (int k = 0; k < 3; ++k) q[k] = base[k] + int32_t((int64_t(corners[v].q[k]) * step[k]) >> 16);
        t.project(q, P[v]);
        if (t.cut.on && t.cut.side(P[v].x, P[v].y, P[v].d) > 0) P[v].out |= kOutCut;
    }
    const bool white = mode_ == DisplayMode::HiddenLine;
    const pack::Colour c = x.colour;
    const render::Palette& pal = palette(white ? kPaper : c.a ? uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 : kDefaultRgb);
    const render::Cull cull = t.closed ? render::Cull::Back : render::Cull::None;
    const uint32_t second = t.mirrored ? 2 : 1, third = 3 - second;
    const uint32_t pixels = raster_.stats.pixels;
    const pack::ProxyTriangle* tri = index.proxy_triangles().data() + x.first_triangle;
    for (uint32_t k = 0; k < x.triangle_count; ++k) {
        // Flat: each triangle lit by its own normal (x 127 in the pack; Q14 here).
        const int16_t n[3] = {int16_t(tri[k].n[0] * 129), int16_t(tri[k].n[1] * 129), int16_t(tri[k].n[2] * 129)};
        const uint8_t shade = white ? uint8_t(200 + ((t.shade(n) * 55) >> 8)) : t.shade(n);
        Projected a = P[tri[k].v[0]], b = P[tri[k].v[second]], cc = P[tri[k].v[third]];
        a.s.shade = b.s.shade = cc.s.shade = shade;
        if (!(a.out | b.out | cc.out)) refused_ += !ok(raster_.draw(a.s, b.s, cc.s, pal, cull));
        else triangle(t, a, b, cc, pal, cull, nullptr);
    }
    return 1 + x.vertex_count / 4 + x.triangle_count + (raster_.stats.pixels - pixels) / 64;
}

} // namespace facet::module
