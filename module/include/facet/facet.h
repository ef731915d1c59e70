/* facet: the C API, a thin layer over the C++ one (facet/viewer.h), call for call: creating a
 * viewer, loading a pack, stepping, input (keys, the pointer, the wheel, touch), and every action
 * of the built-in interface (the camera and the standard views, fitting, the projection, display
 * modes, detail, picking, the selection and measuring, parts, the section plane), under the same
 * rules for memory, threads and interrupts (read viewer.h's head). Every call takes a NULL viewer
 * (a call that returns a facet_result says so; the others do nothing or return zeros). C99.
 *
 *   static uint8_t workspace[FACET_WORKSPACE_BYTES_DEFAULT] __attribute__((aligned(8)));
 *   facet_config cfg;
 *   facet_config_init(&cfg);
 *   cfg.display = ...;                        buffers, flush callback (facet/sizes.h)
 *   facet_result why;
 *   facet_viewer *v = facet_create(&cfg, workspace, sizeof workspace, &why);
 *   facet_load(v, pack, pack_bytes, NULL, 0);
 *   for (;;) { feed input; if (facet_step(v, 5000) == FACET_ACTIVITY_IDLE) wait for input; }
 */
#ifndef FACET_FACET_H
#define FACET_FACET_H

#include "facet/base.h"
#include "facet/sizes.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct facet_viewer facet_viewer;
typedef uint16_t facet_rgb565;

/* The enums a caller passes in end with a *_WIDE_ value: it keeps each type as wide as a 32-bit
 * integer, so that whatever number a caller passes is a value of it (C lets any int through); the
 * calls refuse the numbers they do not know (FACET_OUT_OF_RANGE) or ignore them where they
 * return nothing. */

/* What a call says: Ok, or the kind of failure (the text says more). A face whose geometry the
 * tessellation refuses (degenerate, loops that cross) is CORRUPT here. */
typedef enum {
    FACET_OK = 0, FACET_OUT_OF_RANGE, FACET_FULL, FACET_CORRUPT, FACET_UNSUPPORTED, FACET_NOT_FOUND, FACET_BUSY,
    FACET_IO = 9, /* the product's storage failed (facet/storage.h: a card pulled) */
    FACET_STATUS_WIDE_ = 0x7FFFFFFF
} facet_status;

/* A status, what went wrong and where ("face 12, loop 3"); kinds NULL when not given, indexes
 * FACET_NONE when a whole thing is meant. */
typedef struct {
    facet_status status;
    const char *what;
    const char *where_kind;
    uint32_t where_index;
    const char *at_kind;
    uint32_t at_index;
} facet_result;
/* The result as one line of text ("face 12, loop 3: loops cross"); returns its length. */
size_t facet_describe(const facet_result *result, char *buffer, size_t size);

typedef struct {
    uint32_t faces, edges, samples, face_points, loops, slivers, mesh_vertices, mesh_triangles;
} facet_capacity;

typedef struct {
    uint16_t x, y, width, height;
} facet_area;

typedef enum { FACET_FLUSH_COPY = 0, FACET_FLUSH_SCANOUT = 1, FACET_FLUSH_WIDE_ = 0x7FFFFFFF } facet_flush_mode;

typedef struct {
    uint16_t width, height;
    uint16_t band_lines;           /* = height: full frames; fewer: bands of these lines */
    facet_rgb565 *buffers[2];      /* width * band_lines pixels each; the second may be NULL */
    uint16_t *depth[2];            /* width * band_lines entries; one, or one per draw buffer */
    facet_flush_mode mode;
    /* The area of the screen in `pixels` is ready; the viewer that drew it (for facet_flush_done()). */
    void (*flush)(facet_viewer *viewer, void *user, const facet_area *area, const facet_rgb565 *pixels);
    void *user;
    uint16_t x, y; /* facet's rectangle at (x, y) of the screen (copy mode): flush areas and touch in the screen's */
    /* A faces layer (optional; full frames): width * height pixels and depth entries where the
       view's faces are kept apart from their edges; a frame at rest copies it and draws the
       edges over it. NULL: every frame draws its faces. */
    facet_rgb565 *faces;
    uint16_t *faces_depth;
} facet_display;

