#pragma once
// The levels of detail the viewer works with, in one place: each a factor of a chordal
// tolerance (larger: coarser). The default tolerance is the model's (geom::default_tolerance:
// 0.1% of its diagonal); a pass has one tolerance; each block of a pass has its own from the view.
#include "geom/pack_format.h"

namespace facet::module {

struct DetailScale {
    // Viewer::set_detail(): the user's factor of the default tolerance, from 1/8 (finer) to 16.
    static constexpr float kUserFinest = 1.0f / 8.0f, kUserCoarsest = 16.0f;
    // A block's tolerance in a pass (from its nearest point on the screen): at most this many
    // times the pass's (a far part).
    static constexpr float kBlockCoarsest = 4.0f;
    // A block refined as the view nears it: down to this many times finer than the pass's,
    // a level kStep times apart from the one it has (both ways) before it is made again.
    static constexpr float kRefineFinest = 16.0f, kStep = 2.0f;
    // The first pass short of room goes coarser, up to this many times the tolerance asked for
    // (what facet-pack's Needs are measured to).
    static constexpr float kFirstPassCoarsest = pack::kCoarsestFirst;
    // Triangles bounded by the screen (issue 52): a blocked model whose last whole frame took
    // more triangles than one per kPixelsPerTriangle pixels of the view (at least
    // kLeastTriangleBound) takes its screen error kStep times coarser, up to kCrowdCoarsest
    // times for the parts drawn as their proxies and kCrowdMeshCoarsest times for the blocks'
    // tessellations; well under the bound, kStep finer again (Detail::bound_triangles).
    // (640x480: 19,200 triangles; 480x272: 8,192.) A part left out, on its way in, stands as a
    // proxy within kCrowdCoarsest times the screen error.
    static constexpr uint32_t kPixelsPerTriangle = 16, kLeastTriangleBound = pack::kLeastTriangleBound;
    static constexpr float kCrowdCoarsest = 16.0f, kCrowdMeshCoarsest = 4.0f;
    // A view whose whole frame takes longer than a frame at rest may (Config::frame_budget_us,
    // else this: 20 M instructions at 600 MHz, tools/budget_rules.py's) is crowded too; one
    // under half of it has room.
    static constexpr uint32_t kRestFrameUs = 33333;
};

} // namespace facet::module
