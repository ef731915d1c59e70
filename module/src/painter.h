#pragma once
// Drawing the scene into the rasterizer's target (a frame, or a band of it): the background,
// a face's triangles (clipped against the near plane and the guard band where they cross
// them), its B-rep edges over it, and the palettes that colour them.
#include "camera.h"
#include "facet/viewer.h"
#include "geom/pmi.h"
#include "overlay.h"
#include "render/raster.h"
#include "scene.h"

#include <bit>
#include <span>
#include <utility>

namespace facet::module {

constexpr uint32_t kPaper = 0x00FFFFFFu; // hidden-line faces (and proxies): white
constexpr uint16_t kLineBias = 384;       // depth units edges are pulled toward the eye
constexpr Rgb565 kEdgeColour = rgb565(28, 30, 38);

// The smallest face worth its triangles: one under this many pixels across (its sphere's
// diameter) wherever the view shows it is left untessellated, drawn by its edges or as a speck
// until the view makes it larger (detail.cpp, painter.cpp). Its edges, a pixel wide, cover
// most of what such a face would show (issue 25: the frames and the first view follow the
// screen, not the model's count of small features).
constexpr int32_t kFacePixels = 4;
// While the view is dragged, a face under this across is drawn as a splat in its colour, not
// as its triangles (coarser detail while dragging, for the frame rate).
constexpr int32_t kSplatPixels = 2 * kFacePixels;
// In a crowded view, a face under this across is drawn without its edges (Painter::set_crowded).
constexpr int32_t kCrowdedEdgePixels = 2 * kFacePixels;
// A part under this across (its sphere's) is drawn as its proxy (or box) until it grows (issue
// 25); a group whose every member is, as the group's proxy.
constexpr int32_t kTinyPartPixels = 5;

// A mesh point as the instance being drawn projects it: a slot of the painter's projection
// cache (Painter::point).
struct ProjectedPoint {
    int32_t p[3];    // the point, in shell coordinates
    uint32_t stamp;  // the instance drawing it was projected for (Painter's stamp_; 0: none)
    Projected at;
};

// The projection cache's slots: a power of two (the hash's top bits pick one). Faces are drawn
// near the faces they share points with, so a few thousand slots catch nearly every point
// asked for again (the distinct 10 k-face assembly's frame at rest: 46.6 k of 46.9 k).
constexpr uint32_t kProjectionSlots = 4096;
constexpr int kProjectionSlotBits = std::countr_zero(kProjectionSlots);
static_assert(std::has_single_bit(kProjectionSlots));

class Painter {
public:
    struct Memory {
        std::span<Projected> projected;       // one face's vertices
        std::span<ProjectedPoint> points;     // the projection cache: slots by the point's hash
        std::span<uint8_t> edge_drawn;        // per pack edge: drawn in this instance already
        std::span<render::Palette> palettes;  // the shades of recently drawn face colours
        std::span<uint32_t> palette_rgb;      // which colour each holds (kNoColour: none)
    };

