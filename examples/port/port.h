/* What the examples need from the product they live in: its panel, its input, a clock and the
 * pack (in flash or RAM). examples/port/ has these for the QEMU boards and the host (each built
 * with PORT_NAME, the example's name, for its log lines and screenshot); in a product they are
 * a few lines over its own drivers. */
#ifndef PORT_H
#define PORT_H

#include "facet/facet.h"

#include <stdint.h>

uint16_t port_width(void);
uint16_t port_height(void);
/* Copies an area (width * height pixels, row after row) onto the panel. */
void port_display_write(const facet_area *area, const facet_rgb565 *pixels);
/* The pack file, and memory to inflate it in (NULL, 0 for a plain pack in flash). */
const void *port_pack(uint32_t *bytes, void **memory, uint32_t *memory_bytes);
/* The next input: 1 and a key (or a touch) when there is one, 0 otherwise. */
int port_poll(uint32_t *key, int16_t *x, int16_t *y, int *touch_down, int *is_touch);
uint32_t port_now_us(void *user);
void port_log(const char *line);
/* Called when the viewer has nothing left to do; 1: leave the loop (a test is done). */
int port_idle(void);

/* Where large buffers go: a board puts them in its external RAM with a linker section. */
#ifdef PORT_LARGE_SECTION
#define PORT_LARGE __attribute__((section(PORT_LARGE_SECTION)))
#else
#define PORT_LARGE
#endif

#endif
