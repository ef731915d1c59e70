#pragma once
// The render bench's views of a model, drawn by the module through its public API: the one
// sequence the bench firmware draws on the boards (main.cpp, beside the peer) and
// facet-render-views draws on the host (views_host.cpp), so that their pictures can be
// compared byte for byte (render.py --host-views: the same pixels on every board as on the
// host simulator's core).
//
// For each screen size: the model loaded and every face done, the level of detail `finer`
// steps finer than the default; the fitted view ("full"), then kZoomSteps closer ("zoomed").
// Each view in shaded with edges, then shaded alone, then back in shaded with edges (the
// peer's turn on the boards: it draws the module's camera).
#include "facet/viewer.h"

#include <cstdint>
#include <initializer_list>

namespace bench {

struct ViewSize {
    uint16_t width, height;
};
inline constexpr ViewSize kViewSizes[] = {{480, 272}, {640, 480}};
inline constexpr int kZoomSteps = 3;
// The memory a pack is inflated into: what fits decides what is drawn, so the boards and the
// host take the same.
inline constexpr uint32_t kPackMemoryBytes = 1536u * 1024;

inline void settle(facet::Viewer& v) {
    while (v.step(0) != facet::Activity::Idle) {
    }
}

// The viewer's configuration for one size: full frames into one buffer, no interface (the
// model alone, as the peer draws it), every face tessellated (none left waiting by the view,
// as the peer's mesh has them all).
inline facet::Config view_config(ViewSize s, facet::Rgb565* frame, uint16_t* depth, void (*flush)(facet::Viewer&, void*, const facet::Area&, const facet::Rgb565*),
                          void (*on_event)(void*, const facet::Event&), void* user) {
    facet::Config cfg;
    cfg.display.width = s.width, cfg.display.height = s.height, cfg.display.band_lines = s.height;
    cfg.display.buffers[0] = frame, cfg.display.depth[0] = depth;
    cfg.display.mode = facet::Flush::Copy;
    cfg.display.flush = flush;
    cfg.display.user = user;
    cfg.on_event = on_event;
    cfg.event_user = user;
    cfg.interface = facet::Interface::Off;
    cfg.screen_error_px = 0;
    return cfg;
}

// Whether the last frame (its FrameDone event) is a full one of the finished model: what a
// picture of a view must be.
inline bool whole_model_drawn(const facet::Event& frame) {
    return frame.kind == facet::Event::Kind::FrameDone && frame.frame.full && frame.frame.faces_done == frame.frame.faces_total;
}

// After load: every face done, then `finer` steps finer.
inline void prepare(facet::Viewer& v, uint32_t finer) {
    settle(v);
    for (uint32_t k = 0; k < finer; ++k) {
        v.act(facet::Action::Finer);
        settle(v);
    }
}

// The two views: picture(name, edges) once each frame is drawn (false stops: the view is not
// what the bench measures), peer(name) once a view's pictures are taken.
template <typename Picture, typename Peer>
bool draw_views(facet::Viewer& v, Picture&& picture, Peer&& peer) {
    for (const char* name : {"full", "zoomed"}) {
        if (name[0] == 'z') {
            for (int i = 0; i < kZoomSteps; ++i) v.act(facet::Action::ZoomIn);
            settle(v);
        }
        for (int edges = 1; edges >= 0; --edges) {
            (void)v.set_display_mode(edges ? facet::DisplayMode::ShadedEdges : facet::DisplayMode::Shaded);
            settle(v);
            if (!picture(name, edges == 1)) return false;
        }
        (void)v.set_display_mode(facet::DisplayMode::ShadedEdges);
        settle(v);
        if (!peer(name)) return false;
    }
    return true;
}

} // namespace bench
