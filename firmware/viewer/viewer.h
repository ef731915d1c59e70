#pragma once
// The viewer's core, portable (the firmware runs it on the boards; facet-viewer-ref runs the
// same code on the host to render reference images):
//
//   open()    validate the pack, sample every edge once, show the wireframe of all edges
//   step()    tessellate the next face in the CET arena, append it to the mesh, and show it:
//             the face's triangles and its edges are drawn into each display buffer (one
//             z-buffer per buffer), so filling in costs a face, not a frame
//   handle()  keys and pointer: orbit, zoom, pan, fit, level of detail (re-triangulates), help
//
// Geometry arithmetic per frame is integer: mesh positions are quantized once per face
// (shell coordinates, diag/2^20 units), each frame's camera and instance placement become one
// fixed-point matrix per instance, and the perspective divide is one 32-bit division per vertex.
// Triangles crossing the near plane or the rasterizer's guard band are clipped. B-rep edges
// are drawn over the faces with a depth bias, as CAD viewers show them. Closed shells cull
// back faces; open ones are lit on both sides.
#include "cdt/arena.h"
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "hal/board.h"
#include "render/raster.h"

#include <cstdint>
#include <span>

namespace facet::viewer {

// Capacities of the viewer's buffers: the firmware's static arrays and the host reference
// renderer's vectors are both sized from these, so both tessellate and draw identically.
namespace capacity {
constexpr size_t kFaces = 8192;
constexpr size_t kEdges = 16384;
constexpr size_t kSamples = 65536;       // edge samples of the whole model
constexpr size_t kFaceVertices = 12000;  // per face, in the 16-bit CDT arena
constexpr size_t kLoops = 512;           // per face
constexpr size_t kSlivers = 1024;        // per face: loop points closer than the CDT grid
constexpr size_t kPalettes = 16;         // face colours shaded at once (more are rebuilt as needed)
constexpr size_t kMeshVertices = 65536;
constexpr size_t kMeshTriangles = 98304;
} // namespace capacity

struct DrawVertex {
    int32_t p[3];  // shell coordinates in units of the pack's diagonal / 2^20
    int16_t n[3];  // unit normal, Q14
    uint16_t pad;
};
static_assert(sizeof(DrawVertex) == 20);

enum class FaceState : uint8_t { Pending, Done, Failed };

struct FaceInfo {
    uint32_t first_vertex, vertex_count, first_index, triangle_count;
    uint32_t rgb;      // r | g << 8 | b << 16
    int32_t centre[3]; // a sphere holding the face's vertices (DrawVertex units), so a face
    int32_t radius;    // off the screen is skipped whole; radius 0: none known
    FaceState state;
    bool planar;       // one normal: a closed shell's plane facing away is skipped whole
};

// A vertex in camera space (x right, y up, d = depth in front of the eye; units of the
// diagonal / 2^16) and on the screen.
struct Projected {
    int32_t x, y, d;
    render::ScreenVertex s;
    uint8_t out; // bit 0: behind the near plane; bit 1: beyond the guard band
};

// All storage, owned by the caller (static buffers on the device).
struct Memory {
    std::span<uint16_t> depth[2];      // one z-buffer per display buffer
    std::span<hal::Rgb565> line;       // one row
    geom::EdgeSamples samples;
    std::span<int32_t> sample_q;       // 3 per pool sample: quantized like DrawVertex::p
    geom::FaceScratch scratch;
    geom::Mesh face_mesh;              // one face's float output, before quantizing
    std::span<DrawVertex> vertices;    // the mesh, face after face
    std::span<uint16_t> indices;       // 3 per triangle, relative to the face's first vertex
    std::span<FaceInfo> faces;         // per pack face
    std::span<uint32_t> done_order;    // faces in the order they were finished
    std::span<Projected> projected;    // one face's vertices (or one edge's samples)
    std::span<uint8_t> edge_drawn;     // per pack edge (a full frame draws each edge once)
    std::span<render::Palette> palettes; // the shades of recently drawn face colours
    std::span<uint32_t> palette_rgb;   // which colour each holds (kNoColour: none)
};

// Every buffer of Memory except the display-sized ones, at the capacities above (a static
// object in the firmware's .arena section; one heap object on the host).
struct Storage {
    uint32_t edge_first[capacity::kEdges];
    uint16_t edge_count[capacity::kEdges];
    uint8_t edge_drawn[capacity::kEdges];
    float sample_t[capacity::kSamples];
    geom::Vec3 sample_p[capacity::kSamples];
    int32_t sample_q[3 * capacity::kSamples];
    cdt::Arena<uint16_t, capacity::kFaceVertices> arena;
    cdt::Point loop_points[capacity::kFaceVertices];
    uint32_t loop_sizes[capacity::kLoops];
    geom::Vec2 face_uv[capacity::kFaceVertices];
    uint8_t pinned[capacity::kFaceVertices];
    geom::Vec3 face_xyz[capacity::kFaceVertices];
    uint32_t mesh_of[capacity::kFaceVertices];
    geom::TriangleMeasure measured[cdt::triangles_for(capacity::kFaceVertices)];
    geom::Sliver slivers[capacity::kSlivers];
    geom::MeshVertex face_vertices[capacity::kFaceVertices];
    uint32_t face_indices[3 * cdt::triangles_for(capacity::kFaceVertices)];
    DrawVertex mesh_vertices[capacity::kMeshVertices];
    uint16_t mesh_indices[3 * capacity::kMeshTriangles];
    FaceInfo faces[capacity::kFaces];
    uint32_t done_order[capacity::kFaces];
    Projected projected[capacity::kFaceVertices];
    render::Palette palettes[capacity::kPalettes];
    uint32_t palette_rgb[capacity::kPalettes];