typedef enum {
    FACET_EVENT_LOADED, FACET_EVENT_PASS, FACET_EVENT_SAMPLED, FACET_EVENT_PROGRESS, FACET_EVENT_FACE_FAILED,
    FACET_EVENT_PASS_FAILED, FACET_EVENT_TESSELLATED, FACET_EVENT_FRAME_DONE, FACET_EVENT_BUDGET_EXCEEDED,
    FACET_EVENT_PICKED, FACET_EVENT_VIEW_CHANGED, FACET_EVENT_WORK_BEGIN, FACET_EVENT_WORK_END,
    FACET_EVENT_MODEL_FAILED /* a library's model could not be opened (why); the one before is opened again */
} facet_event_kind;

typedef enum { FACET_WORK_UNPACK, FACET_WORK_SAMPLING, FACET_WORK_FACE, FACET_WORK_FRAME, FACET_WORK_UPDATE, FACET_WORK_FIT, FACET_WORK_OVERLAY } facet_work;

typedef struct {
    facet_event_kind kind;
    union {
        struct { uint32_t faces, edges, shells, instances, pack_bytes, file_bytes, boxed_parts, boxed_faces; } loaded;
        struct { uint32_t pass; float tolerance_mm; uint32_t samples; } pass;
        struct { uint32_t done, failed, total, triangles; } progress;
        struct { uint32_t face; } failed;
        struct { uint32_t pass, faces, failed, triangles, vertices, mesh_bytes, arena_peak_bytes; float tolerance_mm; } tessellated;
        /* frame: triangles set up, culled, pixels depth-tested (drawn or hidden), ... */
        struct { uint32_t triangles, culled, pixels, cost_us, pieces, faces_done, faces_total, pass; bool full, boxes; } frame;
        struct { bool step; uint32_t budget_us, used_us; } budget;
        struct { bool hit; uint32_t face, instance, shell; uint8_t surface_type; int16_t x, y; } pick;
        struct { float yaw_deg, pitch_deg, zoom; } view;
        struct { facet_work what; uint32_t item; } work;
        struct { uint32_t index; } model;
    } u;
    facet_result why; /* FACE_FAILED, PASS_FAILED, MODEL_FAILED */
} facet_event;

/* facet's own on-screen interface: none (the product's own drives facet_act()), the status line, or all. */
typedef enum {
    FACET_INTERFACE_OFF = 0, FACET_INTERFACE_STATUS_LINE = 1, FACET_INTERFACE_FULL = 2, FACET_INTERFACE_WIDE_ = 0x7FFFFFFF
} facet_interface;

typedef struct {
    facet_display display;
    facet_capacity capacity;
    void (*on_event)(void *user, const facet_event *event);
    void *event_user;
    uint32_t (*now_us)(void *user);
    void *clock_user;
    /* BudgetExceeded past these (0: never); a large assembly whose whole frame takes longer
       than frame_budget_us (0: 33.3 ms) is drawn coarser, and a model whose frames come near
       it shows a new view's faces a frame before their edges */
    uint32_t frame_budget_us, step_slack_us;
    facet_interface interface; /* facet's own on-screen interface (facet_config_init: FACET_INTERFACE_FULL) */
    float screen_error_px; /* a far part's chordal error at rest (facet_config_init: 0.5); 0: every face, one tolerance */
} facet_config;

/* What step() left: more work (call again), a frame waiting for facet_flush_done(), nothing. */
typedef enum { FACET_ACTIVITY_BUSY = 0, FACET_ACTIVITY_WAITING = 1, FACET_ACTIVITY_IDLE = 2 } facet_activity;

enum {
    FACET_KEY_LEFT = 0x100, FACET_KEY_RIGHT, FACET_KEY_UP, FACET_KEY_DOWN, FACET_KEY_PAGE_UP, FACET_KEY_PAGE_DOWN,
    FACET_KEY_HOME
};

typedef struct {
    uint32_t faces, done, failed, triangles, vertices, pass;
    uint32_t mesh_bytes, arena_peak_bytes, pack_bytes, pack_file_bytes, workspace_peak_bytes;
    float tolerance_mm;
    uint32_t refused;
    uint32_t deferred; /* faces the view does not show yet: too small, off the screen, or a solid's back planes (drawn by their edges) */
} facet_stats;

