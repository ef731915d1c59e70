#pragma once
// One face's working memory: everything a FaceJob needs besides the pack, the edge samples and
// the mesh, in one block the caller gives (the module's workspace, a host tool's buffer).
//
//   geom::FaceCapacity cap{};                              // points, loops, slivers, patches
//   static uint64_t memory[geom::face_storage_bytes(cap) / 8 + 1];
//   geom::FaceStorage storage;
//   if (Result r = storage.bind(memory, sizeof memory, cap); !r.ok()) ...
//   job.start(pack, face, samples, opt, storage, mesh);
//
// The plan below lists its arrays once, in order; the bytes a capacity takes are that list
// summed (face_storage_bytes, constexpr), and geom cuts the block by the same list
// (face_storage.cpp, which checks each listed record size against the record itself).
#include "core/status.h"

#include <cstddef>
#include <cstdint>

namespace facet::geom {

constexpr uint32_t kPatchCacheWords = 16384; // 64 KB: 230 spans of a bicubic rational surface, 142 of a quintic one
constexpr uint32_t kMaxFacePoints = 32760;   // the 16-bit CDT arena's most (with its 4 box corners)

struct FaceCapacity {
    uint32_t points = 12000;  // CDT points of one face: its loops' samples and refinement's points
    uint32_t loops = 2048;    // loops of one face (a plate of 1,600 holes: 1,601)
    uint32_t slivers = 1024;  // loop points of one face closer than its CDT grid (kept as slivers)
    // A free-form face's spans as fixed-point patches (geom/patches.h); 0: its points are
    // evaluated in float (slower on a core without an FPU, and a hair different: give host
    // tools the same as the device).
    uint32_t patch_words = kPatchCacheWords;
};

// The arrays of a face's storage, in the order they lie in the block.
enum class FaceArray : uint8_t {
    CdtVertices, CdtTriangles, CdtWork, CdtOrder, CdtMinSeq, CdtIns, CdtKeys, // the CDT arena
    LoopPoints, LoopSizes,                   // the loops on the CDT's integer grid
    Uv, Pinned, Xyz, MeshOf,                 // per point: (u,v), which of them are exact, 3D, its vertex
    Measured,                                // per CDT triangle slot: refinement's last measure of it
    Slivers,                                 // loop points dropped from the grid, as triangles
    Patches,                                 // a free-form surface's fixed-point patches (words)
};

// The plan: take(array, count, bytes of one, alignment) for each array, in order. V points
// with the CDT's 4 box corners make at most 2 V - 6 triangles (cdt/arena.h); the CDT's work
// buffer is 8 V + 64 entries.
template <typename Take>
constexpr void face_storage_plan(const FaceCapacity& c, Take&& take) {
    const size_t V = size_t(c.points) + 4, T = 2 * V - 6;
    take(FaceArray::CdtVertices, V, 12, 4); // cdt::Vertex<uint16_t>
    take(FaceArray::CdtTriangles, T, 14, 2); // cdt::Triangle<uint16_t>
    take(FaceArray::CdtWork, 8 * V + 64, 2, 2);
    take(FaceArray::CdtOrder, V, 2, 2);
    take(FaceArray::CdtMinSeq, V, 2, 2);
    take(FaceArray::CdtIns, V, 2, 2);
    take(FaceArray::CdtKeys, V, 4, 4);
    take(FaceArray::LoopPoints, V, 8, 4);    // cdt::Point
    take(FaceArray::LoopSizes, size_t(c.loops), 4, 4);
    take(FaceArray::Uv, V, 8, 4);            // Vec2
    take(FaceArray::Pinned, V, 1, 1);
    take(FaceArray::Xyz, V, 12, 4);          // Vec3
    take(FaceArray::MeshOf, V, 4, 4);
    take(FaceArray::Measured, T, 24, 8);     // refinement's TriangleMeasure
    take(FaceArray::Slivers, size_t(c.slivers), 60, 4);
    take(FaceArray::Patches, size_t(c.patch_words), 4, 4);
}

// The bytes of a block (8-byte aligned) for a face of this capacity.
constexpr size_t face_storage_bytes(const FaceCapacity& c) {
    size_t at = 0;
    face_storage_plan(c, [&](FaceArray, size_t count, size_t bytes, size_t align) {
        at = (at + align - 1) / align * align + count * bytes;
    });
    return at;
}

// The bytes of a block before its patches (the plan's last array): free as scratch while no
// face is under way (the patches stay from face to face, found again by their surface).
constexpr size_t face_scratch_bytes(const FaceCapacity& c) {
    size_t at = 0, before_patches = 0;
    face_storage_plan(c, [&](FaceArray what, size_t count, size_t bytes, size_t align) {
        at = (at + align - 1) / align * align;
        if (what == FaceArray::Patches) before_patches = at;
        at += count * bytes;
    });
    return before_patches;
}

// The bytes of the CDT arena's arrays alone for a face of `points` points (what a face's
// triangulation itself took: the arena's peak in the budgets).
constexpr size_t face_arena_bytes(uint32_t points) {
    size_t bytes = 0;
    face_storage_plan(FaceCapacity{points, 0, 0, 0}, [&](FaceArray what, size_t count, size_t size, size_t) {
        if (what <= FaceArray::CdtKeys) bytes += count * size;
    });
    return bytes;
}

// The most vertices and triangles one face of this capacity can add to a mesh (its CDT's; the
// slivers' take room of their own).
constexpr uint32_t face_mesh_vertices(const FaceCapacity& c) { return c.points + 4; }
constexpr uint32_t face_mesh_triangles(const FaceCapacity& c) { return 2 * (c.points + 4) - 6; }

// A block bound to a capacity, for FaceJob (geom/tessellate.h). The block must stay put while
// a job uses it; a job's patches stay in it for the next face of the same surface.
class FaceStorage {
public:
    // OutOfRange: no memory, not 8-byte aligned, or a capacity out of range (points 8 to
    // kMaxFacePoints, loops at least 1); Full: fewer bytes than face_storage_bytes(capacity).
    Result bind(void* memory, size_t bytes, const FaceCapacity& capacity);
    bool bound() const { return base_ != nullptr; }
    const FaceCapacity& capacity() const { return capacity_; }
    uint8_t* memory() const { return base_; }

private:
    uint8_t* base_ = nullptr;
    FaceCapacity capacity_{};
};

} // namespace facet::geom
