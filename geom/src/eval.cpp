#include "geom/eval.h"
#include "bspline.h"
#include "geom/elementary.h"
#include "geom/fmath.h"

namespace facet::geom {
namespace {

using namespace facet::pack;
using detail::basis;

// w turned about the unit axis D by the angle whose cosine and sine are cu and su (Rodrigues).
Vec3 turn(Vec3 D, Vec3 w, float cu, float su) { return w * cu + cross(D, w) * su + D * (dot(D, w) * (1 - cu)); }

// A B-spline curve of dimension dim at t: position and derivative (rational by the quotient rule).
// der null: the position alone (the same value: the same sums, without the derivative's).
void bspline_curve(const Pack& pack, const Curve& c, int dim, float t, float* pos, float* der) {
    const BSplineCurveView C = bspline(pack, c);
    const int p = C.p;
    const bool rational = C.rational;
    const float *poles = C.poles, *weights = C.weights;
    float N[kMaxDegree + 1], dN[kMaxDegree + 1];
    const int s = basis(C.knots, C.n, p, t, C.periodic, N, der ? dN : nullptr);
    float A[3] = {0, 0, 0}, dA[3] = {0, 0, 0}, W = 0, dW = 0;
    for (int j = 0; j <= p; ++j) {
        const int i = s - p + j;
        const float w = rational ? weights[i] : 1.0f;
        for (int c = 0; c < dim; ++c) A[c] += N[j] * w * poles[i * dim + c];
        W += N[j] * w;
        if (!der) continue;
        for (int c = 0; c < dim; ++c) dA[c] += dN[j] * w * poles[i * dim + c];
        dW += dN[j] * w;
    }
    if (W == 0) W = 1;
    for (int c = 0; c < dim; ++c) {
        pos[c] = A[c] / W;
        if (der) der[c] = (dA[c] - pos[c] * dW) / W;
    }
}

} // namespace

bool u_periodic(const Surface& s) {
    return s.type == uint8_t(SurfaceType::Cylinder) || s.type == uint8_t(SurfaceType::Cone) ||
           s.type == uint8_t(SurfaceType::Sphere) || s.type == uint8_t(SurfaceType::Torus) ||
           s.type == uint8_t(SurfaceType::Revolution);
}
bool v_periodic(const Surface& s) { return s.type == uint8_t(SurfaceType::Torus); }

Curve3Point eval_curve3(const Pack& pack, const Curve& c, float t) {
    switch (CurveType(c.type)) {
    case CurveType::Line: {
        const Line3Params& L = params<Line3Params>(pack, c);
        return {vec3(L.origin) + vec3(L.direction) * t, vec3(L.direction)};
    }
    case CurveType::Circle: {
        const Circle3Params& C = params<Circle3Params>(pack, c);
        const float r = C.radius;
        float st, ct;
        sincos_f(t, st, ct);
        return {vec3(C.origin) + (vec3(C.x) * ct + vec3(C.y) * st) * r, (vec3(C.x) * -st + vec3(C.y) * ct) * r};
    }
    case CurveType::Ellipse: {
        const Ellipse3Params& E = params<Ellipse3Params>(pack, c);
        const float a = E.major, b = E.minor;
        float st, ct;
        sincos_f(t, st, ct);
        return {vec3(E.origin) + vec3(E.x) * (a * ct) + vec3(E.y) * (b * st), vec3(E.x) * (-a * st) + vec3(E.y) * (b * ct)};
    }
    case CurveType::BSpline: {
        float p[3], d[3];
        bspline_curve(pack, c, 3, t, p, d);
        return {{p[0], p[1], p[2]}, {d[0], d[1], d[2]}};
    }
    }
    return {};
}

Vec3 eval_curve3_point(const Pack& pack, const Curve& c, float t) {
    if (CurveType(c.type) != CurveType::BSpline) return eval_curve3(pack, c, t).p;
    float p[3];
    bspline_curve(pack, c, 3, t, p, nullptr);
    return {p[0], p[1], p[2]};
}

Curve2Point eval_curve2(const Pack& pack, const Curve& c, float t) {
    switch (CurveType(c.type)) {
    case CurveType::Line: {
        const Line2Params& L = params<Line2Params>(pack, c);
        return {{L.origin[0] + L.direction[0] * t, L.origin[1] + L.direction[1] * t}, {L.direction[0], L.direction[1]}};
    }
    case CurveType::Circle: {
        const Circle2Params& C = params<Circle2Params>(pack, c);
        const float r = C.radius;
        float st, ct;
        sincos_f(t, st, ct);
        return {{C.origin[0] + r * (C.x[0] * ct + C.y[0] * st), C.origin[1] + r * (C.x[1] * ct + C.y[1] * st)},
                {r * (-C.x[0] * st + C.y[0] * ct), r * (-C.x[1] * st + C.y[1] * ct)}};
    }
    case CurveType::Ellipse: {
        const Ellipse2Params& E = params<Ellipse2Params>(pack, c);
        const float a = E.major, b = E.minor;
        float st, ct;
        sincos_f(t, st, ct);
        return {{E.origin[0] + a * ct * E.x[0] + b * st * E.y[0], E.origin[1] + a * ct * E.x[1] + b * st * E.y[1]},
                {-a * st * E.x[0] + b * ct * E.y[0], -a * st * E.x[1] + b * ct * E.y[1]}};
    }
    case CurveType::BSpline: {
        float p[2], d[2];
        bspline_curve(pack, c, 2, t, p, d);
        return {{p[0], p[1]}, {d[0], d[1]}};
    }
    }
    return {};
}

SurfacePoint eval_surface(const Pack& pack, const Surface& s, float u, float v) {
    switch (SurfaceType(s.type)) {
    case SurfaceType::Plane:
    case SurfaceType::Cylinder:
    case SurfaceType::Cone:
    case SurfaceType::Sphere:
    case SurfaceType::Torus: return Elementary(pack, s).at(u, v);
    case SurfaceType::BSpline: {
        const BSplineSurfaceView B = bspline(pack, s);
        const int pu = B.pu, pv = B.pv, nv = B.nv;
        const bool rational = B.rational;
        const float *poles = B.poles, *weights = B.weights;
        float Nu[kMaxDegree + 1], dNu[kMaxDegree + 1], Nv[kMaxDegree + 1], dNv[kMaxDegree + 1];
        const int su = detail::u_basis(B, u, Nu, dNu), sv = detail::v_basis(B, v, Nv, dNv);
        Vec3 A{0, 0, 0}, Au{0, 0, 0}, Av{0, 0, 0};
        float W = 0, Wu = 0, Wv = 0;
        for (int a = 0; a <= pu; ++a) {
            const int i = su - pu + a;
            for (int b = 0; b <= pv; ++b) {
                const int j = sv - pv + b;
                const float w = rational ? weights[i * nv + j] : 1.0f;
                const float* pole = poles + 3 * (i * nv + j);
                const Vec3 P = Vec3{pole[0], pole[1], pole[2]} * w;
                A = A + P * (Nu[a] * Nv[b]);
                Au = Au + P * (dNu[a] * Nv[b]);
                Av = Av + P * (Nu[a] * dNv[b]);
                W += Nu[a] * Nv[b] * w;
                Wu += dNu[a] * Nv[b] * w;
                Wv += Nu[a] * dNv[b] * w;
            }
        }
        if (W == 0) W = 1;
        const Vec3 p = A * (1 / W);
        return {p, (Au - p * Wu) * (1 / W), (Av - p * Wv) * (1 / W)};
    }
    case SurfaceType::Revolution: {
        // C(v) turned by u about the axis (origin O, unit direction D).
        const RevolutionParams& R = params<RevolutionParams>(pack, s);
        const Vec3 O = vec3(R.axis_origin), D = normalized(vec3(R.axis_direction));
        const Curve3Point c = eval_curve3(pack, pack.curves3()[s.ref], v);
        float su, cu;
        sincos_f(u, su, cu);
        const Vec3 turned = turn(D, c.p - O, cu, su);
        return {O + turned, cross(D, turned), turn(D, c.d, cu, su)};
    }
    case SurfaceType::Extrusion: {
        const Curve3Point c = eval_curve3(pack, pack.curves3()[s.ref], u);
        const Vec3 D = vec3(params<ExtrusionParams>(pack, s).direction);
        return {c.p + D * v, c.d, D};
    }
    }
    return {};
}

Vec3 eval_surface_point(const Pack& pack, const Surface& s, float u, float v) {
    switch (SurfaceType(s.type)) {
    case SurfaceType::Revolution: { // as eval_surface's, without the derivatives (the same value)
        const RevolutionParams& R = params<RevolutionParams>(pack, s);
        const Vec3 O = vec3(R.axis_origin), D = normalized(vec3(R.axis_direction));
        float su, cu;
        sincos_f(u, su, cu);
        return O + turn(D, eval_curve3_point(pack, pack.curves3()[s.ref], v) - O, cu, su);
    }
    case SurfaceType::Extrusion:
        return eval_curve3_point(pack, pack.curves3()[s.ref], u) + vec3(params<ExtrusionParams>(pack, s).direction) * v;
    case SurfaceType::BSpline: break;
    default: return eval_surface(pack, s, u, v).p;
    }
    // The position alone: basis values without derivatives, one weighted sum of the poles.
    const BSplineSurfaceView B = bspline(pack, s);
    const int pu = B.pu, pv = B.pv, nv = B.nv;
    const bool rational = B.rational;
    const float *poles = B.poles, *weights = B.weights;
    float Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
    const int su = detail::u_basis(B, u, Nu, nullptr), sv = detail::v_basis(B, v, Nv, nullptr);
    float x = 0, y = 0, z = 0;
    if (!rational) { // the basis functions sum to one: no weights, no division
        for (int a = 0; a <= pu; ++a) {
            const float* row = poles + 3 * ((su - pu + a) * nv + sv - pv);
            float rx = 0, ry = 0, rz = 0; // the row of poles contracted in v first
            for (int b = 0; b <= pv; ++b, row += 3) rx += row[0] * Nv[b], ry += row[1] * Nv[b], rz += row[2] * Nv[b];
            x += rx * Nu[a], y += ry * Nu[a], z += rz * Nu[a];
        }
        return {x, y, z};
    }
    float W = 0;
    for (int a = 0; a <= pu; ++a) {
        const int i = su - pu + a;
        float rx = 0, ry = 0, rz = 0, rw = 0;
        for (int b = 0; b <= pv; ++b) {
            const int j = sv - pv + b;
            const float* P = poles + 3 * (i * nv + j);
            const float w = weights[i * nv + j] * Nv[b];
            rx += P[0] * w, ry += P[1] * w, rz += P[2] * w, rw += w;
        }
        x += rx * Nu[a], y += ry * Nu[a], z += rz * Nu[a], W += rw * Nu[a];
    }
    if (W == 0) W = 1;
    const float inv = 1 / W;
    return {x * inv, y * inv, z * inv};
}

int invert_candidates(const Pack& pack, const Surface& s, Vec3 P, const float uv_min[2], const float uv_max[2], Vec2 out[2]) {
    if (!is_elementary(s)) return 0;
    return Elementary(pack, s).preimages(P, uv_min, uv_max, out);
}

bool invert_elementary(const Pack& pack, const Surface& s, Vec3 P, const float uv_min[2], const float uv_max[2], Vec2& uv) {
    if (!is_elementary(s)) return false;
    uv = Elementary(pack, s).inverse(P, uv_min, uv_max);
    return true;
}

} // namespace facet::geom
