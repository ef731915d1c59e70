// facet-viewer-ref: runs the viewer's core (firmware/viewer/viewer.h) on the host, on a fake
// display of the board's size, through the same scripted session the QEMU runner plays, and
// writes every capture as NAME.f565. The QEMU tests compare the device's screenshots with
// these pixel for pixel: geometry and rendering are the same code, and the float arithmetic is
// bit-identical (-ffp-contract=off, no libm in geom/ or the viewer).
//
//   facet-viewer-ref --size WxH --pack MODEL.fpk --out DIR [--send ENTRY]...
//   ENTRY: 'keys TEXT' (C escapes \n \r \\) or 'mouse DX DY [left|right|middle]', played one
//   per idle moment, as tools/qemu/run.py does; the session ends when they run out.
#include "hal/fake.h"
#include "hal/print.h"
#include "geom/pack_file.h"
#include "viewer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

using namespace facet;

namespace {

struct Host {
    hal::fake::Display* display;
    std::string dir;
    int failures = 0;
};

Status capture(void* context, const char* name) {
    Host& h = *static_cast<Host*>(context);
    const hal::DisplayInfo d = h.display->info();
    const std::string path = h.dir + "/" + name + ".f565";
    if (!hal::fake::write_f565(path, h.display->front(), d.width, d.height)) {
        std::fprintf(stderr, "facet-viewer-ref: cannot write %s\n", path.c_str());
        ++h.failures;
        return Status::Io;
    }
    std::printf("@shot %s\n", name);
    return Status::Ok;
}

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

// One script entry as input events (what the board drivers produce for it).
bool events(const std::string& entry, std::vector<hal::InputEvent>& out) {
    using Kind = hal::InputEvent::Kind;
    if (entry.rfind("keys ", 0) == 0) {
        for (char c : unescape(entry.substr(5))) {
            hal::InputEvent e{};
            e.kind = Kind::Key;
            e.key = uint8_t(c);
            out.push_back(e);
        }
        return true;
    }
    int dx = 0, dy = 0;
    char button[16] = "left";
    if (std::sscanf(entry.c_str(), "mouse %d %d %15s", &dx, &dy, button) >= 2) {
        const uint8_t b = std::strcmp(button, "right") == 0 ? 2 : std::strcmp(button, "middle") == 0 ? 4 : 1;
        hal::InputEvent e{};
        e.kind = Kind::PointerDown;
        e.buttons = b;
        out.push_back(e);
        e.kind = Kind::PointerMove;
        e.dx = int16_t(dx);
        e.dy = int16_t(dy);
        out.push_back(e);
        e = {};
        e.kind = Kind::PointerUp;
        e.buttons = 0;
        out.push_back(e);
        return true;
    }
    return false;
}

} // namespace

int main(int argc, char** argv) {
    int w = 0, h = 0;
    std::string pack_path, out_dir;
    std::vector<std::string> script;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size" && i + 1 < argc && std::sscanf(argv[i + 1], "%dx%d", &w, &h) == 2) ++i;
        else if (a == "--pack" && i + 1 < argc) pack_path = argv[++i];
        else if (a == "--out" && i + 1 < argc) out_dir = argv[++i];
        else if (a == "--send" && i + 1 < argc) script.push_back(argv[++i]);
        else {
            std::fprintf(stderr, "usage: facet-viewer-ref --size WxH --pack MODEL.fpk --out DIR [--send ENTRY]...\n");
            return 2;
        }
    }
    if (w <= 0 || h <= 0 || w > 4096 || h > 4096 || pack_path.empty() || out_dir.empty()) {
        std::fprintf(stderr, "facet-viewer-ref: --size, --pack and --out are required\n");
        return 2;
    }
    std::ifstream in(pack_path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        std::fprintf(stderr, "facet-viewer-ref: cannot read %s\n", pack_path.c_str());
        return 1;
    }
    // The file at the start of a region as the device's (8-byte aligned), large enough for the
    // pack and its deflated file together.
    uint64_t capacity = bytes.size();
    if (geom::pack_file_kind(bytes.data(), uint32_t(bytes.size())) == geom::PackFileKind::Deflated && bytes.size() >= sizeof(pack::DeflatedHead)) {
        pack::DeflatedHead head;
        std::memcpy(&head, bytes.data(), sizeof head);
        capacity += std::min<uint64_t>(head.pack_bytes, pack::kMaxBytes);
    }
    std::vector<uint64_t> pack((capacity + 7) / 8);
    if (!bytes.empty()) std::memcpy(pack.data(), bytes.data(), bytes.size());

    hal::fake::Display display{uint16_t(w), uint16_t(h)};
    hal::fake::Console console;
    hal::fake::Clock clock;
    hal::fake::Input input;
    hal::Board board{"host", console, clock, display, input};
    std::vector<uint16_t> depth0(size_t(w) * h), depth1(size_t(w) * h);
    std::vector<hal::Rgb565> line(static_cast<size_t>(w));
    auto storage = std::make_unique<viewer::Storage>();
    viewer::Memory mem = storage->memory(depth0, depth1, line);
    Host host{&display, out_dir};
    viewer::Viewer v(board, mem, capture, &host);
    if (!ok(v.open(reinterpret_cast<uint8_t*>(pack.data()), uint32_t(capacity)))) {
        std::fputs(console.output.c_str(), stderr);
        return 1;
    }
    // The firmware's loop, with the script played at each idle moment.
    size_t next = 0;
    while (!v.quit()) {
        hal::InputEvent e;
        while (!v.quit() && input.poll(e)) v.handle(e);
        if (v.quit()) break;
        if (v.step()) continue;
        if (next == script.size()) break;
        std::vector<hal::InputEvent> evs;
        if (!events(script[next], evs)) {
            std::fprintf(stderr, "facet-viewer-ref: unknown script entry: %s\n", script[next].c_str());
            return 2;
        }
        ++next;
        for (const hal::InputEvent& x : evs) input.queue.push_back(x);
    }
    std::fputs(console.output.c_str(), stdout);
    if (display.rejected) {
        std::fprintf(stderr, "facet-viewer-ref: %llu spans out of range\n", (unsigned long long)display.rejected);
        return 1;
    }
    return host.failures ? 1 : 0;
}
