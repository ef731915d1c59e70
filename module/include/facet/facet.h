/* facet: the C API, a thin layer over part of the C++ one (facet/viewer.h): creating a viewer,
 * loading a pack, stepping, input (keys, the pointer, the wheel, touch), flush_done and the
 * statistics, under the same rules for memory, threads and interrupts (read viewer.h's head).
 * The C++ API has more (display modes, parts, the section plane, the camera, measurements);
 * they are not in C yet. C99.
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

#include "facet/sizes.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct facet_viewer facet_viewer;
typedef uint16_t facet_rgb565;

typedef enum {
    FACET_OK = 0, FACET_OUT_OF_RANGE, FACET_FULL, FACET_CORRUPT, FACET_UNSUPPORTED, FACET_NOT_FOUND, FACET_BUSY,
    FACET_DEGENERATE, FACET_CROSSING, FACET_IO
} facet_status;

/* A status, what went wrong and where ("face 12, loop 3"); kinds NULL when not given, indexes
 * 0xFFFFFFFF when a whole thing is meant. */
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

typedef enum { FACET_FLUSH_COPY = 0, FACET_FLUSH_SCANOUT = 1 } facet_flush_mode;

typedef struct {
    uint16_t width, height;
    uint16_t band_lines;           /* = height: full frames; fewer: bands of these lines */
    facet_rgb565 *buffers[2];      /* width * band_lines pixels each; the second may be NULL */
    uint16_t *depth[2];            /* width * band_lines entries; one, or one per draw buffer */
    facet_flush_mode mode;
    void (*flush)(void *user, const facet_area *area, const facet_rgb565 *pixels);
    void *user;
    uint16_t x, y; /* facet's rectangle at (x, y) of the screen (copy mode): flush areas and touch in the screen's */
} facet_display;

typedef enum {
    FACET_EVENT_LOADED, FACET_EVENT_PASS, FACET_EVENT_SAMPLED, FACET_EVENT_PROGRESS, FACET_EVENT_FACE_FAILED,
    FACET_EVENT_PASS_FAILED, FACET_EVENT_TESSELLATED, FACET_EVENT_FRAME_DONE, FACET_EVENT_BUDGET_EXCEEDED,
    FACET_EVENT_PICKED, FACET_EVENT_VIEW_CHANGED, FACET_EVENT_WORK_BEGIN, FACET_EVENT_WORK_END
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
        struct { uint32_t triangles, culled, pixels, cost_us, pieces, faces_done, faces_total, pass; uint8_t full, boxes; } frame;
        struct { uint8_t step; uint32_t budget_us, used_us; } budget;
        struct { uint8_t hit; uint32_t face, instance, shell; uint8_t surface_type; int16_t x, y; } pick;
        struct { float yaw_deg, pitch_deg, zoom; } view;
        struct { facet_work what; uint32_t item; } work;
    } u;
    facet_result why; /* FACE_FAILED, PASS_FAILED */
} facet_event;

typedef struct {
    facet_display display;
    facet_capacity capacity;
    void (*on_event)(void *user, const facet_event *event);
    void *event_user;
    uint32_t (*now_us)(void *user);
    void *clock_user;
    uint32_t frame_budget_us, step_slack_us;
    int interface; /* facet's own on-screen interface: 0 none, 1 all (facet_config_init), 2 the status line alone */
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
/* What a pack needs (facet::model_needs: its counts, pack memory, the least workspace that
 * opens it and one with room to refine), from its head or index alone. */
typedef struct {
    uint32_t faces, edges, parts, pack_memory_bytes;
    size_t least_workspace_bytes, workspace_bytes;
} facet_model_needs_t;
facet_result facet_model_needs(const void *file, uint32_t file_bytes, facet_model_needs_t *needs);

facet_viewer *facet_create(const facet_config *config, void *workspace, size_t bytes, facet_result *why);
facet_result facet_load(facet_viewer *viewer, const void *file, uint32_t file_bytes, void *memory, uint32_t memory_bytes);
facet_activity facet_step(facet_viewer *viewer, uint32_t budget_us);
void facet_flush_done(facet_viewer *viewer); /* any context, an interrupt included */
void facet_key(facet_viewer *viewer, uint32_t key);
void facet_pointer(facet_viewer *viewer, int16_t dx, int16_t dy, uint8_t buttons);
void facet_wheel(facet_viewer *viewer, int16_t clicks);
void facet_touch(facet_viewer *viewer, uint8_t id, int16_t x, int16_t y, int down);
facet_stats facet_get_stats(const facet_viewer *viewer);

#ifdef __cplusplus
}
#endif

#endif /* FACET_FACET_H */
