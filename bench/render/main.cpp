// facet-render-bench: facet's frames and a peer's (tgx) on the same mesh and camera, counted
// by the same instruction counter in one boot (./facet bench render, bench/render/render.py).
//
// The pack is loaded at the board's pack address and the peer's mesh blob (tgx_mesh.py: the
// same model tessellated by facet-mesh, as tgx meshes) half-way into the pack region. For each
// screen size, the module (its public API only) tessellates the model and draws it: the fitted
// view once every face is done ("full"), then three steps closer ("zoomed"); each view with its
// B-rep edges (display mode shaded with edges) and without (shaded). The peer draws the same
// view from the module's own camera (Viewer::camera()). The host types the level of detail at
// boot, a digit: how many times the viewer's Finer key is pressed first (0: the default).
//
//   regions    "frame": each piece of facet's frames (the host sums a frame's pieces up to its
//              '@bench_frame' line); "tgx": one peer frame, clear included, as facet's includes its
//              background
//   lines      @bench_frame pieces N triangles T pixels P full F done D total N
//              @bench_view NAME WIDTHxHEIGHT mode edges|shaded covered C     (after facet's frame)
//              @peer NAME WIDTHxHEIGHT triangles T covered C       (after the peer's frame)
//              @dump NAME FILE                                     (the pictures, F565)
#include "facet/viewer.h"
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "hal/report.h"
#include "tgx_side.h"
#include "views.h"

namespace {

using namespace facet;

constexpr uint16_t kMaxW = 640, kMaxH = 480;
constexpr uint32_t kMaxPixels = uint32_t(kMaxW) * kMaxH;
constexpr uint32_t kMeshOffset = board_config::kPackBytes / 2; // the peer's blob, in the pack region

alignas(64) __attribute__((section(".framebuffers"))) Rgb565 frame[kMaxPixels];
alignas(64) __attribute__((section(".framebuffers"))) uint16_t peer_frame[kMaxPixels];
alignas(64) __attribute__((section(".zbuffer"))) uint16_t depth[kMaxPixels];
alignas(64) __attribute__((section(".zbuffer"))) uint16_t peer_depth[kMaxPixels];
alignas(8) __attribute__((section(".arena"))) uint8_t workspace[FACET_WORKSPACE_BYTES_DEFAULT];
alignas(8) __attribute__((section(".pack_memory"))) uint8_t pack_memory[bench::kPackMemoryBytes]; // the inflated pack (the file stays)

struct Bench {
    hal::Console* con = nullptr;
    Viewer* viewer = nullptr;
    uint32_t pieces = 0; // frame pieces since the last full frame
    Event last_frame{};
} state;

void on_event(void*, const Event& e) {
    hal::Console& con = *state.con;
    switch (e.kind) {
    case Event::Kind::WorkBegin:
        if (e.work.what == Work::Frame) hal::measure_begin(con, "frame"), ++state.pieces;
        break;
    case Event::Kind::WorkEnd:
        if (e.work.what == Work::Frame) hal::measure_end(con, "frame");
        break;
    case Event::Kind::FrameDone:
        print(con, "@bench_frame pieces {} triangles {} pixels {} full {} done {} total {}\n", state.pieces, e.frame.triangles,
              e.frame.pixels, e.frame.full ? 1 : 0, e.frame.faces_done, e.frame.faces_total);
        state.pieces = 0;
        state.last_frame = e;
        break;
    case Event::Kind::FaceFailed: print(con, "bench: face {} failed: {}\n", e.failed.face, e.why); break;
    default: break;
    }
}

void flush(Viewer& viewer, void*, const Area&, const Rgb565*) { viewer.flush_done(); }

uint32_t covered(const uint16_t* z, uint32_t n, uint16_t empty) {
    uint32_t c = 0;
    for (uint32_t i = 0; i < n; ++i) c += z[i] != empty;
    return c;
}

bool dump(const char* name, const uint16_t* pixels, uint16_t w, uint16_t h) {
    hal::Capture* c = hal::board().capture;
    const Status s = c ? c->dump(name, reinterpret_cast<const Rgb565*>(pixels), w, h) : Status::Unsupported;
    if (!ok(s)) print(*state.con, "bench: picture {} not written: {}\n", name, s);
    return ok(s);
}

// facet's frame of the view (already drawn: the last one).
bool picture(const char* name, bool edges, uint16_t w, uint16_t h) {
    hal::Console& con = *state.con;
    if (!bench::whole_model_drawn(state.last_frame)) {
        print(con, "bench: no full frame of the finished model for {}\n", name);
        return false;
    }
    print(con, "@bench_view {} {}x{} mode {} covered {}\n", name, w, h, edges ? "edges" : "shaded", covered(depth, uint32_t(w) * h, 0xFFFF));
    char shot[48];
    format(shot, sizeof shot, "{}-{}x{}-facet{}", name, w, h, edges ? "" : "-shaded");
    return dump(shot, reinterpret_cast<const uint16_t*>(frame), w, h);
}

// The peer's frame of the same camera.
bool peer_view(const Viewer& v, const char* name, uint16_t w, uint16_t h, const bench::PeerMesh& peer) {
    hal::Console& con = *state.con;
    const uint32_t n = uint32_t(w) * h;
    char shot[48];
    const Viewer::CameraView c = v.camera();
    bench::PeerCamera pc{};
    for (int i = 0; i < 9; ++i) pc.rotation[i] = c.rotation[i];
    for (int i = 0; i < 3; ++i) pc.target_mm[i] = c.target_mm[i];
    pc.distance_mm = c.distance_mm, pc.focal_px = c.focal_px, pc.radius_mm = peer.radius_mm;
    hal::measure_begin(con, "tgx");
    bench::peer_draw(pc, w, h, peer_frame, peer_depth);
    hal::measure_end(con, "tgx");
    print(con, "@peer {} {}x{} triangles {} covered {}\n", name, w, h, peer.triangles, covered(peer_depth, n, 0));
    format(shot, sizeof shot, "{}-{}x{}-tgx", name, w, h);
    return dump(shot, peer_frame, w, h);
}

} // namespace

