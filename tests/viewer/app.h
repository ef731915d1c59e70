#pragma once
// An application of the module, for the viewer tests: its buffers, its display (a panel it
// copies bands or frames into, or one it shows full frames on), its event log, its input.
#include "core.h"
#include "core/format.h"
#include "facet/viewer.h"
#include "pack_io.h"
#include "packs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

namespace facet::test {

inline std::string text(const Result& r) {
    char buf[200];
    describe(r, buf, sizeof buf);
    return buf;
}

// A piece of work by name (for messages).
inline const char* work_name(Work w) {
    switch (w) {
    case Work::Unpack: return "unpack";
    case Work::Sampling: return "sampling";
    case Work::Face: return "face";
    case Work::Frame: return "frame";
    case Work::Update: return "update";
    case Work::Fit: return "fit";
    case Work::Overlay: return "overlay";
    }
    return "?";
}

struct App {
    uint16_t w = 160, h = 120;
    uint16_t lines = 120;
    int buffers = 2;
    Flush mode = Flush::Copy;
    bool late_done = false; // a DMA: flush_done() comes later (call done())
    std::vector<Rgb565> buf[2];
    std::vector<uint16_t> depth[2];
    bool faces_layer = false;            // Display::faces (full frames)
    std::vector<Rgb565> layer;
    std::vector<uint16_t> layer_depth;
    std::vector<Rgb565> panel;
    const Rgb565* shown = nullptr;
    std::vector<uint64_t> workspace;
    std::vector<uint32_t> file, memory;
    Viewer* v = nullptr;
    std::vector<Event> events;
    uint32_t flushes = 0, pending = 0;
    uint32_t clock_us = 0, tick_us = 0; // a fake clock: each read advances it
    bool use_clock = false;
    void (*on_clock)(void* user) = nullptr; // told of each clock read (time passing: a storage's transfer ends)
    void* clock_user = nullptr;
    Interface interface = Interface::Off; // the model alone (the on-screen interface has tests of its own)
    // facet's rectangle on a larger screen (Display::x, y): the screen's size (0: w x h) and where.
    uint16_t screen_w = 0, screen_h = 0, at_x = 0, at_y = 0;
    uint16_t stride() const { return screen_w ? screen_w : w; }
    float screen_error_px = Config{}.screen_error_px;

    Capacity capacity;
    size_t workspace_size = 0; // 0: FACET_WORKSPACE_BYTES_DEFAULT (or the capacity's own, when larger)

