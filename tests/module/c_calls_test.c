/* Every action of the built-in interface as a C call (facet/facet.h), from C99, on the sample
 * part: each call's effect checked through the other calls (the camera, the standard views and
 * fits, the projection, display modes, detail, picking, the selection and measuring, parts, the
 * section plane, the model), exact values against the faces' own, then each call with bad
 * arguments (a NULL viewer, no model yet, parts, faces, axes and values out of range). Built
 * with the sanitizers in the host-asan preset. Exits 0 when every check holds.
 *
 *   c_calls_test MODEL.fpk */
#include "facet/facet.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 240
#define H 180

static uint8_t workspace[FACET_WORKSPACE_BYTES_DEFAULT] __attribute__((aligned(8)));
static uint8_t no_model[FACET_WORKSPACE_BASE_BYTES] __attribute__((aligned(8))); /* a second viewer's, never loaded */
static facet_rgb565 frames[2][W * H];
static uint16_t depth[2][W * H];
static int events[FACET_EVENT_MODEL_FAILED + 1];
static int failures;

#define CHECK(cond)                                                                                 \
    do {                                                                                            \
        if (!(cond)) {                                                                              \
            fprintf(stderr, "c_calls_test: %s:%d: %s\n", __FILE__, __LINE__, #cond);               \
            ++failures;                                                                             \
        }                                                                                           \
    } while (0)
#define NEAR(a, b, eps) (fabs((double)(a) - (double)(b)) <= (eps))

static void flush(facet_viewer *v, void *user, const facet_area *a, const facet_rgb565 *pixels) {
    (void)v, (void)user, (void)a, (void)pixels;
}

static void on_event(void *user, const facet_event *e) {
    (void)user;
    ++events[e->kind];
}

/* Steps until nothing is left to do (every flush taken at once). */
static void settle(facet_viewer *v) {
    int i;
    for (i = 0; i < 100000; ++i) {
        facet_flush_done(v);
        if (facet_step(v, 5000) == FACET_ACTIVITY_IDLE) return;
    }
    CHECK(!"the viewer settles");
}

static facet_viewer *make(uint8_t *memory, size_t bytes) {
    facet_config cfg;
    facet_result why;
    facet_viewer *v;
    facet_config_init(&cfg);
    cfg.display.width = W;
    cfg.display.height = H;
    cfg.display.band_lines = H;
    cfg.display.buffers[0] = frames[0];
    cfg.display.buffers[1] = frames[1];
    cfg.display.depth[0] = depth[0];
    cfg.display.depth[1] = depth[1];
    cfg.display.flush = flush;
    cfg.on_event = on_event;
    v = facet_create(&cfg, memory, bytes, &why);
    CHECK(v != NULL && why.status == FACET_OK);
    return v;
}

/* The first face of the part with this surface (and, for a plane, a normal along `axis`, 0-2,
 * its sign `sign`; -1: any), or 0xFFFFFFFF. */
static uint32_t find_face(facet_viewer *v, facet_surface surface, int axis, double sign) {
    facet_model_info m = facet_get_model(v);
    facet_face_facts f;
    uint32_t i;
    for (i = 0; i < m.faces; ++i) {
        if (facet_get_face(v, 0, i, &f).status != FACET_OK || f.surface != surface) continue;
        if (axis < 0 || NEAR(f.axis[axis], sign, 1e-6)) return i;
    }
    return FACET_NONE;
}

/* Every call with what it must refuse; nothing may crash, and the refusals say so. */
static void misuse(facet_viewer *loaded) {
    facet_viewer *none = NULL, *empty;
    facet_face_facts f, two[2];
    facet_orbit o;
    facet_section sec;
    const char *lines[3];
    facet_measurement m;
    facet_annotation an;
    facet_node node;
    uint32_t ids[4];

    memset(&f, 0, sizeof f);
    memset(&o, 0, sizeof o);
    memset(&sec, 0, sizeof sec);
    /* A NULL viewer: every call. */
    CHECK(facet_load(none, workspace, 64, NULL, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_step(none, 1000) == FACET_ACTIVITY_IDLE);
    facet_flush_done(none);
    facet_key(none, 'a');
    facet_pointer(none, 1, 1, 1);
    facet_wheel(none, 1);
    facet_touch(none, 0, 1, 1, 1);
    facet_act(none, FACET_ACTION_FIT);
    CHECK(facet_get_stats(none).faces == 0);
    CHECK(facet_get_model(none).faces == 0);
    CHECK(facet_get_orbit(none).dolly == 0);
    CHECK(facet_set_orbit(none, &o).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_camera(none).distance_mm == 0);
    CHECK(facet_show_view(none, FACET_VIEW_TOP).status == FACET_OUT_OF_RANGE);
    facet_fit(none);
    CHECK(facet_fit_part(none, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_fit_face(none, 0, 0).status == FACET_OUT_OF_RANGE);
    facet_set_parallel(none, 1);
    CHECK(facet_get_display_mode(none) == FACET_MODE_SHADED_EDGES);
    CHECK(facet_set_display_mode(none, FACET_MODE_SHADED).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_tangent_edges(none) == 0);
    facet_set_tangent_edges(none, 0);
    CHECK(facet_get_detail(none) == 0);
    CHECK(facet_set_detail(none, 1).status == FACET_OUT_OF_RANGE);
    CHECK(facet_pick(none, 1, 1).hit == 0);
    CHECK(facet_get_face(none, 0, 0, &f).status == FACET_OUT_OF_RANGE);
    CHECK(facet_select(none, 0, 0).status == FACET_OUT_OF_RANGE);
    facet_clear_selection(none);
    CHECK(facet_get_selection(none, two) == 0);
    facet_set_measuring(none, 1);
    CHECK(facet_get_measuring(none) == 0);
    m = facet_measure(none, &f, &f);
    CHECK(m.kind == FACET_MEASURE_NONE);
    CHECK(facet_get_measurement_lines(none, lines) == 0);
    CHECK(facet_get_part_count(none) == 0);
    CHECK(facet_get_part(none, 0).faces == 0);
    CHECK(facet_show_part(none, 0, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_isolate_part(none, 0).status == FACET_OUT_OF_RANGE);
    facet_show_all_parts(none);
    CHECK(facet_choose_part(none, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_chosen_part(none) == FACET_NONE);
    CHECK(facet_get_node_count(none) == 0 && facet_get_node(none, 0, &node).status == FACET_OUT_OF_RANGE && facet_get_part_node(none, 0) == FACET_NONE &&
          facet_get_chosen_node(none) == FACET_NONE && facet_get_explode(none) == 0 && facet_show_node(none, 0, 0).status == FACET_OUT_OF_RANGE &&
          facet_isolate_node(none, 0).status == FACET_OUT_OF_RANGE && facet_fit_node(none, 0).status == FACET_OUT_OF_RANGE &&
          facet_choose_node(none, 0).status == FACET_OUT_OF_RANGE && facet_set_explode(none, 1).status == FACET_OUT_OF_RANGE);
    facet_show_annotations(none, 0);
    CHECK(facet_get_annotation_count(none) == 0 && facet_get_annotations_shown(none) == 0 && facet_get_annotation(none, 0, &an).status == FACET_OUT_OF_RANGE &&
          facet_get_face_annotations(none, 0, 0, ids, 4) == 0 && facet_choose_annotation(none, 0).status == FACET_OUT_OF_RANGE &&
          facet_get_chosen_annotation(none) == FACET_NONE);
    CHECK(facet_get_section(none).on == 0);
    CHECK(facet_set_section(none, &sec).status == FACET_OUT_OF_RANGE);
    CHECK(facet_section_through(none, 0, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_section_across(none, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_move_section(none, 1).status == FACET_OUT_OF_RANGE);

    /* NULL records and values out of range, on the loaded viewer: refused, nothing changed. */
    o = facet_get_orbit(loaded);
    CHECK(facet_set_orbit(loaded, NULL).status == FACET_OUT_OF_RANGE);
    o.dolly = 0;
    CHECK(facet_set_orbit(loaded, &o).status == FACET_OUT_OF_RANGE);
    o.dolly = 1, o.yaw_deg = (float)NAN;
    CHECK(facet_set_orbit(loaded, &o).status == FACET_OUT_OF_RANGE);
    o.yaw_deg = 0, o.pan_mm[1] = (float)INFINITY;
    CHECK(facet_set_orbit(loaded, &o).status == FACET_OUT_OF_RANGE);
    CHECK(facet_set_display_mode(loaded, (facet_display_mode)77).status == FACET_OUT_OF_RANGE);
    facet_act(loaded, (facet_action)200);   /* no such action: nothing */
    CHECK(facet_show_view(loaded, (facet_standard_view)9).status == FACET_OUT_OF_RANGE);
    CHECK(facet_set_detail(loaded, 100).status == FACET_OUT_OF_RANGE);
    CHECK(facet_set_detail(loaded, 1.0f / 16).status == FACET_OUT_OF_RANGE);
    CHECK(facet_set_detail(loaded, (float)NAN).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_face(loaded, 0, 0, NULL).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_face(loaded, 1, 0, &f).status == FACET_OUT_OF_RANGE && f.hit == 0);
    CHECK(facet_get_face(loaded, 0, 1000000, &f).status == FACET_OUT_OF_RANGE);
    CHECK(facet_select(loaded, 0, FACET_NONE).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_selection(loaded, NULL) == 0);
    CHECK(facet_measure(loaded, NULL, &f).kind == FACET_MEASURE_NONE);
    f.hit = 1, f.part = 7, f.face = 3;
    CHECK(facet_measure(loaded, &f, &f).kind == FACET_MEASURE_NONE);
    CHECK(facet_get_measurement_lines(loaded, NULL) == 0);
    CHECK(facet_fit_part(loaded, 1).status == FACET_OUT_OF_RANGE);
    CHECK(facet_fit_face(loaded, 0, FACET_NONE).status == FACET_OUT_OF_RANGE);
    CHECK(facet_show_part(loaded, 5, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_isolate_part(loaded, 5).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_part(loaded, 5).name != NULL && facet_get_part(loaded, 5).faces == 0);
    CHECK(facet_choose_part(loaded, 5).status == FACET_OUT_OF_RANGE);
    CHECK(facet_get_chosen_part(loaded) == FACET_NONE);
    /* A part (no assembly tree): no node, nothing to explode. */
    CHECK(facet_get_node_count(loaded) == 0 && facet_get_node(loaded, 0, NULL).status == FACET_OUT_OF_RANGE && facet_get_part_node(loaded, 0) == FACET_NONE &&
          facet_get_node(loaded, 0, &node).status == FACET_OUT_OF_RANGE && facet_fit_node(loaded, 0).status == FACET_OUT_OF_RANGE &&
          facet_set_explode(loaded, 1).status == FACET_NOT_FOUND);
    /* A model without annotations: none to read, list or choose; all kinds shown. */
    CHECK(facet_get_annotation_count(loaded) == 0 && facet_get_annotations_shown(loaded) == FACET_ALL_ANNOTATION_KINDS &&
          facet_get_annotation(loaded, 0, NULL).status == FACET_OUT_OF_RANGE && facet_get_annotation(loaded, 0, &an).status == FACET_OUT_OF_RANGE &&
          facet_get_face_annotations(loaded, 0, 0, NULL, 4) == 0 && facet_get_face_annotations(loaded, 9, 0, ids, 4) == 0 &&
          facet_choose_annotation(loaded, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_choose_annotation(loaded, FACET_NONE).status == FACET_OK && facet_get_chosen_annotation(loaded) == FACET_NONE);
    facet_act(loaded, FACET_ACTION_ANNOTATIONS);
    CHECK(facet_get_annotations_shown(loaded) == 0);
    facet_show_annotations(loaded, FACET_ALL_ANNOTATION_KINDS);
    CHECK(facet_set_section(loaded, NULL).status == FACET_OUT_OF_RANGE);
    CHECK(facet_section_across(loaded, 3).status == FACET_OUT_OF_RANGE);
    CHECK(facet_section_through(loaded, 0, 1000000).status == FACET_OUT_OF_RANGE);
    sec.on = 1; /* a zero normal, a NaN one, an infinite offset: refused, nothing changed */
    CHECK(facet_set_section(loaded, &sec).status == FACET_OUT_OF_RANGE && facet_get_section(loaded).on == 0);
    sec.normal[0] = (float)NAN;
    CHECK(facet_set_section(loaded, &sec).status == FACET_OUT_OF_RANGE && facet_get_section(loaded).on == 0);
    sec.normal[0] = 1, sec.offset_mm = (float)INFINITY;
    CHECK(facet_set_section(loaded, &sec).status == FACET_OUT_OF_RANGE && facet_get_section(loaded).on == 0);
    sec.normal[0] = 0, sec.offset_mm = 0;
    CHECK(facet_move_section(loaded, 1).status == FACET_NOT_FOUND);
    CHECK(facet_get_key_binding(facet_get_key_binding_count()).help == NULL);

    /* A viewer with no model yet: every call, refused where it returns a result. */
    empty = make(no_model, sizeof no_model);
    if (!empty) return;
    CHECK(facet_get_model(empty).faces == 0 && facet_get_model(empty).name != NULL);
    CHECK(facet_set_orbit(empty, &o).status == FACET_NOT_FOUND);
    CHECK(facet_get_camera(empty).distance_mm == 0);
    CHECK(facet_show_view(empty, FACET_VIEW_TOP).status == FACET_NOT_FOUND);
    facet_fit(empty);
    facet_set_parallel(empty, 1);
    facet_act(empty, FACET_ACTION_SECTION);
    CHECK(facet_fit_part(empty, 0).status == FACET_NOT_FOUND);
    CHECK(facet_fit_face(empty, 0, 0).status == FACET_NOT_FOUND);
    CHECK(facet_set_detail(empty, 0.5f).status == FACET_NOT_FOUND);
    CHECK(facet_pick(empty, W / 2, H / 2).hit == 0);
    CHECK(facet_get_face(empty, 0, 0, &f).status == FACET_NOT_FOUND);
    CHECK(facet_select(empty, 0, 0).status == FACET_NOT_FOUND);
    facet_clear_selection(empty);
    facet_set_measuring(empty, 1);
    CHECK(facet_get_measuring(empty) == 0);
    CHECK(facet_get_part_count(empty) == 0);
    CHECK(facet_show_part(empty, 0, 0).status == FACET_OUT_OF_RANGE);
    CHECK(facet_isolate_part(empty, 0).status == FACET_NOT_FOUND);
    facet_show_all_parts(empty);
    CHECK(facet_section_through(empty, 0, 0).status == FACET_NOT_FOUND);
    CHECK(facet_section_across(empty, 0).status == FACET_NOT_FOUND);
    CHECK(facet_move_section(empty, 1).status == FACET_NOT_FOUND);
    CHECK(facet_step(empty, 1000) == FACET_ACTIVITY_IDLE);
}

/* A storage of one file, "/models/sample.fpk" (the pack in memory), through C callbacks. */
typedef struct {
    const uint8_t *bytes;
    uint32_t size;
    int open_files, listed, present;
} mem_storage;
static facet_status mem_open(void *user, const char *path, void **file, uint32_t *bytes) {
    mem_storage *m = (mem_storage *)user;
    if (!m->present) return FACET_IO;
    if (strcmp(path, "/models/sample.fpk") != 0) return FACET_NOT_FOUND;
    *file = m, *bytes = m->size;
    ++m->open_files;
    return FACET_OK;
}
static facet_status mem_read(void *user, void *file, uint32_t offset, void *into, uint32_t bytes) {
    mem_storage *m = (mem_storage *)user;
    (void)file;
    if (!m->present) return FACET_IO;
    memcpy(into, m->bytes + offset, bytes);
    return FACET_OK;
}
static void mem_close(void *user, void *file) {
    (void)file;
    --((mem_storage *)user)->open_files;
}
static facet_status mem_dir_open(void *user, const char *path, void **dir) {
    mem_storage *m = (mem_storage *)user;
    if (strcmp(path, "/models") != 0) return FACET_NOT_FOUND;
    m->listed = 0, *dir = m;
    return FACET_OK;
}
static facet_status mem_dir_read(void *user, void *dir, facet_storage_entry *entry) {
    mem_storage *m = (mem_storage *)user;
    (void)dir;
    if (m->listed++ > 0) return FACET_NOT_FOUND;
    strcpy(entry->name, "sample.fpk");
    entry->bytes = m->size, entry->folder = false;
    return FACET_OK;
}
static void mem_dir_close(void *user, void *dir) { (void)user, (void)dir; }

int main(int argc, char **argv) {
    FILE *file;
    long size;
    uint32_t *pack, plane_up, plane_down, cylinder, n, i;
    facet_viewer *v;
    facet_model_info model;
    facet_orbit o, o2;
    facet_camera cam;
    facet_face_facts f, up, down, cyl, sel[2];
    facet_measurement m;
    facet_section sec;
    facet_stats s;
    const char *lines[3];
    int changed;

    if (argc != 2) return 2;
    file = fopen(argv[1], "rb");
    if (!file) return 2;
    fseek(file, 0, SEEK_END);
    size = ftell(file);
    fseek(file, 0, SEEK_SET);
    pack = malloc((size_t)size + 4);
    if (!pack || fread(pack, 1, (size_t)size, file) != (size_t)size) return 2;
    fclose(file);
    v = make(workspace, sizeof workspace);
    if (!v) return 1;
    CHECK(facet_load(v, pack, (uint32_t)size, NULL, 0).status == FACET_OK);
    settle(v);

    /* The model. */
    model = facet_get_model(v);
    s = facet_get_stats(v);
    CHECK(model.name[0] != 0 && strcmp(model.unit, "mm") == 0 && model.unit_mm == 1);
    CHECK(model.parts == 1 && model.faces == s.faces && model.edges > model.faces && model.boxed_parts == 0);
    CHECK(model.radius_mm > 0);

    /* The key table. */
    n = facet_get_key_binding_count();
    CHECK(n > 10);
    for (i = 0; i < n; ++i) CHECK(facet_get_key_binding(i).help != NULL && facet_get_key_binding(i).action != FACET_ACTION_NONE);

    /* The camera: an orbit set at once is the orbit got; a view change event each. */
    changed = events[FACET_EVENT_VIEW_CHANGED];
    o.yaw_deg = 30, o.pitch_deg = -60, o.dolly = 1.5f, o.pan_mm[0] = 2, o.pan_mm[1] = -1, o.parallel = 0;
    CHECK(facet_set_orbit(v, &o).status == FACET_OK);
    o2 = facet_get_orbit(v);
    CHECK(NEAR(o2.yaw_deg, 30, 1e-3) && NEAR(o2.pitch_deg, -60, 1e-3) && o2.dolly == 1.5f && o2.pan_mm[0] == 2 && o2.pan_mm[1] == -1);
    CHECK(events[FACET_EVENT_VIEW_CHANGED] == changed + 1);
    settle(v);
    /* The front view looks along +y: the camera's z (to the eye) is -y. */
    CHECK(facet_show_view(v, FACET_VIEW_FRONT).status == FACET_OK);
    settle(v);
    cam = facet_get_camera(v);
    CHECK(NEAR(cam.rotation[6], 0, 1e-4) && NEAR(cam.rotation[7], -1, 1e-4) && NEAR(cam.rotation[8], 0, 1e-4));
    CHECK(cam.distance_mm > model.radius_mm && cam.focal_px > 0 && cam.parallel == 0);
    /* Fit: from far away, framed again (closer). */
    o = facet_get_orbit(v);
    o.dolly = 10;
    CHECK(facet_set_orbit(v, &o).status == FACET_OK);
    facet_fit(v);
    settle(v);
    CHECK(facet_get_orbit(v).dolly < 2);
    /* A part and a face framed: the face fills less of the view than its part, so the eye is nearer. */
    CHECK(facet_fit_part(v, 0).status == FACET_OK);
    settle(v);
    o = facet_get_orbit(v);
    cylinder = find_face(v, FACET_SURFACE_CYLINDER, -1, 0);
    CHECK(cylinder != FACET_NONE);
    CHECK(facet_fit_face(v, 0, cylinder).status == FACET_OK);
    settle(v);
    CHECK(facet_get_orbit(v).dolly < o.dolly);
    /* The projection. */
    facet_set_parallel(v, 1);
    settle(v);
    CHECK(facet_get_orbit(v).parallel == 1 && facet_get_camera(v).parallel == 1);
    facet_set_parallel(v, 0);
    settle(v);
    CHECK(facet_get_orbit(v).parallel == 0);
    CHECK(facet_show_view(v, FACET_VIEW_ISO).status == FACET_OK);
    settle(v);

    /* Display modes, and the action that cycles them. */
    CHECK(facet_set_display_mode(v, FACET_MODE_WIREFRAME).status == FACET_OK && facet_get_display_mode(v) == FACET_MODE_WIREFRAME);
    facet_act(v, FACET_ACTION_NEXT_DISPLAY_MODE);
    CHECK(facet_get_display_mode(v) == FACET_MODE_HIDDEN_LINE);
    CHECK(facet_set_display_mode(v, FACET_MODE_SHADED_EDGES).status == FACET_OK);
    /* Tangent edges: drawn by default; left out; the action toggles them back. */
    CHECK(facet_get_tangent_edges(v) == 1);
    facet_set_tangent_edges(v, 0);
    CHECK(facet_get_tangent_edges(v) == 0);
    facet_act(v, FACET_ACTION_TANGENT_EDGES);
    CHECK(facet_get_tangent_edges(v) == 1);

    /* Detail: finer makes more triangles; the action's cycle comes back to the default. */
    CHECK(facet_get_detail(v) == 1);
    s = facet_get_stats(v);
    CHECK(facet_set_detail(v, 0.25f).status == FACET_OK && facet_get_detail(v) == 0.25f);
    settle(v);
    CHECK(facet_get_stats(v).triangles > s.triangles);
    CHECK(facet_set_detail(v, 1).status == FACET_OK);
    settle(v);
    CHECK(facet_get_stats(v).triangles == s.triangles);

    /* Faces: exact values. The top and bottom planes (normals +z and -z), a cylinder. */
    plane_up = find_face(v, FACET_SURFACE_PLANE, 2, 1);
    plane_down = find_face(v, FACET_SURFACE_PLANE, 2, -1);
    CHECK(plane_up != FACET_NONE && plane_down != FACET_NONE);
    CHECK(facet_get_face(v, 0, plane_up, &up).status == FACET_OK && up.hit && up.part == 0 && up.face == plane_up);
    CHECK(facet_get_face(v, 0, plane_down, &down).status == FACET_OK);
    CHECK(facet_get_face(v, 0, cylinder, &cyl).status == FACET_OK && cyl.radius_mm > 0);
    CHECK(NEAR(cyl.axis[0] * cyl.axis[0] + cyl.axis[1] * cyl.axis[1] + cyl.axis[2] * cyl.axis[2], 1, 1e-9));
    /* Parallel planes: their distance is their offsets' along one normal. */
    m = facet_measure(v, &up, &down);
    CHECK(m.kind == FACET_MEASURE_PLANES && m.parallel && m.has_distance && NEAR(m.angle_deg, 0, 1e-9));
    CHECK(NEAR(m.distance_mm, fabs(up.offset_mm + down.offset_mm), 1e-6) && m.distance_mm > 0);
    /* A plane and an axis: the angle between them, 0 to 90 degrees. */
    m = facet_measure(v, &up, &cyl);
    CHECK(m.kind == FACET_MEASURE_PLANE_AXIS && m.angle_deg >= 0 && m.angle_deg <= 90.000001);

    /* Pick: the face drawn at the middle of the screen, the same facts as by number. */
    facet_show_view(v, FACET_VIEW_TOP);
    settle(v);
    f = facet_pick(v, W / 2, H / 2);
    CHECK(f.hit && f.part == 0 && f.x == W / 2 && f.y == H / 2);
    CHECK(facet_get_face(v, 0, f.face, &sel[0]).status == FACET_OK && sel[0].surface == f.surface && sel[0].radius_mm == f.radius_mm);
    CHECK(memcmp(sel[0].axis, f.axis, sizeof f.axis) == 0 && sel[0].offset_mm == f.offset_mm);
    CHECK(facet_get_selection(v, sel) == 0); /* a pick selects nothing */
    CHECK(facet_pick(v, 0, 0).hit == 0);     /* a corner: background */
    /* The selection and measuring: two faces selected, their relation in the panel's third line. */
    CHECK(facet_select(v, 0, plane_up).status == FACET_OK && facet_get_selection(v, sel) == 1 && sel[0].face == plane_up);
    facet_set_measuring(v, 1);
    CHECK(facet_get_measuring(v) == 1);
    CHECK(facet_select(v, 0, plane_down).status == FACET_OK && facet_get_selection(v, sel) == 2 && sel[1].face == plane_down);
    settle(v);
    CHECK(facet_get_measurement_lines(v, lines) == 3 && strstr(lines[2], "parallel planes") != NULL);
    facet_set_measuring(v, 0);
    facet_clear_selection(v);
    CHECK(facet_get_selection(v, sel) == 0 && facet_get_measurement_lines(v, lines) == 0);

    /* Parts. */
    CHECK(facet_get_part_count(v) == 1 && facet_get_part(v, 0).name[0] != 0 && facet_get_part(v, 0).faces == model.faces);
    CHECK(facet_show_part(v, 0, 0).status == FACET_OK && facet_get_part(v, 0).shown == 0);
    settle(v);
    CHECK(facet_pick(v, W / 2, H / 2).hit == 0); /* hidden: nothing to pick */
    facet_show_all_parts(v);
    CHECK(facet_get_part(v, 0).shown == 1);
    CHECK(facet_isolate_part(v, 0).status == FACET_OK && facet_get_part(v, 0).shown == 1);
    facet_choose_part(v, 0);
    CHECK(facet_get_chosen_part(v) == 0);
    facet_choose_part(v, FACET_NONE);
    CHECK(facet_get_chosen_part(v) == FACET_NONE);

    /* The section plane: across z through the middle, moved, through a planar face, off. */
    CHECK(facet_section_across(v, 2).status == FACET_OK);
    sec = facet_get_section(v);
    CHECK(sec.on && sec.normal[0] == 0 && sec.normal[1] == 0 && sec.normal[2] == 1 && sec.offset_mm == model.centre_mm[2]);
    CHECK(facet_move_section(v, 1.5f).status == FACET_OK);
    CHECK(NEAR(facet_get_section(v).offset_mm, model.centre_mm[2] + 1.5f, 1e-4));
    settle(v);
    CHECK(facet_section_through(v, 0, plane_up).status == FACET_OK);
    sec = facet_get_section(v);
    CHECK(sec.on && NEAR(sec.normal[2], 1, 1e-6) && NEAR(sec.offset_mm, up.offset_mm, 1e-3));
    CHECK(facet_section_through(v, 0, cylinder).status == FACET_UNSUPPORTED); /* a plane only */
    CHECK(NEAR(facet_get_section(v).offset_mm, up.offset_mm, 1e-3));          /* unchanged */
    sec.on = 0;
    CHECK(facet_set_section(v, &sec).status == FACET_OK && facet_get_section(v).on == 0);
    settle(v);

    misuse(v);
    settle(v);
    CHECK(facet_get_stats(v).refused == 0);

    /* A library: not this pack; no library set; then unloading, and loading again. */
    {
        facet_library_model_t lm;
        CHECK(facet_library_count(pack, (uint32_t)size) == 0 && facet_library_count(NULL, 0) == 0);
        CHECK(facet_library_model(pack, (uint32_t)size, 0, &lm).status == FACET_CORRUPT && lm.file == NULL);
        CHECK(facet_library_model(pack, (uint32_t)size, 0, NULL).status == FACET_OUT_OF_RANGE);
        CHECK(facet_set_library(v, pack, (uint32_t)size, NULL, 0).status == FACET_CORRUPT);
        CHECK(facet_set_library(NULL, pack, (uint32_t)size, NULL, 0).status == FACET_OUT_OF_RANGE);
        CHECK(facet_open_model(v, 0).status == FACET_NOT_FOUND && facet_open_model(NULL, 0).status == FACET_OUT_OF_RANGE);
        CHECK(facet_get_model_index(v) == FACET_NONE && facet_get_model_index(NULL) == FACET_NONE);
    }
    /* The same pack as a file on the product's storage: listed with its size and faces, opened, a
     * card pulled (the list empty, the model stays) and put back. */
    {
        static mem_storage mem;
        static facet_storage store = {&mem, mem_open, mem_read, mem_close, mem_dir_open, mem_dir_read, mem_dir_close};
        facet_listed_model lm;
        mem.bytes = (const uint8_t *)pack, mem.size = (uint32_t)size, mem.present = 1;
        CHECK(facet_set_storage(v, &store, "/nowhere", NULL, 0).status == FACET_NOT_FOUND);
        CHECK(facet_set_storage(v, &store, "/models", NULL, 0).status == FACET_OK);
        CHECK(facet_get_model_count(v) == 1 && facet_get_model_count(NULL) == 0);
        CHECK(facet_get_listed_model(v, 0, &lm).status == FACET_OK && strcmp(lm.name, "sample.fpk") == 0 && lm.bytes == (uint32_t)size);
        CHECK(lm.faces == model.faces);
        CHECK(facet_get_listed_model(v, 1, &lm).status == FACET_OUT_OF_RANGE && facet_get_listed_model(v, 0, NULL).status == FACET_OUT_OF_RANGE);
        CHECK(facet_open_model(v, 0).status == FACET_OK && facet_get_model_index(v) == 0);
        settle(v);
        CHECK(facet_get_model(v).faces == model.faces && facet_get_stats(v).done > 0);
        CHECK(facet_open_file(v, "/models/none.fpk").status == FACET_NOT_FOUND && facet_open_file(NULL, "x").status == FACET_OUT_OF_RANGE);
        CHECK(facet_open_file(v, "/models/sample.fpk").status == FACET_OK);
        settle(v);
        mem.present = 0;
        CHECK(facet_storage_changed(v, false).status == FACET_OK && facet_get_model_count(v) == 0);
        CHECK(facet_get_model(v).faces == model.faces); /* the model stays */
        CHECK(facet_open_file(v, "/models/sample.fpk").status == FACET_IO);
        mem.present = 1;
        CHECK(facet_storage_changed(v, true).status == FACET_OK && facet_get_model_count(v) == 1);
        CHECK(facet_set_storage(v, NULL, "/", NULL, 0).status == FACET_OUT_OF_RANGE && facet_storage_changed(NULL, true).status == FACET_OUT_OF_RANGE);
        facet_read_done(NULL, FACET_OK);
        CHECK(mem.open_files == 0);
    }
    facet_unload(NULL);
    facet_unload(v);
    CHECK(facet_get_model(v).faces == 0 && facet_get_part_count(v) == 0 && facet_step(v, 1000) == FACET_ACTIVITY_IDLE);
    CHECK(facet_load(v, pack, (uint32_t)size, NULL, 0).status == FACET_OK);
    settle(v);
    CHECK(facet_get_model(v).faces == model.faces && facet_get_stats(v).done > 0);
    free(pack);
    if (failures) return 1;
    printf("c_calls_test: every call checked from C, and every call with bad arguments (%u faces)\n", model.faces);
    return 0;
}
