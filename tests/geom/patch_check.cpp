// The fixed-point patches (geom/patches.h) against the B-spline surface itself, on every
// B-spline surface of real packs (and the fixed-point curve spans against every 3D B-spline
// curve they take): points and their derivatives (for normals) over each
// surface's whole parameter range (a
// grid through every knot, the knots themselves, points just outside), in a cache that holds
// every span and in one that holds a single patch (every span change converts again), and
// in one kept from surface to surface, over every pack, that began as noise (the span matrices
// it keeps are found by their knots, and checked: the same points as a fresh cache's).
//
//   facet-patch-check PACK_OR_DIR...     exit 1 if a point strays past the bound
//
// The bounds: points within 1e-6 of the model's bounding-box diagonal, a thousandth of the
// default tessellation tolerance (0.1% of the diagonal); derivatives (they make the vertex
// normals) within 5e-3 of the surface's largest: a normal within about 0.3 degrees, a tenth
// of one shading step of an RGB565 screen. The reference is the B-spline evaluation in double
// (the device's own basis functions, in double): the float evaluation the patches replace is
// itself off by up to 1.3% in the derivatives on linkrods' short spans (v spans of 1.4e-4),
// where the Bézier patches agree with a double-precision finite difference to 1e-5.
#include "bspline.h"
#include "geom/eval.h"
#include "geom/pack.h"
#include "geom/patches.h"
#include "geom/tessellate.h"
#include "pack_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

struct SurfacePointD {
    double p[3], du[3], dv[3];
};

