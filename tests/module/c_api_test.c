/* The C API (facet/facet.h) from C99 (built with -std=c99 -pedantic -Wall -Wextra -Werror):
 * every call, with a pack file given on the command line, in bands of 10 lines with two band
 * buffers and a late flush_done (as a DMA's). Exits 0 when every check holds.
 *
 *   c_api_test MODEL.fpk */
#include "facet/facet.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 200
#define H 150
#define LINES 10

static uint8_t workspace[FACET_WORKSPACE_BYTES_DEFAULT] __attribute__((aligned(8)));
static facet_rgb565 bands[2][W * LINES];
static uint16_t depth[W * LINES];
static facet_rgb565 screen[W * H];
static int events[FACET_EVENT_MODEL_FAILED + 1];
static int pending, failures;
static int origin_x, origin_y; /* the viewer's rectangle on the screen (facet_display.x, y) */
static facet_viewer *viewer;

#define CHECK(cond)                                                                                 \
    do {                                                                                            \
        if (!(cond)) {                                                                              \
            fprintf(stderr, "c_api_test: %s:%d: %s\n", __FILE__, __LINE__, #cond);                 \
            ++failures;                                                                             \
        }                                                                                           \
    } while (0)

static void flush(facet_viewer *v, void *user, const facet_area *a, const facet_rgb565 *pixels) {
    int y;
    CHECK(v == viewer); /* the viewer that drew it: no global needed to call facet_flush_done() */
    CHECK(user == (void *)screen);
    CHECK(a->x == origin_x && a->width == W && a->height <= LINES && a->y >= origin_y && a->y + a->height <= origin_y + H);
    for (y = 0; y < a->height; ++y) memcpy(&screen[(a->y - origin_y + y) * W], pixels + y * W, W * 2);
    ++pending; /* done later, as a DMA would */
}

static void on_event(void *user, const facet_event *e) {
    (void)user;
    CHECK((int)e->kind >= 0 && e->kind <= FACET_EVENT_MODEL_FAILED);
    ++events[e->kind];
    if (e->kind == FACET_EVENT_FRAME_DONE) CHECK(e->u.frame.faces_total > 0);
}

static uint32_t clock_us(void *user) {
    static uint32_t now;
    (void)user;
    return now += 100;
}

int main(int argc, char **argv) {
    facet_config cfg;
    facet_result why;
    facet_stats s;
    char text[160];
    FILE *f;
    long size;
    uint32_t *file, *memory, need;
    int i, n;

    if (argc != 2) return 2;
    facet_config_init(&cfg);
    /* The model's counts planned at load (0), one face's working memory at its default. */
    CHECK(cfg.capacity.faces == 0 && cfg.capacity.face_points == FACET_DEFAULT_FACE_POINTS && cfg.step_slack_us > 0);
    cfg.display.width = W;
    cfg.display.height = H;
    cfg.display.band_lines = LINES;
    cfg.display.buffers[0] = bands[0];
    cfg.display.buffers[1] = bands[1];
    cfg.display.depth[0] = depth;
    cfg.display.mode = FACET_FLUSH_COPY;
    cfg.display.flush = flush;
    cfg.display.user = screen;
    cfg.on_event = on_event;
    cfg.now_us = clock_us;

    /* Refused before anything is stored in it: a workspace too small (by a byte too), none, one
     * not 8-byte aligned; then a scan-out display in bands. The least the formula says opens. */
    CHECK(facet_create(&cfg, workspace, 1024, &why) == NULL && why.status == FACET_FULL);
    CHECK(facet_create(&cfg, workspace, FACET_WORKSPACE_BASE_BYTES - 1, &why) == NULL && why.status == FACET_FULL);
    /* A face of twice the points takes more than the default's workspace: refused there, with
     * the bytes it needs. An interface the module does not know is refused too. */
    cfg.capacity.face_points *= 2;
    CHECK(facet_create(&cfg, workspace, FACET_WORKSPACE_BASE_BYTES, &why) == NULL && why.status == FACET_FULL &&
          why.where_index == facet_workspace_bytes(&cfg.capacity) && why.where_index > FACET_WORKSPACE_BASE_BYTES);
    cfg.capacity.face_points /= 2;
    cfg.interface = (facet_interface)7;
    CHECK(facet_create(&cfg, workspace, sizeof workspace, &why) == NULL && why.status == FACET_OUT_OF_RANGE);
    cfg.interface = FACET_INTERFACE_FULL;
    CHECK(facet_create(&cfg, NULL, sizeof workspace, &why) == NULL && why.status == FACET_OUT_OF_RANGE);
    memset(workspace, 0xA5, 64);
    CHECK(facet_create(&cfg, workspace + 4, sizeof workspace - 4, &why) == NULL && why.status == FACET_OUT_OF_RANGE);
    CHECK(workspace[4] == 0xA5);
    viewer = facet_create(&cfg, workspace, FACET_WORKSPACE_BASE_BYTES, &why);
    CHECK(viewer != NULL && why.status == FACET_OK);
    cfg.display.mode = FACET_FLUSH_SCANOUT;
    CHECK(facet_create(&cfg, workspace, sizeof workspace, &why) == NULL && why.status == FACET_OUT_OF_RANGE);
    facet_describe(&why, text, sizeof text);
    CHECK(strstr(text, "display") != NULL);
    cfg.display.mode = FACET_FLUSH_COPY;
    viewer = facet_create(&cfg, workspace, sizeof workspace, &why);
    CHECK(viewer != NULL && why.status == FACET_OK);
    if (!viewer) return 1;

    /* A bad pack: refused with its reason. */
    memset(screen, 0, sizeof screen);
    why = facet_load(viewer, screen, 64, NULL, 0);
    CHECK(why.status == FACET_CORRUPT);
    CHECK(facet_describe(&why, text, sizeof text) > 0 && strstr(text, "no pack here") != NULL);

    f = fopen(argv[1], "rb");
    if (!f) return 2;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    file = malloc((size_t)size + 4);
    if (!file || fread(file, 1, (size_t)size, f) != (size_t)size) return 2;
    fclose(f);
    need = facet_pack_memory_bytes(file, (uint32_t)size);
    {
        facet_model_needs_t needs;
        why = facet_model_needs(file, (uint32_t)size, &needs);
        CHECK(why.status == FACET_OK && needs.faces > 0 && needs.edges > 0 && needs.pack_memory_bytes == need);
        CHECK(needs.least_workspace_bytes > FACET_WORKSPACE_BASE_BYTES && needs.least_workspace_bytes <= needs.workspace_bytes);
        CHECK(needs.workspace_bytes <= sizeof workspace);
        CHECK(facet_model_needs(file, (uint32_t)size, NULL).status == FACET_OUT_OF_RANGE);
    }
    memory = malloc(need + 4);
    why = facet_load(viewer, file, (uint32_t)size, memory, need);
    CHECK(why.status == FACET_OK);

    for (i = 0; i < 200000; ++i) {
        const facet_activity a = facet_step(viewer, 2000);
        if (a == FACET_ACTIVITY_IDLE && !pending) break;
        for (; pending; --pending) facet_flush_done(viewer);
    }
    s = facet_get_stats(viewer);
    CHECK(s.faces > 0 && s.done > 0 && s.done + s.deferred == s.faces && s.failed == 0 && s.triangles > 0); /* a solid's planes turned away wait */
    CHECK(events[FACET_EVENT_LOADED] == 1 && events[FACET_EVENT_TESSELLATED] == 1);
    CHECK(events[FACET_EVENT_FRAME_DONE] > 0 && events[FACET_EVENT_WORK_BEGIN] == events[FACET_EVENT_WORK_END]);

    /* Input: keys, a drag, the wheel, a tap (a pick). */
    facet_key(viewer, 'd');
    facet_key(viewer, FACET_KEY_LEFT);
    facet_pointer(viewer, 0, 0, 2);
    facet_pointer(viewer, 10, 5, 2);
    facet_pointer(viewer, 0, 0, 0);
    facet_wheel(viewer, 1);
    CHECK(events[FACET_EVENT_VIEW_CHANGED] == 4);
    facet_touch(viewer, 0, W / 2, H / 2, 1);
    facet_touch(viewer, 0, W / 2, H / 2, 0);
    CHECK(events[FACET_EVENT_PICKED] == 1);
    for (i = 0; i < 200000; ++i) {
        const facet_activity a = facet_step(viewer, 2000);
        if (a == FACET_ACTIVITY_IDLE && !pending) break;
        for (; pending; --pending) facet_flush_done(viewer);
    }
    /* Anew in the same workspace: in a rectangle at (7, 5) of a larger screen, the interface
     * reduced to the status line. Flush areas come in the screen's coordinates (flush()
     * checks), and so do touches: one in the rectangle picks, one outside it is the product's. */
    origin_x = cfg.display.x = 7, origin_y = cfg.display.y = 5;
    cfg.interface = FACET_INTERFACE_STATUS_LINE;
    viewer = facet_create(&cfg, workspace, sizeof workspace, &why);
    CHECK(viewer != NULL && why.status == FACET_OK);
    if (!viewer) return 1;
    CHECK(facet_load(viewer, file, (uint32_t)size, memory, need).status == FACET_OK);
    i = events[FACET_EVENT_FRAME_DONE];
    for (; pending; --pending) facet_flush_done(viewer);
    for (n = 0; n < 200000 && (facet_step(viewer, 2000) != FACET_ACTIVITY_IDLE || pending); ++n)
        for (; pending; --pending) facet_flush_done(viewer);
    CHECK(events[FACET_EVENT_FRAME_DONE] > i);
    i = events[FACET_EVENT_PICKED];
    facet_touch(viewer, 0, 2, 2, 1); /* outside the rectangle */
    facet_touch(viewer, 0, 2, 2, 0);
    CHECK(events[FACET_EVENT_PICKED] == i);
    facet_touch(viewer, 0, 7 + W / 2, 5 + H / 2, 1);
    facet_touch(viewer, 0, 7 + W / 2, 5 + H / 2, 0);
    CHECK(events[FACET_EVENT_PICKED] == i + 1);
    for (n = 0; n < 200000 && (facet_step(viewer, 2000) != FACET_ACTIVITY_IDLE || pending); ++n)
        for (; pending; --pending) facet_flush_done(viewer);
    free(file);
    free(memory);
    if (failures) return 1;
    printf("c_api_test: %u faces, %u triangles, %d frames, %d pieces of work, every C call checked\n", s.faces,
           s.triangles, events[FACET_EVENT_FRAME_DONE], events[FACET_EVENT_WORK_BEGIN]);
    return 0;
}