/* Defaults: the default capacities, no callbacks, a step slack of 2 ms. */
void facet_config_init(facet_config *config);
size_t facet_workspace_bytes(const facet_capacity *capacity);
uint32_t facet_pack_memory_bytes(const void *file, uint32_t file_bytes);
/* What a pack needs (facet::model_needs: its counts, pack memory, the least workspace in which
 * every face shows, at up to 16 times the default tolerance, and one in which every face shows at
 * the default detail), from its head or index alone. */
typedef struct {
    uint32_t faces, edges, parts, pack_memory_bytes;
    size_t least_workspace_bytes, workspace_bytes;
} facet_model_needs_t;
facet_result facet_model_needs(const void *file, uint32_t file_bytes, facet_model_needs_t *needs);

facet_viewer *facet_create(const facet_config *config, void *workspace, size_t bytes, facet_result *why);
facet_result facet_load(facet_viewer *viewer, const void *file, uint32_t file_bytes, void *memory, uint32_t memory_bytes);
facet_activity facet_step(facet_viewer *viewer, uint32_t budget_us);
void facet_unload(facet_viewer *viewer); /* the model dropped, its memory free for the next load */

/* Several models on the device: a library (facet-pack --library, ./facet flash A.step B.step),
 * 8-byte aligned, read in place. Its models without a viewer (count 0: no sound library), and
 * the viewer's: facet_open_model loads one as facet_load does (facet's interface lists them). */
typedef struct { const void *file; uint32_t bytes; const char *name; } facet_library_model_t;
uint32_t facet_library_count(const void *library, uint32_t bytes);
facet_result facet_library_model(const void *library, uint32_t bytes, uint32_t index, facet_library_model_t *out);
facet_result facet_set_library(facet_viewer *viewer, const void *library, uint32_t bytes, void *memory, uint32_t memory_bytes);
facet_result facet_open_model(facet_viewer *viewer, uint32_t index);
uint32_t facet_get_model_index(const facet_viewer *viewer); /* FACET_NONE: none from the library */

/* Models on the product's own storage (facet/storage.h says the same in C++): a memory card,
 * USB mass storage, SPI flash, a file of an RTOS filesystem, behind callbacks shaped as LVGL's
 * lv_fs_drv_t and FatFs: open a file by its path (its handle and size), read bytes at an offset
 * (FACET_OK: there; FACET_BUSY: a transfer goes on and facet_read_done() says when it ends, from
 * any context), close it; a folder's entries for the chooser (optional: NULL lists nothing). The
 * facet_storage itself must stay where it is while the viewer uses it (a static, as LVGL's
 * drivers are). facet_set_storage lists `folder`'s *.fpk files (with sizes and faces) in the
 * chooser; facet_open_model opens one, facet_open_file any by its path; a blocked pack is read
 * an index and then a block at a time, never whole. FACET_IO: the storage failed. */
typedef struct { char name[96]; uint32_t bytes; bool folder; } facet_storage_entry;
typedef struct {
    void *user;
    facet_status (*open)(void *user, const char *path, void **file, uint32_t *bytes);
    facet_status (*read)(void *user, void *file, uint32_t offset, void *into, uint32_t bytes);
    void (*close)(void *user, void *file);
    facet_status (*dir_open)(void *user, const char *path, void **dir);
    facet_status (*dir_read)(void *user, void *dir, facet_storage_entry *entry); /* FACET_NOT_FOUND: the end */
    void (*dir_close)(void *user, void *dir);
} facet_storage;
facet_result facet_set_storage(facet_viewer *viewer, const facet_storage *storage, const char *folder, void *memory,
                               uint32_t memory_bytes);
