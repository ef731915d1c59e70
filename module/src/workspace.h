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

// The arrays of the workspace, in the order they lie in it (after the Core itself).
enum class Array : uint8_t {
    EdgeFirst, EdgeCount, EdgeDrawn,  // per pack edge: its first sample, its samples, drawn this frame
    SampleT, SampleP, SampleQ,        // per edge sample: parameter, 3D point, quantized point
    FaceStorage,                      // one face's working memory (geom/face_storage.h), one block
    FaceVertices, FaceIndices,        // one face's float mesh, before the scene quantizes it
    MeshVertices, MeshIndices,        // the model's mesh
    Faces, DoneOrder,                 // per pack face: what the scene keeps; the order faces finished
    Projected,                        // one face's vertices on the screen
    Palettes, PaletteRgb,             // the shades of the recently drawn colours, and which they are
};

// The face capacity a workspace capacity gives; patch_words: kPatchCacheWords (the device's
// path), or 0 to measure a model that has no free-form surface.
constexpr geom::FaceCapacity face_capacity(const Capacity& c, uint32_t patch_words = geom::kPatchCacheWords) {
    return {c.face_points, c.loops, c.slivers, patch_words};
}

// The plan: take.array(what, count, bytes of one, alignment) for each array, and
// take.face(capacity) for the face's block, in order.
template <typename Take>
constexpr void workspace_plan(const Capacity& c, uint32_t patch_words, Take& take) {
    const geom::FaceCapacity f = face_capacity(c, patch_words);
    take.array(Array::EdgeFirst, c.edges, sizeof(uint32_t), alignof(uint32_t));
    take.array(Array::EdgeCount, c.edges, sizeof(uint16_t), alignof(uint16_t));
    take.array(Array::EdgeDrawn, c.edges, sizeof(uint8_t), alignof(uint8_t));
    take.array(Array::SampleT, c.samples, sizeof(float), alignof(float));
    take.array(Array::SampleP, c.samples, sizeof(geom::Vec3), alignof(geom::Vec3));
    take.array(Array::SampleQ, 3 * size_t(c.samples), sizeof(int32_t), alignof(int32_t));
    take.face(f);
    take.array(Array::FaceVertices, geom::face_mesh_vertices(f), sizeof(geom::MeshVertex), alignof(geom::MeshVertex));
    take.array(Array::FaceIndices, 3 * size_t(geom::face_mesh_triangles(f)), sizeof(uint32_t), alignof(uint32_t));
    take.array(Array::MeshVertices, c.mesh_vertices, sizeof(DrawVertex), alignof(DrawVertex));
    take.array(Array::MeshIndices, 3 * size_t(c.mesh_triangles), sizeof(uint16_t), alignof(uint16_t));
    take.array(Array::Faces, c.faces, sizeof(FaceInfo), alignof(FaceInfo));
    take.array(Array::DoneOrder, c.faces, sizeof(uint32_t), alignof(uint32_t));
    take.array(Array::Projected, geom::face_mesh_vertices(f), sizeof(Projected), alignof(Projected));
    take.array(Array::Palettes, kPalettes, sizeof(render::Palette), alignof(render::Palette));
    take.array(Array::PaletteRgb, kPalettes, sizeof(uint32_t), alignof(uint32_t));
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

private:
    uint8_t* base_ = nullptr;
    size_t room_ = 0;
    size_t at_ = 0;
};

} // namespace facet::module
