/* facet in a product's own screen: the product draws its buttons and text line, facet the model in a
 * viewport beside them (its interface off); each button is a C API call. C99. A demo script taps as a
 * finger would, then ends (a product waits for input). */
#include "facet/facet.h"
#include "port.h"

#include <string.h>

/* The screen's widest, facet's band, the buttons' column, the text line at the bottom, a button. */
enum { MAX_WIDTH = 640, LINES = 16, PANEL = 64, STATUS = 16, BUTTON = 32 };

static uint8_t workspace[FACET_WORKSPACE_BYTES_DEFAULT] PORT_LARGE __attribute__((aligned(8)));
static facet_rgb565 bands[2][MAX_WIDTH * LINES];
static facet_rgb565 canvas[MAX_WIDTH * STATUS] PORT_LARGE; /* where the product draws its own */
static uint16_t depth[MAX_WIDTH * LINES];
static facet_viewer *viewer;
static char measured[64], cut[32], status[96]; /* the product's text: what is measured, the cut */

enum { FRONT, TOP, ISO, FIT, CUT, MEAS, BUTTONS };
static const char *const labels[BUTTONS] = {"FRONT", "TOP", "ISO", "FIT", "CUT", "MEAS"};

/* The product's own font: 3x5 glyphs drawn twice their size, each row one octal digit. */
static const char glyph_chars[] = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.-:";
static const char glyph_rows[] =
    "75557262277174771717557117471774757711227575775717257556565634443655567464774644345535575572227111525565544447"
    "5775565555255526564425563656553421672222555575555255775552555522271247000020070002020";

/* Text into the canvas (width w pixels) at x, y. */
static void text(int w, int x, int y, const char *s, facet_rgb565 ink) {
    for (; *s && x + 8 <= w; ++s, x += 8) {
        const char *at = strchr(glyph_chars, *s);
        if (*s == ' ' || !at) continue;
        for (int r = 0; r < 5; ++r)
            for (int c = 0; c < 3; ++c)
                if ((glyph_rows[(at - glyph_chars) * 5 + r] - '0') & (4 >> c)) {
                    facet_rgb565 *p = canvas + (y + 2 * r) * w + x + 2 * c;
                    p[0] = p[1] = p[w] = p[w + 1] = ink;
                }
    }
}

/* The product's panel (lit: what is on) and its text line, over the screen beside facet's. */
static void paint(void) {
    facet_area a = {0, 0, PANEL, BUTTON};
    for (int b = 0; b < BUTTONS; ++b, a.y += BUTTON + 4) {
        const int lit = (b == CUT && facet_get_section(viewer).on) || (b == MEAS && facet_get_measuring(viewer));
        for (int i = 0; i < PANEL * BUTTON; ++i) canvas[i] = lit ? 0xFD20 : (i / PANEL) % BUTTON < 2 ? 0x4208 : 0x2945;
        text(PANEL, 4, (BUTTON - 10) / 2, labels[b], 0xFFFF);
        port_display_write(&a, canvas);
    }
    a.y = (uint16_t)(port_height() - STATUS), a.width = port_width(), a.height = STATUS;
    for (int i = 0; i < a.width * STATUS; ++i) canvas[i] = 0x0010;
    strcat(strcat(strcpy(status, measured), "  "), cut);
    text(a.width, 4, 3, status, 0xFFE0);
    port_display_write(&a, canvas);
}

/* A label and a value to 3 decimals after `out`'s end (no printf: its floats can pull in malloc). */
static void append(char *out, const char *label, double v) {
    char digits[24];
    long n = (long)(v * 1000 + (v < 0 ? -0.5 : 0.5)), k = 0;
    strcat(strcat(out, label), n < 0 ? "-" : "");
    for (n = n < 0 ? -n : n; n || k < 4; n /= 10) digits[k++] = (char)('0' + n % 10);
    for (out += strlen(out); k > 0; *out = 0) {
        *out++ = digits[--k];
        if (k == 3) *out++ = '.';
    }
}

/* What the selection says, in the product's words. */
static void describe_selection(void) {
    facet_face_facts f[2];
    const uint32_t n = facet_get_selection(viewer, f);
    measured[0] = 0;
    if (n == 2) {
        const facet_measurement m = facet_measure(viewer, &f[0], &f[1]);
        if (m.kind == FACET_MEASURE_NONE) strcpy(measured, "NO EXACT MEASURE");
        if (m.has_distance) append(measured, m.parallel ? "PARALLEL " : "", m.distance_mm), strcat(measured, " MM APART");
        if (m.kind != FACET_MEASURE_NONE && !m.parallel) append(measured, " AT ", m.angle_deg), strcat(measured, " DEG");
    } else if (n == 1) {
        const int plane = f[0].surface == FACET_SURFACE_PLANE;
        append(measured, plane ? "PLANE AT " : "RADIUS ", plane ? f[0].offset_mm : f[0].radius_mm);
    } else if (facet_get_measuring(viewer))
        strcpy(measured, "MEAS: TAP TWO FACES");
}

