// The examples' port (port.h) for the QEMU boards: the board's display with a
// frame in RAM it scans out, the UART's keys, the board's clock, the pack its runner loaded.
// At idle it takes the screenshot the test compares (PORT_NAME) and ends the example.
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"

extern "C" {
#include "port.h"
int app_main(void);
}

namespace {

using namespace facet;
constexpr uint16_t kW = board_config::kDisplayWidth, kH = board_config::kDisplayHeight;
alignas(64) __attribute__((section(".framebuffers"))) Rgb565 frame[uint32_t(kW) * kH];
// A board whose pack region is flash (the EVKB's configuration) inflates a deflated pack into
// RAM of its own; the others inflate it in place.
constexpr uint32_t kPackMemory = board_config::kPackWritable ? 8 : board_config::kPackMemoryBytes;
alignas(8) __attribute__((section(".pack_memory"))) uint8_t pack_memory[kPackMemory];
hal::Board* board;

} // namespace

extern "C" uint16_t port_width(void) { return kW; }
extern "C" uint16_t port_height(void) { return kH; }

extern "C" void port_display_write(const facet_area* a, const facet_rgb565* pixels) {
    if (Status s = board->display.write({a->x, a->y, a->width, a->height}, pixels); !ok(s)) {
        print(board->console, PORT_NAME ": the display refused an area ({})\n", s);
    }
}

extern "C" const void* port_pack(uint32_t* bytes, void** memory, uint32_t* memory_bytes) {
    // The runner loads the file at the start of the pack region; it is inflated in place there,
    // or into pack_memory when the region is flash.
    void* region = reinterpret_cast<void*>(board_config::kPackAddress);
    *bytes = board_config::kPackBytes;
    *memory = board_config::kPackWritable ? region : static_cast<void*>(pack_memory);
    *memory_bytes = board_config::kPackWritable ? board_config::kPackBytes : uint32_t(sizeof pack_memory);
    return region;
}

extern "C" int port_poll(uint32_t* key, int16_t*, int16_t*, int*, int* is_touch) {
    hal::InputEvent e;
    while (board->input.poll(e)) {
        if (e.kind != hal::InputEvent::Kind::Key) continue; // the mouse: not in this example
        *key = e.key;
        *is_touch = 0;
        return 1;
    }
    return 0;
}

extern "C" uint32_t port_now_us(void*) {
    return uint32_t(board->clock.ticks() * 1'000'000 / board->clock.ticks_per_second());
}

extern "C" void port_log(const char* line) { print(board->console, PORT_NAME ": {}\n", line); }

// Idle: the test's screenshot, and the example is done (a product would wait for input).
extern "C" int port_idle(void) {
    print(board->console, PORT_NAME ": idle\n");
    const Status s = board->capture ? board->capture->shot(PORT_NAME) : Status::Unsupported;
    if (!ok(s)) print(board->console, PORT_NAME ": no screenshot ({})\n", s);
    return 1;
}

int facet_main(hal::Board& b) {
    board = &b;
    if (Status s = b.display.show(frame); !ok(s)) {
        print(b.console, PORT_NAME ": the display refused the frame ({})\n", s);
        return 1;
    }
    return app_main();
}
