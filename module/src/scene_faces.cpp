// What the scene says of a face from its pack and its edges' samples, without its mesh: its
// exact geometry placed, its surface's kind, its plane (in floats, and its normal in Q14 without soft float), a point of
// its boundary.
#include "scene.h"

#include "geom/measure.h"
#include "geom/params.h"

#include <bit>

namespace facet::module {

Result Scene::face_geometry(uint32_t f, uint32_t instance, geom::FaceGeometry& out) const {
    const Block& b = block_of_face(f);
    return geom::describe_face(b.pack, f - b.first_face, instances()[instance].m, out);
}

uint8_t Scene::surface_type(uint32_t f) const {
    const Block& b = block_of_face(f);
    return b.pack.surfaces()[b.pack.faces()[f - b.first_face].surface].type;
}

const pack::Frame* Scene::plane_frame(uint32_t f, bool& reversed) const {
    const Block& b = block_of_face(f);
    const pack::Face& F = b.pack.faces()[f - b.first_face];
    const pack::Surface& S = b.pack.surfaces()[F.surface];
    if (S.type != uint8_t(pack::SurfaceType::Plane)) return nullptr;
    reversed = F.reversed != 0;
    return &geom::params<pack::PlaneParams>(b.pack, S).frame;
}

bool Scene::face_plane(uint32_t f, float point[3], float normal[3]) const {
    bool reversed;
    const pack::Frame* at = plane_frame(f, reversed);
    if (!at) return false;
    const pack::Frame& frame = *at;
    const float sign = (reversed ? -1.0f : 1.0f) * handedness(frame);
    for (int k = 0; k < 3; ++k) point[k] = frame.origin[k], normal[k] = sign * frame.z[k];
    return true;
}

namespace {

// A component of a unit vector (|v| <= 1) in Q14, rounded half away from zero: what rounding
// v * 16384 gives, from v's bits (v * 2^14 is exact: a power of two).
int32_t unit_q14(float v) {
    const uint32_t bits = std::bit_cast<uint32_t>(v);
    const int32_t exponent = int32_t((bits >> 23) & 0xFF);
    if (exponent == 0) return 0; // zero, or below the normal range
    const uint32_t mantissa = (bits & 0x7FFFFF) | 0x800000; // |v| = mantissa 2^(exponent - 150)
    const int32_t shift = 136 - exponent;                    // |v| 2^14 = mantissa 2^-shift
    // (shift <= 0: |v| 2^14 is 2^23 or more, a broken frame: the most Q14 holds)
    const uint32_t q = shift <= 0 ? 32767 : shift > 25 ? 0 : (mantissa + (1u << (shift - 1))) >> shift;
    const int32_t m = q > 32767 ? 32767 : int32_t(q);
    return bits >> 31 ? -m : m;
}

} // namespace

bool Scene::plane_normal(uint32_t f, int16_t n[3]) const {
    bool reversed;
    const pack::Frame* at = plane_frame(f, reversed);
    if (!at) return false;
    const pack::Frame& frame = *at;
    int64_t x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) x[k] = unit_q14(frame.x[k]), y[k] = unit_q14(frame.y[k]), z[k] = unit_q14(frame.z[k]);
    // handedness(): the sign of (x cross y) . z, in whole Q14 units (a unit frame's is about
    // +-2^42, far beyond their rounding).
    const int64_t turn = (x[1] * y[2] - x[2] * y[1]) * z[0] + (x[2] * y[0] - x[0] * y[2]) * z[1] + (x[0] * y[1] - x[1] * y[0]) * z[2];
    const bool flip = reversed != (turn < 0);
    for (int k = 0; k < 3; ++k) n[k] = int16_t(flip ? -z[k] : z[k]);
    return true;
}

const int32_t* Scene::boundary_point(uint32_t f) const {
    const Block& b = block_of_face(f);
    const pack::Face& F = b.pack.faces()[f - b.first_face];
    for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
        const pack::Loop& L = b.pack.loops()[l];
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const uint32_t e = b.first_edge + b.pack.coedges()[c].edge();
            if (mem_.samples.count[e] > 0) return sample_q(mem_.samples.first[e]);
        }
    }
    return nullptr;
}

} // namespace facet::module
