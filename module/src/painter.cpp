#include "painter.h"

#include "render/fixed.h"
#include "render/text.h"

#include <algorithm>

namespace facet::module {
namespace {

constexpr Rgb565 kBoxColour = rgb565(96, 104, 128); // a part's box before its edges are in
constexpr uint32_t kNoColour = 0xFF000000u; // no palette in the slot (colours are 24-bit)
constexpr uint32_t kPicked = 0x00C830FFu;   // the picked face (B, G, R bytes: magenta, rare in CAD colours)
constexpr uint32_t kPicked2 = 0x00FFD020u;  // the second one (measuring: cyan)
constexpr uint32_t kCap = 0x003C46CDu;      // the inside of a cut solid (a section): brick red
constexpr uint8_t kCapShade = 255;          // drawn flat, in that colour
// A face left untessellated for its size (under kFacePixels across) and under this across now
// is drawn as a speck, not as its edges.
constexpr int32_t kSpeckPixels = kFacePixels + 1;
// A face tessellated for another instance of its part and under this across in this one is
// drawn as a speck too (the size the view tessellates a face for).
constexpr int32_t kShownPixels = kFacePixels;
constexpr uint8_t kSpeckShade = 200;        // a speck in the face's colour: lit about halfway
// A splat's side: about 0.7 of the face's size across (a disc of diameter D holds a square of 0.7 D).
static_assert(kSplatPixels * 11 / 16 <= render::Rasterizer::kMaxSplat, "the largest splat is one the rasterizer draws");

// X / d for d >= 1, to about 2^-15 relative, without dividing (render/fixed.h).
inline int32_t divide(int64_t x, int32_t d) { return render::divide(x, render::reciprocal(uint32_t(d))); }

inline int32_t round_to_int(float v) { return int32_t(v + (v >= 0 ? 0.5f : -0.5f)); }

} // namespace

// Whether the face's sphere lies wholly on the side the section cuts away.
bool Painter::cut_away(const Transform& t, const FaceInfo& F) {
    if (F.radius <= 0) return false;
    int32_t x, y, d;
    t.to_view(F.centre, x, y, d);
    const int64_t rv = (int64_t(F.radius) * t.k16) >> 16;
    return t.cut.side(x, y, d) > (rv + rv / 8 + 2) * 16384;
}

// A point in camera space onto the screen (false: behind the near plane or beyond the guard band).
bool Painter::to_screen(const Transform& t, Projected& p) {
    const int32_t over = t.ortho ? t.dist : p.d;
    if (p.d < t.near) return false;
    const int64_t X = int64_t(p.x) * t.f16, Y = int64_t(p.y) * t.f16, G = int64_t(t.guard) * over;
    if (X > G || -X > G || Y > G || -Y > G) return false;
    p.s.x = t.cx16 + divide(X, over);
    p.s.y = t.cy16 - divide(Y, over);
    const int64_t zz = (int64_t(p.d - t.near) * t.zk) >> 16;
    p.s.z = uint16_t(zz > 65535 ? 65535 : zz);
    return true;
}

void Painter::init(const Memory& memory) {
    mem_ = memory;
    for (uint32_t& rgb : mem_.palette_rgb) rgb = kNoColour;
    next_palette_ = 0;
    for (ProjectedPoint& slot : mem_.points) slot.stamp = 0;
    stamp_ = base_ = stamp_end_ = 1;
}

void Painter::begin_frame(uint32_t instances) {
    if (stamp_end_ + instances + 1 < stamp_end_) { // (after 2^32 instances drawn)
        for (ProjectedPoint& slot : mem_.points) slot.stamp = 0;
        stamp_end_ = 1;
    }
    base_ = stamp_end_, stamp_ = base_;
    stamp_end_ = base_ + instances + 1;
}

const render::Palette& Painter::palette(uint32_t rgb) {
    for (uint32_t i = 0; i < mem_.palette_rgb.size(); ++i)
        if (mem_.palette_rgb[i] == rgb) return mem_.palettes[i];
    const uint32_t i = next_palette_;
    next_palette_ = (next_palette_ + 1) % uint32_t(mem_.palettes.size());
    mem_.palette_rgb[i] = rgb;
    render::make_palette(mem_.palettes[i], uint8_t(rgb & 255), uint8_t((rgb >> 8) & 255), uint8_t((rgb >> 16) & 255));
    return mem_.palettes[i];
}

Rows Painter::rows(const Transform& t) const {
    const render::Target& tg = raster_.target();
    return {t.cy16 - render::subpixel::start(tg.y0), render::subpixel::start(tg.y0 + tg.rows) - t.cy16};
}

void Painter::background() {
    const render::Target& t = raster_.target();
    // A CAD-style background: light at the top, darker toward the bottom (16.16 steps per row,
    // from the screen's top whatever the band).
    const int32_t rows = t.height > 1 ? t.height - 1 : 1;
    const int32_t dr = (80 << 16) / rows, dg = (78 << 16) / rows, db = (64 << 16) / rows;
    int32_t r = (214 << 16) - int32_t(t.y0) * dr, g = (222 << 16) - int32_t(t.y0) * dg, b = (234 << 16) - int32_t(t.y0) * db;
    for (int32_t y = t.y0; y < t.y0 + t.rows; ++y, r -= dr, g -= dg, b -= db) {
        render::fill_pixels(t.row(y), t.width, rgb565(uint8_t(r >> 16), uint8_t(g >> 16), uint8_t(b >> 16)));
    }
}

void Painter::reset_edges(uint32_t part) {
    uint32_t first = 0, count = 0;
    if (!scene_.part_edges(part, first, count)) first = 0, count = scene_.edge_count();
    for (uint8_t& drawn : mem_.edge_drawn.subspan(first, count)) drawn = 0;
}

namespace {

// Whether a camera-space point lies in front of twice the near distance and within nine tenths
// of the guard band (Painter::triangle's planes but the section's keep it, whatever their float
// rounding).
bool well_within(const Transform& t, const Projected& p) {
    if (p.d < 2 * t.near) return false;
    const int64_t over = t.ortho ? t.dist : p.d;
    const int64_t X = int64_t(p.x < 0 ? -int64_t(p.x) : p.x) * t.f16, Y = int64_t(p.y < 0 ? -int64_t(p.y) : p.y) * t.f16;
    const int64_t most = 9 * int64_t(t.guard) * over;
    return 10 * X <= most && 10 * Y <= most;
}

} // namespace

void Painter::triangle(const Transform& t, const Projected& a, const Projected& b, const Projected& c,
                       const render::Palette& pal, render::Cull cull, const render::Palette* cap) {
    if (!(a.out | b.out | c.out)) {
        if (cap && render::doubled_area(a.s, b.s, c.s) > 0) {
            // A back face seen through the cut: the solid's inside, flat in the cap colour.
            // Where the front faces drawn before it hide all of it, it is left out.
            if (raster_.hidden(a.s, b.s, c.s)) return;
            render::ScreenVertex s[3] = {a.s, b.s, c.s};
            for (render::ScreenVertex& v : s) v.shade = kCapShade;
            refused_ += !ok(raster_.draw(s[0], s[1], s[2], *cap, render::Cull::None));
            return;
        }
        refused_ += !ok(raster_.draw(a.s, b.s, c.s, pal, cull)); // inside the guard band: never refused
        return;
    }
    if (a.out & b.out & c.out & (kOutNear | kOutCut)) return;
    // Clip against the near plane and the guard band (camera space, float: a rare path but for
    // a section), and the section. A triangle whose corners lie well within the others (twice
    // the near distance, nine tenths of the band, in integers) is clipped by the section's alone:
    // the others would keep it whole.
    const bool cut_only = t.cut.on && well_within(t, a) && well_within(t, b) && well_within(t, c);
    struct V {
        float x, y, d, shade;
    };
    const float near = float(t.near), f16 = float(t.f16);
    const float G = float(t.guard) * 0.98f; // inside the band after rounding
    V poly[10], tmp[10];
    int n = 3;
    const Projected* src[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i) poly[i] = {float(src[i]->x), float(src[i]->y), float(src[i]->d), float(src[i]->s.shade)};
    const float dist = float(t.dist);
    // The section's side (a plane in camera space; positive: cut away), scaled to view units.
    const float cx = float(t.cut.nx), cy = float(t.cut.ny), cd = float(t.cut.nd), cc = t.cut.c_float;
    auto plane = [&](const V& v, int k) {
        const float over = t.ortho ? dist : v.d; // the guard band's sides: parallel in a parallel view
        switch (k) {
        case 0: return v.d - near * 1.01f;
        case 1: return G * over - f16 * v.x;
        case 2: return G * over + f16 * v.x;
        case 3: return G * over - f16 * v.y;
        case 4: return G * over + f16 * v.y;
        default: return -(cx * v.x + cy * v.y + cd * v.d + cc);
        }
    };
    for (int k = cut_only ? 5 : 0; k < (t.cut.on ? 6 : 5) && n >= 3; ++k) {
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const V& p = poly[i];
            const V& q = poly[(i + 1) % n];
            const float dp = plane(p, k), dq = plane(q, k);
            if (dp >= 0) tmp[m++] = p;
            if ((dp >= 0) != (dq >= 0)) {
                const float s = dp / (dp - dq);
                tmp[m++] = {p.x + (q.x - p.x) * s, p.y + (q.y - p.y) * s, p.d + (q.d - p.d) * s, p.shade + (q.shade - p.shade) * s};
            }
        }
        n = m;
        for (int i = 0; i < n; ++i) poly[i] = tmp[i];
    }
    if (n < 3) return;
    render::ScreenVertex s[10];
    for (int i = 0; i < n; ++i) {
        const int32_t d = round_to_int(poly[i].d) > t.near ? round_to_int(poly[i].d) : t.near;
        const int32_t over = t.ortho ? t.dist : d; // parallel: x and y over the centre's depth
        s[i].x = t.cx16 + divide(int64_t(round_to_int(poly[i].x)) * t.f16, over);
        s[i].y = t.cy16 - divide(int64_t(round_to_int(poly[i].y)) * t.f16, over);
        const int64_t zz = (int64_t(d - t.near) * t.zk) >> 16;
        s[i].z = uint16_t(zz > 65535 ? 65535 : zz);
        s[i].shade = uint8_t(poly[i].shade);
    }
    if (cap) { // the polygon's orientation: a back face through the cut takes the cap colour
        int64_t area2 = 0;
        for (int i = 1; i + 1 < n; ++i) {
            area2 += int64_t(s[i].x - s[0].x) * (s[i + 1].y - s[0].y) - int64_t(s[i].y - s[0].y) * (s[i + 1].x - s[0].x);
        }
        if (area2 > 0) {
            for (int i = 0; i < n; ++i) s[i].shade = kCapShade;
            for (int i = 1; i + 1 < n; ++i) refused_ += !ok(raster_.draw(s[0], s[i], s[i + 1], *cap, render::Cull::None));
            return;
        }
    }
    for (int i = 1; i + 1 < n; ++i) refused_ += !ok(raster_.draw(s[0], s[i], s[i + 1], pal, cull));
}

