// libFuzzer target for tessellation: a pack that the reader accepts can still hold nonsense
// geometry (knots out of order, huge or tiny coordinates, loops that cross, a pole in the
// middle of a face). Edge sampling and every face's tessellation must return a status, in
// bounded time, and an Ok face's triangles must index its own vertices.
//
// Input: a plain pack; its size and CRC are fixed up so the fuzzer gets past them.
#include "cdt/cdt.h"
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

constexpr size_t kV = 512;      // CDT vertices per face (small: the fuzzer runs many inputs; more gives Full)
constexpr size_t kMesh = 20000; // mesh vertices for all faces together
constexpr uint32_t kFaces = 8;  // faces tessellated per input

struct Buffers {
    std::vector<cdt::Vertex<uint16_t>> av = std::vector<cdt::Vertex<uint16_t>>(kV);
    std::vector<cdt::Triangle<uint16_t>> at = std::vector<cdt::Triangle<uint16_t>>(cdt::triangles_for(kV));
    std::vector<uint16_t> aw = std::vector<uint16_t>(cdt::work_for(kV)), ao = std::vector<uint16_t>(kV),
                          am = std::vector<uint16_t>(kV), ai = std::vector<uint16_t>(kV);
    std::vector<uint32_t> ak = std::vector<uint32_t>(kV);
    std::vector<cdt::Point> lp = std::vector<cdt::Point>(kV);
    std::vector<uint32_t> ls = std::vector<uint32_t>(256), mesh_of = std::vector<uint32_t>(kV);
    std::vector<Vec2> uvs = std::vector<Vec2>(kV);
    std::vector<Vec3> xyz = std::vector<Vec3>(kV);
    std::vector<uint8_t> pinned = std::vector<uint8_t>(kV);
    std::vector<TriangleMeasure> measured = std::vector<TriangleMeasure>(cdt::triangles_for(kV));
    std::vector<Sliver> slivers = std::vector<Sliver>(256);
    std::vector<uint32_t> patches = std::vector<uint32_t>(kPatchCacheWords);
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

    FaceScratch sc{{b.av, b.at, b.aw, b.ao, b.am, b.ai, b.ak}, b.lp, b.ls, b.uvs, b.pinned, b.xyz, b.mesh_of, b.measured, b.slivers, b.patches};
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
