#pragma once
// The elementary surfaces (plane, cylinder, cone, sphere, torus): every closed form the
// tessellation uses on them, in one place. Each knows its frame (pack_format.h: origin, x, y,
// z; z the surface's own normal direction, the frame possibly left-handed) and its radii:
//
//   Plane     P(u,v) = O + u X + v Y
//   Cylinder  P(u,v) = O + R (cos u X + sin u Y) + v Z
//   Cone      P(u,v) = O + (R + v sin a)(cos u X + sin u Y) + v cos a Z
//   Sphere    P(u,v) = O + R cos v (cos u X + sin u Y) + R sin v Z
//   Torus     P(u,v) = O + (R + r cos v)(cos u X + sin u Y) + r sin v Z
//
// geom's one interface to these surfaces, for the tessellation and the module alike: the frame
// and radii (read from the record by params.h's ElementaryRecord), points and derivatives,
// the inverse (a point's (u,v)), oriented normals in closed form, bending and distance.
// Made once per surface (a face's set-up, refinement) or per call where a caller evaluates
// one point; the cone's sine and cosine are taken once, when it is made.
#include "geom/eval.h"
#include "geom/fmath.h"
#include "geom/params.h"

#include <cmath>

namespace facet::geom {

class Elementary {
public:
    // Surface s of the pack; one that is not elementary (is_elementary(s)) gets an empty
    // object, whose answers mean nothing.
    Elementary(const Pack& pack, const pack::Surface& s);

    pack::SurfaceType type() const { return type_; }
    Vec3 origin() const { return O_; }
    Vec3 axis() const { return Z_; } // z: the axis of the round ones, the normal of a plane

    // Position and partial derivatives at (u, v). (Inlined: eval_surface() is its one caller,
    // and the frame stays in registers.)
    [[gnu::always_inline]] SurfacePoint at(float u, float v) const;

    // (u,v) of a point on the surface, choosing the branch that fits the face's bounds
    // (geom/eval.h: invert_elementary).
    Vec2 inverse(Vec3 p, const float uv_min[2], const float uv_max[2]) const;
    // Every preimage (1, or 2 on a self-intersecting torus); returns the count.
    int preimages(Vec3 p, const float uv_min[2], const float uv_max[2], Vec2 out[2]) const;

    // Signed distance from x to the untrimmed surface (positive outward: along z on a plane,
    // away from the axis or the centre on the others; the nearer sheet of a cone past its
    // apex, the nearer tube of a self-intersecting torus).
    FACET_INLINE_WITH_FPU float signed_distance(Vec3 x) const {
        const Vec3 d = x - O_;
        const float a = dot(d, X_), b = dot(d, Y_), z = dot(d, Z_);
        const float rho2 = a * a + b * b;
        switch (type_) {
        case pack::SurfaceType::Cylinder: return sqrt_f(rho2) - radius_;
        case pack::SurfaceType::Cone: {
            // In the half-plane through the axis and x, the cone is the line (R + v sin a,
            // v cos a); past the apex its radius is negative: x is then nearer the mirror line.
            const float rho = sqrt_f(rho2);
            const float near_side = (rho - radius_) * cos_a_ - z * sin_a_, far_side = (-rho - radius_) * cos_a_ - z * sin_a_;
            return std::fabs(near_side) <= std::fabs(far_side) ? near_side : far_side;
        }
        case pack::SurfaceType::Sphere: return sqrt_f(rho2 + z * z) - radius_;
        case pack::SurfaceType::Torus: {
            // The tube on x's side of the axis, or (a self-intersecting torus) the other side's.
            const float rho = sqrt_f(rho2), w = rho - radius_;
            const float e = sqrt_f(w * w + z * z) - minor_;
            if (minor_ <= radius_) return e;
            const float w2 = rho + radius_, e2 = sqrt_f(w2 * w2 + z * z) - minor_;
            return std::fabs(e) <= std::fabs(e2) ? e : e2;
        }
        default: return z; // plane
        }
    }

    // How much the surface bends along u and along v at parameter v: the normal curvatures
    // of the parameter directions (1/mm, magnitudes).
    void bending(float v, float& ku, float& kv) const;

    // What refinement may leave as it is without sampling, an exact bound: every triangle of
    // a plane (Everywhere); on a cylinder or a cone (developable, every chord's sag exactly
    // known) a triangle whose corners span at most `limit` in u (USpan, for v within the
    // face's [v_min, v_max]); on a sphere one whose circumcircle's squared radius is at most
    // `limit` (its plane cuts the sphere there). None on a torus.
    struct FlatBound {
        enum class Kind : uint8_t { None, Everywhere, USpan, Circumradius } kind = Kind::None;
        float limit = 0;
    };
    FlatBound flat_bound(float tol, float v_min, float v_max) const;
    // Whether every chord's sag is known exactly (plane, cylinder, cone: the bounds above are
    // the deviation itself, not an estimate).
    bool developable() const {
        return type_ == pack::SurfaceType::Plane || type_ == pack::SurfaceType::Cylinder || type_ == pack::SurfaceType::Cone;
    }

