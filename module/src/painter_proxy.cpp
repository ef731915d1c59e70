// A part's proxy drawn where its box would be, or for the part where the view is crowded
// (painter.h: proxy_level(), part_proxy()): a coarse mesh a blocked pack's index holds for it
// (geom/host/proxies.h), placed by the instance's transform, flat-shaded in its colour.
#include "painter.h"

#include <algorithm>
#include <cmath>

namespace facet::module {
uint32_t Painter::proxy_level(uint32_t part, const int32_t sphere_centre[3], int32_t radius, const Transform& t, ProxyNeed need) {
    const geom::PackIndex& index = scene_.index();
    const uint32_t levels = scene_.blocked() && part < index.parts().size() ? index.proxy_levels() : 0;
    if (levels == 0 || mode_ == DisplayMode::Wireframe) return kNone;
    const bool must = need != ProxyNeed::Optional;
    if (!must) { // a part in memory: only in a crowded view, and drawn as itself where it is lit or cut
        if (!crowded_ || proxy_subpixels_ <= 0 || radius <= 0 || chosen(instance_) || hl_[0].instance == instance_ ||
            hl_[1].instance == instance_) {
            return kNone;
        }
        if (t.cut_may_cross(sphere_centre, radius)) return kNone;
    }
    // The coarsest level within the view's proxy error; for a part that must stand as one and
    // has none so near, the coarsest within the left-out error, else the finest.
    uint32_t finest = kNone, left_out = kNone;
    if (need == ProxyNeed::Coarsest) {
        for (uint32_t l = 0; l < levels; ++l) {
            const pack::ProxyPart& x = index.proxy(part, l);
            if (x.triangle_count && x.vertex_count <= mem_.projected.size()) return l;
        }
        return kNone;
    }
    const float per_unit = 0.5f / scene_.unit(); // (a sphere of half the error: across() gives its diameter)
    for (uint32_t l = 0; l < levels; ++l) {
        const pack::ProxyPart& x = index.proxy(part, l);
        if (x.triangle_count == 0 || x.vertex_count > mem_.projected.size()) continue;
        finest = l;
        if (radius <= 0) continue;
        Projected centre;
        const float half = x.error_mm * per_unit;
        const int32_t strays = half < float(radius) ? across(sphere_centre, int32_t(half) + 1, t, centre) : -1;
        if (strays < 0) continue;
        if (strays <= proxy_subpixels_) return must || x.triangle_count < own_triangles(part) ? l : kNone;
        if (strays <= left_out_subpixels_ && left_out == kNone) left_out = l;
    }
    return !must ? kNone : left_out != kNone ? left_out : finest;
}

// The triangles the part's own faces have now, or two a face if more (what it will have: a
// proxy stands for it only with fewer).
uint32_t Painter::own_triangles(uint32_t part) const {
    const Part sh = scene_.part(part);
    uint32_t n = 0;
    for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) n += scene_.face(f).triangle_count;
    return std::max(n, 2 * sh.face_count);
}

// The level's corners projected into mem_.projected (the cut's side marked), over the box they
// are quantized in (a part's, a group's): corner q (0-65535) in the mesh's units is
// base + q x step / 2^16.
void Painter::project_proxy(const float box_min[3], const float box_max[3], const pack::ProxyPart& x, const Transform& t) {
    const geom::PackIndex& index = scene_.index();
    int32_t base[3], step[3];
    const float inv = 1.0f / scene_.unit();
    for (int k = 0; k < 3; ++k) {
        base[k] = int32_t(std::lround(box_min[k] * inv));
        step[k] = int32_t(std::lround((box_max[k] - box_min[k]) * inv * (65536.0f / 65535.0f)));
    }
    Projected* P = mem_.projected.data();
    const pack::ProxyVertex* corners = index.proxy_vertices().data() + x.first_vertex;
    for (uint32_t v = 0; v < x.vertex_count; ++v) {
        int32_t q[3];
        for (int k = 0; k < 3; ++k) q[k] = base[k] + int32_t((int64_t(corners[v].q[k]) * step[k]) >> 16);
        t.project(q, P[v]);
        if (t.cut.on && t.cut.side(P[v].x, P[v].y, P[v].d) > 0) P[v].out |= kOutCut;
    }
}

