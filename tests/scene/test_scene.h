#pragma once
// The fixed 3D test scene of the foundation: a cube pierced by a sphere over a gradient,
// Gouraud-lit and depth-buffered. Drawn identically by the firmware and by the host reference
// renderer (tools/scene-ref), so a screenshot can be compared pixel for pixel.
#include "render/fixed.h"
#include "render/raster.h"

namespace facet::render {

struct SceneView {
    uint16_t yaw;   // turns/65536 about the vertical axis
    uint16_t pitch; // turns/65536 about the horizontal axis
};

// The views the tests capture: "scene-a" and "scene-b".
constexpr SceneView kSceneViews[2] = {{degrees(35), degrees(25)}, {degrees(150), degrees(-20)}};

// Draws the frame into the rasterizer's target (background, then geometry), for the screen
// size the target states (the whole screen, or one band of it).
Status draw_test_scene(Rasterizer& raster, const SceneView& view);

} // namespace facet::render
