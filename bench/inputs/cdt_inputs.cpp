#include "cdt_inputs.h"

#include <cmath>
#include <cstring>

namespace facet::bench {

const char* const kInputNames[] = {"paper",      "plate1k",      "plate10k",      "plate100k",
                                   "plate1M",    "plate1k+grid", "plate10k+grid", "plate100k+grid",
                                   "plate1M+grid", "lattice317", "circle100k",   "touch5000"};
const size_t kInputCount = sizeof kInputNames / sizeof kInputNames[0];

namespace {

using cdt::Point;

// Writes an input into the buffers, or (count_only) just counts what it would write.
struct Builder {
    const InputBuffers& b;
    bool count_only = false;
    size_t np = 0, nl = 0, ni = 0;
    bool ok = true;

    void begin_loop() {
        if (count_only) ++nl;
        else if (nl == b.loops_capacity) ok = false;
        else b.loop_sizes[nl++] = 0;
    }
    void point(int32_t x, int32_t y) {
        if (count_only) {
            ++np;
        } else if (!ok || nl == 0 || np == b.loop_capacity) {
            ok = false;
        } else {
            b.loop_points[np++] = {x, y};
            ++b.loop_sizes[nl - 1];
        }
    }
    void inner(int32_t x, int32_t y) {
        if (count_only) ++ni;
        else if (ni == b.interior_capacity) ok = false;
        else b.interior[ni++] = {x, y};
    }
    void rectangle(int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t segments) {
        begin_loop();
        const uint32_t per = segments / 4, extra = segments % 4;
        const uint32_t n[4] = {per + (extra > 0), per + (extra > 1), per + (extra > 2), per};
        for (uint32_t i = 0; i < n[0]; ++i) point(x0 + int32_t(int64_t(x1 - x0) * i / n[0]), y0);
        for (uint32_t i = 0; i < n[1]; ++i) point(x1, y0 + int32_t(int64_t(y1 - y0) * i / n[1]));
        for (uint32_t i = 0; i < n[2]; ++i) point(x1 - int32_t(int64_t(x1 - x0) * i / n[2]), y1);
        for (uint32_t i = 0; i < n[3]; ++i) point(x0, y1 - int32_t(int64_t(y1 - y0) * i / n[3]));
    }
    void circle(int32_t cx, int32_t cy, int32_t r, uint32_t n, bool ccw) {
        begin_loop();
        for (uint32_t i = 0; i < n; ++i) {
            const double a = 6.283185307179586 * i / n * (ccw ? 1 : -1);
            point(cx + int32_t(std::lround(r * std::cos(a))), cy + int32_t(std::lround(r * std::sin(a))));
        }
    }
};

// An outer rectangle and k = 0.9 N / 32 holes of 32 segments on a square grid; the outer loop
// takes the remaining segments. Optionally a jittered grid of about N interior points.
void plate(Builder& b, uint32_t segments, bool grid) {
    const uint32_t holes = segments * 9 / 10 / 32;
    const uint32_t outer = segments - 32 * holes;
    uint32_t side = 1;
    while (side * side < holes) ++side;
    const int32_t cell = (1 << 23) / int32_t(side), half = int32_t(side) * cell / 2;
    b.rectangle(-half - cell / 2, -half - cell / 2, half + cell / 2, half + cell / 2, outer);
    for (uint32_t h = 0; h < holes; ++h) {
        const int32_t cx = -half + cell / 2 + int32_t(h % side) * cell;
        const int32_t cy = -half + cell / 2 + int32_t(h / side) * cell;
        b.circle(cx, cy, cell * 3 / 10, 32, false);
    }
    if (!grid) return;
    uint32_t g = 1;
    while (g * g < segments) ++g;
    const int32_t step = (2 * half + cell) / int32_t(g + 1);
    uint32_t state = 12345;
    for (uint32_t y = 1; y <= g; ++y) {
        for (uint32_t x = 1; x <= g; ++x) {
            state = state * 1103515245u + 12345u;
            const int32_t jx = int32_t((state >> 8) % 101) - 50, jy = int32_t((state >> 16) % 101) - 50;
            b.inner(-half - cell / 2 + int32_t(x) * step + jx * step / 400,
                    -half - cell / 2 + int32_t(y) * step + jy * step / 400);
        }
    }
}

bool build(const char* name, Builder& b) {
    if (!std::strcmp(name, "paper")) {
        b.begin_loop();
        for (int i = 0; i < 16; ++i) b.point(i * 1000, 0);
        for (int i = 0; i < 7; ++i) b.point(16000, i * 1000);
        for (int i = 0; i < 16; ++i) b.point(16000 - i * 1000, 7000);
        for (int i = 0; i < 7; ++i) b.point(0, 7000 - i * 1000);
        b.circle(8000, 3500, 2200, 64, false);
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 11; ++x) b.inner(700 + x * 1460, 600 + y * 1160);
        return true;
    }
    if (!std::strncmp(name, "plate", 5)) {
        const char* p = name + 5;
        uint32_t n = 0;
        while (*p >= '0' && *p <= '9') n = n * 10 + uint32_t(*p++ - '0');
        if (*p == 'k') n *= 1000, ++p;
        else if (*p == 'M') n *= 1000000, ++p;
        const bool grid = !std::strcmp(p, "+grid");
        if (!grid && *p) return false;
        plate(b, n, grid);
        return true;
    }
    if (!std::strcmp(name, "lattice317")) {
        constexpr int32_t n = 317, s = 1000;
        b.rectangle(0, 0, (n - 1) * s, (n - 1) * s, 4 * (n - 1));
        for (int32_t y = 1; y < n - 1; ++y)
            for (int32_t x = 1; x < n - 1; ++x) b.inner(x * s, y * s);
        return true;
    }
    if (!std::strcmp(name, "circle100k")) {
        b.circle(0, 0, 1 << 23, 100000, true);
        return true;
    }
    if (!std::strcmp(name, "touch5000")) {
        constexpr int32_t n = 100, s = 1000;
        b.rectangle(-s, -s, (n + 1) * s, (n + 1) * s, 4);
        for (int32_t y = 0; y < n; ++y)
            for (int32_t x = 0; x < n; ++x)
                if ((x + y) % 2 == 0) {
                    b.begin_loop();
                    b.point(x * s, y * s);
                    b.point(x * s, (y + 1) * s);
                    b.point((x + 1) * s, (y + 1) * s);
                    b.point((x + 1) * s, y * s);
                }
        return true;
    }
    return false;
}

} // namespace

bool input_size(const char* name, InputSize& size) {
    const InputBuffers none{nullptr, 0, nullptr, 0, nullptr, 0};
    Builder b{none, true};
    if (!build(name, b)) return false;
    size = {b.np, b.nl, b.ni};
    return true;
}

bool make_input(const char* name, const InputBuffers& buffers, Input& out) {
    Builder b{buffers};
    if (!build(name, b) || !b.ok) return false;
    out.face = {{buffers.loop_points, b.np}, {buffers.loop_sizes, b.nl}, {buffers.interior, b.ni}};
    out.segments = uint32_t(b.np);
    return true;
}

} // namespace facet::bench