int facet_main(hal::Board& board) {
    hal::Console& con = board.console;
    state.con = &con;
    hal::report_board(board);
    auto* region = reinterpret_cast<const uint8_t*>(board_config::kPackAddress);
    bench::PeerMesh peer{};
    if (!bench::peer_load(region + kMeshOffset, board_config::kPackBytes - kMeshOffset, peer)) {
        print(con, "bench: no peer mesh blob at {} (render.py loads one there)\n", hex(board_config::kPackAddress + kMeshOffset));
        return 1;
    }
    if (pack_memory_bytes(region, kMeshOffset) > sizeof pack_memory) {
        print(con, "bench: the pack inflates to {} B, over the bench's {} B\n", pack_memory_bytes(region, kMeshOffset),
              uint32_t(sizeof pack_memory));
        return 1;
    }
    uint32_t finer = 0; // the level of detail, typed by the host
    for (bool got = false; !got;) {
        hal::InputEvent e;
        while (!got && board.input.poll(e)) {
            if (e.kind == hal::InputEvent::Kind::Key && e.key >= '0' && e.key <= '3') finer = e.key - '0', got = true;
        }
    }
    for (const bench::ViewSize s : bench::kViewSizes) {
        const uint16_t w = s.width, h = s.height;
        const Config cfg = bench::view_config(s, frame, depth, flush, on_event, nullptr);
        Result why;
        state.viewer = Viewer::create(cfg, workspace, sizeof workspace, &why);
        if (!state.viewer) {
            print(con, "bench: {} ({})\n", why, why.status);
            return 1;
        }
        Viewer& v = *state.viewer;
        if (Result r = v.load(region, kMeshOffset, pack_memory, sizeof pack_memory); !r.ok()) {
            print(con, "bench: no valid pack: {} ({})\n", r, r.status);
            return 1;
        }
        bench::prepare(v, finer);
        const Stats st = v.stats();
        print(con, "@bench_model faces {} failed {} triangles {} peer_triangles {} peer_meshes {} finer {}\n", st.faces, st.failed,
              st.triangles, peer.triangles, peer.meshes, finer);
        if (!bench::draw_views(
                v, [&](const char* name, bool edges) { return picture(name, edges, w, h); },
                [&](const char* name) { return peer_view(v, name, w, h, peer); })) {
            return 1;
        }
    }
    return 0;
}
