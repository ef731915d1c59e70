// facet-viewer: the module (facet/viewer.h) on a board. The pack file comes from the board's
// pack address (QEMU: run.py --load FILE@ADDR; the EVKB: flashed there, ./facet flash), or a
// library of several models (./facet flash A B, ./facet run A B: the first opens, key b lists
// them); the viewer shows its wireframe, fills in the faces, and then follows the keys on the UART, the
// mouse (versatilepb's PL050) and the touch panel (the EVKB) until 'q'.
//
// This program is one user of the module's events: it turns them into the UART test protocol
// the host runner and the tests read (and a person with a board watches), and it owns the
// buffers (two full frames shown by the display's scan-out, a depth buffer each) and hands the
// module all the free RAM as its workspace (the model's arrays; the pack decoded at its end).
//
//   from the firmware   @library, @model, @pass, @lod, @progress, @face N failed, @tessellation /
//                       @retessellation, @frame, @view, @pick, @budget, @memory, @stats
//                       (facet/records.h); "@begin NAME" /
//                       "@end NAME" around each piece of work (instruction-count regions:
//                       unpack, edges, face, frame, update; step with !budget); @shot (capture);
//                       @idle when the viewer has nothing left to do
//   from the host       keys; ENQ (0x05) after each scripted entry (then "@idle" again once
//                       handled); "!shot NAME" + Enter: a screenshot (once the viewer has
//                       drawn all the input before it); "!budget US" + Enter: step
//                       budget, each step an instruction-count region; ESC leaves a command
#include "card_storage.h"
#include "facet/records.h"
#include "facet/viewer.h"
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "hal/report.h"

#include <algorithm>

