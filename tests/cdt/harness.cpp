#include "harness.h"

#include <cmath>

namespace facet::cdt::test {

std::vector<Point> rectangle(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int per_side, bool ccw) {
    std::vector<Point> p;
    for (int i = 0; i < per_side; ++i) p.push_back({x0 + int32_t(int64_t(x1 - x0) * i / per_side), y0});
    for (int i = 0; i < per_side; ++i) p.push_back({x1, y0 + int32_t(int64_t(y1 - y0) * i / per_side)});
    for (int i = 0; i < per_side; ++i) p.push_back({x1 - int32_t(int64_t(x1 - x0) * i / per_side), y1});
    for (int i = 0; i < per_side; ++i) p.push_back({x0, y1 - int32_t(int64_t(y1 - y0) * i / per_side)});
    if (!ccw) std::reverse(p.begin(), p.end());
    return p;
}

std::vector<Point> circle(int32_t cx, int32_t cy, int32_t r, int n, bool ccw) {
    std::vector<Point> p;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n * (ccw ? 1 : -1);
        p.push_back({cx + int32_t(std::lround(r * std::cos(a))), cy + int32_t(std::lround(r * std::sin(a)))});
    }
    return p;
}

} // namespace facet::cdt::test
