#pragma once
// facet: the records the Viewer's calls take and give (facet/viewer.h has the calls): the
// configuration, the display, events, actions, display modes, statistics, and what a pick,
// a measurement and the camera say.
#include "core/pixel.h"
#include "core/status.h"
#include "facet/base.h"
#include "facet/sizes.h"

#include <cstddef>
#include <cstdint>

namespace facet {

class Viewer;

// Every call that can fail returns a Result (core/status.h: its Status, what went wrong and
// where). The Viewer's calls and events give the public statuses only: Ok, OutOfRange, Full,
// Corrupt, Unsupported, NotFound and Busy (geometry the tessellation refuses is Corrupt, its
// text says why); Degenerate, Crossing and Io are the layers' own and never reach you.

// No part, no face, no model: the one "none" (FACET_NONE in C).
constexpr uint32_t kNone = FACET_NONE;

// One face's working memory (face_points, loops, slivers) is laid out by create(); the model's
// arrays by load(), for its faces and edges in the room left: 0 plans a count, a number fixes it.
struct Capacity {
    uint32_t faces = 0, edges = 0, samples = 0;
    uint32_t face_points = FACET_DEFAULT_FACE_POINTS, loops = FACET_DEFAULT_LOOPS, slivers = FACET_DEFAULT_SLIVERS;
    uint32_t mesh_vertices = 0, mesh_triangles = 0;
};

// What a pack needs (from its head or index alone): counts, pack memory (from the workspace's end
// when load() is given none), the least workspace in which every face shows (meshed at up to 16
// times the default tolerance: a first level short of room goes coarser) and one in which every
// face shows at the default detail. From what the packer measured with the module's own code
// (the pack's Needs section); a pack without it is sized from estimates. Below the least, faces
// the mesh has no room for stay wireframe; below what the model's edges take, load() says Full.
struct ModelNeeds {
    uint32_t faces, edges, parts, pack_memory_bytes;
    size_t least_workspace_bytes, workspace_bytes;
};

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
    // The area of the screen in `pixels` (area.width * area.height, row after row) is ready;
    // `viewer` drew it (flush_done() once it is taken or shown).
    void (*flush)(Viewer& viewer, void* user, const Area& area, const Rgb565* pixels) = nullptr;
    void* user = nullptr;
    uint16_t x = 0, y = 0; // facet's rectangle at (x, y) of the screen (Copy): flush areas and touch in the screen's
    // A faces layer (optional; full frames): width * height pixels and as many depth entries,
    // where the view's faces are drawn apart from their edges. While the faces stay the same (a
    // frame at rest: edges shown or hidden, the overlay, the end of a drag or of a pass), a frame
    // is this layer copied and the edges drawn over it: about half a frame's work on a large
    // model. Null: every frame draws its faces.
    Rgb565* faces = nullptr;
    uint16_t* faces_depth = nullptr;
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
        ModelFailed,     // a model of the library could not be opened (why); the one open before is opened again
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
        struct { uint32_t index; } model;                                       // ModelFailed: the library's model
    };
    Result why; // FaceFailed, PassFailed, ModelFailed
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
    // BudgetExceeded past these (0: never); a large assembly whose whole frame takes longer than
    // frame_budget_us (0: 33.3 ms, 20 M instructions at 600 MHz) is drawn coarser (docs/scale.md),
    // and a model whose frames come near it shows a new view's faces a frame before their edges.
    uint32_t frame_budget_us = 0, step_slack_us = 2000;
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
    Models,          // the models on the device (a library: Viewer::set_library) on/off: tap one to open it
    TangentEdges,    // tangent edges (between faces that meet smoothly: a fillet's sides) shown / hidden
    Annotations,     // the model's annotations (PMI: dimensions, tolerances, datums, notes) shown / hidden
    Explode,         // the exploded view (an assembly's parts out from their assemblies' centres, its slider) / back
};

// What an annotation (PMI, Viewer::annotation) is; as bits (annotation_kind_bit), the kinds shown.
enum class AnnotationKind : uint8_t { Dimension, Tolerance, Datum, Note };
constexpr uint32_t annotation_kind_bit(AnnotationKind k) { return 1u << uint32_t(k); }
constexpr uint32_t kAllAnnotationKinds = 15;

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

// The standard views of a z-up model: front looks along +y, right along -x, top down -z,
// isometric from (+1, -1, +1).
enum class StandardView : uint8_t { Front, Back, Right, Left, Top, Bottom, Iso };

// The view as an orbit about the model's centre: yaw about z, then pitch (degrees); the eye's
// distance as a factor of the fitted one (< 1: closer; 0.05 to 20); a pan (mm, along the
// screen's right and up); the projection (parallel or perspective).
struct Orbit {
    float yaw_deg = 0, pitch_deg = 0, dolly = 1, pan_mm[2] = {0, 0};
    bool parallel = false;
};

// A face's surface (the pack's surface types).
enum class Surface : uint8_t { None, Plane, Cylinder, Cone, Sphere, Torus, BSpline, Revolution, Extrusion };

// A face of a part and its surface's exact values, placed in the model (mm; directions of unit
// length), from the pack's parameters, not from the mesh: what a pick finds and a measurement takes.
struct FaceFacts {
    bool hit = false;            // a face is there (pick(): under the point); else the rest is zero
    uint32_t part = 0, face = 0; // the part (as part()) and the face (the model's numbering, as events)
    Surface surface = Surface::None;
    bool hole = false;           // cylinder, cone: the face looks at its axis
    double origin_mm[3] = {};    // plane: its origin; cylinder, cone, torus: a point of the axis; sphere: the centre
    double axis[3] = {};         // plane: its outward normal; cylinder, cone, torus, revolution: the axis; extrusion: its way
    double offset_mm = 0;        // plane: axis . p for every point p of it
    double radius_mm = 0;        // cylinder, sphere; cone: at the origin; torus: the major radius
    double minor_mm = 0;         // torus: the tube's radius
    double half_angle_deg = 0;   // cone
    int16_t x = 0, y = 0;        // pick(): the screen point
};

// How two faces relate, exactly: the angle between their planes or axes (0 to 90 degrees) and,
// where there is one, the distance (between parallel planes, a plane and a parallel axis, two
// axes, centres); None for a free-form face.
struct Measurement {
    enum class Kind : uint8_t { None, Planes, PlaneAxis, Axes, PlanePoint, AxisPoint, Points } kind = Kind::None;
    bool parallel = false, has_distance = false;
    double distance_mm = 0, angle_deg = 0;
};

// What the loaded model is.
struct ModelInfo {
    const char* name = "";  // the STEP file's top product (or the file's name)
    const char* unit = "";  // the file's length unit: mm, cm, m, in, ft, or units
    float unit_mm = 1;
    uint32_t parts = 0, faces = 0, edges = 0;
    uint32_t boxed_parts = 0, boxed_faces = 0; // larger than the memory: parts left out now (drawn as their proxies, or boxes)
    float centre_mm[3] = {0, 0, 0}, radius_mm = 0; // the placed model's sphere
};

} // namespace facet