namespace {

using namespace facet;

constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
constexpr uint32_t kPixels = uint32_t(kW) * kH;
constexpr uint8_t kEnq = 0x05, kEsc = 0x1B;

alignas(64) __attribute__((section(".framebuffers"))) Rgb565 frames[2][kPixels];
alignas(64) __attribute__((section(".zbuffer"))) uint16_t depth[2][kPixels];

struct Session {
    hal::Board* board = nullptr;
    Viewer* viewer = nullptr;
    bool prompt = true, quit = false;
    bool wireframe_shot = false, half_shot = false, done_shot = false;
    uint32_t step_us = 8000;
    bool step_regions = false;
    char line[48] = {};
    uint32_t line_len = 0;
    bool in_line = false;
    char shot[48] = {};  // a screenshot asked for: taken once the viewer has caught up (idle)
    bool flush_pending = false;
    bool measured = false; // a pick: print the measurement panel's lines once input is handled
} session;

const char* work_name(Work w) {
    switch (w) {
    case Work::Unpack: return "unpack";
    case Work::Sampling: return "edges";
    case Work::Face: return "face";
    case Work::Frame: return "frame";
    case Work::Update: return "update";
    case Work::Fit: return "fit";
    case Work::Overlay: return "overlay";
    }
    return "work";
}

// A screenshot, on a board with a host to take it (its Capture; QEMU's). The first pass's
// shots are taken from on_event, inside a step: with step regions on, the wait for the host
// (as long as the host takes, not the module's work) is a region of its own, "shot", nested in
// the step, which tests/qemu/step_budget_test.py takes out of the step's count.
void capture(const char* name) {
    hal::Capture* c = session.board->capture;
    if (!c) {
        print(session.board->console, "viewer: no screenshot '{}' on this board (it has no capture)\n", name);
        return;
    }
    if (session.step_regions) hal::measure_begin(session.board->console, "shot");
    const Status s = c->shot(name);
    if (session.step_regions) hal::measure_end(session.board->console, "shot");
    if (!ok(s)) print(session.board->console, "viewer: capture {} failed ({})\n", name, s);
}

// A record of the protocol (facet/records.h writes each) on the console.
void write_record(hal::Console& con, uint32_t length, const char* line) {
    if (length == 0) return; // (an event without a record)
    if (length >= kRecordBytes) print(con, "viewer: a record of {} bytes was cut to {}\n", length, kRecordBytes - 1);
    con.write(line, std::min(length, kRecordBytes - 1));
}

void record(hal::Console& con, const Event& e) {
    char line[kRecordBytes];
    write_record(con, event_record(e, line, sizeof line), line);
}

// Every kind has its case (the same dispatch for the work regions' marks, which count what is
// between them: nothing of this handler's is done before a mark).
void on_event(void*, const Event& e) {
    hal::Console& con = session.board->console;
    switch (e.kind) {
    // Pieces of work as instruction-count regions (with !budget, whole steps instead).
    case Event::Kind::WorkBegin:
        if (!session.step_regions) hal::measure_begin(con, work_name(e.work.what));
        break;
    case Event::Kind::WorkEnd:
        if (!session.step_regions) hal::measure_end(con, work_name(e.work.what));
        break;
    case Event::Kind::Loaded:
        record(con, e);
        if (e.loaded.boxed_parts) {
            print(con, "viewer: the model is larger than the memory: {} parts ({} faces) left out, drawn as their proxies (boxes without)\n",
                  e.loaded.boxed_parts, e.loaded.boxed_faces);
        }
        break;
    case Event::Kind::FrameDone: {
        record(con, e);
        const auto& f = e.frame;
        // The screenshots of the first pass: the wireframe, half the faces, all of them.
        if (f.pass != 0 || f.boxes) break; // (the parts' boxes while the edges are sampled: no screenshot)
        if (!session.wireframe_shot && f.faces_done == 0) session.wireframe_shot = true, capture("wireframe");
        if (!session.half_shot && f.faces_done > 0 && 2 * f.faces_done >= f.faces_total) session.half_shot = true, capture("half");
        if (!session.done_shot && f.full && f.faces_done == f.faces_total) session.done_shot = true, capture("done");
        break;
    }
    case Event::Kind::Picked:
        record(con, e);
        if (e.pick.hit) session.measured = true; // its exact values once the event is handled (the panel is set after it)
        break;
    case Event::Kind::Pass:
    case Event::Kind::PassFailed:
    case Event::Kind::ModelFailed:
    case Event::Kind::Sampled:
    case Event::Kind::Progress:
    case Event::Kind::FaceFailed:
    case Event::Kind::Tessellated:
    case Event::Kind::ViewChanged:
    case Event::Kind::BudgetExceeded: record(con, e); break;
    }
}

// Scan-out: the display shows the finished frame from its next refresh on. A controller that
// switches at vertical blank (the EVKB's eLCDIF) is busy until then: flush_done() waits for it
// (the main loop), so the viewer never draws into the frame still on the glass. QEMU's
// displays switch at once.
void flush(Viewer& viewer, void*, const Area&, const Rgb565* pixels) {
    if (Status s = session.board->display.show(const_cast<Rgb565*>(pixels)); !ok(s)) {
        print(session.board->console, "viewer: the display refused a frame ({})\n", s);
    }
    session.flush_pending = true;
    if (!session.board->display.busy()) session.flush_pending = false, viewer.flush_done();
}

// Microseconds from the board's clock, without a 64-bit division per call (a library call
// of over a hundred instructions on these cores): the ticks since the last call, times
// 1,000,000 / ticks_per_second reduced to num / den (5 / 3 for QEMU versatilepb's 600,000
// target ticks a second, 1 / 15 for the mps2's, 1 / 1 for the EVKB's GPT), the remainder
// carried over.
uint32_t now_us(void*) {
    static uint64_t last = 0;
    static uint32_t us = 0, rest = 0, num = 0, den = 0;
    hal::Clock& c = session.board->clock;
    if (!den) {
        uint32_t a = 1'000'000, b = c.ticks_per_second();
        while (b) { const uint32_t r = a % b; a = b, b = r; } // a = gcd
        num = 1'000'000 / a, den = c.ticks_per_second() / a;
    }
    const uint64_t t = c.ticks();
    const uint64_t x = (t - last) * num + rest;
    last = t;
    if (den == 1) return us += uint32_t(x), us;
    if (x >> 32) { // a long pause between calls
        us += uint32_t(x / den), rest = uint32_t(x % den);
    } else {
        us += uint32_t(x) / den, rest = uint32_t(x) % den;
    }
    return us;
}

void help(hal::Console& con) {
    print(con, "keys:");
    const KeyBindings keys = key_bindings();
    for (uint32_t i = 0; i < keys.count; ++i) {
        const char key[2] = {char(keys.table[i].key), 0};
        if (keys.table[i].key < 0x80) print(con, " {}", key);
    }
    print(con, " (turn, tilt, zoom, pan, fit, coarser/finer detail; h or ? this help), q quit;\n"
               "      !shot NAME<enter> takes a screenshot; mouse: left drag turns, right drag pans, middle drag zooms\n");
}

// A screenshot's name: letters, digits, '-' and '_' only (the host makes a file of it).
bool good_name(const char* s) {
    if (!*s) return false;
    for (; *s; ++s) {
        const char c = *s;
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
    }
    return true;
}

void command(const char* text) {
    hal::Console& con = session.board->console;
    auto starts = [&](const char* p) {
        uint32_t i = 0;
        for (; p[i]; ++i)
            if (text[i] != p[i]) return false;
        return true;
    };
    if (starts("shot ")) {
        if (!good_name(text + 5)) {
            print(con, "viewer: a screenshot's name is letters, digits, - and _ only: '{}'\n", text + 5);
            return;
        }
        if (session.shot[0]) capture(session.shot); // an earlier one, before this one's input
        uint32_t i = 0;
        for (const char* p = text + 5; *p && i + 1 < sizeof session.shot; ++p) session.shot[i++] = *p;
        session.shot[i] = 0;
        return;
    }
    if (starts("budget ")) {
        uint32_t us = 0;
        for (const char* p = text + 7; *p >= '0' && *p <= '9'; ++p) us = us * 10 + uint32_t(*p - '0');
        session.step_us = us;
        session.step_regions = true;
        print(con, "@step_budget_us {}\n", us);
        return;
    }
    print(con, "viewer: unknown command '{}'\n", text);
}

// Whether `text` (n bytes) can still become a command: a prefix of a command's word, or the
// word and its space followed by anything.
bool command_prefix(const char* text, uint32_t n) {
    static constexpr const char* kWords[] = {"shot ", "budget "};
    for (const char* word : kWords) {
        uint32_t i = 0;
        while (i < n && word[i] && text[i] == word[i]) ++i;
        if (i == n || !word[i]) return true;
    }
    return false;
}

// A byte from the UART: the protocol's own bytes and commands, or a key for the viewer.
void key(uint8_t k) {
    Session& s = session;
    if (s.in_line) {
        hal::Console& con = s.board->console;
        if (k == '\n' || k == '\r') {
            s.line[s.line_len] = 0;
            s.in_line = false;
            command(s.line);
            return;
        }
        if (k == kEsc || k == kEnq || k < 0x20 || k >= 0x7F) {
            s.in_line = false; // not command text: the command is dropped
            print(con, "viewer: command dropped\n");
            if (k == kEnq) s.prompt = true;
            return;
        }
        if (s.line_len + 1 >= sizeof s.line) {
            s.in_line = false;
            print(con, "viewer: command dropped: longer than {} bytes\n", uint32_t(sizeof s.line - 1));
            return;
        }
        s.line[s.line_len++] = char(k);
        if (command_prefix(s.line, s.line_len)) return;
        // No command starts so: '!' was a key press, and so is this byte (a stream of keys
        // with no newline never stays stuck in command mode).
        s.in_line = false;
        s.line[s.line_len] = 0;
        print(con, "viewer: '!{}' is not a command (shot, budget): '!' and '{}' are keys\n", s.line, char(k));
    }
    switch (k) {
    case kEnq: s.prompt = true; return;
    case '!': s.in_line = true, s.line_len = 0; return;
    case 'q': s.quit = true; return; // the firmware's own key; every other is the module's table's
    case '\r': case '\n': case ' ': return;
    default: break;
    }
    const KeyBindings keys = key_bindings();
    for (uint32_t i = 0; i < keys.count; ++i) {
        if (keys.table[i].key == k) {
            if (keys.table[i].action == Action::Help) help(s.board->console); // on the console too
            s.viewer->key(k);
            return;
        }
    }
    print(s.board->console, "viewer: unknown key {} (h for help)\n", uint32_t(k));
}

// The free RAM less a library lying in it (a QEMU board's runner loads it into RAM): the larger
// of the two sides, 8-byte aligned. (On a board whose pack region is flash it lies elsewhere.)
hal::FreeRam around_library(hal::FreeRam ram, const uint8_t* library, uint32_t models) {
    const uint8_t *start = library, *end = library;
    for (uint32_t i = 0; i < models; ++i) {
        LibraryModel m;
        if (library_model(library, board_config::kPackBytes, i, m).ok()) end = std::max(end, static_cast<const uint8_t*>(m.file) + m.bytes);
    }
    uint8_t* const ram_end = ram.start + ram.bytes;
    if (end <= ram.start || start >= ram_end) return ram;
    const size_t below = start > ram.start ? size_t(start - ram.start) : 0;
    uint8_t* const after = reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(end) + 7) & ~uintptr_t(7));
    const size_t above = after < ram_end ? size_t(ram_end - after) : 0;
    return below >= above ? hal::FreeRam{ram.start, below & ~size_t(7)} : hal::FreeRam{after, above};
}