uint32_t Painter::part_proxy(uint32_t part, const Transform& t, uint32_t level) {
    const pack::Part& p = scene_.index().parts()[part];
    return draw_proxy(scene_.index().proxy(part, level), p.box_min, p.box_max, t);
}

uint32_t Painter::draw_proxy(const pack::ProxyPart& x, const float box_min[3], const float box_max[3], const Transform& t) {
    const geom::PackIndex& index = scene_.index();
    project_proxy(box_min, box_max, x, t);
    const Projected* P = mem_.projected.data();
    const bool white = mode_ == DisplayMode::HiddenLine;
    const pack::Colour c = x.colour;
    const render::Palette& pal = palette(white ? kPaper : c.a ? uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 : kDefaultRgb);
    const render::Cull cull = t.closed ? render::Cull::Back : render::Cull::None;
    const uint32_t second = t.mirrored ? 2 : 1, third = 3 - second;
    const uint32_t pixels = raster_.stats.pixels;
    const pack::ProxyTriangle* tri = index.proxy_triangles().data() + x.first_triangle;
    for (uint32_t k = 0; k < x.triangle_count; ++k) {
        const Projected &pa = P[tri[k].v[0]], &pb = P[tri[k].v[second]], &pc = P[tri[k].v[third]];
        if (cull == render::Cull::Back && !(pa.out | pb.out | pc.out)) { // turned away: culled before it is lit
            const int64_t area2 = int64_t(pb.s.x - pa.s.x) * (pc.s.y - pa.s.y) - int64_t(pb.s.y - pa.s.y) * (pc.s.x - pa.s.x);
            if (area2 >= 0) {
                ++raster_.stats.culled;
                continue;
            }
        }
        // Flat: each triangle lit by its own normal (x 127 in the pack; Q14 here).
        const int16_t n[3] = {int16_t(tri[k].n[0] * 129), int16_t(tri[k].n[1] * 129), int16_t(tri[k].n[2] * 129)};
        const uint8_t shade = white ? uint8_t(200 + ((t.shade(n) * 55) >> 8)) : t.shade(n);
        Projected a = pa, b = pb, cc = pc;
        a.s.shade = b.s.shade = cc.s.shade = shade;
        if (!(a.out | b.out | cc.out)) refused_ += !ok(raster_.draw(a.s, b.s, cc.s, pal, cull));
        else triangle(t, a, b, cc, pal, cull, nullptr);
    }
    return 1 + x.vertex_count / 4 + x.triangle_count + (raster_.stats.pixels - pixels) / 64;
}

bool Painter::all_tiny(const int32_t sphere_centre[3], int32_t radius, int32_t each, const Transform& t) {
    Projected centre;
    const int64_t size = across(sphere_centre, each, t, centre); // (at the sphere's centre's depth)
    if (size < 0) return false;
    if (t.ortho) return size < kTinyPartPixels * render::subpixel::kPerPixel;
    const int64_t nearest = int64_t(centre.d) - ((int64_t(radius) * t.k16) >> 16); // (its nearest point's depth)
    return nearest > 0 && size * centre.d < int64_t(kTinyPartPixels * render::subpixel::kPerPixel) * nearest;
}

// A group's level, in a shaded view: the coarsest of all for a frame of the layout (Coarsest);
// the coarsest whose error, at the group's sphere, is within the view's proxy error, for a group
// whose members stand as proxies anyway (Must: left out, or the group a few pixels across:
// else within the left-out error) or in a crowded view (Optional); kNone where its members are
// drawn each.
uint32_t Painter::group_level(uint32_t g, const int32_t sphere_centre[3], int32_t radius, const Transform& t, ProxyNeed need,
                              uint32_t most_triangles) {
    const geom::PackIndex& index = scene_.index();
    const uint32_t levels = index.group_levels();
    if (levels == 0 || radius <= 0 || !(mode_ == DisplayMode::Shaded || mode_ == DisplayMode::ShadedEdges)) return kNone;
    if (need == ProxyNeed::Optional && (!crowded_ || proxy_subpixels_ <= 0)) return kNone;
    const pack::Group& group = index.groups()[g];
    uint32_t left_out = kNone;
    for (uint32_t l = 0; l < levels; ++l) { // (a level's pieces fit the projection's room, or it is not drawn)
        uint32_t fits = 1, triangles = 0;
        for (uint32_t c = 0; c < group.colours; ++c) {
            const pack::ProxyPart& piece = index.group_piece(g, l, c);
            fits &= piece.vertex_count <= mem_.projected.size();
            triangles += piece.triangle_count;
        }
        if (!fits || triangles > most_triangles) continue;
        if (need == ProxyNeed::Coarsest) return l;
        Projected centre;
        const float half = index.group_piece(g, l, 0).error_mm * 0.5f / scene_.unit();
        const int32_t strays = half < float(radius) ? across(sphere_centre, int32_t(half) + 1, t, centre) : -1;
        if (strays < 0) continue;
        if (strays <= proxy_subpixels_) return l;
        if (need == ProxyNeed::Must && strays <= left_out_subpixels_ && left_out == kNone) left_out = l;
    }
    return left_out;
}