facet_result facet_open_file(facet_viewer *viewer, const char *path);
void facet_read_done(facet_viewer *viewer, facet_status status); /* any context */
facet_result facet_storage_changed(facet_viewer *viewer, bool present); /* a card pulled (false) or put back */
/* The chooser's models (a library's or the storage folder's): name, file size, faces (FACET_NONE: unknown). */
typedef struct { const char *name; uint32_t bytes, faces; } facet_listed_model;
uint32_t facet_get_model_count(const facet_viewer *viewer);
facet_result facet_get_listed_model(const facet_viewer *viewer, uint32_t index, facet_listed_model *out);
void facet_flush_done(facet_viewer *viewer); /* any context, an interrupt included */
void facet_key(facet_viewer *viewer, uint32_t key);
void facet_pointer(facet_viewer *viewer, int16_t dx, int16_t dy, uint8_t buttons);
void facet_wheel(facet_viewer *viewer, int16_t clicks);
void facet_touch(facet_viewer *viewer, uint8_t id, int16_t x, int16_t y, bool down);
facet_stats facet_get_stats(const facet_viewer *viewer);

/* Every action of the built-in interface, as its keys and buttons do it (facet::Action). */
typedef enum {
    FACET_ACTION_NONE, FACET_ACTION_TURN_LEFT, FACET_ACTION_TURN_RIGHT, FACET_ACTION_TILT_UP, FACET_ACTION_TILT_DOWN,
    FACET_ACTION_ZOOM_IN, FACET_ACTION_ZOOM_OUT, FACET_ACTION_PAN_LEFT, FACET_ACTION_PAN_RIGHT, FACET_ACTION_PAN_UP,
    FACET_ACTION_PAN_DOWN, FACET_ACTION_FIT, FACET_ACTION_COARSER, FACET_ACTION_FINER, FACET_ACTION_NEXT_DETAIL,
    FACET_ACTION_VIEW_FRONT, FACET_ACTION_VIEW_BACK, FACET_ACTION_VIEW_RIGHT, FACET_ACTION_VIEW_LEFT, FACET_ACTION_VIEW_TOP,
    FACET_ACTION_VIEW_BOTTOM, FACET_ACTION_VIEW_ISO, FACET_ACTION_PROJECTION, FACET_ACTION_NEXT_DISPLAY_MODE,
    FACET_ACTION_NEXT_VIEW, FACET_ACTION_MEASURE, FACET_ACTION_HELP, FACET_ACTION_SECTION, FACET_ACTION_SECTION_IN,
    FACET_ACTION_SECTION_OUT, FACET_ACTION_PARTS, FACET_ACTION_NEXT_PART, FACET_ACTION_HIDE_PART, FACET_ACTION_ISOLATE_PART,
    FACET_ACTION_SHOW_ALL_PARTS, FACET_ACTION_MODELS, FACET_ACTION_TANGENT_EDGES, FACET_ACTION_ANNOTATIONS,
    FACET_ACTION_EXPLODE,
    FACET_ACTION_WIDE_ = 0x7FFFFFFF
} facet_action;
void facet_act(facet_viewer *viewer, facet_action action); /* as if its key were pressed */
/* The keys' table, for a help screen: how many, and each (NULL help past the last). */
typedef struct { uint32_t key; facet_action action; const char *help; } facet_key_binding;
uint32_t facet_get_key_binding_count(void);
facet_key_binding facet_get_key_binding(uint32_t index);

/* The loaded model (zeros and "" before a load). */
typedef struct {
    const char *name, *unit; /* the STEP file's top product; its length unit: mm, cm, m, in, ft or units */
    float unit_mm;
    uint32_t parts, faces, edges;
    uint32_t boxed_parts, boxed_faces; /* larger than the memory: parts left out now (drawn as their proxies, or boxes) */
    float centre_mm[3], radius_mm;     /* the placed model's sphere */
} facet_model_info;
facet_model_info facet_get_model(const facet_viewer *viewer);

/* The camera: an orbit about the model's centre (yaw about z, then pitch, degrees; the eye's
 * distance as a factor of the fitted one, < 1 closer, 0.05 to 20; a pan in mm along the screen's
 * right and up; parallel or perspective), set at once; the standard views and fits glide. */
