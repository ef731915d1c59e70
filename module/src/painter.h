#pragma once
// Drawing the scene into the rasterizer's target (a frame, or a band of it): the background,
// a face's triangles (clipped against the near plane and the guard band where they cross
// them), its B-rep edges over it, and the palettes that colour them.
#include "camera.h"
#include "facet/viewer.h"
#include "overlay.h"
#include "render/raster.h"
#include "scene.h"

#include <span>
#include <utility>

namespace facet::module {

// The smallest face worth its triangles: one under this many pixels across (its sphere's
// diameter) wherever the view shows it is left untessellated, drawn by its edges or as a speck
// until the view makes it larger (detail.cpp, painter.cpp). Its edges, a pixel wide, cover
// most of what such a face would show (issue 25: the frames and the first view follow the
// screen, not the model's count of small features).
constexpr int32_t kFacePixels = 4;
// While the view is dragged, a face under this across is drawn as a splat in its colour, not
// as its triangles (coarser detail while dragging, for the frame rate).
constexpr int32_t kSplatPixels = 2 * kFacePixels;

class Painter {
public:
    struct Memory {
        std::span<Projected> projected;       // one face's vertices
        std::span<uint16_t> vertex_at;        // per place along that face's boundary: a vertex of it there (a hint, checked)
        std::span<uint8_t> edge_drawn;        // per pack edge: drawn in this instance already
        std::span<render::Palette> palettes;  // the shades of recently drawn face colours
        std::span<uint32_t> palette_rgb;      // which colour each holds (kNoColour: none)
    };

    Painter(const Scene& scene, render::Rasterizer& raster) : scene_(scene), raster_(raster) {}
    void init(const Memory& memory);
    void set_edges(std::span<uint8_t> edge_drawn) { mem_.edge_drawn = edge_drawn; } // the model's (load)
    void set_mode(DisplayMode m) { mode_ = m; }
    // While the view is dragged, shaded faces are drawn without their B-rep edges (a third of a
    // frame's work): the edges come back when it rests. Wireframe and hidden line keep theirs.
    void set_dragging(bool on) { dragging_ = on; }
    // Picked faces drawn in the highlight colour (face ~0u: none), and the instance being drawn.
    void set_highlight(uint32_t face0, uint32_t instance0, uint32_t face1, uint32_t instance1) {
        hl_[0] = {face0, instance0}, hl_[1] = {face1, instance1};
    }
    void set_instance(uint32_t i) { instance_ = i, projected_face_ = ~0u; }
    // Something else wrote the projected vertices (a pick): no face's are there.
    void forget_projection() { projected_face_ = ~0u; }
    // Every face of the instance being drawn lies inside the view and the rows (its part's
    // sphere does: Transform::Sight::In): no face is tested on its own.
    void set_inside(bool on) { inside_ = on; }
    // The part chosen in the parts list (every face in the highlight colour; ~0u: none), and
    // the part see-through mode draws solid (~0u: every part see-through).
    void set_part(uint32_t instance) { part_ = instance; }
    void set_focus(uint32_t instance) { focus_ = instance; }
    DisplayMode mode() const { return mode_; }

    // The background of the target's rows: light at the top, darker toward the bottom.
    void background();
    // The face's triangles from triangle `from` on (0: projects its vertices first), if it may
    // show in `rows`, until about `units` of work are spent (a unit: a triangle's set-up or 64
    // pixels; `spent` says how many). Returns the next triangle: the face's triangle count
    // when it is done (at once when it cannot show). The projected vertices stay for the rest.
    uint32_t face(uint32_t f, const Transform& t, Rows rows, uint32_t from, uint32_t units, uint32_t& spent);
    // The edges of the face, each at most once per reset_edges() when `once`. Returns the work.
    // Right after face() has drawn the face, its edges' samples are its projected vertices
    // where one lies at a sample (the same point: the same pixels), projected again elsewhere.
    uint32_t face_edges(uint32_t f, const Transform& t, Rows rows, bool once);
    // The part's box (Scene::part_box) as twelve lines: while its edges are not sampled yet, for
    // a part left out of a model larger than the memory, and for one tiny() on the screen.
    uint32_t part_box(uint32_t part, const Transform& t);
    // Whether a part's sphere (Scene::part_sphere) is under a few pixels across: the part is
    // drawn as its box until it grows.
    bool tiny(const int32_t sphere_centre[3], int32_t radius, const Transform& t);
    void reset_edges(uint32_t part); // (its edges: all of them where a part's are not known apart)
    // The rows of the screen being drawn (the target's band) for culling.
    Rows rows(const Transform& t) const;
    // Edge samples taken from a face's projected vertices and projected again, since the last
    // call (what the reuse spares); and the reuse turned off (every sample projected: the
    // reference it must match pixel for pixel, for tests).
    struct EdgeSampleCounts {
        uint32_t from_vertices = 0, projected = 0;
    };
    EdgeSampleCounts take_edge_sample_counts() { return std::exchange(edge_samples_, {}); }
    void set_vertex_reuse(bool on) { reuse_ = on; }
    // Triangles and lines the rasterizer refused (outside its guard band): none, as every
    // one is projected or clipped into the band first; counted so that none goes unseen.
    uint32_t refused() const { return refused_; }

private:
    // `cap`: the palette of back faces seen through a section's cut (null: none).
    void triangle(const Transform& t, const Projected& a, const Projected& b, const Projected& c, const render::Palette& pal,
                  render::Cull cull, const render::Palette* cap);
    // Edge e's samples joined by lines; `face`: the face whose projected vertices may hold
    // them (null: none), the edge's first sample at `place` along its boundary (its last when
    // `reversed`), in the loop beginning at `loop_place`.
    struct Along {
        const FaceInfo* face = nullptr;
        uint32_t place = 0, loop_place = 0;
        bool reversed = false;
    };
    uint32_t edge(uint32_t e, const Transform& t, const Along& along);
    // The projected vertex of along.face at sample s (place along its boundary), or null:
    // vertex_at's hint there, or before it (a coedge's first sample is the one the previous
    // coedge ended on), or at the loop's start (where the loop closes), checked to lie at s.
    const Projected* vertex_at_sample(const Along& along, uint32_t place, uint32_t s) const;
    int32_t across(const int32_t sphere_centre[3], int32_t radius, const Transform& t, Projected& centre); // on the screen (sub-pixels)
    bool lit(uint32_t f) const { // picked, or of the part chosen: in the highlight colour
        return (hl_[0].face == f && hl_[0].instance == instance_) || (hl_[1].face == f && hl_[1].instance == instance_) || part_ == instance_;
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
    DisplayMode mode_ = DisplayMode::ShadedEdges;
    struct Highlight {
        uint32_t face = ~0u, instance = ~0u;
    } hl_[2];
    uint32_t instance_ = 0;
    uint32_t projected_face_ = ~0u; // the face whose vertices `projected` holds (this instance's)
    bool reuse_ = true;
    EdgeSampleCounts edge_samples_;
    bool inside_ = false;
    uint32_t part_ = ~0u, focus_ = ~0u;
    uint32_t refused_ = 0;
};

} // namespace facet::module