    Result create(bool depth_per_buffer = true) {
        for (int b = 0; b < 2; ++b) {
            buf[b].assign(size_t(w) * lines, 0);
            depth[b].assign(size_t(w) * lines, 0);
        }
        panel.assign(size_t(stride()) * (screen_h ? screen_h : h), 0);
        Config cfg;
        cfg.display.width = w, cfg.display.height = h, cfg.display.band_lines = lines;
        cfg.display.buffers[0] = buf[0].data();
        cfg.display.buffers[1] = buffers == 2 ? buf[1].data() : nullptr;
        cfg.display.depth[0] = depth[0].data();
        cfg.display.depth[1] = depth_per_buffer && buffers == 2 ? depth[1].data() : nullptr;
        if (faces_layer) {
            layer.assign(size_t(w) * h, 0), layer_depth.assign(size_t(w) * h, 0);
            cfg.display.faces = layer.data(), cfg.display.faces_depth = layer_depth.data();
        }
        cfg.display.mode = mode;
        cfg.display.flush = [](Viewer&, void* self, const Area& a, const Rgb565* px) { static_cast<App*>(self)->flushed(a, px); };
        cfg.display.user = this;
        cfg.display.x = at_x, cfg.display.y = at_y;
        cfg.on_event = [](void* self, const Event& e) { static_cast<App*>(self)->events.push_back(e); };
        cfg.event_user = this;
        if (use_clock) {
            cfg.now_us = [](void* self) {
                App& a = *static_cast<App*>(self);
                if (a.on_clock) a.on_clock(a.clock_user);
                return a.clock_us += a.tick_us;
            };
            cfg.clock_user = this;
        }
        cfg.capacity = capacity;
        cfg.interface = interface;
        cfg.screen_error_px = screen_error_px;
        const size_t bytes = workspace_size ? workspace_size : std::max<size_t>(workspace_bytes(capacity), FACET_WORKSPACE_BYTES_DEFAULT);
        workspace.assign(bytes / 8, 0);
        Result why;
        v = Viewer::create(cfg, workspace.data(), bytes / 8 * 8, &why);
        return why;
    }
    void flushed(const Area& a, const Rgb565* px) {
        ++flushes;
        if (mode == Flush::Scanout) {
            shown = px;
        } else {
            for (uint16_t y = 0; y < a.height; ++y)
                std::memcpy(&panel[size_t(a.y + y) * stride() + a.x], px + size_t(y) * a.width, size_t(a.width) * 2);
        }
        if (late_done) ++pending;
        else v->flush_done();
    }
    void done() {
        for (; pending; --pending) v->flush_done();
    }
    // A finger down and up at (x, y), and what follows.
    void tap(int x, int y) {
        v->touch(0, int16_t(x), int16_t(y), true);
        v->touch(0, int16_t(x), int16_t(y), false);
        run();
    }
    // A row inside the toolbar button of `a` (-1: none).
    int button_row(const module::Overlay& o, Action a) const {
        for (int y = 0; y < h; ++y)
            if (o.button_at(int16_t(w - 5), int16_t(y)) == a) return y + 5;
        return -1;
    }
    std::vector<Rgb565> screen() const { return mode == Flush::Scanout ? std::vector<Rgb565>(shown, shown + size_t(w) * h) : panel; }
    Result load(const Bytes& pack_file) {
        file.assign(pack_file.size() / 4 + 1, 0);
        std::memcpy(file.data(), pack_file.data(), pack_file.size());
        memory.assign(pack_memory_bytes(file.data(), uint32_t(pack_file.size())) / 4 + 1, 0);
        return v->load(file.data(), uint32_t(pack_file.size()), memory.data(), uint32_t(memory.size() * 4));
    }
    void run() {
        for (int i = 0; i < 100000 && v->step(100000) != Activity::Idle; ++i) done();
        EXPECT_EQ(v->stats().refused, 0u) << "everything drawn was clipped into the rasterizer's range first";
    }
    int count(Event::Kind k) const {
        int n = 0;
        for (const Event& e : events) n += e.kind == k;
        return n;
    }
    const Event* last(Event::Kind k) const {
        for (auto it = events.rbegin(); it != events.rend(); ++it)
            if (it->kind == k) return &*it;
        return nullptr;
    }
    // The last whole frame's (FrameDone with full), or null.
    const Event* last_full_frame() const {
        for (auto it = events.rbegin(); it != events.rend(); ++it)
            if (it->kind == Event::Kind::FrameDone && it->frame.full) return &*it;
        return nullptr;
    }
};

// The screen box of one instance's faces (pixels), from the camera; face: one of them only.
// A face not tessellated (a solid's plane turned away waits: detail.cpp) by its edges' samples.
inline std::array<int, 4> box_of(const Core& core, uint32_t instance, uint16_t w, uint16_t h, uint32_t face = ~0u) {
    const module::Scene& scene = core.scene();
    const module::Transform t = core.camera().transform(scene, instance, w, h);
    int l = INT32_MAX, top = INT32_MAX, r = INT32_MIN, b = INT32_MIN;
    auto add = [&](const int32_t q[3]) {
        module::Projected p{};
        t.project(q, p);
        l = std::min(l, p.s.x / 16), r = std::max(r, p.s.x / 16), top = std::min(top, p.s.y / 16), b = std::max(b, p.s.y / 16);
    };
    for (uint32_t f = 0; f < 6; ++f) {
        if (face != ~0u && f != face) continue;
        const module::FaceInfo& F = scene.face(f);
        for (uint32_t k = 0; k < F.vertex_count; ++k) add(scene.vertices()[F.first_vertex + k].p);
        if (F.vertex_count) continue;
        const module::Block& block = scene.block_of_face(f);
        const pack::Face& record = block.pack.faces()[f - block.first_face];
        const pack::Loop& loop = block.pack.loops()[record.first_loop];
        for (uint32_t c = loop.first_coedge; c < loop.first_coedge + loop.coedge_count; ++c) {
            const uint32_t e = block.first_edge + block.pack.coedges()[c].edge();
            for (uint32_t k = 0; k < scene.samples().count[e]; ++k) add(scene.sample_q(scene.samples().first[e] + k));
        }
    }
    return {l, top, r, b};
}

} // namespace facet::test
