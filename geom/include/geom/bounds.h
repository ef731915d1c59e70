#pragma once
// A box that holds every point of a shell's faces, from its records alone (no evaluation):
// its vertices; each edge's curve's (a circle's or an ellipse's whole box, a B-spline's poles);
// each face's surface where it can bulge past its edges (a sphere's or a torus's whole box, a
// B-spline's poles, a swept curve's reach). Conservative: larger than the shell where its
// curves turn away, never smaller. For packs without the packer's exact boxes (a whole pack
// read as one block, a blocked pack made without them).
#include "geom/pack.h"

#include <cstdint>

namespace facet::geom {

struct Box3 {
    float lo[3] = {3e38f, 3e38f, 3e38f}, hi[3] = {-3e38f, -3e38f, -3e38f};
    bool empty() const { return lo[0] > hi[0]; }
    void add(const float p[3]) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = p[k] < lo[k] ? p[k] : lo[k];
            hi[k] = p[k] > hi[k] ? p[k] : hi[k];
        }
    }
    void add_ball(const float c[3], float r) {
        const float a[3] = {c[0] - r, c[1] - r, c[2] - r}, b[3] = {c[0] + r, c[1] + r, c[2] + r};
        add(a), add(b);
    }
};

// The box of shell `shell` of a validated pack (empty for a shell without faces).
Box3 shell_box(const Pack& pack, uint32_t shell);

} // namespace facet::geom