// The faces layer (Display::faces: a frame at rest copies the view's faces and draws their
// edges over them), from the start of the free RAM when it is a quarter of it or less: its
// colour, then its depth. Reported as a RAM region of its own ("@ram faces").
hal::FreeRam take_faces_layer(hal::Console& con, hal::FreeRam ram, Display& d) {
    constexpr size_t kBytes = size_t(kPixels) * (sizeof(Rgb565) + sizeof(uint16_t));
    uint8_t* const at = reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(ram.start) + 63) & ~uintptr_t(63));
    const size_t used = size_t(at - ram.start) + kBytes;
    if (4 * used > ram.bytes) return ram;
    d.faces = reinterpret_cast<Rgb565*>(at);
    d.faces_depth = reinterpret_cast<uint16_t*>(at + size_t(kPixels) * sizeof(Rgb565));
    print(con, "@ram faces {} {}\n", hex(reinterpret_cast<uintptr_t>(at)), uint32_t(kBytes));
    return {ram.start + used, (ram.bytes - used) & ~size_t(7)};
}

// The card's root folder in the chooser and its first model that opens (each listed on the
// console: "@card N name bytes faces"); false when there is no card or nothing on it opens.
bool open_card(firmware::CardStorage& card, hal::Card& slot, Viewer& v, Result& opened) {
    hal::Console& con = session.board->console;
    if (!slot.present()) return false;
    if (Result r = card.mount(slot); !r.ok()) {
        print(con, "viewer: the card cannot be read: {} ({})\n", r, r.status);
        return false;
    }
    if (Result r = v.set_storage(card.storage(), "/"); !r.ok()) {
        print(con, "viewer: the card's folder cannot be listed: {} ({})\n", r, r.status);
        return false;
    }
    const uint32_t n = v.model_count();
    print(con, "viewer: a card with {} models (key b lists them)\n", n);
    for (uint32_t i = 0; i < n; ++i) {
        Viewer::ListedModel m;
        if (v.listed_model(i, m).ok()) print(con, "@card {} bytes {} faces {} {}\n", i + 1, m.bytes, m.faces == kNone ? 0 : m.faces, m.name);
    }
    for (uint32_t i = 0; i < n; ++i) {
        opened = v.open_model(i);
        if (opened.ok()) return true;
    }
    return n > 0; // (said: no model of the card opens)
}