    Painter(const Scene& scene, render::Rasterizer& raster) : scene_(scene), raster_(raster) {}
    void init(const Memory& memory);
    void set_edges(std::span<uint8_t> edge_drawn) { mem_.edge_drawn = edge_drawn; } // the model's (load)
    void set_mode(DisplayMode m) { mode_ = m; }
    // Whether edges whose two faces meet tangentially (geom::Pack::smooth_edge) are drawn.
    void set_tangent_edges(bool shown) { tangent_edges_ = shown; }
    bool tangent_edges() const { return tangent_edges_; }
    // While the view is dragged, shaded faces are drawn without their B-rep edges (a third of a
    // frame's work): the edges come back when it rests. Wireframe and hidden line keep theirs.
    void set_dragging(bool on) { dragging_ = on; }
    // A crowded view (Detail::crowd(): more triangles than the screen's bound): shaded with
    // edges or in hidden line, a face drawn by its triangles under kCrowdedEdgePixels across
    // leaves its edges out (a knot of lines a few pixels long, a third of such a frame's work);
    // a larger neighbour still draws the edge they share. The wireframe keeps every edge.
    void set_crowded(bool on) { crowded_ = on; }
    // Picked faces drawn in the highlight colour (face kNone: none), and the instance being drawn.
    void set_highlight(uint32_t face0, uint32_t instance0, uint32_t face1, uint32_t instance1) {
        hl_[0] = {face0, instance0}, hl_[1] = {face1, instance1};
    }
    // A frame of `instances` begins (one view): its points projected for an instance are its
    // own in the projection cache, in each of the frame's passes over the instances (a point a
    // face's vertex in the faces' pass is taken again for its edges, if no other took the slot).
    void begin_frame(uint32_t instances);
    // The instance to draw next, and its transform from here on (the same in all of a frame).
    void set_instance(uint32_t i) { instance_ = i, stamp_ = base_ + i; }
    // Every face of the instance being drawn lies inside the view and the rows (its part's
    // sphere does: Transform::Sight::In): no face is tested on its own.
    void set_inside(bool on) { inside_ = on; }
    // The part chosen in the parts list (every face in the highlight colour; kNone: none), and
    // the part see-through mode draws solid (kNone: every part see-through).
    void set_part(uint32_t instance) { part_ = instance, part_end_ = instance == kNone ? kNone : instance + 1; }
    // A node of the assembly tree chosen: every part of its run of instances, as set_part's one.
    void set_parts(uint32_t first, uint32_t count) { part_ = count ? first : kNone, part_end_ = count ? first + count : kNone; }
    // Faces drawn into a faces layer take their own colours (no highlight: the layer holds the
    // view's faces whatever is picked); the highlighted ones are drawn again over its copy.
    void set_plain(bool on) { plain_ = on; }
    // The highlighted faces of the instance being drawn (picked, or all of the part chosen),
    // among its part's faces [first, first + count), drawn again over a copy of the faces
    // layer, a depth unit nearer than their own (so a pixel where one shows takes its
    // highlight, and no other). Returns the work.
    uint32_t highlighted_faces(uint32_t first, uint32_t count, const Transform& t, Rows rows);
    void set_focus(uint32_t instance) { focus_ = instance; }
    // The faces of an annotation chosen (geom::Annotations; null: none), in every instance of
    // their part, in the highlight colour.
    void set_annotation(const geom::Annotations* pmi, uint32_t annotation) { pmi_ = pmi, annotation_ = annotation; }
    DisplayMode mode() const { return mode_; }