/* A button of the product's panel, pressed. */
static void press(int16_t y) {
    facet_section section = facet_get_section(viewer);
    switch (y / (BUTTON + 4)) {
    case FRONT: facet_show_view(viewer, FACET_VIEW_FRONT); break;
    case TOP: facet_show_view(viewer, FACET_VIEW_TOP); break;
    case ISO: facet_show_view(viewer, FACET_VIEW_ISO); break;
    case FIT: facet_fit(viewer); break;
    case CUT: /* across x through the middle, or off */
        cut[0] = 0;
        if (section.on) section.on = 0, (void)facet_set_section(viewer, &section);
        else if (facet_section_across(viewer, 0).status == FACET_OK) append(cut, "CUT X AT ", facet_get_section(viewer).offset_mm);
        break;
    case MEAS: facet_set_measuring(viewer, !facet_get_measuring(viewer)), describe_selection(); break;
    }
    paint();
}

/* A finger: on the panel, a button; on the model, facet's (a tap picks, a drag turns). */
static void touch(int16_t x, int16_t y, int down) {
    if (x >= PANEL) facet_touch(viewer, 0, x, y, down);
    else if (down) press(y);
}

static void on_event(void *user, const facet_event *e) {
    if (e->kind == FACET_EVENT_PICKED) describe_selection(), paint();
    (void)user;
}

static void flush(facet_viewer *drawn_by, void *user, const facet_area *area, const facet_rgb565 *pixels) {
    (void)user;
    port_display_write(area, pixels);
    facet_flush_done(drawn_by);
}

int app_main(void) {
    facet_config cfg;
    facet_result why;
    uint32_t bytes = 0, memory_bytes = 0, key, step = 0;
    void *memory = NULL;
    int16_t x, y, w = (int16_t)port_width(), h = (int16_t)port_height();
    int down, is_touch;
    /* The demo's taps: from the top, measuring the pocket's floor against the top face; a turn; the cut. */
    const int16_t script[][2] = {{2, TOP * (BUTTON + 4) + 8}, {2, MEAS * (BUTTON + 4) + 8},
                                 {(int16_t)(PANEL + (w - PANEL) / 4), (int16_t)((h - STATUS) / 2)},
                                 {(int16_t)(PANEL + (w - PANEL) / 2), (int16_t)((h - STATUS) / 4)},
                                 {2, ISO * (BUTTON + 4) + 8}, {2, CUT * (BUTTON + 4) + 8}};

    if (w > MAX_WIDTH) return 1;
    facet_config_init(&cfg);
    cfg.display.x = PANEL, cfg.display.width = (uint16_t)(w - PANEL), cfg.display.height = (uint16_t)(h - STATUS);
    cfg.display.buffers[0] = bands[0], cfg.display.buffers[1] = bands[1], cfg.display.depth[0] = depth;
    cfg.display.band_lines = LINES, cfg.display.flush = flush;
    cfg.on_event = on_event, cfg.now_us = port_now_us;
    cfg.interface = FACET_INTERFACE_OFF; /* the product's interface, not facet's */
    viewer = facet_create(&cfg, workspace, sizeof workspace, &why);
    if (viewer) {
        const void *pack = port_pack(&bytes, &memory, &memory_bytes);
        why = facet_load(viewer, pack, bytes, memory, memory_bytes);
    }
    if (!viewer || why.status != FACET_OK)
        return facet_describe(&why, status, sizeof status), port_log(status), 1;
    strncat(measured, facet_get_model(viewer).name, sizeof measured - 1); /* (its name, as long as it fits) */
    paint();
    for (;;) {
        while (port_poll(&key, &x, &y, &down, &is_touch))
            if (is_touch) touch(x, y, down);
        if (facet_step(viewer, 5000) != FACET_ACTIVITY_IDLE) continue;
        if (step < sizeof script / sizeof script[0]) touch(script[step][0], script[step][1], 1), touch(script[step][0], script[step][1], 0), ++step;
        else if (port_idle()) return 0; /* (the demo is over; a product waits for input) */
    }
}
