#pragma once
// facet-sim's session: the module with a board's buffers (full frames shown by scan-out, or
// bands copied into a panel), what the screen shows, the test protocol's screenshots, and
// the entries of a scripted session. The headless and the SDL front end share it.
#include "facet/records.h"
#include "facet/viewer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sim {

// One step of a scripted session (tools/qemu/run.py's entries, and touch ones):
//   keys TEXT            text (C escapes \n \r \\); "!shot NAME\n" takes a screenshot
//   mouse DX DY [BUTTON] a drag with the button held (left, right, middle)
//   move DX DY           the pointer moved, no button held
//   click                a left click where the pointer is
//   wheel N              N wheel clicks (> 0: zoom in)
//   tap X Y              a finger down and up at (X, Y)
//   drag X Y DX DY       one finger from (X, Y) moved by (DX, DY)
//   pinch X Y D0 D1      two fingers around (X, Y), D0 apart, moved to D1 apart
struct Input {
    enum class Kind : uint8_t { Key, Pointer, Wheel, Touch } kind;
    uint8_t key = 0;
    int16_t dx = 0, dy = 0;
    uint8_t buttons = 0;
    uint8_t id = 0;
    int16_t x = 0, y = 0;
    bool down = false;
};
bool parse_entry(const std::string& entry, std::vector<Input>& out);

struct Options {
    uint16_t width = 640, height = 480;
    uint16_t band_lines = 0; // 0: full frames, double-buffered, a depth buffer each
    std::string pack, out;   // the pack file; the screenshots' folder
    bool quiet = false;
    bool verbose = false; // every view change too (@view)
    bool clock = true; // false: no clock (each step one piece of work; no frame times on the status bar)
    // A device's RAM for the module (bytes; 0: what the model asks for): the workspace, with the
    // pack decoded at its end, as the boards hand it (a model larger opens in part).
    size_t ram_bytes = 0;
};

class Session {
public:
    bool open(const Options& options, std::string& error);
    facet::Viewer& viewer() { return *viewer_; }
    const Options& options() const { return opt_; }

    void key(uint8_t c);   // the boards' UART protocol: '!' commands, 'q', the viewer's keys
    void apply(const Input& in); // an input, straight to the module
    facet::Activity step(uint32_t budget_us);
    bool quit() const { return quit_; }
    int failures() const { return failures_; }

    // What the display shows (the last frame shown, with the bands copied into it).
    const std::vector<facet::Rgb565>& screen() const { return screen_; }
    // Called after each flush with the area that changed (the SDL window's texture).
    void (*on_flush)(void* user, const facet::Area& area) = nullptr;
    void* flush_user = nullptr;
    bool capture(const std::string& name);

private:
    static void flush(facet::Viewer& viewer, void* self, const facet::Area& area, const facet::Rgb565* pixels);
    static void event(void* self, const facet::Event& e);
    void command(const std::string& text);
    void record(uint32_t length); // record_'s first `length` bytes on the standard output

    Options opt_;
    std::vector<uint8_t> workspace_storage_;
    std::vector<facet::Rgb565> buffers_[2];
    std::vector<uint16_t> depth_[2];
    std::vector<facet::Rgb565> faces_;     // the faces layer (full frames, as the firmware's)
    std::vector<uint16_t> faces_depth_;
    std::vector<uint64_t> file_;   // the pack file or library (8-byte aligned)
    std::vector<uint32_t> memory_; // a deflated pack, inflated
    std::vector<facet::Rgb565> screen_;
    facet::Viewer* viewer_ = nullptr;
    bool quit_ = false, in_line_ = false;
    bool wireframe_ = false, half_ = false, done_ = false;
    std::string line_, shot_;
    char record_[facet::kRecordBytes] = {};
    int failures_ = 0;
};

} // namespace sim
