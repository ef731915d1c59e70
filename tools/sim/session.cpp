#include "session.h"

#include "hal/fake.h"
#include "core/format.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

namespace sim {
namespace {

std::string unescape(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '\\' || i + 1 == s.size()) {
            out += s[i];
            continue;
        }
        const char c = s[++i];
        out += c == 'n' ? '\n' : c == 'r' ? '\r' : c == 't' ? '\t' : c;
    }
    return out;
}

Input key_input(uint8_t c) {
    Input in{Input::Kind::Key};
    in.key = c;
    return in;
}
Input pointer(int16_t dx, int16_t dy, uint8_t buttons) {
    Input in{Input::Kind::Pointer};
    in.dx = dx, in.dy = dy, in.buttons = buttons;
    return in;
}
Input finger(uint8_t id, int x, int y, bool down) {
    Input in{Input::Kind::Touch};
    in.id = id, in.x = int16_t(x), in.y = int16_t(y), in.down = down;
    return in;
}

uint32_t now_us(void*) {
    using namespace std::chrono;
    return uint32_t(duration_cast<microseconds>(steady_clock::now().time_since_epoch()).count());
}

bool good_name(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
    return true;
}

} // namespace

bool parse_entry(const std::string& entry, std::vector<Input>& out) {
    if (entry.rfind("keys ", 0) == 0) {
        for (char c : unescape(entry.substr(5))) out.push_back(key_input(uint8_t(c)));
        return true;
    }
    int a = 0, b = 0, c = 0, d = 0;
    char button[16] = "left";
    if (std::sscanf(entry.c_str(), "mouse %d %d %15s", &a, &b, button) >= 2) {
        const uint8_t bit = std::strcmp(button, "right") == 0 ? 2 : std::strcmp(button, "middle") == 0 ? 4 : 1;
        out.push_back(pointer(0, 0, bit));
        out.push_back(pointer(int16_t(a), int16_t(b), bit));
        out.push_back(pointer(0, 0, 0));
        return true;
    }
    if (std::sscanf(entry.c_str(), "move %d %d", &a, &b) == 2) { // the pointer, no button held
        out.push_back(pointer(int16_t(a), int16_t(b), 0));
        return true;
    }
    if (entry == "click") {
        out.push_back(pointer(0, 0, 1));
        out.push_back(pointer(0, 0, 0));
        return true;
    }
    if (std::sscanf(entry.c_str(), "wheel %d", &a) == 1) {
        Input in{Input::Kind::Wheel};
        in.dy = int16_t(a);
        out.push_back(in);
        return true;
    }
    if (std::sscanf(entry.c_str(), "tap %d %d", &a, &b) == 2) {
        out.push_back(finger(0, a, b, true));
        out.push_back(finger(0, a, b, false));
        return true;
    }
    if (std::sscanf(entry.c_str(), "drag %d %d %d %d", &a, &b, &c, &d) == 4) {
        out.push_back(finger(0, a, b, true));
        for (int k = 1; k <= 4; ++k) out.push_back(finger(0, a + c * k / 4, b + d * k / 4, true));
        out.push_back(finger(0, a + c, b + d, false));
        return true;
    }
    if (std::sscanf(entry.c_str(), "pinch %d %d %d %d", &a, &b, &c, &d) == 4) {
        out.push_back(finger(0, a - c / 2, b, true));
        out.push_back(finger(1, a + c / 2, b, true));
        for (int k = 1; k <= 4; ++k) {
            const int half = (c + (d - c) * k / 4) / 2;
            out.push_back(finger(0, a - half, b, true));
            out.push_back(finger(1, a + half, b, true));
        }
        out.push_back(finger(0, a - d / 2, b, false));
        out.push_back(finger(1, a + d / 2, b, false));
        return true;
    }
    return false;
}