    // The background of the target's rows: light at the top, darker toward the bottom.
    void background();
    // The face's triangles from triangle `from` on (0: projects its vertices first), if it may
    // show in `rows`, until about `units` of work are spent (a unit: a triangle's set-up or 64
    // pixels; `spent` says how many). Returns the next triangle: the face's triangle count
    // when it is done (at once when it cannot show). The projected vertices stay for the rest.
    uint32_t face(uint32_t f, const Transform& t, Rows rows, uint32_t from, uint32_t units, uint32_t& spent);
    // The edges of the face, each at most once per reset_edges() when `once`. Returns the work.
    // A sample at a point projected already in this instance (a vertex of a face drawn, the
    // end of an edge drawn) is taken from the projection cache: the same point, the same pixels.
    uint32_t face_edges(uint32_t f, const Transform& t, Rows rows, bool once);
    // The part's box (Scene::part_box) as twelve lines: while its edges are not sampled yet, for
    // a part left out of a model larger than the memory, and for one tiny() on the screen, where
    // it has no proxy.
    uint32_t part_box(uint32_t part, const Transform& t);
    // A part's proxy (a coarse mesh of it in a blocked pack's index, at a few levels:
    // geom/host/proxies.h) stands for it where a box would (a need: left out, not sampled yet,
    // tiny), and, in a crowded view, for a part in memory (not a lit part, nor one the section
    // crosses) whose own faces have more triangles, at the coarsest level that strays on the
    // screen by no more than the view's proxy error; a part that must and has none so near, at
    // the coarsest within the left-out error (else the finest: a block on its way in); at the
    // coarsest of all before the view's triangles are known (Coarsest: a model's first
    // frames). Drawn with the faces, in its colour, each triangle lit by its own normal.
    // proxy_level(): the level, or kNone (the part's own faces, or its box where it must and
    // the mode draws no faces).
    enum class ProxyNeed : uint8_t { Optional, Must, Coarsest };
    uint32_t proxy_level(uint32_t part, const int32_t sphere_centre[3], int32_t radius, const Transform& t, ProxyNeed need);
    uint32_t part_proxy(uint32_t part, const Transform& t, uint32_t level);
    uint32_t own_triangles(uint32_t part) const; // its faces' now, or two a face if more
    void project_proxy(const float box_min[3], const float box_max[3], const pack::ProxyPart& x, const Transform& t);
    uint32_t draw_proxy(const pack::ProxyPart& x, const float box_min[3], const float box_max[3], const Transform& t); // the work
    // A group of instances (a blocked pack's index: pack::Group), placed by the identity: the
    // level it is drawn at as one proxy, or kNone (its members each); its pieces drawn (the work).
    uint32_t group_level(uint32_t group, const int32_t sphere_centre[3], int32_t radius, const Transform& t, ProxyNeed need,
                         uint32_t most_triangles); // (a level with more is not drawn)
    uint32_t group_proxy(uint32_t group, const Transform& t, uint32_t level);
    // Whether an instance is lit (picked, or a highlighted face's): drawn as itself, never in a group's proxy.
    bool lit_instance(uint32_t i) const { return chosen(i) || hl_[0].instance == i || hl_[1].instance == i; }
    bool chosen(uint32_t i) const { return i >= part_ && i < part_end_; } // (the part, or a node's parts, chosen)
    // Hidden line: the proxy's outline and creases, over the faces (painter_proxy.cpp); the work.
    uint32_t proxy_outline(uint32_t part, const Transform& t, uint32_t level);
    // The screen error a proxy may have (pixels): the view's (its screen error times its
    // crowd), and one that stands for a part left out (coarser) until it comes in.
    void set_proxy_error(float pixels, float left_out_pixels) {
        proxy_subpixels_ = int32_t(pixels * float(render::subpixel::kPerPixel));
        left_out_subpixels_ = int32_t(left_out_pixels * float(render::subpixel::kPerPixel));
    }
    // Whether a part's sphere (Scene::part_sphere) is under a few pixels across: the part is
    // drawn as its proxy (or box) until it grows.
    bool tiny(const int32_t sphere_centre[3], int32_t radius, const Transform& t);
    // Whether every sphere of radius `each` within the sphere (a group's members' parts) is tiny().
    bool all_tiny(const int32_t sphere_centre[3], int32_t radius, int32_t each, const Transform& t);
    void reset_edges(uint32_t part); // (its edges: all of them where a part's are not known apart)
    // The rows of the screen being drawn (the target's band) for culling.
    Rows rows(const Transform& t) const;
    // Points (face vertices and edge samples) taken from the projection cache and projected,
    // since the last call (what the cache spares); and the cache turned off (every point
    // projected: the reference it must match pixel for pixel, for tests).
    struct PointCounts {
        uint32_t cached = 0, projected = 0;
    };
    PointCounts take_point_counts() { return std::exchange(point_counts_, {}); }
    void set_point_cache(bool on) { cache_on_ = on, begin_frame(0); }
    // Triangles and lines the rasterizer refused (outside its guard band): none, as every
    // one is projected or clipped into the band first; counted so that none goes unseen.
    uint32_t refused() const { return refused_; }

private:
    // `cap`: the palette of back faces seen through a section's cut (null: none).
    void triangle(const Transform& t, const Projected& a, const Projected& b, const Projected& c, const render::Palette& pal,
                  render::Cull cull, const render::Palette* cap);
    // Edge e's samples joined by lines.
    uint32_t edge(uint32_t e, const Transform& t);
    // The mesh point p as t projects it: from the cache when this instance projected it
    // already (a point of two faces, an edge's sample at a face's vertex), else projected
    // into the slot its hash picks. The reference is good until the next call.
    const Projected& point(const int32_t p[3], const Transform& t);
    bool caching() const { return cache_on_ && mem_.points.size() == kProjectionSlots; }
    static uint32_t slot_of(const int32_t p[3]);                                  // the slot p's hash picks
    const Projected& point_in(uint32_t slot, const int32_t p[3], const Transform& t); // point(), its slot known
    int32_t across(const int32_t sphere_centre[3], int32_t radius, const Transform& t, Projected& centre); // on the screen (sub-pixels)
    bool lit(uint32_t f) const { // picked, of the part chosen, or of the annotation chosen: in the highlight colour
        return !plain_ && ((hl_[0].face == f && hl_[0].instance == instance_) || (hl_[1].face == f && hl_[1].instance == instance_) ||
                           chosen(instance_) || (pmi_ && pmi_->applies_to(annotation_, f)));
    }
    uint32_t speck(uint32_t f, const Transform& t, int32_t pixels); // a face under `pixels` across: the work (0: not one)
    // Whether a sphere is under `pixels` across on the screen (its centre projected into `centre`).
    bool under(const int32_t sphere_centre[3], int32_t radius, const Transform& t, int32_t pixels, Projected& centre);
    // Specks in the solid modes (faces hide what lies behind) and with no section (a face the
    // cut crosses shows its edges).
    bool speckable(const Transform& t) const { return mode_ != DisplayMode::Wireframe && mode_ != DisplayMode::SeeThrough && !t.cut.on; }
    bool far_copy_specks(uint32_t f, const Transform& t) const; // a tessellated face that may be a speck here
    // Whether a tessellated face's edges are drawn: not when shaded alone, nor shaded with edges
    // while the view is dragged (they come back when it rests).
    bool done_faces_show_edges() const { return mode_ != DisplayMode::Shaded && !(dragging_ && mode_ == DisplayMode::ShadedEdges); }
    bool waiting_plane_hidden(uint32_t f, const Transform& t) const; // a deferred plane turned away
    uint32_t silhouette(const FaceInfo& F, const Transform& t); // hidden line: a curved face's outline; the work

