#pragma once
// facet: a CAD model shown from its exact geometry, in caller memory, a bounded step at a time.
//
//   facet::Config cfg{};                      // the display, callbacks, capacities (below)
//   facet::Viewer* v = facet::Viewer::create(cfg, workspace, sizeof workspace, &why);
//   v->load(pack, pack_bytes);                 // a pack file, in flash or RAM
//   for (;;) {                                 // a bare-metal loop, or an RTOS task's
//       feed input: v->key(k), v->pointer(dx, dy, buttons), v->touch(id, x, y, down), ...
//       if (v->step(5000) == facet::Activity::Idle) sleep until input;
//   }
//
// The module allocates nothing: every byte it uses is handed in (facet/sizes.h gives the sizes).
// It draws into the caller's draw buffers and hands each finished area to display.flush, like
// LVGL's flush_cb; it reports through on_event and never prints.
//
// Threads and interrupts: a Viewer is used from one thread (a task or the main loop), not
// re-entrant. flush_done() alone may be called from any context (a DMA or vertical-blank
// interrupt): it only sets a flag. The callbacks run inside step() and load() on that thread and
// may call flush_done() and the queries only. Input from an interrupt is queued by the
// application and fed from its thread. Several Viewers (each with its own memory) are independent.
#include "core/pixel.h"
#include "core/status.h"
#include "facet/sizes.h"

#include <cstddef>
#include <cstdint>

