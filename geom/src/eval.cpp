#include "geom/eval.h"
#include "bspline.h"
#include "geom/fmath.h"

namespace facet::geom {
namespace {

using namespace facet::pack;
using detail::basis;
using detail::BSplineSurfaceView;
constexpr float kTwoPi = 6.28318530717958647692f;

Vec3 v3(const float* p) { return {p[0], p[1], p[2]}; }

// w turned about the unit axis D by the angle whose cosine and sine are cu and su (Rodrigues).
Vec3 turn(Vec3 D, Vec3 w, float cu, float su) { return w * cu + cross(D, w) * su + D * (dot(D, w) * (1 - cu)); }

// A B-spline curve of dimension dim at t: position and derivative (rational by the quotient rule).
// der null: the position alone (the same value: the same sums, without the derivative's).
void bspline_curve(const float* prm, int dim, float t, float* pos, float* der) {
    const detail::BSplineCurveView C(prm, dim);
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

bool is_elementary(const Surface& s) { return s.type >= uint8_t(SurfaceType::Plane) && s.type <= uint8_t(SurfaceType::Torus); }
bool u_periodic(const Surface& s) {
    return s.type == uint8_t(SurfaceType::Cylinder) || s.type == uint8_t(SurfaceType::Cone) ||
           s.type == uint8_t(SurfaceType::Sphere) || s.type == uint8_t(SurfaceType::Torus) ||
           s.type == uint8_t(SurfaceType::Revolution);
}
bool v_periodic(const Surface& s) { return s.type == uint8_t(SurfaceType::Torus); }

Curve3Point eval_curve3(const Pack& pack, const Curve& c, float t) {
    const float* q = pack.floats().data() + c.params;
    switch (CurveType(c.type)) {
    case CurveType::Line: return {v3(q) + v3(q + 3) * t, v3(q + 3)};
    case CurveType::Circle: {
        const float r = q[9];
        float st, ct;
        sincos_f(t, st, ct);
        return {v3(q) + (v3(q + 3) * ct + v3(q + 6) * st) * r, (v3(q + 3) * -st + v3(q + 6) * ct) * r};
    }
    case CurveType::Ellipse: {
        const float a = q[9], b = q[10];
        float st, ct;
        sincos_f(t, st, ct);
        return {v3(q) + v3(q + 3) * (a * ct) + v3(q + 6) * (b * st), v3(q + 3) * (-a * st) + v3(q + 6) * (b * ct)};
    }
    case CurveType::BSpline: {
        float p[3], d[3];
        bspline_curve(q, 3, t, p, d);
        return {v3(p), v3(d)};
    }
    }
    return {};
}

Vec3 eval_curve3_point(const Pack& pack, const Curve& c, float t) {
    if (CurveType(c.type) != CurveType::BSpline) return eval_curve3(pack, c, t).p;
    float p[3];
    bspline_curve(pack.floats().data() + c.params, 3, t, p, nullptr);
    return v3(p);
}

Curve2Point eval_curve2(const Pack& pack, const Curve& c, float t) {
    const float* q = pack.floats().data() + c.params;
    switch (CurveType(c.type)) {
    case CurveType::Line: return {{q[0] + q[2] * t, q[1] + q[3] * t}, {q[2], q[3]}};
    case CurveType::Circle: {
        const float r = q[6];
        float st, ct;
        sincos_f(t, st, ct);
        return {{q[0] + r * (q[2] * ct + q[4] * st), q[1] + r * (q[3] * ct + q[5] * st)},
                {r * (-q[2] * st + q[4] * ct), r * (-q[3] * st + q[5] * ct)}};
    }
    case CurveType::Ellipse: {
        const float a = q[6], b = q[7];
        float st, ct;
        sincos_f(t, st, ct);
        return {{q[0] + a * ct * q[2] + b * st * q[4], q[1] + a * ct * q[3] + b * st * q[5]},
                {-a * st * q[2] + b * ct * q[4], -a * st * q[3] + b * ct * q[5]}};
    }
    case CurveType::BSpline: {
        float p[2], d[2];
        bspline_curve(q, 2, t, p, d);
        return {{p[0], p[1]}, {d[0], d[1]}};
    }
    }
    return {};
}

SurfacePoint eval_surface(const Pack& pack, const Surface& s, float u, float v) {
    const float* q = pack.floats().data() + s.params;
    const Vec3 O = v3(q), X = v3(q + 3), Y = v3(q + 6), Z = v3(q + 9);
    switch (SurfaceType(s.type)) {
    case SurfaceType::Plane: return {O + X * u + Y * v, X, Y};
    case SurfaceType::Cylinder: {
        const float r = q[12];
        float su, cu;
        sincos_f(u, su, cu);
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * r + Z * v, (X * -su + Y * cu) * r, Z};
    }
    case SurfaceType::Cone: {
        const float r0 = q[12], a = q[13];
        float su, cu, sa, ca;
        sincos_f(u, su, cu);
        sincos_f(a, sa, ca);
        const float r = r0 + v * sa;
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * r + Z * (v * ca), (X * -su + Y * cu) * r, radial * sa + Z * ca};
    }
    case SurfaceType::Sphere: {
        const float r = q[12];
        float su, cu, sv, cv;
        sincos_f(u, su, cu);
        sincos_f(v, sv, cv);
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * (r * cv) + Z * (r * sv), (X * -su + Y * cu) * (r * cv), radial * (-r * sv) + Z * (r * cv)};
    }
    case SurfaceType::Torus: {
        const float R = q[12], r = q[13];
        float su, cu, sv, cv;
        sincos_f(u, su, cu);
        sincos_f(v, sv, cv);
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * (R + r * cv) + Z * (r * sv), (X * -su + Y * cu) * (R + r * cv), radial * (-r * sv) + Z * (r * cv)};
    }
    case SurfaceType::BSpline: {
        const BSplineSurfaceView B(q);
        const int pu = B.pu, pv = B.pv, nv = B.nv;
        const bool rational = B.rational;
        const float *poles = B.poles, *weights = B.weights;
        float Nu[kMaxDegree + 1], dNu[kMaxDegree + 1], Nv[kMaxDegree + 1], dNv[kMaxDegree + 1];
        const int su = B.u_basis(u, Nu, dNu), sv = B.v_basis(v, Nv, dNv);
        Vec3 A{0, 0, 0}, Au{0, 0, 0}, Av{0, 0, 0};
        float W = 0, Wu = 0, Wv = 0;
        for (int a = 0; a <= pu; ++a) {
            const int i = su - pu + a;
            for (int b = 0; b <= pv; ++b) {
                const int j = sv - pv + b;
                const float w = rational ? weights[i * nv + j] : 1.0f;
                const Vec3 P = v3(poles + 3 * (i * nv + j)) * w;
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
        const Vec3 D = normalized(v3(q + 3));
        const Curve3Point c = eval_curve3(pack, pack.curves3()[s.ref], v);
        float su, cu;
        sincos_f(u, su, cu);
        const Vec3 turned = turn(D, c.p - O, cu, su);
        return {O + turned, cross(D, turned), turn(D, c.d, cu, su)};
    }
    case SurfaceType::Extrusion: {
        const Curve3Point c = eval_curve3(pack, pack.curves3()[s.ref], u);
        const Vec3 D = v3(q);
        return {c.p + D * v, c.d, D};
    }
    }
    return {};
}

Vec3 eval_surface_point(const Pack& pack, const Surface& s, float u, float v) {
    const float* q = pack.floats().data() + s.params;
    switch (SurfaceType(s.type)) {
    case SurfaceType::Revolution: { // as eval_surface's, without the derivatives (the same value)
        const Vec3 O = v3(q), D = normalized(v3(q + 3));
        float su, cu;
        sincos_f(u, su, cu);
        return O + turn(D, eval_curve3_point(pack, pack.curves3()[s.ref], v) - O, cu, su);
    }
    case SurfaceType::Extrusion: return eval_curve3_point(pack, pack.curves3()[s.ref], u) + v3(q) * v;
    case SurfaceType::BSpline: break;
    default: return eval_surface(pack, s, u, v).p;
    }
    // The position alone: basis values without derivatives, one weighted sum of the poles.
    const BSplineSurfaceView B(q);
    const int pu = B.pu, pv = B.pv, nv = B.nv;
    const bool rational = B.rational;
    const float *poles = B.poles, *weights = B.weights;
    float Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
    const int su = B.u_basis(u, Nu, nullptr), sv = B.v_basis(v, Nv, nullptr);
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

namespace {

// One preimage of a torus point: the tube centre on the point's side of the axis (which = 0:
// R + r cos v = rho) or on the other side (which = 1: R + r cos v = -rho, possible only on a
// self-intersecting torus, r > R). Angles are placed within pi of the face's middle.
Vec2 torus_candidate(const float* q, float x, float y, float z, const float uv_min[2], const float uv_max[2], int which) {
    const float R = q[12], rho = sqrt_f(x * x + y * y), u1 = atan2_f(y, x);
    const float um = 0.5f * (uv_min[0] + uv_max[0]), vm = 0.5f * (uv_min[1] + uv_max[1]);
    auto near = [](float a, float mid) {
        float r = std::fmod(a - (mid - kTwoPi / 2), kTwoPi);
        if (r < 0) r += kTwoPi;
        return mid - kTwoPi / 2 + r;
    };
    return which == 0 ? Vec2{near(u1, um), near(atan2_f(z, rho - R), vm)}
                      : Vec2{near(u1 + kTwoPi / 2, um), near(atan2_f(z, -rho - R), vm)};
}

// How far (u,v) lies outside the bounds (0 inside).
float outside(Vec2 p, const float lo[2], const float hi[2]) {
    const float du = p.x < lo[0] ? lo[0] - p.x : (p.x > hi[0] ? p.x - hi[0] : 0);
    const float dv = p.y < lo[1] ? lo[1] - p.y : (p.y > hi[1] ? p.y - hi[1] : 0);
    return du + dv;
}

} // namespace

int invert_candidates(const Pack& pack, const Surface& s, Vec3 P, const float uv_min[2], const float uv_max[2], Vec2 out[2]) {
    if (s.type != uint8_t(SurfaceType::Torus)) return invert_elementary(pack, s, P, uv_min, uv_max, out[0]) ? 1 : 0;
    const float* q = pack.floats().data() + s.params;
    const Vec3 d = P - v3(q);
    const float x = dot(d, v3(q + 3)), y = dot(d, v3(q + 6)), z = dot(d, v3(q + 9));
    out[0] = torus_candidate(q, x, y, z, uv_min, uv_max, 0);
    out[1] = torus_candidate(q, x, y, z, uv_min, uv_max, 1);
    return q[13] > q[12] ? 2 : 1; // only a self-intersecting torus has a second preimage
}

bool invert_elementary(const Pack& pack, const Surface& s, Vec3 P, const float uv_min[2], const float uv_max[2], Vec2& uv) {
    const float* q = pack.floats().data() + s.params;
    const Vec3 d = P - v3(q);
    const float x = dot(d, v3(q + 3)), y = dot(d, v3(q + 6)), z = dot(d, v3(q + 9));
    auto wrap = [](float a, float lo) { // into [lo, lo + 2 pi)
        if (a < lo) a += kTwoPi; // atan2 is within pi of 0: one turn does it for most faces
        else if (a >= lo + kTwoPi) a -= kTwoPi;
        if (a >= lo && a < lo + kTwoPi) return a;
        float r = std::fmod(a - lo, kTwoPi);
        if (r < 0) r += kTwoPi;
        return lo + r;
    };
    switch (SurfaceType(s.type)) {
    case SurfaceType::Plane: uv = {x, y}; return true;
    case SurfaceType::Cylinder: uv = {wrap(atan2_f(y, x), uv_min[0]), z}; return true;
    case SurfaceType::Cone: {
        // v from the height alone; past the apex the radius R + v sin a is negative and the
        // point lies opposite its direction from the axis.
        float sa, ca;
        sincos_f(q[13], sa, ca);
        const float v = z / ca;
        const float turn = q[12] + v * sa < 0 ? kTwoPi / 2 : 0;
        uv = {wrap(atan2_f(y, x) + turn, uv_min[0]), v};
        return true;
    }
    case SurfaceType::Sphere:
        uv = {wrap(atan2_f(y, x), uv_min[0]), atan2_f(z, sqrt_f(x * x + y * y))};
        return true;
    case SurfaceType::Torus: {
        const Vec2 c[2] = {torus_candidate(q, x, y, z, uv_min, uv_max, 0), torus_candidate(q, x, y, z, uv_min, uv_max, 1)};
        // The candidate inside the face's bounds (or nearer its middle).
        uv = outside(c[0], uv_min, uv_max) <= outside(c[1], uv_min, uv_max) ? c[0] : c[1];
        return true;
    }
    default: return false;
    }
}

} // namespace facet::geom