    // Unit normals in closed form from a point on the surface, for a face of sense `flip`
    // (+1, or -1 when the face is reversed), oriented as du x dv times flip. No trigonometry
    // and no square root per point on planes, cylinders, cones and spheres; `at` is false
    // where there is no closed form (a torus, a cone's apex): the caller takes the derivatives.
    class Normals {
    public:
        bool at(Vec3 p, Vec3& n) const {
            const Vec3 d = p - O_;
            switch (type_) {
            case pack::SurfaceType::Plane: n = plane_; return true;
            case pack::SurfaceType::Cylinder: n = (d - Z_ * dot(d, Z_)) * scale_; return true;
            case pack::SurfaceType::Sphere: n = d * scale_; return true;
            case pack::SurfaceType::Cone: {
                // (cos a radial - sin a Z) on the near side of the apex, mirrored past it.
                const float z = dot(d, Z_), s = radius_ + z / cos_a_ * sin_a_; // the signed radius there
                if (std::fabs(s) > 1e-6f * (std::fabs(radius_) + std::fabs(z))) {
                    n = ((d - Z_ * z) * (cos_a_ / std::fabs(s)) - Z_ * (s < 0 ? -sin_a_ : sin_a_)) * scale_;
                    return true;
                }
                return false; // the apex
            }
            default: return false;
            }
        }

    private:
        friend class Elementary;
        pack::SurfaceType type_ = pack::SurfaceType::Torus;
        Vec3 O_{}, Z_{}, plane_{};
        float scale_ = 1, radius_ = 0, sin_a_ = 0, cos_a_ = 1;
    };
    Normals normals(float flip) const;

private:
    // One preimage of a torus point (x, y, z in the frame): the tube centre on the point's
    // side of the axis (which = 0) or on the other side (which = 1: only on a
    // self-intersecting torus, r > R). Angles within pi of the face's middle.
    Vec2 torus_candidate(float x, float y, float z, const float uv_min[2], const float uv_max[2], int which) const;

    pack::SurfaceType type_;
    Vec3 O_, X_, Y_, Z_;
    float radius_ = 0; // Cylinder, Sphere: R; Cone: R at v = 0; Torus: R, the major radius
    float minor_ = 0;  // Torus: r, the tube's radius
    float sin_a_ = 0, cos_a_ = 1; // Cone: its semi-angle's sine and cosine
};

inline Elementary::Elementary(const Pack& pack, const pack::Surface& s) : type_(pack::SurfaceType(s.type)) {
    if (!is_elementary(s)) {
        O_ = X_ = Y_ = Z_ = {0, 0, 0};
        return;
    }
    ElementaryRecord e;
    (void)elementary(pack, s, e);
    const pack::Frame& f = *e.frame;
    O_ = vec3(f.origin), X_ = vec3(f.x), Y_ = vec3(f.y), Z_ = vec3(f.z);
    radius_ = e.radius, minor_ = e.minor;
    if (type_ == pack::SurfaceType::Cone) sincos_f(e.semi_angle, sin_a_, cos_a_);
}

[[gnu::always_inline]] inline SurfacePoint Elementary::at(float u, float v) const {
    const Vec3 &O = O_, &X = X_, &Y = Y_, &Z = Z_;
    switch (type_) {
    case pack::SurfaceType::Plane: return {O + X * u + Y * v, X, Y};
    case pack::SurfaceType::Cylinder: {
        const float r = radius_;
        float su, cu;
        sincos_f(u, su, cu);
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * r + Z * v, (X * -su + Y * cu) * r, Z};
    }
    case pack::SurfaceType::Cone: {
        float su, cu;
        sincos_f(u, su, cu);
        const float r = radius_ + v * sin_a_;
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * r + Z * (v * cos_a_), (X * -su + Y * cu) * r, radial * sin_a_ + Z * cos_a_};
    }
    case pack::SurfaceType::Sphere: {
        const float r = radius_;
        float su, cu, sv, cv;
        sincos_f(u, su, cu);
        sincos_f(v, sv, cv);
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * (r * cv) + Z * (r * sv), (X * -su + Y * cu) * (r * cv), radial * (-r * sv) + Z * (r * cv)};
    }
    case pack::SurfaceType::Torus: {
        const float R = radius_, r = minor_;
        float su, cu, sv, cv;
        sincos_f(u, su, cu);
        sincos_f(v, sv, cv);
        const Vec3 radial = X * cu + Y * su;
        return {O + radial * (R + r * cv) + Z * (r * sv), (X * -su + Y * cu) * (R + r * cv), radial * (-r * sv) + Z * (r * cv)};
    }
    default: return {};
    }
}

inline Elementary::Normals Elementary::normals(float flip) const {
    Normals n;
    n.type_ = type_, n.O_ = O_, n.Z_ = Z_;
    // du x dv is +-(X x Y)-oriented: the sign of a left-handed placement goes with it.
    const float hand = left_handed(X_, Y_, Z_) ? -flip : flip;
    switch (type_) {
    case pack::SurfaceType::Plane: n.plane_ = Z_ * hand; break;
    case pack::SurfaceType::Cylinder:
    case pack::SurfaceType::Sphere: n.scale_ = hand / radius_; break;
    case pack::SurfaceType::Cone:
        n.sin_a_ = sin_a_, n.cos_a_ = cos_a_;
        n.radius_ = radius_;
        n.scale_ = hand;
        break;
    default: break;
    }
    return n;
}

} // namespace facet::geom