// The pack region's pack, or its library's first model that opens.
Result open_region(Viewer& v, const uint8_t* region, uint32_t models) {
    hal::Console& con = session.board->console;
    if (models > 0) {
        print(con, "viewer: a library of {} models (key b lists them)\n", models);
        for (uint32_t i = 0; i < models; ++i) {
            LibraryModel m;
            if (library_model(region, board_config::kPackBytes, i, m).ok()) print(con, "@library {} bytes {} {}\n", i + 1, m.bytes, m.name); // (the name last: it may hold spaces)
        }
    }
    // A library opens its first model that opens (the others' failures said as they fail).
    Result opened = models > 0 ? v.set_library(region, board_config::kPackBytes) : v.load(region, board_config::kPackBytes);
    for (uint32_t i = 0; models > 0 && opened.ok() && i < models; ++i) {
        if (v.open_model(i).ok()) break;
        if (i + 1 == models) opened = Result::fail(Status::Corrupt, "no model of the library opens");
    }
    return opened;
}

} // namespace

int facet_main(hal::Board& board) {
    hal::Console& con = board.console;
    session.board = &board;
    hal::report_board(board);

    Config cfg;
    cfg.display.width = kW, cfg.display.height = kH, cfg.display.band_lines = kH;
    cfg.display.buffers[0] = frames[0], cfg.display.buffers[1] = frames[1];
    cfg.display.depth[0] = depth[0], cfg.display.depth[1] = depth[1];
    cfg.display.mode = Flush::Scanout;
    cfg.display.flush = flush;
    cfg.on_event = on_event;
    cfg.now_us = now_us;
    Result why;
    // The workspace: all the RAM nothing else uses. The module plans the model's arrays in it
    // at load, and decodes the pack at its end (a pack QEMU loaded into it, where it lies). A
    // library (several models) in RAM stays whole: the workspace is the larger side of it.
    auto* region = reinterpret_cast<uint8_t*>(board_config::kPackAddress);
    const uint32_t models = library_count(region, board_config::kPackBytes);
    hal::FreeRam ram = hal::free_ram();
    if (models > 0) ram = around_library(ram, region, models);
    ram = take_faces_layer(con, ram, cfg.display);
    session.viewer = Viewer::create(cfg, ram.start, ram.bytes, &why);
    if (!session.viewer) {
        print(con, "viewer: {} ({})\n", why, why.status);
        return 1;
    }
    Viewer& v = *session.viewer;
    // A memory card with models comes first (QEMU: ./facet run --card; the EVKB's microSD): its
    // root folder's packs in the chooser; else the pack region's pack or library.
    static firmware::CardStorage card;
    Result opened = Result::fail(Status::NotFound, "no model on the card");
    const bool from_card = board.card && open_card(card, *board.card, v, opened);
    if (!from_card) opened = open_region(v, region, models);
    if (Result r = opened; !r.ok()) {
        char line[kRecordBytes];
        write_record(con, load_failed_record(r, line, sizeof line), line);
        print(con, "viewer: no valid pack: {} ({})\n", r, r.status);
        const bool blank = (region[0] == 0 && region[1] == 0 && region[2] == 0 && region[3] == 0) ||
                           (region[0] == 0xFF && region[1] == 0xFF && region[2] == 0xFF && region[3] == 0xFF);
        if (blank && !from_card) {
            print(con, "viewer: nothing was loaded at {} ({})\n", hex(board_config::kPackAddress),
                  board_config::kPackWritable ? "run.py --load MODEL.fpk@ADDRESS" : "./facet flash MODEL.step writes one there");
        }
        return 1;
    }
    help(con);
    while (!session.quit) {
        hal::InputEvent e;
        while (!session.quit && board.input.poll(e)) {
            switch (e.kind) {
            case hal::InputEvent::Kind::Key: key(e.key); break;
            case hal::InputEvent::Kind::PointerDown:
            case hal::InputEvent::Kind::PointerUp: v.pointer(0, 0, e.buttons); break;
            case hal::InputEvent::Kind::PointerMove: v.pointer(e.dx, e.dy, e.buttons); break;
            case hal::InputEvent::Kind::Touch: v.touch(e.finger, e.x, e.y, e.down); break;
            }
        }
        if (session.flush_pending && !board.display.busy()) session.flush_pending = false, v.flush_done();
        if (Result why; card.poll(v, why)) { // a card pulled or put back
            print(con, "@card_changed {}\n", card.present() ? "inserted" : "removed");
            if (!why.ok()) print(con, "viewer: the card: {} ({})\n", why, why.status);
        }
        if (session.measured) { // the picked faces' exact values, for the host (report.json)
            session.measured = false;
            const char* lines[3];
            const uint32_t n = v.measurement(lines);
            for (uint32_t i = 0; i < n; ++i) print(con, "@measure {}\n", lines[i]);
        }
        if (session.quit) break;
        if (session.step_regions) hal::measure_begin(con, "step");
        const Activity a = v.step(session.step_us);
        if (session.step_regions) hal::measure_end(con, "step");
        if (a != Activity::Idle) continue;
        if (session.shot[0]) { // the picture of everything before the command
            capture(session.shot);
            session.shot[0] = 0;
        }
        if (session.prompt) {
            print(con, "@idle\n");
            session.prompt = false;
        }
    }
    const Stats t = v.stats();
    // What this model needed: the pack (inflated, and the file it came from, both held while
    // inflating) and the workspace at its peak (the host adds the display buffers, code and
    // stack high-water: the model's peak RAM).
    char line[kRecordBytes];
    write_record(con, memory_record(t, line, sizeof line), line);
    if (t.refused) print(con, "viewer: the rasterizer refused {} triangles or lines\n", t.refused);
    write_record(con, stats_record(t, line, sizeof line), line);
    print(con, "viewer: {} faces ({} failed, {} not shown by the view yet), {} triangles; bye\n", t.faces, t.failed, t.deferred, t.triangles);
    return 0;
}