uint32_t Painter::face(uint32_t f, const Transform& t, Rows rows, uint32_t from, uint32_t units, uint32_t& spent) {
    const FaceInfo& F = scene_.face(f);
    Projected* P = mem_.projected.data();
    const DrawVertex* verts = scene_.vertices() + F.first_vertex;
    spent = 0;
    if (mode_ == DisplayMode::Wireframe) return F.triangle_count; // edges only
    const bool white = mode_ == DisplayMode::HiddenLine; // faces mostly hide what is behind them
    const bool inside = t.closed && t.inside_shows();    // its back faces may show through a section
    const bool outlines = white && !F.planar;            // a curved face's silhouette: no B-rep edge draws it
    if (from == 0) { // the face's vertices, once
        if (F.state != FaceState::Done || (!inside_ && !t.visible(F.centre, F.radius, rows))) return F.triangle_count;
        if (t.cut.on && cut_away(t, F)) return F.triangle_count;
        if (F.planar && F.vertex_count && t.hides_plane(verts[0].p, verts[0].n)) return F.triangle_count;
        if (dragging_ && (mode_ == DisplayMode::ShadedEdges || mode_ == DisplayMode::Shaded) && !t.cut.on && !lit(f)) {
            // A face a few pixels across while the view moves: a square of its colour, lit by
            // its first normal, about its area (a sphere's diameter D holds a square of side 0.7 D).
            Projected centre;
            const int32_t size = across(F.centre, F.radius, t, centre);
            if (size >= 0 && size < kSplatPixels * render::subpixel::kPerPixel) {
                const int32_t side = std::clamp<int32_t>((size * 11 / 16 + render::subpixel::kHalfPixel) >> render::subpixel::kFractionBits, 1, kSplatPixels * 11 / 16);
                refused_ += !ok(raster_.splat(centre.s, side, Rgb565(palette(F.rgb).colour[t.shade(verts[0].n)])));
                spent = 1;
                return F.triangle_count;
            }
        }
        Projected centre;
        if (!dragging_ && far_copy_specks(f, t) && under(F.centre, F.radius, t, kShownPixels, centre)) return F.triangle_count; // (its speck: face_edges)
        const bool caching = this->caching();
        for (uint32_t v = 0; v < F.vertex_count; ++v) {
            P[v] = caching ? point_in(slot_of(verts[v].p), verts[v].p, t) : point(verts[v].p, t);
            if (t.cut.on && t.cut.side(P[v].x, P[v].y, P[v].d) > 0) P[v].out |= kOutCut;
            // Hidden line: paper faces, lit just enough (200-255) that curved outlines (no B-rep
            // edge: a cylinder's silhouette) still read against each other.
            P[v].s.shade = white ? uint8_t(200 + ((t.shade(verts[v].n) * 55) >> 8)) : t.shade(verts[v].n);
            if (outlines) P[v].front = t.facing(verts[v].p, verts[v].n) > 0;
        }
        if (nearer_) { // (the same depths less one: its own pixels pass, no other's)
            for (uint32_t v = 0; v < F.vertex_count; ++v) P[v].s.z -= P[v].s.z > 0;
        }
        spent = 1 + (F.vertex_count >> (outlines ? 1 : 2));
    }
    const render::Palette& pal = palette(lit(f) ? (hl_[1].face == f && hl_[1].instance == instance_ ? kPicked2 : kPicked) : white ? kPaper : F.rgb);
    const render::Cull cull = t.closed && !inside ? render::Cull::Back : render::Cull::None;
    const render::Palette* cap = inside ? &palette(kCap) : nullptr;
    raster_.set_stipple(mode_ == DisplayMode::SeeThrough && instance_ != focus_ && !chosen(instance_));
    const uint16_t* id = scene_.indices() + F.first_index + 3 * from;
    const uint32_t pixels = raster_.stats.pixels;
    uint32_t k = from;
    // A unit: a triangle's set-up, or 64 pixels; one triangle at least, whatever the units.
    // (A mirrored instance turns its triangles' winding: their second and third corners swap.)
    const uint32_t second = t.mirrored ? 2 : 1, third = 3 - second;
    for (; k < F.triangle_count && (k == from || spent + (raster_.stats.pixels - pixels) / 64 < units); ++k, id += 3, ++spent) {
        const Projected &a = P[id[0]], &b = P[id[second]], &c = P[id[third]];
        if (!(a.out | b.out | c.out) && !cap) refused_ += !ok(raster_.draw(a.s, b.s, c.s, pal, cull)); // (triangle()'s common case)
        else triangle(t, a, b, c, pal, cull, cap);
    }
    raster_.set_stipple(false);
    if (outlines && k == F.triangle_count) spent += silhouette(F, t);
    spent += (raster_.stats.pixels - pixels) / 64;
    return k;
}

