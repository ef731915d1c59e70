// A face's storage cut by its plan (geom/face_storage.h) into the typed arrays of FaceScratch.
#include "geom/face_storage.h"

#include "cdt/arena.h"
#include "face_internal.h"

namespace facet::geom {
namespace {

// What each array of the plan holds: its record's size and alignment, as the plan lists them.
template <typename T>
constexpr bool holds(size_t bytes, size_t align) {
    return sizeof(T) == bytes && alignof(T) <= align;
}
constexpr bool records_match_the_plan() {
    bool ok = true;
    face_storage_plan(FaceCapacity{}, [&](FaceArray what, size_t, size_t bytes, size_t align) {
        switch (what) {
        case FaceArray::CdtVertices: ok = ok && holds<cdt::Vertex<uint16_t>>(bytes, align); break;
        case FaceArray::CdtTriangles: ok = ok && holds<cdt::Triangle<uint16_t>>(bytes, align); break;
        case FaceArray::CdtWork:
        case FaceArray::CdtOrder:
        case FaceArray::CdtMinSeq:
        case FaceArray::CdtIns: ok = ok && holds<uint16_t>(bytes, align); break;
        case FaceArray::CdtKeys: ok = ok && holds<uint32_t>(bytes, align); break;
        case FaceArray::LoopPoints: ok = ok && holds<cdt::Point>(bytes, align); break;
        case FaceArray::LoopSizes: ok = ok && holds<uint32_t>(bytes, align); break;
        case FaceArray::Uv: ok = ok && holds<Vec2>(bytes, align); break;
        case FaceArray::Pinned: ok = ok && holds<uint8_t>(bytes, align); break;
        case FaceArray::Xyz: ok = ok && holds<Vec3>(bytes, align); break;
        case FaceArray::MeshOf: ok = ok && holds<uint32_t>(bytes, align); break;
        case FaceArray::Measured: ok = ok && holds<detail::TriangleMeasure>(bytes, align); break;
        case FaceArray::Slivers: ok = ok && holds<detail::Sliver>(bytes, align); break;
        case FaceArray::Patches: ok = ok && holds<uint32_t>(bytes, align); break;
        }
    });
    return ok;
}
static_assert(records_match_the_plan(), "face_storage_plan() lists each array's record as it is");
static_assert(cdt::triangles_for(4 + 100) == 2 * (4 + 100) - 6 && cdt::work_for(104) == 8 * 104 + 64,
              "the plan's triangle and work counts are the arena's");
static_assert(face_arena_bytes(100) == cdt::arena_bytes<uint16_t>(100 + cdt::kBoxVertices), "the arena's bytes, as cdt/ counts them");

template <typename T>
std::span<T> as(void* p, size_t count) {
    return {static_cast<T*>(p), count};
}

} // namespace

Result FaceStorage::bind(void* memory, size_t bytes, const FaceCapacity& c) {
    base_ = nullptr;
    if (!memory || (reinterpret_cast<uintptr_t>(memory) & 7)) {
        return Result::fail(Status::OutOfRange, "a face's storage must be 8-byte aligned memory");
    }
    if (c.points < 8 || c.points > kMaxFacePoints || c.loops == 0) {
        return Result::fail(Status::OutOfRange, "a face's capacity is out of range (points 8 to 32,760, loops above 0)");
    }
    if (bytes < face_storage_bytes(c)) return Result::fail(Status::Full, "the face storage is smaller than face_storage_bytes()");
    base_ = static_cast<uint8_t*>(memory);
    capacity_ = c;
    return {};
}

detail::FaceScratch detail::scratch_of(const FaceStorage& storage) {
    FaceScratch s{};
    uint8_t* const base = storage.memory();
    size_t at = 0;
    face_storage_plan(storage.capacity(), [&](FaceArray what, size_t count, size_t bytes, size_t align) {
        at = (at + align - 1) / align * align;
        void* const p = base + at;
        at += count * bytes;
        switch (what) {
        case FaceArray::CdtVertices: s.arena.vertices = as<cdt::Vertex<uint16_t>>(p, count); break;
        case FaceArray::CdtTriangles: s.arena.triangles = as<cdt::Triangle<uint16_t>>(p, count); break;
        case FaceArray::CdtWork: s.arena.work = as<uint16_t>(p, count); break;
        case FaceArray::CdtOrder: s.arena.order = as<uint16_t>(p, count); break;
        case FaceArray::CdtMinSeq: s.arena.minseq = as<uint16_t>(p, count); break;
        case FaceArray::CdtIns: s.arena.ins = as<uint16_t>(p, count); break;
        case FaceArray::CdtKeys: s.arena.keys = as<uint32_t>(p, count); break;
        case FaceArray::LoopPoints: s.loop_points = as<cdt::Point>(p, count); break;
        case FaceArray::LoopSizes: s.loop_sizes = as<uint32_t>(p, count); break;
        case FaceArray::Uv: s.uv = as<Vec2>(p, count); break;
        case FaceArray::Pinned: s.pinned = as<uint8_t>(p, count); break;
        case FaceArray::Xyz: s.xyz = as<Vec3>(p, count); break;
        case FaceArray::MeshOf: s.mesh_of = as<uint32_t>(p, count); break;
        case FaceArray::Measured: s.measured = as<TriangleMeasure>(p, count); break;
        case FaceArray::Slivers: s.slivers = as<Sliver>(p, count); break;
        case FaceArray::Patches: s.patches = as<uint32_t>(p, count); break;
        }
    });
    return s;
}

} // namespace facet::geom
