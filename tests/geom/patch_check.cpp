// The fixed-point patches (geom/patches.h) against the B-spline evaluation they replace, on
// every B-spline surface of real packs: points and their derivatives (for normals) over each
// surface's whole parameter range (a
// grid through every knot, the knots themselves, points just outside), in a cache that holds
// every span and in one that holds a single patch (every span change converts again).
//
//   facet-patch-check PACK_OR_DIR...     exit 1 if a point strays past the bound
//
// The bounds: points within 1e-6 of the model's bounding-box diagonal, a thousandth of the
// default tessellation tolerance (0.1% of the diagonal); derivatives (they make the vertex
// normals) within 5e-3 of the surface's largest: a normal within about 0.3 degrees, a tenth
// of one shading step of an RGB565 screen. The float B-spline derivatives are no better at
// the corners of short spans, where both come from cancelling sums (tail_section_asm:
// 2.1e-3 at a corner of surface 183; elsewhere under 1e-4).
#include "geom/eval.h"
#include "geom/pack.h"
#include "geom/patches.h"
#include "geom/tessellate.h"
#include "pack_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

struct Worst {
    double error = 0;      // over the diagonal
    double derivative = 0; // over the surface's largest derivative
    uint32_t surface = 0;
    float u = 0, v = 0;
    uint32_t points = 0, surfaces = 0, skipped = 0;
};

// Parameter values along one direction: every knot, the midpoints and quarter points of each
// span, and a little outside the range.
std::vector<float> params(const float* knots, int count) {
    std::vector<float> t;
    for (int i = 0; i < count; ++i) {
        t.push_back(knots[i]);
        if (i + 1 < count && knots[i + 1] > knots[i]) {
            for (int k = 1; k < 4; ++k) t.push_back(knots[i] + (knots[i + 1] - knots[i]) * float(k) / 4);
        }
    }
    const float span = knots[count - 1] - knots[0];
    t.push_back(knots[0] - 0.01f * span);
    t.push_back(knots[count - 1] + 0.01f * span);
    return t;
}

void check_surface(const Pack& pack, uint32_t s, double diagonal, std::vector<uint32_t>& memory, Worst& w) {
    const pack::Surface& S = pack.surfaces()[s];
    const float* q = pack.floats().data() + S.params;
    const int ku = int(q[4]), kv = int(q[5]);
    const std::vector<float> us = params(q + 9, ku), vs = params(q + 9 + ku, kv);
    PatchCache cache(pack, S, memory);
    if (!cache.usable()) {
        ++w.skipped;
        return;
    }
    ++w.surfaces;
    auto distance = [](Vec3 a, Vec3 b) {
        return std::sqrt(double(a.x - b.x) * (a.x - b.x) + double(a.y - b.y) * (a.y - b.y) + double(a.z - b.z) * (a.z - b.z));
    };
    double largest = 0, off = 0; // derivatives: the largest, and the largest difference
    for (float u : us) {
        for (float v : vs) {
            const Vec3 a = cache.point(u, v), b = eval_surface_point(pack, S, u, v);
            const double e = distance(a, b) / diagonal;
            ++w.points;
            if (e > w.error || e != e) w.error = e, w.surface = s, w.u = u, w.v = v;
            const SurfacePoint da = cache.point_and_derivatives(u, v), db = eval_surface(pack, S, u, v);
            const double ep = distance(da.p, db.p) / diagonal;
            if (ep > w.error || ep != ep) w.error = ep, w.surface = s, w.u = u, w.v = v;
            largest = std::max({largest, distance(db.du, {0, 0, 0}), distance(db.dv, {0, 0, 0})});
            const double d = std::max(distance(da.du, db.du), distance(da.dv, db.dv));
            off = d != d ? d : std::max(off, d);
        }
    }
    const double rel = largest > 0 ? off / largest : off;
    if (rel > w.derivative || rel != rel) w.derivative = rel;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::filesystem::is_directory(argv[i])) {
            for (const auto& e : std::filesystem::directory_iterator(argv[i]))
                if (e.path().extension() == ".fpk") files.push_back(e.path().string());
        } else {
            files.push_back(argv[i]);
        }
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) {
        std::fprintf(stderr, "usage: facet-patch-check PACK_OR_DIR...\n");
        return 2;
    }
    constexpr double kBound = 1e-6, kDerivativeBound = 5e-3;
    bool failed = false;
    for (const std::string& f : files) {
        LoadedPack lp;
        std::string error;
        Pack pack;
        if (!load_pack_file(f, lp, error) || !pack.open(lp.data(), lp.bytes).ok()) {
            std::printf("FAIL %s: cannot read (%s)\n", f.c_str(), error.c_str());
            failed = true;
            continue;
        }
        const double diagonal = double(default_tolerance(pack)) * 1000;
        Worst big, small;
        for (uint32_t s = 0; s < pack.surfaces().size(); ++s) {
            if (pack.surfaces()[s].type != uint8_t(pack::SurfaceType::BSpline)) continue;
            std::vector<uint32_t> all(kPatchCacheWords), one;
            const float* q = pack.floats().data() + pack.surfaces()[s].params;
            one.resize(1 + PatchCache::slot_words(int(q[0]), int(q[1]), q[6] != 0));
            check_surface(pack, s, diagonal, all, big);
            check_surface(pack, s, diagonal, one, small);
        }
        const double worst = std::max(big.error, small.error);
        const bool bad = !(worst <= kBound) || !(big.derivative <= kDerivativeBound) || big.error != small.error;
        failed |= bad;
        const Worst& w = big.error >= small.error ? big : small;
        std::printf("%s %s: %u B-spline surfaces (%u of a degree over %d, in float), %u points; largest difference "
                    "%.2e of the diagonal (surface %u at %g, %g), of the derivatives %.2e of the largest%s\n",
                    bad ? "FAIL" : "ok", std::filesystem::path(f).filename().c_str(), big.surfaces, big.skipped,
                    kMaxPatchDegree, big.points, worst, w.surface, double(w.u), double(w.v), big.derivative,
                    big.error != small.error ? "; a one-patch cache differs" : "");
    }
    return failed ? 1 : 0;
}