uint32_t Painter::highlighted_faces(uint32_t first, uint32_t count, const Transform& t, Rows rows) {
    if (mode_ == DisplayMode::Wireframe) return 0;
    uint32_t work = 0;
    auto again = [&](uint32_t f) {
        uint32_t used;
        (void)face(f, t, rows, 0, kNone, used);
        work += used + 1;
    };
    nearer_ = true;
    if (chosen(instance_)) {
        for (uint32_t f = first; f < first + count; ++f) again(f);
    } else {
        for (const Highlight& h : hl_) {
            if (h.instance == instance_ && h.face >= first && h.face < first + count) again(h.face);
        }
        if (pmi_) // (an annotation's faces: no face is both picked and an annotation's, the selection ends a choice)
            for (uint32_t f : pmi_->faces(annotation_)) if (f >= first && f < first + count) again(f);
    }
    nearer_ = false;
    return work;
}

// Where a triangle's vertex normals turn from the eye to away from it, the surface's outline
// crosses it: from the vertex alone on its side, the points of its two edges where n . (eye -
// p) is zero (interpolated on the screen, as the triangle's depth is), joined by an outline:
// a line depth-tested one pixel beyond it. Triangles cut away or off the view are left out.
uint32_t Painter::silhouette(const FaceInfo& F, const Transform& t) {
    const Projected* P = mem_.projected.data();
    const DrawVertex* verts = scene_.vertices() + F.first_vertex;
    const uint16_t* id = scene_.indices() + F.first_index;
    uint32_t crossed = 0;
    for (uint32_t k = 0; k < F.triangle_count; ++k, id += 3) {
        const uint8_t fronts = P[id[0]].front + P[id[1]].front + P[id[2]].front;
        if (fronts == 0 || fronts == 3 || (P[id[0]].out | P[id[1]].out | P[id[2]].out)) continue;
        // The lone vertex first: the one whose side the other two do not share.
        const int lone = P[id[0]].front != P[id[1]].front ? (P[id[0]].front != P[id[2]].front ? 0 : 1) : 2;
        const uint16_t v[3] = {id[lone], id[(lone + 1) % 3], id[(lone + 2) % 3]};
        int64_t g[3];
        for (int j = 0; j < 3; ++j) g[j] = t.facing(verts[v[j]].p, verts[v[j]].n);
        render::ScreenVertex end[2];
        for (int j = 0; j < 2; ++j) {
            // u = g0 / (g0 - g), in [0, 1] as the signs differ: both to 16 bits, one reciprocal.
            uint64_t num = uint64_t(g[0] < 0 ? -g[0] : g[0]), den = num + uint64_t(g[j + 1] < 0 ? -g[j + 1] : g[j + 1]);
            const int drop = 48 - __builtin_clzll(den); // den >> drop < 2^16
            if (drop > 0) num >>= drop, den >>= drop;
            const int32_t u = den ? render::divide(int64_t(num) << 16, render::reciprocal(uint32_t(den))) : 0; // Q16
            const Projected &a = P[v[0]], &b = P[v[j + 1]];
            end[j].x = a.s.x + int32_t((int64_t(b.s.x - a.s.x) * u) >> 16);
            end[j].y = a.s.y + int32_t((int64_t(b.s.y - a.s.y) * u) >> 16);
            end[j].z = uint16_t(a.s.z + int32_t((int64_t(int32_t(b.s.z) - a.s.z) * u) >> 16));
            end[j].shade = 0;
        }
        // Beyond the outline: where the surface's normal points there (it lies across the view
        // there, outward), along the axis across the line (x for a steep one, y for a flat one).
        int32_t n[3];
        for (int c = 0; c < 3; ++c) n[c] = verts[v[0]].n[c] + verts[v[1]].n[c] + verts[v[2]].n[c];
        int64_t across[3];
        t.rotate(n, across); // view x right, y up
        const int32_t lx = end[1].x - end[0].x, ly = end[1].y - end[0].y;
        const bool steep = (ly < 0 ? -ly : ly) > (lx < 0 ? -lx : lx);
        const uint8_t beyond = steep ? (across[0] >= 0 ? 0 : 2) : (across[1] <= 0 ? 1 : 3);
        refused_ += !ok(raster_.outline(end[0], end[1], kEdgeColour, kLineBias, beyond));
        ++crossed;
    }
    return F.triangle_count / 16 + crossed;
}