bool Session::open(const Options& o, std::string& error) {
    opt_ = o;
    const uint16_t w = o.width, h = o.height, lines = o.band_lines ? o.band_lines : o.height;
    for (int b = 0; b < 2; ++b) {
        buffers_[b].assign(size_t(w) * lines, 0);
        depth_[b].assign(size_t(w) * lines, 0);
    }
    screen_.assign(size_t(w) * h, 0);
    facet::Config cfg;
    cfg.display.width = w, cfg.display.height = h, cfg.display.band_lines = lines;
    cfg.display.buffers[0] = buffers_[0].data(), cfg.display.buffers[1] = buffers_[1].data();
    cfg.display.depth[0] = depth_[0].data();
    cfg.display.depth[1] = o.band_lines ? nullptr : depth_[1].data(); // bands share one band-sized depth buffer
    if (!o.band_lines) { // full frames: a faces layer, as the firmware has
        faces_.assign(size_t(w) * h, 0), faces_depth_.assign(size_t(w) * h, 0);
        cfg.display.faces = faces_.data(), cfg.display.faces_depth = faces_depth_.data();
    }
    cfg.display.mode = facet::Flush::Copy;
    cfg.display.flush = flush;
    cfg.display.user = this;
    cfg.on_event = event;
    cfg.event_user = this;
    cfg.now_us = o.clock ? now_us : nullptr;
    std::ifstream in(o.pack, std::ios::binary);
    if (!in) {
        error = "cannot read " + o.pack;
        return false;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() > (64u << 20)) {
        error = o.pack + ": larger than any pack (64 MiB)";
        return false;
    }
    file_.assign(bytes.size() / 8 + 1, 0);
    std::memcpy(file_.data(), bytes.data(), bytes.size());
    // The models: a pack, or a library's (each opened in turn in the same memory).
    const uint32_t file_bytes = uint32_t(bytes.size());
    const uint32_t models = facet::library_count(file_.data(), file_bytes);
    std::vector<facet::LibraryModel> files;
    for (uint32_t i = 0; i < models; ++i) {
        facet::LibraryModel m;
        if (facet::library_model(file_.data(), file_bytes, i, m).ok()) files.push_back(m);
    }
    if (models == 0) files.push_back({file_.data(), file_bytes, ""});
    // The workspace the largest model needs at the default detail with room to refine (a board
    // hands the module all its free RAM; the simulator what the model asks for, at least the default).
    char text[200];
    size_t ws_bytes = FACET_WORKSPACE_BYTES_DEFAULT;
    uint32_t need = 0;
    for (const facet::LibraryModel& m : files) {
        facet::ModelNeeds needs{};
        if (facet::model_needs(m.file, m.bytes, needs).ok() && needs.workspace_bytes > ws_bytes) ws_bytes = (needs.workspace_bytes + 7) / 8 * 8;
        need = std::max(need, facet::pack_memory_bytes(m.file, m.bytes));
    }
    if (opt_.ram_bytes) ws_bytes = opt_.ram_bytes / 8 * 8;
    workspace_storage_.assign(ws_bytes + 8, 0);
    void* ws = workspace_storage_.data() + ((8 - reinterpret_cast<uintptr_t>(workspace_storage_.data()) % 8) % 8);
    facet::Result why;
    viewer_ = facet::Viewer::create(cfg, ws, ws_bytes, &why);
    if (!viewer_) {
        facet::describe(why, text, sizeof text);
        error = std::string("the viewer: ") + text;
        return false;
    }
    if (opt_.ram_bytes) need = 0;
    memory_.assign(need ? need / 4 + 1 : 0, 0);
    void* const memory = need ? memory_.data() : nullptr;
    facet::Result r;
    if (models == 0) {
        r = viewer_->load(file_.data(), file_bytes, memory, uint32_t(memory_.size() * 4));
    } else if ((r = viewer_->set_library(file_.data(), file_bytes, memory, uint32_t(memory_.size() * 4))).ok()) {
        for (uint32_t i = 0; i < models && !(r = viewer_->open_model(i)).ok(); ++i) {} // the first that opens (key b: the others)
    }
    if (!r.ok()) {
        facet::describe(r, text, sizeof text);
        error = o.pack + ": " + text;
        return false;
    }
    return true;
}

void Session::flush(facet::Viewer& viewer, void* self, const facet::Area& a, const facet::Rgb565* pixels) {
    Session& s = *static_cast<Session*>(self);
    for (uint16_t y = 0; y < a.height; ++y)
        std::memcpy(&s.screen_[size_t(a.y + y) * s.opt_.width + a.x], pixels + size_t(y) * a.width, size_t(a.width) * 2);
    if (s.on_flush) s.on_flush(s.flush_user, a);
    viewer.flush_done(); // copied out
}

bool Session::capture(const std::string& name) {
    const std::string path = opt_.out + "/" + name + ".f565";
    if (!facet::hal::fake::write_f565(path, screen_, opt_.width, opt_.height)) {
        std::fprintf(stderr, "facet-sim: cannot write %s\n", path.c_str());
        ++failures_;
        return false;
    }
    if (!opt_.quiet) std::printf("@shot %s\n", name.c_str());
    return true;
}