typedef struct { float yaw_deg, pitch_deg, dolly, pan_mm[2]; bool parallel; } facet_orbit;
typedef enum {
    FACET_VIEW_FRONT, FACET_VIEW_BACK, FACET_VIEW_RIGHT, FACET_VIEW_LEFT, FACET_VIEW_TOP, FACET_VIEW_BOTTOM, FACET_VIEW_ISO,
    FACET_VIEW_WIDE_ = 0x7FFFFFFF
} facet_standard_view;
/* For marks of one's own over the model (facet::Viewer::CameraView says how to project). */
typedef struct { float rotation[9], target_mm[3], distance_mm, focal_px; bool parallel; } facet_camera;
facet_orbit facet_get_orbit(const facet_viewer *viewer);
facet_result facet_set_orbit(facet_viewer *viewer, const facet_orbit *orbit);
facet_camera facet_get_camera(const facet_viewer *viewer);
facet_result facet_show_view(facet_viewer *viewer, facet_standard_view view);
void facet_fit(facet_viewer *viewer);
facet_result facet_fit_part(facet_viewer *viewer, uint32_t part);
facet_result facet_fit_face(facet_viewer *viewer, uint32_t part, uint32_t face);
void facet_set_parallel(facet_viewer *viewer, bool parallel);

typedef enum {
    FACET_MODE_SHADED_EDGES, FACET_MODE_SHADED, FACET_MODE_WIREFRAME, FACET_MODE_HIDDEN_LINE, FACET_MODE_SEE_THROUGH,
    FACET_MODE_WIDE_ = 0x7FFFFFFF
} facet_display_mode;
facet_display_mode facet_get_display_mode(const facet_viewer *viewer);
facet_result facet_set_display_mode(facet_viewer *viewer, facet_display_mode mode);
/* Tangent edges (between faces that meet smoothly: a fillet's sides): drawn (the default) or left out. */
bool facet_get_tangent_edges(const facet_viewer *viewer);
void facet_set_tangent_edges(facet_viewer *viewer, bool shown);
/* The level of detail as a factor of the default tolerance: 1/8 (finest) to 16. */
float facet_get_detail(const facet_viewer *viewer);
facet_result facet_set_detail(facet_viewer *viewer, float factor);

/* A face and its surface's exact values, placed (facet::FaceFacts). */
typedef enum {
    FACET_SURFACE_NONE, FACET_SURFACE_PLANE, FACET_SURFACE_CYLINDER, FACET_SURFACE_CONE, FACET_SURFACE_SPHERE,
    FACET_SURFACE_TORUS, FACET_SURFACE_BSPLINE, FACET_SURFACE_REVOLUTION, FACET_SURFACE_EXTRUSION
} facet_surface;
typedef struct {
    bool hit;
    uint32_t part, face;
    facet_surface surface;
    bool hole;
    double origin_mm[3], axis[3], offset_mm, radius_mm, minor_mm, half_angle_deg;
    int16_t x, y;
} facet_face_facts;
typedef enum {
    FACET_MEASURE_NONE, FACET_MEASURE_PLANES, FACET_MEASURE_PLANE_AXIS, FACET_MEASURE_AXES, FACET_MEASURE_PLANE_POINT,
    FACET_MEASURE_AXIS_POINT, FACET_MEASURE_POINTS
} facet_measure_kind;
typedef struct {
    facet_measure_kind kind;
    bool parallel, has_distance;
    double distance_mm, angle_deg;
} facet_measurement;
/* The face drawn at a screen point (the screen's coordinates, as facet_touch), selecting nothing. */
facet_face_facts facet_pick(facet_viewer *viewer, int16_t x, int16_t y);
facet_result facet_get_face(const facet_viewer *viewer, uint32_t part, uint32_t face, facet_face_facts *out);
/* The selection (highlighted; measuring: the second face selected joins the first). */
facet_result facet_select(facet_viewer *viewer, uint32_t part, uint32_t face);
void facet_clear_selection(facet_viewer *viewer);
uint32_t facet_get_selection(const facet_viewer *viewer, facet_face_facts out[2]);
void facet_set_measuring(facet_viewer *viewer, bool on);
bool facet_get_measuring(const facet_viewer *viewer);
facet_measurement facet_measure(const facet_viewer *viewer, const facet_face_facts *a, const facet_face_facts *b);
/* The measurement panel's lines (up to 3, valid until the next input or load). */
uint32_t facet_get_measurement_lines(const facet_viewer *viewer, const char *lines[3]);

