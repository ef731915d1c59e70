#pragma once
// Small float vectors for the geometry code.
#include "geom/fmath.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace facet::geom {

struct Vec2 {
    float x, y;
};
struct Vec3 {
    float x, y, z;
};

// One point: the same bits (compared as integers: float compares are library calls on a
// soft-float core). Samples of one point are copies of one computation.
inline bool same_point(Vec3 p, Vec3 q) {
    return std::bit_cast<uint32_t>(p.x) == std::bit_cast<uint32_t>(q.x) && std::bit_cast<uint32_t>(p.y) == std::bit_cast<uint32_t>(q.y) &&
           std::bit_cast<uint32_t>(p.z) == std::bit_cast<uint32_t>(q.z);
}

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline float length2(Vec3 a) { return dot(a, a); } // squared: compare against a squared tolerance
inline float length(Vec3 a) { return sqrt_f(length2(a)); }
inline Vec3 normalized(Vec3 a) {
    const float l = length(a);
    return l > 0 ? a * (1.0f / l) : Vec3{0, 0, 0};
}
inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(Vec2 a, float s) { return {a.x * s, a.y * s}; }

} // namespace facet::geom