// The module's events as the boards' firmware prints them (facet/records.h), and its screenshots.
// Quiet: none; verbose: every record; else all but those of each frame and view change.
void Session::event(void* self, const facet::Event& e) {
    using Kind = facet::Event::Kind;
    Session& s = *static_cast<Session*>(self);
    const bool chatty = e.kind == Kind::FrameDone || e.kind == Kind::ViewChanged || e.kind == Kind::Progress;
    if (!s.opt_.quiet && (s.opt_.verbose || !chatty)) s.record(facet::event_record(e, s.record_, sizeof s.record_));
    switch (e.kind) {
    case Kind::PassFailed: {
        char text[facet::kRecordBytes];
        facet::describe(e.why, text, sizeof text);
        std::fprintf(stderr, "facet-sim: the edges at this level of detail: %s\n", text);
        break;
    }
    case Kind::FrameDone: {
        const auto& f = e.frame;
        if (f.pass != 0 || f.boxes) break; // (the parts' boxes while the edges are sampled: no screenshot)
        if (!s.wireframe_ && f.faces_done == 0) s.wireframe_ = true, s.capture("wireframe");
        if (!s.half_ && f.faces_done > 0 && 2 * f.faces_done >= f.faces_total) s.half_ = true, s.capture("half");
        if (!s.done_ && f.full && f.faces_done == f.faces_total) s.done_ = true, s.capture("done");
        break;
    }
    default: break;
    }
}

void Session::record(uint32_t length) {
    if (length == 0) return;
    if (length >= sizeof record_) {
        std::fprintf(stderr, "facet-sim: a record of %u bytes was cut to %zu\n", length, sizeof record_ - 1);
        length = uint32_t(sizeof record_ - 1);
    }
    std::fwrite(record_, 1, length, stdout);
}

void Session::command(const std::string& text) {
    if (text.rfind("shot ", 0) == 0) {
        const std::string name = text.substr(5);
        if (!good_name(name)) {
            std::fprintf(stderr, "facet-sim: a screenshot's name is letters, digits, - and _ only: '%s'\n", name.c_str());
            return;
        }
        if (!shot_.empty()) capture(shot_);
        shot_ = name; // taken once the viewer has drawn everything before it (idle)
        return;
    }
    std::fprintf(stderr, "facet-sim: unknown command '%s'\n", text.c_str());
}

void Session::key(uint8_t c) {
    if (in_line_) {
        if (c == '\n' || c == '\r') {
            in_line_ = false;
            command(line_);
        } else if (c < 0x20 || c >= 0x7F) {
            in_line_ = false;
        } else {
            line_ += char(c);
        }
        return;
    }
    if (c == '!') {
        in_line_ = true;
        line_.clear();
        return;
    }
    if (c == 'q') {
        quit_ = true;
        return;
    }
    // Every other key is the module's (its one table); a help key also lists them here.
    const facet::KeyBindings keys = facet::key_bindings();
    for (uint32_t i = 0; i < keys.count; ++i) {
        if (keys.table[i].key != c || keys.table[i].action != facet::Action::Help) continue;
        for (uint32_t j = 0; j < keys.count; ++j) {
            if (keys.table[j].key < 0x80) std::printf("  %c  %s\n", char(keys.table[j].key), keys.table[j].help);
        }
        std::printf("  arrows turn and tilt, PageUp/PageDown zoom, Home fits; left drag orbits, right drag pans,\n"
                    "  wheel zooms, a click picks; two fingers pinch and pan; q or Esc quits\n");
        break;
    }
    viewer_->key(c);
}

void Session::apply(const Input& in) {
    switch (in.kind) {
    case Input::Kind::Key: key(in.key); break;
    case Input::Kind::Pointer: viewer_->pointer(in.dx, in.dy, in.buttons); break;
    case Input::Kind::Wheel: viewer_->wheel(in.dy); break;
    case Input::Kind::Touch: viewer_->touch(in.id, in.x, in.y, in.down); break;
    }
}

facet::Activity Session::step(uint32_t budget_us) {
    const facet::Activity a = viewer_->step(budget_us);
    if (a == facet::Activity::Idle && !shot_.empty()) {
        capture(shot_);
        shot_.clear();
    }
    return a;
}

} // namespace sim
