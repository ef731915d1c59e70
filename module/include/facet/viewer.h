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
#include "facet/storage.h"
#include "facet/types.h"

#include <cstddef>
#include <cstdint>

namespace facet {

// The least workspace create() takes (the default: FACET_WORKSPACE_BASE_BYTES); plus the model's.
constexpr size_t workspace_bytes(const Capacity& c = {}) {
    return FACET_WORKSPACE_BYTES(c.faces, c.edges, c.samples, c.face_points, c.loops, c.slivers, c.mesh_vertices, c.mesh_triangles);
}
constexpr size_t draw_bytes(uint16_t width, uint16_t lines) { return FACET_DRAW_BYTES(width, lines); }
constexpr size_t depth_bytes(uint16_t width, uint16_t lines) { return FACET_DEPTH_BYTES(width, lines); }

// Pack memory load() needs for a file: 0 read in place (plain, aligned), else what it decodes to
// (+ LZMA state; a blocked pack's compressed blocks and their table); 0 for bytes that are no pack.
uint32_t pack_memory_bytes(const void* file, uint32_t file_bytes);

// Ok, or why the bytes are no pack (Corrupt, Unsupported).
Result model_needs(const void* file, uint32_t file_bytes, ModelNeeds& needs);

// A library: several model files in one (facet-pack --library; ./facet flash A.step B.step),
// read in place. How many models (0: the bytes are no sound library) and each one's file and name.
struct LibraryModel {
    const void* file;
    uint32_t bytes;
    const char* name; // UTF-8
};
uint32_t library_count(const void* library, uint32_t bytes);
Result library_model(const void* library, uint32_t bytes, uint32_t index, LibraryModel& out);

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

    // The model dropped, its memory free for the next load() (the screen keeps its picture).
    void unload();
    // Several models on the device: set_library() checks a library's table (8-byte aligned, read
    // in place); open_model() loads one of its models as load() does into `memory` (or the
    // workspace's end); facet's interface then lists them (Action::Models; a tap opens one). A
    // model that cannot be opened is said (ModelFailed, why) and the one open before comes back.
    Result set_library(const void* library, uint32_t bytes, void* memory = nullptr, uint32_t memory_bytes = 0);
    Result open_model(uint32_t index);
    uint32_t model_index() const; // the library's model open; kNone: none (or one load() was given)

    // Models on the product's own storage (facet/storage.h: a memory card, USB, SPI flash, an
    // RTOS filesystem). set_storage() lists `folder`'s pack files ("" or "/": the root) for the
    // chooser, with their sizes and face counts; open_model() opens one of them, open_file() any
    // by its path. A blocked pack (facet-pack's default) has its index read into `memory` (or
    // the workspace's end) and its blocks as the view needs them; another pack is read whole
    // into it and decoded there. Io: the storage failed (a read that never ends is given up
    // after 5 s); NotFound: no such folder or file.
    Result set_storage(const Storage& storage, const char* folder = "", void* memory = nullptr, uint32_t memory_bytes = 0);
    // The chooser's models (a library's, or the storage folder's): how many, and each one's name,
    // file size and faces (kNone: not known before it is opened).
    struct ListedModel {
        const char* name; // UTF-8
        uint32_t bytes, faces;
    };
    uint32_t model_count() const;
    Result listed_model(uint32_t index, ListedModel& out) const;
    Result open_file(const char* path);
    // A storage read that returned Busy has ended (any context: a DMA or card interrupt).
    void read_done(Status status);
    // The storage went away (false: a card pulled: the model on screen stays, what it had not
    // read stays out: proxies or boxes; the chooser is empty) or came back (true: the folder listed again, and
    // the open model's blocks read again if its file is the same).
    Result storage_changed(bool present);

    // Does pieces of work (a frame, a piece of a face's tessellation) until `budget_us` have
    // passed on the clock, and at least one piece. A piece takes at most about a millisecond
    // on a 600 MHz core (docs/viewer.md, "Pieces of work": the measured bound).
    Activity step(uint32_t budget_us);

