#pragma once
// The peer's side of the render bench: tgx (../shared/peers/tgx, built only into this bench)
// drawing a mesh blob made by bench/render/tgx_mesh.py with a camera given as facet's viewer
// describes its own (facet::Viewer::CameraView). Kept apart from main.cpp so the peer's
// headers, warnings and float maths stay in this one translation unit.
#include <cstdint>

namespace bench {

struct PeerCamera {
    float rotation[9], target_mm[3], distance_mm, focal_px; // facet::Viewer::CameraView
    float radius_mm;                                         // the model's bounding sphere (near/far)
};

// What a blob holds: its triangles, the tgx meshes they are chained in, and the model's
// bounding sphere radius (mm).
struct PeerMesh {
    uint32_t triangles, meshes;
    float radius_mm;
};

// Reads the blob (TGXM, version 1) into chained tgx meshes that point into it. False: not a
// blob this bench made, or more meshes than it holds.
bool peer_load(const void* blob, uint32_t bytes, PeerMesh& out);

// One frame: clears `pixels` (a flat background) and `depth`, then draws the mesh with
// Gouraud shading, a z-buffer and back faces culled, into width x height.
void peer_draw(const PeerCamera& camera, uint16_t width, uint16_t height, uint16_t* pixels, uint16_t* depth);

} // namespace bench