/* The parts (the pack's instances, in pack order). */
typedef struct {
    const char *name, *instance; /* the part's and the occurrence's own ("" when none) */
    uint32_t faces;
    bool shown;
} facet_part;
uint32_t facet_get_part_count(const facet_viewer *viewer);
facet_part facet_get_part(const facet_viewer *viewer, uint32_t index); /* "" and zeros past the last */
facet_result facet_show_part(facet_viewer *viewer, uint32_t index, bool shown);
facet_result facet_isolate_part(facet_viewer *viewer, uint32_t index);
void facet_show_all_parts(facet_viewer *viewer);
facet_result facet_choose_part(facet_viewer *viewer, uint32_t index); /* FACET_NONE: none */
uint32_t facet_get_chosen_part(const facet_viewer *viewer);

/* The assembly tree (none: facet_get_node_count 0); node 0 the model, a node's parts a run of
   the parts list. The exploded view: 0 assembled, up to 2. */
typedef struct {
    const char *name, *occurrence;
    uint32_t parent, first_child, next_sibling; /* FACET_NONE: none */
    uint32_t first_part, part_count, depth;
} facet_node;
uint32_t facet_get_node_count(const facet_viewer *viewer);
facet_result facet_get_node(const facet_viewer *viewer, uint32_t index, facet_node *out);
uint32_t facet_get_part_node(const facet_viewer *viewer, uint32_t part);
facet_result facet_show_node(facet_viewer *viewer, uint32_t index, bool shown);
facet_result facet_isolate_node(facet_viewer *viewer, uint32_t index);
facet_result facet_fit_node(facet_viewer *viewer, uint32_t index);
facet_result facet_choose_node(facet_viewer *viewer, uint32_t index); /* FACET_NONE: none */
uint32_t facet_get_chosen_node(const facet_viewer *viewer);
float facet_get_explode(const facet_viewer *viewer);
facet_result facet_set_explode(facet_viewer *viewer, float factor);

/* Annotations (PMI of an AP242 file): dimensions, geometric tolerances, datums, notes. */
typedef enum {
    FACET_ANNOTATION_DIMENSION, FACET_ANNOTATION_TOLERANCE, FACET_ANNOTATION_DATUM, FACET_ANNOTATION_NOTE,
    FACET_ANNOTATION_WIDE_ = 0x7FFFFFFF
} facet_annotation_kind;
#define FACET_ALL_ANNOTATION_KINDS 15u /* bit (1 << kind) of each kind shown */
typedef struct {
    facet_annotation_kind kind;
    uint8_t type;          /* the kind's own: geom/pmi_format.h's DimensionType, ToleranceType */
    bool semantic, presented;
    const char *text;      /* UTF-8, with the GD&T symbols: "\xE2\x8C\x80" is the diameter sign */
    float value, lower, upper;
    const uint32_t *faces; /* the faces it applies to (as facet_select numbers them) */
    uint32_t face_count;
} facet_annotation;
uint32_t facet_get_annotation_count(const facet_viewer *viewer);
facet_result facet_get_annotation(const facet_viewer *viewer, uint32_t index, facet_annotation *out);
uint32_t facet_get_annotations_shown(const facet_viewer *viewer);
void facet_show_annotations(facet_viewer *viewer, uint32_t kinds);
uint32_t facet_get_face_annotations(const facet_viewer *viewer, uint32_t part, uint32_t face, uint32_t *out, uint32_t max);
facet_result facet_choose_annotation(facet_viewer *viewer, uint32_t index); /* FACET_NONE: none */
uint32_t facet_get_chosen_annotation(const facet_viewer *viewer);

/* The section plane: normal . p = offset_mm; the side the normal points to is cut away. */
typedef struct { bool on; float normal[3], offset_mm; } facet_section;
facet_section facet_get_section(const facet_viewer *viewer);
facet_result facet_set_section(facet_viewer *viewer, const facet_section *plane);
facet_result facet_section_through(facet_viewer *viewer, uint32_t part, uint32_t face); /* a planar face */
facet_result facet_section_across(facet_viewer *viewer, uint8_t axis); /* 0 x, 1 y, 2 z: through the middle */
facet_result facet_move_section(facet_viewer *viewer, float by_mm);

#ifdef __cplusplus
}
#endif

#endif /* FACET_FACET_H */