    // The last flushed area is taken (Flush::Copy) or shown (Flush::Scanout). Any context.
    void flush_done();

    void key(uint32_t key);                              // a key press
    void pointer(int16_t dx, int16_t dy, uint8_t buttons); // relative motion; buttons: 1 left, 2 right, 4 middle
    void wheel(int16_t clicks);                          // > 0: away from the user (zoom in)
    void touch(uint8_t id, int16_t x, int16_t y, bool down); // a finger (id 0, 1) at (x, y) pixels
    void act(Action action);                             // as if its key were pressed

    Stats stats() const;
    ModelInfo model() const; // what the loaded model is (zero before a load)
    const char* model_name() const; // its name (model().name)

    // Every action of the built-in interface is a call (its buttons and keys use these). Those
    // that take a part, a face or a value say why they refuse it (OutOfRange; NotFound before a
    // load); a refused call changes nothing. The view's calls emit ViewChanged.

    // The camera. orbit()/set_orbit(): the view as angles, distance and pan, set at once.
    Orbit orbit() const;
    Result set_orbit(const Orbit& orbit); // OutOfRange: a value not finite, a dolly outside 0.05-20, a pan past 64 model radii
    Result show_view(StandardView view);  // framed, with a short glide (OutOfRange: no such view)
    void fit();                           // the model framed from where the eye is (a section's kept side)
    Result fit_part(uint32_t part);       // one part framed (with a glide)
    Result fit_face(uint32_t part, uint32_t face); // one face, among its neighbours
    void set_parallel(bool parallel);     // the projection: parallel or perspective (framed again)
    // For an application's own 3D marks over the model: a point p (mm, placed model) is at
    // c = R (p - target) (x right, y up, z to the eye; R row-major), in facet's rectangle at
    // (width/2 + focal_px c.x / s, height/2 - focal_px c.y / s), s = distance_mm - c.z (parallel:
    // s = distance_mm); on the screen, plus the display's x and y. Zero before a model is loaded.
    struct CameraView { float rotation[9], target_mm[3], distance_mm, focal_px; bool parallel; };
    CameraView camera() const;

    DisplayMode display_mode() const;
    Result set_display_mode(DisplayMode mode); // OutOfRange: no such mode
    // Tangent edges: the B-rep edges between faces that meet smoothly (a fillet's sides, a split
    // cylinder's halves; the pack says which), drawn (the default) or left out.
    bool tangent_edges() const;
    void set_tangent_edges(bool shown);
    // The level of detail: the chordal tolerance (and the screen error) as a factor of the
    // default: 1, finer below (down to 1/8), coarser above (up to 16); the faces are made again.
    float detail() const;
    Result set_detail(float factor);

    // Picking and measuring. pick(): the face drawn at a screen point (the screen's coordinates,
    // as touch()), nothing selected by it; facts(): a face's by number.
    FaceFacts pick(int16_t x, int16_t y);
    Result facts(uint32_t part, uint32_t face, FaceFacts& out) const;
    // The selection: the faces highlighted (and measured), as taps make it. select() a face: it
    // replaces the selection, or when measuring and one face is selected, becomes the second.
    Result select(uint32_t part, uint32_t face);
    void clear_selection();
    uint32_t selection(FaceFacts out[2]) const; // how many (0 to 2)
    void set_measuring(bool on);                // taps then select two faces to measure
    bool measuring() const;
    Measurement measure(const FaceFacts& a, const FaceFacts& b) const; // None unless both hit
    // The measurement panel's lines (the selected faces' exact values; measuring, their distance
    // and angle): how many, up to 3, into lines[] (valid until the next input or load).
    uint32_t measurement(const char* lines[3]) const;

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
    Result isolate_part(uint32_t index); // shown alone
    void show_all_parts();
    static constexpr uint32_t kMaxHideableParts = 4096;
    Result choose_part(uint32_t index); // highlighted (see-through mode: drawn solid); kNone: none (OutOfRange: no such part)
    uint32_t chosen_part() const;