struct Worst {
    double error = 0;      // over the diagonal
    double derivative = 0; // over the surface's largest derivative
    uint32_t surface = 0;
    float u = 0, v = 0;
    uint32_t points = 0, surfaces = 0, skipped = 0;
    uint32_t unresolved = 0; // points on spans too short for float parameters: derivatives not compared
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

// The surface's point and first derivatives, in double.
SurfacePointD reference(const BSplineSurfaceView& B, float u, float v) {
    double Nu[kMaxDegree + 1], dNu[kMaxDegree + 1], Nv[kMaxDegree + 1], dNv[kMaxDegree + 1];
    const int su = detail::basis<double>(B.uk, B.nu, B.pu, u, B.u_periodic, Nu, dNu);
    const int sv = detail::basis<double>(B.vk, B.nv, B.pv, v, B.v_periodic, Nv, dNv);
    double A[4] = {}, Au[4] = {}, Av[4] = {};
    for (int a = 0; a <= B.pu; ++a) {
        for (int b = 0; b <= B.pv; ++b) {
            const int at = (su - B.pu + a) * B.nv + sv - B.pv + b;
            const double w = B.rational ? B.weights[at] : 1.0;
            const double H[4] = {B.poles[3 * at] * w, B.poles[3 * at + 1] * w, B.poles[3 * at + 2] * w, w};
            for (int d = 0; d < 4; ++d) {
                A[d] += Nu[a] * Nv[b] * H[d], Au[d] += dNu[a] * Nv[b] * H[d], Av[d] += Nu[a] * dNv[b] * H[d];
            }
        }
    }
    SurfacePointD r;
    for (int d = 0; d < 3; ++d) {
        r.p[d] = A[d] / A[3];
        r.du[d] = (Au[d] - r.p[d] * Au[3]) / A[3];
        r.dv[d] = (Av[d] - r.p[d] * Av[3]) / A[3];
    }
    return r;
}

// Whether the spans of (u, v) are long enough for float parameters to resolve: at least 1e-4
// of the knot range. linkrods' fillets have clusters of knots within 1e-6 that rounding to
// float merged (a knot of multiplicity 72 at degree 10): the surface jumps there, and its
// derivative over a span one or two float steps long is not defined by the stored data. The
// points are still compared there.
bool resolved(const BSplineSurfaceView& B, float u, float v) {
    const int su = detail::find_span(B.uk, B.nu, B.pu, u, B.u_periodic), sv = detail::find_span(B.vk, B.nv, B.pv, v, B.v_periodic);
    return B.uk[su + 1] - B.uk[su] >= 1e-4f * (B.uk[B.ku - 1] - B.uk[0]) && B.vk[sv + 1] - B.vk[sv] >= 1e-4f * (B.vk[B.kv - 1] - B.vk[0]);
}

void check_surface(const Pack& pack, uint32_t s, double diagonal, std::vector<uint32_t>& memory, Worst& w) {
    const pack::Surface& S = pack.surfaces()[s];
    const BSplineSurfaceView B = bspline(pack, S);
    const std::vector<float> us = params(B.uk, B.ku), vs = params(B.vk, B.kv);
    PatchCache cache(pack, S, memory);
    if (!cache.usable()) {
        ++w.skipped;
        return;
    }
    ++w.surfaces;
    auto distance = [](Vec3 a, const double* b) {
        const double x = a.x - b[0], y = a.y - b[1], z = a.z - b[2];
        return std::sqrt(x * x + y * y + z * z);
    };
    double largest = 0, off = 0; // derivatives: the largest, and the largest difference
    for (float u : us) {
        for (float v : vs) {
            const SurfacePointD ref = reference(B, u, v);
            const double e = distance(cache.point(u, v), ref.p) / diagonal;
            ++w.points;
            if (e > w.error || e != e) w.error = e, w.surface = s, w.u = u, w.v = v;
            const SurfacePoint da = cache.point_and_derivatives(u, v);
            const double ep = distance(da.p, ref.p) / diagonal;
            if (ep > w.error || ep != ep) w.error = ep, w.surface = s, w.u = u, w.v = v;
            largest = std::max({largest, distance({0, 0, 0}, ref.du), distance({0, 0, 0}, ref.dv)});
            if (!resolved(B, u, v)) {
                ++w.unresolved;
                continue;
            }
            const double d = std::max(distance(da.du, ref.du), distance(da.dv, ref.dv));
            off = d != d ? d : std::max(off, d);
        }
    }
    const double rel = largest > 0 ? off / largest : off;
    if (rel > w.derivative || rel != rel) w.derivative = rel;
}

// A B-spline curve's point and derivative (dim 2 or 3), in double.
void curve_reference(const BSplineCurveView& C, int dim, float t, double p[3], double d[3]) {
    double N[kMaxDegree + 1], dN[kMaxDegree + 1];
    const int s = detail::basis<double>(C.knots, C.n, C.p, t, C.periodic, N, dN);
    double A[4] = {}, dA[4] = {};
    for (int j = 0; j <= C.p; ++j) {
        const int i = s - C.p + j;
        const double w = C.rational ? C.weights[i] : 1.0;
        double H[4] = {0, 0, 0, w};
        for (int k = 0; k < dim; ++k) H[k] = C.poles[dim * i + k] * w;
        for (int k = 0; k < 4; ++k) A[k] += N[j] * H[k], dA[k] += dN[j] * H[k];
    }
    for (int k = 0; k < 3; ++k) p[k] = A[k] / A[3], d[k] = (dA[k] - p[k] * dA[3]) / A[3];
}

// The fixed-point curve spans (CurveSpans: the edge sampler's 3D B-splines and the loops'
// B-spline pcurves) against the curve in double, over every knot, quarter points and past the
// ends; the same bounds (a pcurve's over its own size: the larger of its extent and its
// largest coordinate, since its points come back as floats, rounded relative to their size).
void check_curve(const Pack& pack, const pack::Curve& C, uint32_t c, double diagonal, Worst& w) {
    CurveSpans spans;
    spans.bind(pack, C);
    if (!spans.usable()) return;
    ++w.surfaces;
    const int dim = C.dim;
    const BSplineCurveView V = bspline(pack, C);
    if (dim == 2) { // the pcurve's own size
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, big = 0;
        for (int i = 0; i < V.n; ++i) {
            for (int k = 0; k < 2; ++k) {
                const double x = V.poles[2 * i + k];
                lo[k] = std::min(lo[k], x), hi[k] = std::max(hi[k], x), big = std::max(big, std::fabs(x));
            }
        }
        diagonal = std::max({std::hypot(hi[0] - lo[0], hi[1] - lo[1]), big, 1e-30});
    }
    double largest = 0, off = 0;
    for (float t : params(V.knots, V.k)) {
        double p[3], d[3];
        curve_reference(V, dim, t, p, d);
        std::vector<Vec3> got;
        if (dim == 3) got = {spans.point(t), spans.point_and_derivative(t).p};
        else got = {Vec3{spans.point2(t).x, spans.point2(t).y, 0}};
        ++w.points;
        for (Vec3 x : got) {
            const double e = std::sqrt((x.x - p[0]) * (x.x - p[0]) + (x.y - p[1]) * (x.y - p[1]) + (x.z - p[2]) * (x.z - p[2])) / diagonal;
            if (e > w.error || e != e) w.error = e, w.surface = c, w.u = t;
        }
        if (dim == 2) continue; // (pcurves: positions only)
        const Curve3Point b = spans.point_and_derivative(t);
        float tt = t;
        const int s = detail::find_span(V.knots, V.n, V.p, tt, V.periodic);
        largest = std::max(largest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        if (!(V.knots[s + 1] - V.knots[s] >= 1e-4f * (V.knots[V.k - 1] - V.knots[0]))) {
            ++w.unresolved;
            continue;
        }
        const double e = std::sqrt((b.d.x - d[0]) * (b.d.x - d[0]) + (b.d.y - d[1]) * (b.d.y - d[1]) + (b.d.z - d[2]) * (b.d.z - d[2]));
        off = e != e ? e : std::max(off, e);
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
    std::vector<uint32_t> kept_memory(kPatchCacheWords);
    uint32_t noise = 12345;
    for (uint32_t& w : kept_memory) w = noise = noise * 1664525u + 1013904223u;
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
        Worst big, small, kept;
        for (uint32_t s = 0; s < pack.surfaces().size(); ++s) {
            if (pack.surfaces()[s].type != uint8_t(pack::SurfaceType::BSpline)) continue;
            std::vector<uint32_t> all(kPatchCacheWords), one;
            const BSplineSurfaceView B = bspline(pack, pack.surfaces()[s]);
            one.resize(1 + PatchCache::slot_words(B.pu, B.pv, B.rational));
            check_surface(pack, s, diagonal, all, big);
            check_surface(pack, s, diagonal, one, small);
            PatchCache::forget(kept_memory); // (as each face's tessellation begins)
            check_surface(pack, s, diagonal, kept_memory, kept);
        }
        const bool kept_differs = kept.error != big.error || kept.derivative != big.derivative;
        const double worst = std::max(big.error, small.error);
        const bool bad = !(worst <= kBound) || !(big.derivative <= kDerivativeBound) || big.error != small.error || kept_differs;
        failed |= bad;
        const Worst& w = big.error >= small.error ? big : small;
        std::printf("%s %s: %u B-spline surfaces (%u of a degree over %d, in float), %u points; largest difference "
                    "%.2e of the diagonal (surface %u at %g, %g), of the derivatives %.2e of the largest (%u points on "
                    "unresolved spans)%s%s\n",
                    bad ? "FAIL" : "ok", std::filesystem::path(f).filename().c_str(), big.surfaces, big.skipped,
                    kMaxBezierDegree, big.points, worst, w.surface, double(w.u), double(w.v), big.derivative, big.unresolved,
                    big.error != small.error ? "; a one-patch cache differs" : "",
                    kept_differs ? "; a cache kept from surface to surface differs" : "");
        for (int dim : {3, 2}) {
            Worst curves;
            const auto list = dim == 3 ? pack.curves3() : pack.curves2();
            for (uint32_t c = 0; c < list.size(); ++c) check_curve(pack, list[c], c, diagonal, curves);
            const bool bad_curve = !(curves.error <= kBound) || !(curves.derivative <= kDerivativeBound);
            failed |= bad_curve;
            if (!curves.surfaces) continue;
            std::printf("%s %s: %u B-spline %s in fixed point (degrees up to %d), %u points; largest difference %.2e "
                        "of the %s (curve %u at %g), of the derivatives %.2e of the largest (%u points on "
                        "unresolved spans)\n",
                        bad_curve ? "FAIL" : "ok", std::filesystem::path(f).filename().c_str(), curves.surfaces,
                        dim == 3 ? "curves" : "pcurves", kMaxBezierDegree, curves.points, curves.error,
                        dim == 3 ? "diagonal" : "pcurve's size", curves.surface, double(curves.u), curves.derivative,
                        curves.unresolved);
        }
    }
    return failed ? 1 : 0;
}