    static bool cut_away(const Transform& t, const FaceInfo& F);
    static bool to_screen(const Transform& t, Projected& p);
    const render::Palette& palette(uint32_t rgb);

    const Scene& scene_;
    render::Rasterizer& raster_;
    Memory mem_{};
    uint32_t next_palette_ = 0; // the palette slot to reuse next
    bool dragging_ = false;
    bool crowded_ = false;
    int32_t proxy_subpixels_ = 0, left_out_subpixels_ = 0; // set_proxy_error()
    DisplayMode mode_ = DisplayMode::ShadedEdges;
    bool tangent_edges_ = true;
    struct Highlight {
        uint32_t face = kNone, instance = kNone;
    } hl_[2];
    uint32_t instance_ = 0;
    uint32_t stamp_ = 1;    // the projection cache's points of this instance's drawing carry it
    uint32_t base_ = 1;     // the frame's first stamp (its instance i's: base_ + i)
    uint32_t stamp_end_ = 1; // past every stamp handed out
    bool cache_on_ = true;
    Projected uncached_{};  // point()'s answer with the cache off
    PointCounts point_counts_;
    bool inside_ = false;
    bool plain_ = false;      // set_plain()
    bool nearer_ = false;     // highlighted_faces(): vertices a depth unit nearer
    uint32_t part_ = kNone, part_end_ = kNone, focus_ = kNone;
    const geom::Annotations* pmi_ = nullptr;
    uint32_t annotation_ = kNone;
    uint32_t refused_ = 0;
};

inline uint32_t Painter::slot_of(const int32_t p[3]) {
    // A multiplicative hash of the three coordinates; its top bits pick the slot.
    const uint32_t h = uint32_t(p[0]) * 0x9E3779B1u + uint32_t(p[1]) * 0x85EBCA77u + uint32_t(p[2]) * 0xC2B2AE3Du;
    return h >> (32 - kProjectionSlotBits);
}

inline const Projected& Painter::point_in(uint32_t s, const int32_t p[3], const Transform& t) {
    ProjectedPoint& slot = mem_.points[s];
    if (slot.stamp == stamp_ && slot.p[0] == p[0] && slot.p[1] == p[1] && slot.p[2] == p[2]) {
        ++point_counts_.cached;
        return slot.at;
    }
    slot.p[0] = p[0], slot.p[1] = p[1], slot.p[2] = p[2];
    slot.stamp = stamp_;
    t.project(p, slot.at);
    ++point_counts_.projected;
    return slot.at;
}

inline const Projected& Painter::point(const int32_t p[3], const Transform& t) {
    if (!caching()) {
        t.project(p, uncached_);
        ++point_counts_.projected;
        return uncached_;
    }
    return point_in(slot_of(p), p, t);
}

} // namespace facet::module
