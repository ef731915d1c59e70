#include "harness.h"

#include <cmath>
#include <random>

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

Face random_face(uint32_t seed, int max_outer, int points) {
    std::mt19937 rng(seed);
    Face f;
    const int n = 20 + int(rng() % uint32_t(max_outer));
    std::vector<double> ang(n);
    for (double& a : ang) a = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    std::sort(ang.begin(), ang.end());
    std::vector<Point> outer;
    for (double a : ang) {
        const double r = std::uniform_real_distribution<double>(60000, 100000)(rng);
        outer.push_back({int32_t(r * std::cos(a)), int32_t(r * std::sin(a))});
    }
    f.add_loop(outer); // star-shaped around the origin: simple and counter-clockwise
    const int holes = int(rng() % 12);
    for (int h = 0; h < holes; ++h) {
        const int cx = -40000 + (h % 4) * 25000, cy = -30000 + (h / 4) * 25000;
        f.add_loop(circle(cx, cy, 4000 + int(rng() % 6000), 3 + int(rng() % 30), false));
    }
    std::uniform_int_distribution<int32_t> d(-110000, 110000);
    for (int i = 0; i < points; ++i) f.interior.push_back({d(rng), d(rng)});
    return f;
}

} // namespace facet::cdt::test