namespace facet {

// One face's working memory (face_points, loops, slivers) is laid out by create(); the model's
// arrays by load(), for its faces and edges in the room left: 0 plans a count, a number fixes it.
struct Capacity {
    uint32_t faces = 0, edges = 0, samples = 0;
    uint32_t face_points = FACET_DEFAULT_FACE_POINTS, loops = FACET_DEFAULT_LOOPS, slivers = FACET_DEFAULT_SLIVERS;
    uint32_t mesh_vertices = 0, mesh_triangles = 0;
};

// The least workspace create() takes (the default: FACET_WORKSPACE_BASE_BYTES); plus the model's.
constexpr size_t workspace_bytes(const Capacity& c = {}) {
    return FACET_WORKSPACE_BYTES(c.faces, c.edges, c.samples, c.face_points, c.loops, c.slivers, c.mesh_vertices, c.mesh_triangles);
}
constexpr size_t draw_bytes(uint16_t width, uint16_t lines) { return FACET_DRAW_BYTES(width, lines); }
constexpr size_t depth_bytes(uint16_t width, uint16_t lines) { return FACET_DEPTH_BYTES(width, lines); }

// Pack memory load() needs for a file: 0 read in place (plain, aligned), else what it decodes to
// (+ LZMA state; a blocked pack's compressed blocks and their table); 0 for bytes that are no pack.
uint32_t pack_memory_bytes(const void* file, uint32_t file_bytes);

// What a pack needs (from its head or index alone): counts, pack memory (from the workspace's end
// when load() is given none), the least workspace that opens it (faces the mesh has no room for
// stay wireframe; less: Full, bytes needed) and one with room to refine the default detail.
struct ModelNeeds {
    uint32_t faces, edges, parts, pack_memory_bytes;
    size_t least_workspace_bytes, workspace_bytes;
};
// Ok, or why the bytes are no pack (Corrupt, Unsupported).
Result model_needs(const void* file, uint32_t file_bytes, ModelNeeds& needs);

// How the application's display takes a finished area.
enum class Flush : uint8_t {
    Copy,    // the pixels are copied out (SPI, DMA, memcpy): flush_done() once copied (then drawn into again)
    Scanout, // full frames the LCD controller reads in place: show the buffer from the next
             // refresh on, and flush_done() once it is shown (the previous frame is then free)
};

struct Display {
    uint16_t width = 0, height = 0;
    uint16_t band_lines = 0;          // = height: full frames; fewer: the screen in bands of these
    Rgb565* buffers[2] = {};          // draw buffers, width * band_lines pixels; the second may be null
    uint16_t* depth[2] = {};          // depth buffers, width * band_lines entries: one, or one per draw
                                      // buffer (full frames: faces fill in without redrawing it whole)
    Flush mode = Flush::Copy;
    // The area of the screen in `pixels` (area.width * area.height, row after row) is ready.
    void (*flush)(void* user, const Area& area, const Rgb565* pixels) = nullptr;
    void* user = nullptr;
    uint16_t x = 0, y = 0; // facet's rectangle at (x, y) of the screen (Copy): flush areas and touch in the screen's
};

enum class Work : uint8_t { Unpack, Sampling, Face, Frame, Update, Fit, Overlay }; // pieces of work (profiling)

struct Event {
    enum class Kind : uint8_t {
        Loaded,          // a pack was validated: counts (a model larger than the memory: its parts left out, as boxes)
        Pass,            // a level of detail begins (the first one at load): tolerance
        Sampled,         // its edges are sampled: samples
        Progress,        // a face was tessellated (or failed): counts
        FaceFailed,      // a face could not be tessellated (why); it stays wireframe
        PassFailed,      // a level's edges could not be sampled (why): the previous level stays
        Tessellated,     // every face of the pass is done: totals
        FrameDone,       // a frame was handed to the display: what it drew and its cost
        BudgetExceeded,  // a step over its budget + step_slack_us, or a frame over frame_budget_us
        Picked,          // a tap or click picked a face (or nothing)
        ViewChanged,     // the camera moved
        WorkBegin,       // a piece of work begins / ends (regions for a profiler)
        WorkEnd,
    } kind;
    union {
        struct { uint32_t faces, edges, shells, instances, pack_bytes, file_bytes, boxed_parts, boxed_faces; } loaded; // boxed: left out
        struct { uint32_t pass; float tolerance_mm; uint32_t samples; } pass;     // Pass, Sampled
        struct { uint32_t done, failed, total, triangles; } progress;
        struct { uint32_t face; } failed;
        struct { uint32_t pass, faces, failed, triangles, vertices, mesh_bytes, arena_peak_bytes; float tolerance_mm; } tessellated;
        // frame: triangles set up, culled, pixels depth-tested (drawn or hidden), ...
        struct { uint32_t triangles, culled, pixels, cost_us, pieces, faces_done, faces_total, pass; bool full, boxes; } frame;
        struct { bool step; uint32_t budget_us, used_us; } budget;
        struct { bool hit; uint32_t face, instance, shell; uint8_t surface_type; int16_t x, y; } pick;
        struct { float yaw_deg, pitch_deg, zoom; } view;
        struct { Work what; uint32_t item; } work;
    };
    Result why; // FaceFailed, PassFailed
};

// facet's own on-screen interface: none (the application's own drives act()), the status line, or all.
enum class Interface : uint8_t { Off, StatusLine, Full };

struct Config {
    Display display;
    Capacity capacity;
    void (*on_event)(void* user, const Event& event) = nullptr; // optional
    void* event_user = nullptr;
    uint32_t (*now_us)(void* user) = nullptr; // optional clock (wraps): step budgets and costs in us;
    void* clock_user = nullptr;               // without one, step() does one piece of work per call
    uint32_t frame_budget_us = 0, step_slack_us = 2000; // BudgetExceeded past these (0: never)
    float screen_error_px = 0.5f; // a far part's chordal error at rest, pixels; 0: no view-dependent detail (every face, one tolerance)
    Interface interface = Interface::Full; // facet's own on-screen interface (Interface)
};

enum class Activity : uint8_t {
    Busy,    // work remains: call step() again (after input and the rest of the application)
    Waiting, // a frame waits for flush_done() and there is nothing else to do
    Idle,    // nothing to do until input
};

// Keys: printable characters as themselves (the table: facet::key_bindings()), and these.
enum Key : uint32_t { KeyLeft = 0x100, KeyRight, KeyUp, KeyDown, KeyPageUp, KeyPageDown, KeyHome };

// What a key, a gesture or an application's own button does.
enum class Action : uint8_t {
    None, TurnLeft, TurnRight, TiltUp, TiltDown, ZoomIn, ZoomOut, PanLeft, PanRight, PanUp, PanDown, Fit,
    Coarser, Finer,
    NextDetail, // the level of detail: default -> finer -> finest -> coarser -> default
    // Standard views (a z-up model: front looks along +y), each framed, with a short glide.
    ViewFront, ViewBack, ViewRight, ViewLeft, ViewTop, ViewBottom, ViewIso,
    Projection, // perspective <-> parallel (orthographic)
    NextDisplayMode, // shaded with edges -> shaded -> wireframe -> hidden line -> ...
    NextView,        // isometric -> front -> right -> top -> back -> left -> bottom -> ...
    Measure,         // measuring on/off: taps then pick two faces for their distance and angle
    Help,            // the help panel on/off
    Section,         // the section plane: off -> through the picked planar face (when one is
                     // picked) -> across x -> y -> z -> off; the side its normal points to is cut away
    SectionIn, SectionOut, // move the plane along its normal by 1/32 of the model, back / forward
    Parts,           // the parts list on/off (tap a name to choose it, its box to hide or show it)
    NextPart,        // choose the next part of the list (highlighted)
    HidePart,        // hide the chosen part
    IsolatePart,     // show the chosen part alone
    ShowAllParts,
};

// How the model is drawn.
enum class DisplayMode : uint8_t {
    ShadedEdges, // shaded faces and their B-rep edges over them
    Shaded,      // shaded faces only
    Wireframe,   // every B-rep edge, hidden ones too; no faces
    HiddenLine,  // the edges a viewer sees, on white faces (a drawing's look)
    SeeThrough,  // the chosen part (or the picked face's) solid, the others screen-door (every
                 // other pixel), so what they hide shows through
};
struct KeyBinding { uint32_t key; Action action; const char* help; };
struct KeyBindings { const KeyBinding* table; uint32_t count; };
KeyBindings key_bindings(); // for a help screen: what each key does

struct Stats {
    uint32_t faces, done, failed, deferred, triangles, vertices, pass; // deferred: not shown by the view yet
    uint32_t mesh_bytes, arena_peak_bytes, pack_bytes, pack_file_bytes, workspace_peak_bytes; // workspace: at its peak
    float tolerance_mm;
    uint32_t refused;              // triangles and lines the rasterizer refused: 0 (all are clipped first)
};

class Viewer {
public:
    // A viewer in `workspace` (8-byte aligned, at least workspace_bytes(config.capacity) bytes),
    // or null with the reason in *why (a buffer too small or missing, a bad size).
    static Viewer* create(const Config& config, void* workspace, size_t bytes, Result* why = nullptr);