    // The viewer's Memory over these buffers and the display-sized ones (depth1 may be empty
    // for a single-buffered display).
    Memory memory(std::span<uint16_t> depth0, std::span<uint16_t> depth1, std::span<hal::Rgb565> line);
};

using CaptureFn = Status (*)(void* context, const char* name);

struct Totals {
    uint32_t faces = 0, done = 0, failed = 0, triangles = 0, vertices = 0;
    uint32_t arena_peak_bytes = 0; // largest CDT use of one face (vertices + triangles)
    uint32_t mesh_bytes = 0;       // vertices + indices in use
    // High-water marks over the session (every level of detail), for storage_in_use().
    uint32_t samples_peak = 0, face_points_peak = 0, slivers_peak = 0, vertices_peak = 0, triangles_peak = 0;
};

class Viewer {
public:
    Viewer(hal::Board& board, Memory& memory, CaptureFn capture, void* capture_context);

    // Takes the pack file loaded at the start of region (capacity bytes, 4-byte aligned): a
    // deflated one is inflated there first (geom/pack_file.h). Then validates the pack (a clear
    // message on the console if it is bad), samples its edges and shows the wireframe. Not Ok:
    // nothing to show.
    Status open(uint8_t* region, uint32_t capacity);
    uint32_t pack_bytes() const { return pack_bytes_; }           // the pack, inflated
    uint32_t pack_file_bytes() const { return pack_file_bytes_; } // the file as loaded

    // One unit of work: the next face (tessellated and drawn). False when there is none.
    bool step();
    void handle(const hal::InputEvent& event);
    bool quit() const { return quit_; }
    const Totals& totals() const { return totals_; }
    // Bytes of Storage this model has needed at its peak (the rest of Storage is capacity for
    // larger models): what a build sized for it would hold.
    uint32_t storage_in_use() const;
    float tolerance() const { return opt_.tolerance; }

private:
    struct Instance; // per-frame fixed-point transform of one pack instance

    Status restart();                  // (re)sample edges at the current tolerance, reset the mesh
    void tessellate(uint32_t face);
    void present();                    // bring the back buffer up to date, flip
    void draw_full(int buffer);
    void draw_face(int buffer, uint32_t face, const Instance& in, bool with_edges);
    void draw_face_edges(int buffer, uint32_t face, const Instance& in, bool once);
    void draw_edge(int buffer, uint32_t edge, const Instance& in);
    void draw_progress();
    void draw_triangle(int buffer, const Instance& in, const Projected& a, const Projected& b, const Projected& c,
                       const render::Palette& pal, render::Cull cull);
    Instance instance_transform(uint32_t instance) const;
    void project(const Instance& in, const int32_t p[3], Projected& out) const;
    bool on_screen(const Instance& in, const FaceInfo& face) const;
    bool faces_away(const Instance& in, const FaceInfo& face) const;
    void command(const char* line);
    void key(uint8_t k);
    void view_changed();
    void help();
    const render::Palette& palette(uint32_t rgb);

    hal::Board& board_;
    Memory& mem_;
    CaptureFn capture_;
    void* capture_context_;
    render::Rasterizer raster_[2];
    int buffers_ = 1, back_ = 0;
    bool stale_[2] = {true, true};
    uint32_t applied_[2] = {0, 0}; // faces of done_order already drawn into each buffer

    geom::Pack pack_;
    uint32_t pack_bytes_ = 0, pack_file_bytes_ = 0;
    geom::TessOptions opt_;
    float default_tolerance_ = 0;
    float unit_ = 1;               // mm per quantized unit (diag / 2^20)
    float centre_[3] = {0, 0, 0};  // of the bounding box
    float radius_ = 1;             // half the diagonal, mm

    // The view: orbit angles (rad), dolly factor (1 = fitted), pan (mm, in view x/y).
    float yaw_ = 0, pitch_ = 0, zoom_ = 1, pan_x_ = 0, pan_y_ = 0;
    uint8_t buttons_ = 0;

    uint32_t next_palette_ = 0;    // the palette slot to reuse next
    uint32_t next_face_ = 0;
    uint32_t pass_ = 0;            // 0: the first tessellation; +1 per level-of-detail change
    bool half_shot_ = false, quit_ = false;
    char line_[48] = {};
    uint32_t line_len_ = 0;
    bool in_line_ = false;
    Totals totals_;
};

} // namespace facet::viewer
