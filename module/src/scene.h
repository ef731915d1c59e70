#pragma once
// The model as the viewer holds it: the pack (read in place), the edges' samples (shared by
// both faces of an edge, and quantized for drawing), and the mesh, face after face, as the
// scheduler tessellates them. Positions are quantized once per face (shell coordinates,
// diag/2^20 units); normals are Q14.
#include "facet/sizes.h"
#include "geom/pack.h"
#include "geom/tessellate.h"

#include <cstdint>
#include <span>

namespace facet::module {

struct DrawVertex {
    int32_t p[3];  // shell coordinates in units of the pack's diagonal / 2^20
    int16_t n[3];  // unit normal, Q14
    uint16_t pad;
};
static_assert(sizeof(DrawVertex) == FACET_BYTES_PER_MESH_VERTEX);

enum class FaceState : uint8_t { Pending, Done, Failed };

struct FaceInfo {
    uint32_t first_vertex, vertex_count, first_index, triangle_count;
    uint32_t rgb;      // r | g << 8 | b << 16
    int32_t centre[3]; // a sphere holding the face's vertices (DrawVertex units), so a face
    int32_t radius;    // off the screen is skipped whole; radius 0: none known
    FaceState state;
    bool planar;       // one normal: a closed shell's plane facing away is skipped whole
};
static_assert(sizeof(FaceInfo) + sizeof(uint32_t) == FACET_BYTES_PER_FACE); // with its done_order entry

// Totals of the current pass, and high-water marks over every pass.
struct Totals {
    uint32_t faces = 0, done = 0, failed = 0, triangles = 0, vertices = 0;
    uint32_t arena_peak_bytes = 0; // largest CDT use of one face (vertices + triangles)
    uint32_t mesh_bytes = 0;       // vertices + indices in use
    uint32_t samples_peak = 0, face_points_peak = 0, slivers_peak = 0, vertices_peak = 0, triangles_peak = 0;
};

class Scene {
public:
    struct Memory {
        geom::EdgeSamples samples;
        std::span<int32_t> sample_q;       // 3 per pool sample: quantized like DrawVertex::p
        std::span<DrawVertex> vertices;    // the mesh, face after face
        std::span<uint16_t> indices;       // 3 per triangle, relative to the face's first vertex
        std::span<FaceInfo> faces;         // per pack face
        std::span<uint32_t> done_order;    // faces in the order they were finished
    };

    void init(const Memory& memory) { mem_ = memory; }
    // Takes a validated pack; Full if it has more faces or edges than the memory holds.
    Result open(const geom::Pack& pack);
    bool loaded() const { return loaded_; }
    void close() { loaded_ = false, pack_ = {}, totals_ = {}; } // no model (the memory stays)

    const geom::Pack& pack() const { return pack_; }
    uint32_t face_count() const { return uint32_t(pack_.faces().size()); }
    uint32_t edge_count() const { return uint32_t(pack_.edges().size()); }
    // The placed model (every instance's shell where the instance puts it): its bounding
    // box's centre and half its diagonal (mm), what the camera frames. The mesh quantum (mm)
    // comes from the shells' own coordinates (the pack's box), which the mesh is stored in.
    const float* centre() const { return centre_; }
    float radius() const { return radius_; }
    float unit() const { return unit_; }
    // The placed box again from the best the scene has: each shell's edge samples and its
    // tessellated faces (`sampled` false: the edges' end vertices only, as at open(), before
    // the pass's samples exist), through every instance's placement. About ten instructions a
    // sample and a vertex (integer compares), then 8 corners an instance.
    void fit_bounds(bool sampled);
    uint32_t shell_of(uint32_t face) const;
    // Parts (instances) shown or hidden; the first kMaxHideable can be hidden (Viewer::show_part
    // refuses the rest, which stay shown). All shown at open().
    static constexpr uint32_t kMaxHideable = 4096;
    bool shown(uint32_t instance) const { return instance >= kMaxHideable || !((hidden_[instance >> 5] >> (instance & 31)) & 1u); }
    void set_shown(uint32_t instance, bool on);
    void show_all();
    uint32_t colour_of(uint32_t face) const; // rgb of the face (or of its shell, or the default)

    geom::EdgeSamples& samples() { return mem_.samples; }
    const geom::EdgeSamples& samples() const { return mem_.samples; }
    const int32_t* sample_q(uint32_t sample) const { return &mem_.sample_q[3 * sample]; }
    // Quantizes samples [from, to) of the pool for drawing.
    void quantize_samples(uint32_t from, uint32_t to);

    // A new pass: no face done, the samples' peak carried over.
    void reset_mesh(bool keep_peaks);
    // Appends a tessellated face (its float mesh) to the drawing mesh. Full when the mesh is full.
    Result append(uint32_t face, const geom::Mesh& mesh, const geom::FaceStats& stats);
    void mark_failed(uint32_t face);

    const FaceInfo& face(uint32_t f) const { return mem_.faces[f]; }
    uint32_t done_face(uint32_t k) const { return mem_.done_order[k]; } // k-th face finished
    const DrawVertex* vertices() const { return mem_.vertices.data(); }
    const uint16_t* indices() const { return mem_.indices.data(); }
    const Totals& totals() const { return totals_; }
    Totals& totals() { return totals_; }

private:
    Memory mem_{};
    geom::Pack pack_;
    bool loaded_ = false;
    float unit_ = 1, centre_[3] = {0, 0, 0}, radius_ = 1, own_radius_ = 1;
    Totals totals_;
    uint32_t hidden_[kMaxHideable / 32] = {};
};

} // namespace facet::module
