// facet-needs-test: facet::model_needs() keeps its word on the board itself, with the board's
// compiler, float and libm (the host's facet-needs-check does the same on the host). The pack at
// the board's pack address is loaded twice, each time into a workspace of exactly what
// model_needs() says, read on the board from the pack's head, with the pack memory taken from
// the workspace's end as facet-viewer does:
//   * least_workspace_bytes: every part shows (none left a box), no level, model or face
//     fails, every face is meshed (none left to its edges for want of room);
//   * workspace_bytes (room to refine): the same, and the first level is the default tolerance.
// Every face is asked for at its level, however small on the screen (screen_error_px 0: the
// most a level takes). One line each, then "@needs kept" or "@needs broken"; exit 0 or 1.
#include "facet/viewer.h"
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"

namespace {

using namespace facet;

constexpr uint16_t kW = 160, kH = 120;
alignas(64) __attribute__((section(".arena"))) Rgb565 buffer[uint32_t(kW) * kH]; // (the arena: the board's large RAM)
alignas(64) __attribute__((section(".arena"))) uint16_t depth[uint32_t(kW) * kH];

struct Failure {
    Event::Kind kind{};
    Result why;
    bool seen = false;
};

void flush(Viewer&, void*, const Area&, const Rgb565*) {}

void on_event(void* user, const Event& e) {
    auto& f = *static_cast<Failure*>(user);
    if (f.seen) return;
    if (e.kind == Event::Kind::PassFailed || e.kind == Event::Kind::ModelFailed || e.kind == Event::Kind::FaceFailed) {
        f.kind = e.kind, f.why = e.why, f.seen = true;
    }
}

const char* failure_name(Event::Kind k) {
    return k == Event::Kind::PassFailed ? "a level failed" : k == Event::Kind::FaceFailed ? "a face failed" : "the model failed";
}

// One load into `bytes` of workspace at `at`; true when the model kept to what was promised.
bool run_at(hal::Console& con, const char* what, uint8_t* at, size_t bytes, const void* file, uint32_t file_bytes, bool refined) {
    Failure failure;
    Config cfg;
    cfg.display.width = kW, cfg.display.height = kH, cfg.display.band_lines = kH;
    cfg.display.buffers[0] = buffer, cfg.display.depth[0] = depth;
    cfg.display.flush = flush;
    cfg.interface = Interface::Off;
    cfg.screen_error_px = 0;
    cfg.on_event = on_event;
    cfg.event_user = &failure;
    Result why;
    Viewer* v = Viewer::create(cfg, at, bytes, &why);
    if (!v) {
        print(con, "@needs {} {} bytes: create: {}\n", what, bytes, why);
        return false;
    }
    if (const Result r = v->load(file, file_bytes); !r.ok()) {
        print(con, "@needs {} {} bytes: load: {}\n", what, bytes, r);
        return false;
    }
    for (uint32_t steps = 0; steps < 10'000'000; ++steps) {
        v->flush_done();
        if (v->step(100'000) == Activity::Idle) break;
    }
    const Stats s = v->stats();
    const ModelInfo m = v->model();
    const uint32_t unmeshed = s.faces - s.done - s.deferred;
    const bool default_level = v->detail() == 1.0f;
    print(con, "@needs {} {} bytes: faces {} done {} deferred {} failed {} boxed {} of {} parts, first level {} times the default: ",
          what, bytes, s.faces, s.done, s.deferred, s.failed, m.boxed_parts, m.parts, fixed(int64_t(v->detail() * 100.0f + 0.5f), 2));
    if (failure.seen) print(con, "{}: {}\n", failure_name(failure.kind), failure.why);
    else if (m.boxed_parts) print(con, "parts left out as boxes\n");
    else if (s.done == 0) print(con, "no face drawn\n");
    else if (s.done + s.deferred < s.faces) print(con, "{} faces not meshed\n", unmeshed);
    else if (refined && !default_level) print(con, "not the default level\n");
    else {
        print(con, "{}\n", refined ? "every face at the default detail" : "every part shows");
        return true;
    }
    return false;
}

} // namespace

int facet_main(hal::Board& board) {
    hal::Console& con = board.console;
    const void* file = reinterpret_cast<const void*>(board_config::kPackAddress);
    const uint32_t file_bytes = board_config::kPackBytes;
    ModelNeeds n;
    if (const Result r = model_needs(file, file_bytes, n); !r.ok()) {
        print(con, "@needs broken: model_needs refused the pack: {}\n", r);
        return 1;
    }
    print(con, "@needs model: faces {} edges {} parts {}, least {} bytes, room to refine {} bytes, pack memory {} bytes\n", n.faces,
          n.edges, n.parts, n.least_workspace_bytes, n.workspace_bytes, n.pack_memory_bytes);
    // The workspaces start at the free RAM, and end before the pack region where QEMU loads the
    // pack into the free RAM (read in place: this test copies nothing).
    const hal::FreeRam ram = hal::free_ram();
    const uintptr_t start = uintptr_t(ram.start), pack = board_config::kPackAddress;
    const size_t room = pack >= start && pack < start + ram.bytes ? pack - start : ram.bytes;
    const size_t memory = (size_t(n.pack_memory_bytes) + 7) / 8 * 8;
    bool kept = true;
    const struct {
        const char* what;
        size_t bytes;
        bool refined;
    } runs[] = {{"least", n.least_workspace_bytes + memory, false}, {"room", n.workspace_bytes + memory, true}};
    for (const auto& run : runs) {
        if (run.bytes > room) {
            print(con, "@needs {} {} bytes: more than the {} bytes before the pack region\n", run.what, run.bytes, room);
            kept = false;
            continue;
        }
        kept = run_at(con, run.what, ram.start, run.bytes, file, file_bytes, run.refined) && kept;
    }
    print(con, "@needs {}\n", kept ? "kept" : "broken");
    return kept ? 0 : 1;
}
