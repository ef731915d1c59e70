// libFuzzer target for tessellation: a pack that the reader accepts can still hold nonsense
// geometry (knots out of order, huge or tiny coordinates, loops that cross, a pole in the
// middle of a face). Edge sampling and every face's tessellation must return a status, in
// bounded time, and an Ok face's triangles must index its own vertices.
//
// Input: a plain pack; its size and CRC are fixed up so the fuzzer gets past them.
#include "geom/pack.h"
#include "geom/tessellate.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

// A face's storage as the device's, small (the fuzzer runs many inputs; more points give Full).
constexpr FaceCapacity kFace{508, 256, 256, kPatchCacheWords};
constexpr size_t kMesh = 20000; // mesh vertices for all faces together
constexpr uint32_t kFaces = 8;  // faces tessellated per input

struct Buffers {
    std::vector<uint64_t> face = std::vector<uint64_t>(face_storage_bytes(kFace) / 8 + 1);
    std::vector<MeshVertex> mv = std::vector<MeshVertex>(kMesh);
    std::vector<uint32_t> mi = std::vector<uint32_t>(3 * kMesh);
    std::vector<Vec2> muv = std::vector<Vec2>(kMesh);
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < sizeof(pack::Header) || size > (1u << 20)) return 0;
    std::vector<uint32_t> aligned(size / 4 + 1);
    std::memcpy(aligned.data(), data, size);
    auto* bytes = reinterpret_cast<uint8_t*>(aligned.data());
    auto* h = reinterpret_cast<pack::Header*>(bytes);
    h->total_bytes = uint32_t(size);
    h->crc32 = pack::crc32(bytes + sizeof(pack::Header), uint32_t(size - sizeof(pack::Header)));
    Pack pack;
    if (!pack.open(bytes, uint32_t(size)).ok()) return 0;

    static Buffers b; // large: allocated once
    const size_t ne = pack.edges().size();
    std::vector<uint32_t> ef(ne);
    std::vector<uint16_t> ec(ne);
    std::vector<float> et(ne * 16 + 256);
    std::vector<Vec3> ep(ne * 16 + 256);
    EdgeSamples samples{ef, ec, et, ep};
    TessOptions opt;
    opt.tolerance = default_tolerance(pack);
    if (!sample_edges(pack, opt, samples).ok()) return 0;

    FaceStorage sc;
    if (!sc.bind(b.face.data(), b.face.size() * 8, kFace).ok()) std::abort();
    Mesh mesh{b.mv, b.mi, b.muv};
    for (uint32_t f = 0; f < pack.faces().size() && f < kFaces; ++f) {
        const uint32_t v0 = mesh.vertex_count, t0 = mesh.triangle_count;
        FaceStats st;
        const Result r = tessellate_face(pack, f, samples, opt, sc, mesh, st);
        if (!r.ok()) {
            if (!r.what || !r.what[0] || !r.where.kind) std::abort(); // a failure names its reason and face
            if (mesh.vertex_count != v0 || mesh.triangle_count != t0) std::abort(); // and leaves the mesh as it was
            continue;
        }
        for (uint32_t t = t0; t < mesh.triangle_count; ++t)
            for (int k = 0; k < 3; ++k)
                if (b.mi[3 * t + k] < v0 || b.mi[3 * t + k] >= mesh.vertex_count) std::abort();
    }
    return 0;
}
