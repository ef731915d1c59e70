// tgx drawing facet's meshes, for the render bench only (see tgx_side.h).
#include "tgx_side.h"

#include "tgx.h"

#include <cstring>

namespace bench {
namespace {

constexpr uint32_t kMagic = 0x4D584754; // "TGXM"
constexpr uint32_t kMaxMeshes = 256;

using Renderer = tgx::Renderer3D<tgx::RGB565, tgx::SHADER_PERSPECTIVE | tgx::SHADER_ZBUFFER | tgx::SHADER_GOURAUD |
                                                  tgx::SHADER_NOTEXTURE,
                                 uint16_t>;

tgx::Mesh3D<tgx::RGB565> meshes[kMaxMeshes];
uint32_t mesh_count = 0;
Renderer renderer;

struct BlobHead {
    uint32_t magic, version, meshes, triangles;
    float centre[3], radius;
};
struct MeshHead {
    uint32_t vertices, triangles, face_words, rgb;
};

} // namespace

bool peer_load(const void* blob, uint32_t bytes, PeerMesh& out) {
    const auto* b = static_cast<const uint8_t*>(blob);
    BlobHead h;
    if (bytes < sizeof h) return false;
    std::memcpy(&h, b, sizeof h);
    if (h.magic != kMagic || h.version != 1 || h.meshes == 0 || h.meshes > kMaxMeshes) return false;
    uint32_t at = sizeof h;
    for (uint32_t i = 0; i < h.meshes; ++i) {
        MeshHead m;
        if (at + sizeof m > bytes) return false;
        std::memcpy(&m, b + at, sizeof m);
        at += sizeof m;
        const uint32_t need = m.vertices * 24 + ((m.face_words * 2 + 3) & ~3u);
        if (m.vertices == 0 || m.vertices > 32767 || need > bytes - at) return false;
        tgx::Mesh3D<tgx::RGB565>& M = meshes[i];
        M = {};
        M.id = 1;
        M.nb_vertices = uint16_t(m.vertices);
        M.nb_normals = uint16_t(m.vertices);
        M.nb_faces = uint16_t(m.triangles);
        M.len_face = uint16_t(m.face_words);
        M.vertice = reinterpret_cast<const tgx::fVec3*>(b + at);
        M.normal = reinterpret_cast<const tgx::fVec3*>(b + at + m.vertices * 12);
        M.face = reinterpret_cast<const uint16_t*>(b + at + m.vertices * 24);
        M.color = tgx::RGBf(float(m.rgb & 255) / 255, float((m.rgb >> 8) & 255) / 255, float((m.rgb >> 16) & 255) / 255);
        M.ambiant_strength = 0.3f; // facet's own lighting: ambient 0.3, diffuse 0.7, no highlight
        M.diffuse_strength = 0.7f;
        M.specular_strength = 0;
        M.specular_exponent = 0;
        M.next = i + 1 < h.meshes ? &meshes[i + 1] : nullptr;
        // Its bounding box (tgx culls a whole mesh by it), as tgx's converter writes it.
        M.bounding_box.minX = M.bounding_box.minY = M.bounding_box.minZ = 1e30f;
        M.bounding_box.maxX = M.bounding_box.maxY = M.bounding_box.maxZ = -1e30f;
        for (uint32_t k = 0; k < m.vertices; ++k) {
            const tgx::fVec3& p = M.vertice[k];
            if (p.x < M.bounding_box.minX) M.bounding_box.minX = p.x;
            if (p.x > M.bounding_box.maxX) M.bounding_box.maxX = p.x;
            if (p.y < M.bounding_box.minY) M.bounding_box.minY = p.y;
            if (p.y > M.bounding_box.maxY) M.bounding_box.maxY = p.y;
            if (p.z < M.bounding_box.minZ) M.bounding_box.minZ = p.z;
            if (p.z > M.bounding_box.maxZ) M.bounding_box.maxZ = p.z;
        }
        at += need;
    }
    mesh_count = h.meshes;
    out = {h.triangles, h.meshes, h.radius};
    return true;
}

void peer_draw(const PeerCamera& c, uint16_t width, uint16_t height, uint16_t* pixels, uint16_t* depth) {
    tgx::Image<tgx::RGB565> image(pixels, int(width), int(height));
    image.fillScreen(tgx::RGB565(tgx::RGBf(0.78f, 0.82f, 0.86f))); // a frame starts clean, as facet's does
    renderer.setViewportSize(width, height);
    renderer.setOffset(0, 0);
    renderer.setImage(&image);
    renderer.setZbuffer(depth);
    renderer.clearZbuffer();
    // facet's camera: eye space e = R (p - target) - (0, 0, distance); x_screen = w/2 + f e.x / -e.z.
    const float* R = c.rotation;
    const float t[3] = {R[0] * c.target_mm[0] + R[1] * c.target_mm[1] + R[2] * c.target_mm[2],
                        R[3] * c.target_mm[0] + R[4] * c.target_mm[1] + R[5] * c.target_mm[2],
                        R[6] * c.target_mm[0] + R[7] * c.target_mm[1] + R[8] * c.target_mm[2]};
    tgx::fMat4 view; // column-major
    const float V[16] = {R[0], R[3], R[6], 0, R[1], R[4], R[7], 0, R[2], R[5], R[8], 0, -t[0], -t[1], -t[2] - c.distance_mm, 1};
    std::memcpy(view.M, V, sizeof V);
    renderer.setViewMatrix(view);
    tgx::fMat4 model;
    model.setIdentity();
    renderer.setModelMatrix(model);
    const float n = c.distance_mm - 1.2f * c.radius_mm > c.radius_mm / 64 ? c.distance_mm - 1.2f * c.radius_mm : c.radius_mm / 64;
    const float f = c.distance_mm + 1.2f * c.radius_mm;
    // x_screen = w/2 + f x / -z: a frustum whose half-width at the near plane is n w / 2f.
    renderer.setFrustum(-n * width / (2 * c.focal_px), n * width / (2 * c.focal_px), -n * height / (2 * c.focal_px),
                        n * height / (2 * c.focal_px), n, f);
    // facet's light, fixed in view space toward the viewer's upper left: in world coordinates,
    // the direction it points toward.
    const float L[3] = {-0.38f, 0.5f, 0.78f};
    const tgx::fVec3 dir(-(R[0] * L[0] + R[3] * L[1] + R[6] * L[2]), -(R[1] * L[0] + R[4] * L[1] + R[7] * L[2]),
                         -(R[2] * L[0] + R[5] * L[1] + R[8] * L[2]));
    renderer.setLight(dir, tgx::RGBf(1, 1, 1), tgx::RGBf(1, 1, 1), tgx::RGBf(0, 0, 0));
    renderer.setShaders(tgx::SHADER_GOURAUD);
    renderer.setCulling(1);
    if (mesh_count) renderer.drawMesh(&meshes[0], true, true);
}

} // namespace bench