uint32_t Painter::face_edges(uint32_t f, const Transform& t, Rows rows, bool once) {
    // Its edges lie in its sphere; a plane facing away hides them unless a neighbour shows them.
    const FaceInfo& info = scene_.face(f);
    if (info.state == FaceState::Done && !dragging_ && far_copy_specks(f, t)) { // (as face() judged it)
        if (const uint32_t work = speck(f, t, kShownPixels)) return work;
    }
    if (info.state == FaceState::Done && !done_faces_show_edges()) return 0; // (a face not in yet shows its edges)
    if (crowded_ && info.state == FaceState::Done && (mode_ == DisplayMode::ShadedEdges || mode_ == DisplayMode::HiddenLine) && !lit(f)) {
        Projected centre;
        if (under(info.centre, info.radius, t, kCrowdedEdgePixels, centre)) return 1; // (its neighbours' edges outline it)
    }
    // A face left to its edges for its size, or waiting for its mesh and as small (its sphere
    // known: the model's bounds give it): a speck, as it will show at rest.
    if ((info.state == FaceState::Deferred || (info.state == FaceState::Pending && info.radius > 0)) && speckable(t)) {
        if (const uint32_t work = speck(f, t, kSpeckPixels)) return work;
    }
    if (!inside_ && !t.visible(info.centre, info.radius, rows)) return 0;
    if (t.cut.on && cut_away(t, info)) return 0;
    if (mode_ != DisplayMode::Wireframe && info.planar) {
        if (info.vertex_count) {
            const DrawVertex& v = scene_.vertices()[info.first_vertex];
            if (t.hides_plane(v.p, v.n)) return 0;
        } else if (waiting_plane_hidden(f, t)) {
            return 0;
        }
    }
    const Block& block = scene_.block_of_face(f);
    const geom::Pack& pack = block.pack;
    const pack::Face& F = pack.faces()[f - block.first_face];
    uint32_t work = 1;
    for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
        const pack::Loop& L = pack.loops()[l];
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const pack::Coedge& C = pack.coedges()[c];
            if (C.seam() != pack::Seam::None) continue; // a periodic surface's seam is no B-rep edge to the eye
            const uint32_t local = C.edge(), e = block.first_edge + local;
            if (pack.edges()[local].curve == pack::kNoIndex) continue; // a pole: nothing to draw
            if (!tangent_edges_ && pack.smooth_edge(local)) continue;  // tangent edges hidden: no outline there
            if (once) {
                if (mem_.edge_drawn[e]) continue;
                mem_.edge_drawn[e] = 1;
            }
            work += edge(e, t);
        }
    }
    return work;
}