uint32_t Painter::group_proxy(uint32_t g, const Transform& t, uint32_t level) {
    const geom::PackIndex& index = scene_.index();
    const pack::Group& group = index.groups()[g];
    uint32_t work = 0;
    for (uint32_t c = 0; c < group.colours; ++c) work += draw_proxy(index.group_piece(g, level, c), group.box_min, group.box_max, t);
    return work;
}

// Hidden line: a proxy's outline (sides between a triangle that shows and one that does not, or
// at a rim) and its creases (sides whose triangles' normals part by more than about 35
// degrees), depth-tested over the faces as a part's edges are. A closed part's triangles turned
// away do not show; an open one's show both sides. A level of more than kOutlineTriangles
// triangles (none the packer makes) draws none.
uint32_t Painter::proxy_outline(uint32_t part, const Transform& t, uint32_t level) {
    constexpr uint32_t kOutlineTriangles = 2048;
    constexpr int32_t kCrease = 13200; // cos 35 degrees x 127^2
    const geom::PackIndex& index = scene_.index();
    const pack::ProxyPart& x = index.proxy(part, level);
    if (mode_ != DisplayMode::HiddenLine || x.triangle_count > kOutlineTriangles) return 1;
    const pack::Part& p = index.parts()[part];
    project_proxy(p.box_min, p.box_max, x, t);
    const Projected* P = mem_.projected.data();
    const pack::ProxyTriangle* tri = index.proxy_triangles().data() + x.first_triangle;
    uint32_t shows[kOutlineTriangles / 32] = {}, front[kOutlineTriangles / 32] = {};
    for (uint32_t k = 0; k < x.triangle_count; ++k) {
        const Projected &a = P[tri[k].v[0]], &b = P[tri[k].v[1]], &c = P[tri[k].v[2]];
        if (a.out | b.out | c.out) continue; // (near the eye, past the band or cut away: no line of it)
        const int64_t area2 = int64_t(b.s.x - a.s.x) * (c.s.y - a.s.y) - int64_t(b.s.y - a.s.y) * (c.s.x - a.s.x);
        const bool faces_eye = t.mirrored ? area2 > 0 : area2 < 0; // (counter-clockwise on the screen, y down)
        if (faces_eye) front[k / 32] |= 1u << (k % 32);
        if (faces_eye || !t.closed) shows[k / 32] |= 1u << (k % 32);
    }
    auto bit = [](const uint32_t* bits, uint32_t k) { return (bits[k / 32] >> (k % 32)) & 1u; };
    uint32_t lines = 0;
    for (uint32_t k = 0; k < x.triangle_count; ++k) {
        if (!bit(shows, k)) continue;
        for (int side = 0; side < 3; ++side) {
            const uint16_t n = tri[k].across[side];
            bool draw = n == pack::kNoProxyNeighbour || !bit(shows, n);
            if (!draw && k < n) {
                const int32_t dot = tri[k].n[0] * tri[n].n[0] + tri[k].n[1] * tri[n].n[1] + tri[k].n[2] * tri[n].n[2];
                draw = bit(front, k) != bit(front, n) || dot < kCrease;
            }
            if (!draw) continue;
            const Projected &a = P[tri[k].v[side]], &b = P[tri[k].v[(side + 1) % 3]];
            refused_ += !ok(raster_.line(a.s, b.s, kEdgeColour, kLineBias));
            ++lines;
        }
    }
    return 1 + x.vertex_count / 4 + x.triangle_count / 4 + lines;
}

} // namespace facet::module