    // The assembly tree: the STEP file's product structure (none for a part, or a file without
    // one: node_count() 0). Node 0 is the model; a node's parts (its own and its sub-assemblies')
    // are a run of the parts list, [first_part, first_part + part_count).
    struct Node {
        const char *name, *occurrence;             // its product's, its occurrence's ("" when none)
        uint32_t parent, first_child, next_sibling; // kNone: none (walk a node's children from first_child)
        uint32_t first_part, part_count;
        uint32_t depth; // the model's 0
    };
    uint32_t node_count() const;
    Result node(uint32_t index, Node& out) const;  // OutOfRange past the last
    uint32_t part_node(uint32_t part) const;        // the deepest node a part is in (kNone: no tree)
    Result show_node(uint32_t index, bool shown);   // every part under it (those past kMaxHideableParts stay shown)
    Result isolate_node(uint32_t index);            // its parts alone
    Result fit_node(uint32_t index);                // its parts framed, with a glide
    Result choose_node(uint32_t index);             // its parts highlighted (kNone: none); a part chosen ends it
    uint32_t chosen_node() const;
    // The exploded view: every part moved out from its assembly's centre, and each sub-assembly
    // from its own assembly's, level by level down the tree (0: assembled; 1: each as far again
    // as it lies from that centre; at most 2). Drawn, picked and framed where it is drawn;
    // measured on the assembled model (the panel says so). NotFound: no tree; OutOfRange: a
    // factor not finite or outside 0-2.
    float explode() const;
    Result set_explode(float factor);

    // Annotations: the product and manufacturing information of an AP242 file (facet-pack puts
    // it in the pack): dimensions, geometric tolerances, datums and notes, drawn over the model
    // (their presentation's lines, and their text on labels where it is too small to read).
    struct Annotation {
        AnnotationKind kind;
        uint8_t type;       // the kind's own (pack::DimensionType, ToleranceType: geom/pmi_format.h)
        bool semantic;      // its values are the file's semantic PMI (else: a presentation alone)
        bool presented;     // the file draws it (else it is placed at its faces)
        const char* text;   // UTF-8, with the GD&T symbols: "⌀52 ±0.15", "⌖ ⌀1 Ⓜ A B C", "A"
        float value, lower, upper; // a dimension's nominal and deviations (mm or degrees); a tolerance's zone
        const uint32_t* faces; // the faces it applies to (as facts() and select() number them)
        uint32_t face_count;
    };
    uint32_t annotation_count() const; // 0: none (or a blocked pack, which does not carry them)
    Result annotation(uint32_t index, Annotation& out) const; // OutOfRange past the last
    // The kinds shown (annotation_kind_bit of each; all by default, 0: none).
    uint32_t annotations_shown() const;
    void show_annotations(uint32_t kinds);
    // The annotations of a face, each once: how many in all, the first `max` into out.
    uint32_t face_annotations(uint32_t part, uint32_t face, uint32_t* out, uint32_t max) const;
    // An annotation chosen: its faces highlighted, its text on the panel (kNone: none).
    Result choose_annotation(uint32_t index);
    uint32_t chosen_annotation() const;

    // The section plane: normal . p = offset_mm (the placed model's coordinates, mm); the side
    // the normal points to is cut away, and a solid's inside shows in a colour of its own.
    struct SectionPlane { bool on; float normal[3], offset_mm; }; // normal: unit length
    SectionPlane section() const;
    // on = false: off. OutOfRange: a normal of no length or not finite, an offset not finite.
    Result set_section(const SectionPlane& plane);
    Result section_through(uint32_t part, uint32_t face); // a planar face's plane, what lies beyond it cut away
    Result section_across(uint8_t axis);  // 0, 1, 2: across x, y or z, through the model's middle
    Result move_section(float by_mm);     // along its normal (NotFound: no section is on)

private:
    Viewer() = default; // lives in the workspace (create())
    friend class Core;
};

} // namespace facet