// A plane not tessellated yet (deferred: turned away when the view was judged) has no mesh
// normal: its surface's, and a point of its boundary.
bool Painter::waiting_plane_hidden(uint32_t f, const Transform& t) const {
    if (!t.closed || t.inside_shows()) return false;
    int16_t n[3];
    const int32_t* p = scene_.boundary_point(f);
    return p && scene_.plane_normal(f, n) && t.hides_plane(p, n);
}

// A sphere (a face's, a part's) across on the screen (sub-pixels, at most 64 pixels' worth), its centre
// projected into `centre`; -1 when no sphere is known or its centre is off (near the eye, or
// past the guard band).
int32_t Painter::across(const int32_t sphere_centre[3], int32_t radius, const Transform& t, Projected& centre) {
    return radius > 0 ? t.across(sphere_centre, radius, 64 * render::subpixel::kPerPixel, centre) : -1;
}

// A face a few pixels across, left out by the view (or tessellated for a nearer copy of its
// part), shows as a speck: the pixel of its sphere's centre
// (within a pixel of the surface), depth-tested like an edge, in the edges' colour (the face's
// own where edges are not drawn). Its edges would be a knot of lines a pixel long, a
// projection per sample for the same few pixels. Returns the work, or 0 when the face is
// larger (or near the eye or the guard band): its edges then, as usual. (No section: a face
// the cut crosses shows its edges.)
uint32_t Painter::speck(uint32_t f, const Transform& t, int32_t pixels) {
    const FaceInfo& info = scene_.face(f);
    Projected centre;
    if (!under(info.centre, info.radius, t, pixels, centre)) return 0;
    const Rgb565 colour = mode_ == DisplayMode::Shaded ? Rgb565(palette(info.rgb).colour[kSpeckShade]) : kEdgeColour;
    refused_ += !ok(raster_.point(centre.s, colour, kLineBias));
    return 1;
}

