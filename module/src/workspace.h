#pragma once
// The workspace the application hands in, cut into the arrays the viewer needs. The plan
// lists every array once, in order (a face's storage as one block, itself planned by geom:
// geom/face_storage.h). From it come the layout (Core's constructor), the bytes a capacity
// takes (constexpr: create() checks a workspace against it), the bytes per item and the fixed
// part that facet/sizes.h states (checked equal when the module is built, core.cpp), and the
// workspace a model needed at its peak (stats()).
#include "facet/viewer.h"
#include "geom/face_storage.h"
#include "geom/tessellate.h"
#include "painter.h"
#include "scene.h"

#include <cstddef>
#include <cstdint>

namespace facet::module {

constexpr uint32_t kPalettes = 16; // face colours shaded at once (more are rebuilt as needed)

// The arrays of the workspace. The base ones (one face's working memory and output, the
// palettes) are laid out by create(), after the Core; the model's (per edge, per sample, the
// mesh, per face) by load(), after the base, sized for the model and the room left.
enum class Array : uint8_t {
    FaceStorage,                      // one face's working memory (geom/face_storage.h), one block
    FaceVertices, FaceIndices,        // one face's float mesh, before the scene quantizes it
    Projected, PointCache,            // one face's vertices on the screen; points projected in the instance drawn
    Palettes, PaletteRgb,             // the shades of the recently drawn colours, and which they are
    EdgeFirst, EdgeCount, EdgeDrawn,  // per pack edge: its first sample, its samples, drawn this frame
    SampleT, SampleP, SampleQ,        // per edge sample: parameter, 3D point, quantized point
    MeshVertices, MeshIndices,        // the model's mesh
    Faces, DoneOrder,                 // per pack face: what the scene keeps; the order faces finished
};

// The face capacity a workspace capacity gives; patch_words: kPatchCacheWords (the device's
// path), or 0 to measure a model that has no free-form surface.
constexpr geom::FaceCapacity face_capacity(const Capacity& c, uint32_t patch_words = geom::kPatchCacheWords) {
    return {c.face_points, c.loops, c.slivers, patch_words};
}
// One default: geom's for a face and the public API's (facet/sizes.h) are the same numbers.
static_assert(face_capacity(Capacity{}).points == geom::FaceCapacity{}.points &&
                  face_capacity(Capacity{}).loops == geom::FaceCapacity{}.loops &&
                  face_capacity(Capacity{}).slivers == geom::FaceCapacity{}.slivers,
              "geom::FaceCapacity's defaults are facet/sizes.h's FACET_DEFAULT_FACE_POINTS, _LOOPS, _SLIVERS");

// The model's part of the workspace: what load() lays out for one model.
struct ModelCapacity {
    uint32_t faces = 0, edges = 0, samples = 0, mesh_vertices = 0, mesh_triangles = 0;
};

// The base plan: take.face(capacity) for the face's block, then take.array(what, count, bytes
// of one, alignment) for each array, in order.
template <typename Take>
constexpr void base_plan(const Capacity& c, uint32_t patch_words, Take& take) {
    const geom::FaceCapacity f = face_capacity(c, patch_words);
    take.face(f);
    take.array(Array::FaceVertices, geom::face_mesh_vertices(f), sizeof(geom::MeshVertex), alignof(geom::MeshVertex));
    take.array(Array::FaceIndices, 3 * size_t(geom::face_mesh_triangles(f)), sizeof(uint32_t), alignof(uint32_t));
    take.array(Array::Projected, geom::face_mesh_vertices(f), sizeof(Projected), alignof(Projected));
    take.array(Array::PointCache, kProjectionSlots, sizeof(ProjectedPoint), alignof(ProjectedPoint));
    take.array(Array::Palettes, kPalettes, sizeof(render::Palette), alignof(render::Palette));
    take.array(Array::PaletteRgb, kPalettes, sizeof(uint32_t), alignof(uint32_t));
}

// The model's plan, after the base.
template <typename Take>
constexpr void model_plan(const ModelCapacity& m, Take& take) {
    take.array(Array::EdgeFirst, m.edges, sizeof(uint32_t), alignof(uint32_t));
    take.array(Array::EdgeCount, m.edges, sizeof(uint16_t), alignof(uint16_t));
    take.array(Array::EdgeDrawn, m.edges, sizeof(uint8_t), alignof(uint8_t));
    take.array(Array::SampleT, m.samples, sizeof(float), alignof(float));
    take.array(Array::SampleP, m.samples, sizeof(geom::Vec3), alignof(geom::Vec3));
    take.array(Array::SampleQ, 3 * size_t(m.samples), sizeof(int32_t), alignof(int32_t));
    take.array(Array::MeshVertices, m.mesh_vertices, sizeof(DrawVertex), alignof(DrawVertex));
    take.array(Array::MeshIndices, 3 * size_t(m.mesh_triangles), sizeof(uint16_t), alignof(uint16_t));
    take.array(Array::Faces, m.faces, sizeof(FaceInfo), alignof(FaceInfo));
    take.array(Array::DoneOrder, m.faces, sizeof(uint32_t), alignof(uint32_t));
}

constexpr ModelCapacity model_capacity(const Capacity& c) {
    return {c.faces, c.edges, c.samples, c.mesh_vertices, c.mesh_triangles};
}

// The whole plan: the base, then the model's at the capacity's own counts.
template <typename Take>
constexpr void workspace_plan(const Capacity& c, uint32_t patch_words, Take& take) {
    base_plan(c, patch_words, take);
    model_plan(model_capacity(c), take);
}

// The bytes the plan takes: laid out (aligned), or its arrays' sizes alone (`packed`: what
// the per-item figures of facet/sizes.h count).
template <bool kPacked>
struct Measure {
    size_t at = 0;
    constexpr void array(Array, size_t count, size_t bytes, size_t align) {
        if (!kPacked) at = (at + align - 1) / align * align;
        at += count * bytes;
    }
    constexpr void face(const geom::FaceCapacity& f) {
        if (kPacked) {
            geom::face_storage_plan(f, [&](geom::FaceArray, size_t count, size_t bytes, size_t) { at += count * bytes; });
        } else {
            at = (at + 7) / 8 * 8 + geom::face_storage_bytes(f);
        }
    }
};

// The bytes of the arrays laid out for a capacity (the Core before them: core.cpp).
constexpr size_t arrays_bytes(const Capacity& c, uint32_t patch_words = geom::kPatchCacheWords) {
    Measure<false> m;
    workspace_plan(c, patch_words, m);
    return m.at;
}

// Bytes of the model's arrays laid out from an 8-byte aligned start.
constexpr size_t model_bytes(const ModelCapacity& m) {
    Measure<false> k;
    model_plan(m, k);
    return k.at;
}

// The model's capacity in `room` bytes. Its faces and edges as they are; the room left goes
// to the edge samples (30% of it), the mesh's vertices (45%) and its triangles (25%), each
// about what a model of B-rep faces takes at the default detail (an assembly of 3,656 faces:
// 29,502 samples, 41,068 vertices, 35,268 triangles; finer detail takes more of each). Counts
// the application fixed (Capacity's nonzero ones) are taken as they are, and the shares are of
// the room after them. `need`: the room the model needs at least (planned samples: two an
// edge of the `sampled` edges, those of the blocks opened: its wireframe at the coarsest);
// fits: room >= need.
struct ModelPlan {
    ModelCapacity capacity;
    size_t need = 0;
    bool fits = false;
};
// The bytes of one edge sample: its arrays' (SampleT, P, Q) in the model's plan.
constexpr size_t sample_bytes() {
    Measure<true> one;
    model_plan(ModelCapacity{0, 0, 1, 0, 0}, one);
    return one.at;
}
constexpr size_t kSampleBytes = sample_bytes();
constexpr uint32_t kSampleShare = 30, kVertexShare = 45, kTriangleShare = 25; // percent of the room left
// The room left whose sample share holds `samples`.
constexpr size_t sample_share_room(size_t samples) { return (samples * kSampleBytes * 100 + kSampleShare - 1) / kSampleShare; }
constexpr ModelPlan plan_model(uint32_t faces, uint32_t edges, size_t room, const Capacity& given, uint32_t sampled = ~0u) {
    if (sampled > edges) sampled = edges;
    ModelPlan p;
    const ModelCapacity fixed_counts{given.faces ? given.faces : faces, given.edges ? given.edges : edges, given.samples,
                                     given.mesh_vertices, given.mesh_triangles};
    const size_t fixed = model_bytes(fixed_counts) + 64; // + the alignment of the arrays after them
    const size_t room_left = room > fixed ? room - fixed : 0;
    ModelCapacity& m = p.capacity;
    m = fixed_counts;
    if (!given.samples) m.samples = uint32_t(room_left * kSampleShare / 100 / kSampleBytes);
    if (!given.mesh_vertices) m.mesh_vertices = uint32_t(room_left * kVertexShare / 100 / sizeof(DrawVertex));
    if (!given.mesh_triangles) m.mesh_triangles = uint32_t(room_left * kTriangleShare / 100 / (3 * sizeof(uint16_t)));
    p.need = fixed + (given.samples ? 0 : sample_share_room(2 * size_t(sampled) + 2));
    p.fits = room >= p.need && model_bytes(m) <= room;
    return p;
}

// The model's arrays with `per_edge` samples an edge (the default detail takes two to four,
// finer up to twice that) and the mesh's share of the room beside them, and room for
// `per_face` mesh vertices a face (and 256 more: a sphere of two faces takes about 180 at the
// default detail), whichever is more.
constexpr size_t model_room_bytes(uint32_t faces, uint32_t edges, uint32_t per_edge, uint32_t per_face) {
    const size_t for_samples = sample_share_room(size_t(per_edge) * edges + 2);
    const size_t for_mesh = per_face ? ((size_t(per_face) * faces + 256) * sizeof(DrawVertex) * 100 + kVertexShare - 1) / kVertexShare : 0;
    return model_bytes({faces, edges, 0, 0, 0}) + 64 + (for_samples > for_mesh ? for_samples : for_mesh);
}

// The model's arrays whose shares (plan_model) hold `samples`, `vertices` and `triangles`: the
// room a measured level of detail takes (pack::Needs). In 64 bits (counts up to 2^31 each);
// past what a size_t holds, its largest value.
// Each count with a margin of 1/64 and 16: the packer measured on its host, whose libm (sin,
// atan2, ...) may round otherwise than the device's, a sample or a triangle more here and there.
constexpr uint64_t share_room(uint64_t bytes, uint32_t share) { return (bytes * 100 + share - 1) / share; }
constexpr uint64_t with_margin(uint32_t count) { return uint64_t(count) + count / 64 + 16; }
constexpr size_t model_room_for(uint32_t faces, uint32_t edges, uint32_t samples, uint32_t vertices, uint32_t triangles) {
    const uint64_t for_samples = share_room((with_margin(samples) + 2) * kSampleBytes, kSampleShare);
    const uint64_t for_vertices = share_room(with_margin(vertices) * sizeof(DrawVertex), kVertexShare);
    const uint64_t for_triangles = share_room(with_margin(triangles) * 3 * sizeof(uint16_t), kTriangleShare);
    const uint64_t most = for_samples > for_vertices ? for_samples : for_vertices;
    const uint64_t all = uint64_t(model_bytes({faces, edges, 0, 0, 0})) + 64 + (most > for_triangles ? most : for_triangles);
    return all < uint64_t(SIZE_MAX) / 2 ? size_t(all) : SIZE_MAX / 2; // (half: the base is added to it)
}

// Cuts caller memory in order, each piece at its alignment; past the end it hands out nothing
// and fits() turns false.
class Carver {
public:
    Carver(void* base, size_t bytes) : base_(static_cast<uint8_t*>(base)), room_(bytes) {}

    void* take(size_t bytes, size_t align) {
        at_ = (at_ + align - 1) / align * align;
        const size_t start = at_;
        at_ += bytes;
        if (!base_ || at_ > room_) return nullptr;
        return base_ + start;
    }
    bool fits() const { return base_ && at_ <= room_; }
    uint8_t* next() const { return base_ + at_; } // where the next piece would start (unaligned)

private:
    uint8_t* base_ = nullptr;
    size_t room_ = 0;
    size_t at_ = 0;
};

} // namespace facet::module

namespace facet {
// Viewer::create() past its check of `bytes` against facet/sizes.h's formula (`least`; the C
// API checks its callers' bytes against it and keeps its bridge in the formula's slack, so it
// gives 0): the workspace's alignment, the capacity's range and the layout's own need.
Viewer* create_viewer(const Config& config, void* workspace, size_t bytes, size_t least, Result* why);
} // namespace facet
