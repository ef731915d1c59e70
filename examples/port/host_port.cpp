// The examples' port (port.h) on the host: a screen in memory, the pack from
// a file; at idle the screen is written as an F565 image (tools/img.py) and the example ends.
//
//   facet-example-NAME MODEL.fpk OUT.f565 [WIDTHxHEIGHT]
#include "hal/fake.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" {
#include "port.h"
int app_main(void);
}

namespace {
uint16_t width = 480, height = 272;
std::vector<facet::Rgb565> screen;
std::vector<uint32_t> file, memory;
uint32_t file_bytes = 0;
std::string out;
} // namespace

extern "C" uint16_t port_width(void) { return width; }
extern "C" uint16_t port_height(void) { return height; }

extern "C" void port_display_write(const facet_area* a, const facet_rgb565* pixels) {
    for (uint16_t y = 0; y < a->height; ++y)
        std::memcpy(&screen[size_t(a->y + y) * width + a->x], pixels + size_t(y) * a->width, size_t(a->width) * 2);
}

extern "C" const void* port_pack(uint32_t* bytes, void** mem, uint32_t* mem_bytes) {
    *bytes = file_bytes;
    *mem = memory.data();
    *mem_bytes = uint32_t(memory.size() * 4);
    return file.data();
}

extern "C" int port_poll(uint32_t*, int16_t*, int16_t*, int*, int*) { return 0; }

extern "C" uint32_t port_now_us(void*) {
    using namespace std::chrono;
    return uint32_t(duration_cast<microseconds>(steady_clock::now().time_since_epoch()).count());
}

extern "C" void port_log(const char* line) { std::printf(PORT_NAME ": %s\n", line); }

extern "C" int port_idle(void) {
    if (!facet::hal::fake::write_f565(out, screen, width, height)) std::fprintf(stderr, PORT_NAME ": cannot write %s\n", out.c_str());
    return 1;
}

int main(int argc, char** argv) {
    int w = 0, h = 0;
    if (argc < 3 || (argc == 4 && (std::sscanf(argv[3], "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 640 || h > 4096))) {
        std::fprintf(stderr, "usage: facet-example-" PORT_NAME " MODEL.fpk OUT.f565 [WIDTHxHEIGHT (at most 640 wide)]\n");
        return 2;
    }
    if (argc == 4) width = uint16_t(w), height = uint16_t(h);
    std::ifstream in(argv[1], std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.eof() && !in.good()) {
        std::fprintf(stderr, PORT_NAME ": cannot read %s\n", argv[1]);
        return 1;
    }
    file.assign(bytes.size() / 4 + 1, 0);
    std::memcpy(file.data(), bytes.data(), bytes.size());
    file_bytes = uint32_t(bytes.size());
    memory.assign(facet_pack_memory_bytes(file.data(), file_bytes) / 4 + 1, 0);
    screen.assign(size_t(width) * height, 0);
    out = argv[2];
    return app_main();
}