bool Painter::under(const int32_t sphere_centre[3], int32_t radius, const Transform& t, int32_t pixels, Projected& centre) {
    const int32_t size = across(sphere_centre, radius, t, centre);
    return size >= 0 && size < pixels * render::subpixel::kPerPixel;
}

// Whether a tessellated face may be a speck in this instance: one under the size the view
// tessellates a face for (kShownPixels; detail.cpp) is drawn as its speck instead of its
// triangles and edges, at rest (face() and face_edges() test its size alike): the view
// judged it by its part's nearest instance, and one further off shows it as the view shows a
// face it left out. Not a picked or chosen face; and a model whose every part is placed once
// has none (its faces were judged where they are).
bool Painter::far_copy_specks(uint32_t f, const Transform& t) const {
    return scene_.instances().size() > scene_.part_count() && speckable(t) && !lit(f);
}

bool Painter::tiny(const int32_t sphere_centre[3], int32_t radius, const Transform& t) {
    Projected centre;
    return under(sphere_centre, radius, t, kTinyPartPixels, centre);
}

uint32_t Painter::part_box(uint32_t part, const Transform& t) {
    int32_t at[8][3];
    if (!scene_.part_corners(part, at)) return 1;
    Projected corner[8];
    for (int c = 0; c < 8; ++c) t.project(at[c], corner[c]);
    for (int c = 0; c < 8; ++c) { // each corner to the ones one bit up: the twelve sides
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (c & bit) continue;
            const Projected &a = corner[c], &b = corner[c | bit];
            if (!(a.out | b.out)) refused_ += !ok(raster_.line(a.s, b.s, kBoxColour, kLineBias));
        }
    }
    return 4;
}

