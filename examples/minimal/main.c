/* facet in a product, the least it takes: buffers, callbacks, the loop. C99.
 * The screen is drawn in bands of 16 lines (2 x 15 KiB at 480 wide) with a band-sized depth
 * buffer, so it fits a board without room for full frames. port.h is the product's side. */
#include "facet/facet.h"
#include "port.h"

#include <stddef.h>

#define MAX_WIDTH 640
#define LINES 16

static uint8_t workspace[FACET_WORKSPACE_BYTES_DEFAULT] PORT_LARGE __attribute__((aligned(8)));
static facet_rgb565 bands[2][MAX_WIDTH * LINES];
static uint16_t depth[MAX_WIDTH * LINES];

/* A finished band: onto the panel. A DMA would call facet_flush_done() from its interrupt. */
static void flush(facet_viewer *viewer, void *user, const facet_area *area, const facet_rgb565 *pixels) {
    (void)user;
    port_display_write(area, pixels);
    facet_flush_done(viewer);
}

static void on_event(void *user, const facet_event *e) {
    char line[160];
    (void)user;
    if (e->kind == FACET_EVENT_FACE_FAILED || e->kind == FACET_EVENT_PASS_FAILED) {
        facet_describe(&e->why, line, sizeof line);
        port_log(line);
    } else if (e->kind == FACET_EVENT_TESSELLATED) {
        port_log("every face is in");
    }
}

int app_main(void) {
    facet_viewer *viewer;
    facet_config cfg;
    facet_result why;
    char line[160];
    uint32_t bytes = 0, memory_bytes = 0, key;
    void *memory = NULL;
    int16_t x, y;
    int down, touch;

    if (port_width() > MAX_WIDTH) return 1;
    facet_config_init(&cfg);
    cfg.display.width = port_width();
    cfg.display.height = port_height();
    cfg.display.band_lines = LINES;
    cfg.display.buffers[0] = bands[0];
    cfg.display.buffers[1] = bands[1];
    cfg.display.depth[0] = depth;
    cfg.display.mode = FACET_FLUSH_COPY;
    cfg.display.flush = flush;
    cfg.on_event = on_event;
    cfg.now_us = port_now_us;
    viewer = facet_create(&cfg, workspace, sizeof workspace, &why);
    if (viewer) {
        const void *pack = port_pack(&bytes, &memory, &memory_bytes);
        why = facet_load(viewer, pack, bytes, memory, memory_bytes);
    }
    if (!viewer || why.status != FACET_OK) {
        facet_describe(&why, line, sizeof line);
        port_log(line);
        return 1;
    }
    for (;;) {
        while (port_poll(&key, &x, &y, &down, &touch)) {
            if (touch) facet_touch(viewer, 0, x, y, down);
            else facet_key(viewer, key);
        }
        if (facet_step(viewer, 5000) == FACET_ACTIVITY_IDLE && port_idle()) return 0;
    }
}