    // Takes a pack file (plain, LZMA, deflated, or blocked: facet-pack's default, an index and
    // blocks of a few parts) and shows its wireframe. A plain, aligned pack is read in place and
    // must stay there, as must a blocked pack's index; the rest is decoded into `memory`
    // (pack_memory_bytes(); a file inside it is decoded there) or, given none, into the
    // workspace's end (a file the board loaded into the workspace is decoded where it lies).
    // Then the model's arrays are planned in the room left. Corrupt names the bad record (and
    // block); Full: the workspace is too small (bytes needed). The previous model is dropped first.
    Result load(const void* file, uint32_t file_bytes, void* memory = nullptr, uint32_t memory_bytes = 0);

    // Does pieces of work (a frame, a piece of a face's tessellation) until `budget_us` have
    // passed on the clock, and at least one piece. A piece takes at most about a millisecond
    // on a 600 MHz core (docs/module.md: the measured bound).
    Activity step(uint32_t budget_us);

    // The last flushed area is taken (Flush::Copy) or shown (Flush::Scanout). Any context.
    void flush_done();

    void key(uint32_t key);                              // a key press
    void pointer(int16_t dx, int16_t dy, uint8_t buttons); // relative motion; buttons: 1 left, 2 right, 4 middle
    void wheel(int16_t clicks);                          // > 0: away from the user (zoom in)
    void touch(uint8_t id, int16_t x, int16_t y, bool down); // a finger (id 0, 1) at (x, y) pixels
    void act(Action action);                             // as if its key were pressed

    Stats stats() const;
    DisplayMode display_mode() const;
    // The measurement panel's lines (the picked faces' exact values; measuring, their distance
    // and angle): how many, up to 3, into lines[] (valid until the next input or load).
    uint32_t measurement(const char* lines[3]) const;
    void set_display_mode(DisplayMode mode);

    // The parts: the pack's instances, each a part of the assembly placed once, in pack order,
    // named after the STEP file's product (and occurrence, when the file names it).
    struct Part {
        const char *name, *instance; // the part's and the occurrence's own ("" when the file names none)
        uint32_t faces;
        bool shown;
    };
    uint32_t part_count() const;
    Part part(uint32_t index) const;
    // Hide or show a part (OutOfRange past the parts, or past the first kMaxHideableParts).
    Result show_part(uint32_t index, bool shown);
    static constexpr uint32_t kMaxHideableParts = 4096;
    void choose_part(uint32_t index); // highlighted (see-through mode: drawn solid); ~0u: none
    uint32_t chosen_part() const;
    const char* model_name() const; // the STEP file's top product (or the file's name)

    // The section plane: normal . p = offset_mm (the placed model's coordinates, mm); the side
    // the normal points to is cut away, and a solid's inside shows in a colour of its own.
    struct SectionPlane { bool on; float normal[3], offset_mm; }; // normal: unit length
    SectionPlane section() const;
    void set_section(const SectionPlane& plane);

    // The camera, for an application's own 3D marks over the model: a point p (mm, placed
    // model) is at c = R (p - target) (x right, y up, z to the eye; R row-major), on the screen
    // at (width/2 + focal_px c.x / s, height/2 - focal_px c.y / s), s = distance_mm - c.z
    // (parallel: s = distance_mm). Zero before a model is loaded.
    struct CameraView { float rotation[9], target_mm[3], distance_mm, focal_px; bool parallel; };
    CameraView camera() const;

private:
    Viewer() = default; // lives in the workspace (create())
    friend class Core;
};

} // namespace facet