uint32_t Painter::edge(uint32_t e, const Transform& t) {
    const geom::EdgeSamples& samples = scene_.samples();
    const uint32_t first = samples.first[e], n = samples.count[e];
    // The previous sample stays in its cache slot unless this one takes that slot (or the
    // cache is off: one answer for all): then it is copied out first.
    Projected kept;
    const Projected* prev = nullptr;
    int64_t prev_side = 0, side = 0;
    const bool caching = this->caching();
    for (uint32_t k = 0; k < n; ++k) {
        const int32_t* p = scene_.sample_q(first + k);
        const Projected* cur;
        if (caching) {
            const uint32_t s = slot_of(p);
            if (prev == &mem_.points[s].at) kept = *prev, prev = &kept;
            cur = &point_in(s, p, t);
        } else {
            if (prev) kept = *prev, prev = &kept;
            cur = &point(p, t);
        }
        if (t.cut.on) side = t.cut.side(cur->x, cur->y, cur->d);
        // Segments that leave the view volume are left out (edges are not clipped); a section
        // keeps the part of a segment on its side. (A face's vertices may carry its cut flag:
        // the segment's side is measured here.)
        if (prev && !((prev->out | cur->out) & (kOutNear | kOutGuard))) {
            if (!t.cut.on || (prev_side <= 0 && side <= 0)) {
                refused_ += !ok(raster_.line(prev->s, cur->s, kEdgeColour, kLineBias));
            } else if (prev_side <= 0 || side <= 0) {
                const float u = float(prev_side) / float(prev_side - side); // where the segment meets the plane
                const Projected& in = prev_side <= 0 ? *prev : *cur;
                Projected at{};
                at.x = round_to_int(float(prev->x) + float(cur->x - prev->x) * u);
                at.y = round_to_int(float(prev->y) + float(cur->y - prev->y) * u);
                at.d = round_to_int(float(prev->d) + float(cur->d - prev->d) * u);
                if (to_screen(t, at)) refused_ += !ok(raster_.line(in.s, at.s, kEdgeColour, kLineBias));
            }
        }
        prev = cur, prev_side = side;
    }
    return 1 + n / 8;
}

} // namespace facet::module
