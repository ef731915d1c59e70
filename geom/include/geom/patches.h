#pragma once
// Points of a B-spline surface without floating-point sums: each knot span of the surface is
// turned, the first time a point falls in it, into a polynomial patch in the span's local
// parameters (s, t in [0, 1]), its coefficients in fixed point, and a point is then two
// Horner schemes of 32 x 32-bit integer multiplies. A rational surface is carried in
// homogeneous coordinates (w x, w y, w z, w): one division at the end.
//
// Why: on a core without an FPU (the ARM926) every float add or multiply is a library call of
// 50 to 100 instructions, and the B-spline sum of a degree-5 surface takes hundreds of them
// per point; refinement measures seven points per triangle. The patch is the same polynomial
// as the B-spline (exact in exact arithmetic); in fixed point it is within about 1e-7 of the
// patch's own extent, far below any tessellation tolerance.
//
// The patches live in memory the caller gives (FaceScratch::patches): a direct-mapped cache
// of as many spans as fit, so memory bounds what it holds, never what it can evaluate.
//
// Past kMaxPatchDegree the power basis loses too much in fixed point: a surface of degree up
// to kMaxBezierDegree has its spans extracted to Bézier form instead (knot insertion, in
// float, once per span) and evaluated by de Casteljau in int32. A surface the cache cannot
// take (not a B-spline, a degree over kMaxBezierDegree, too little memory for one patch)
// says so (usable() false) and the caller evaluates it in float.
#include "geom/eval.h"
#include "geom/pack.h"
#include "geom/vec.h"

#include <cstdint>
#include <span>

namespace facet::geom {

constexpr int kMaxPatchDegree = 7;   // up to this degree: power form, Horner
constexpr int kMaxBezierDegree = 15; // beyond it up to this one: Bézier form, de Casteljau

class PatchCache {
public:
    // Words of one patch: its header and (pu + 1)(pv + 1) coefficients per coordinate.
    static constexpr uint32_t slot_words(int pu, int pv, bool rational) {
        return kHead + uint32_t((pu + 1) * (pv + 1) * (rational ? 4 : 3));
    }

    // A view of `memory` for surface S of the pack. The memory keeps its patches between views
    // of the same surface (a face tessellated in pieces); it is emptied when it held another.
    PatchCache(const Pack& pack, const pack::Surface& S, std::span<uint32_t> memory);

    // Empties the memory (a new pack: the same surface offset may be another surface).
    static void forget(std::span<uint32_t> memory);

    bool usable() const { return slots_ > 0; }
    Vec3 point(float u, float v);
    // The point and its partial derivatives (for normals).
    SurfacePoint point_and_derivatives(float u, float v);
    uint32_t conversions() const { return conversions_; } // patches made by this view

private:
    static constexpr uint32_t kHead = 7; // key, exponents, origin x y z, 2^30 over the spans' lengths
    const uint32_t* patch(int su, int sv);
    // The patch of (u, v) and the local parameters in [0, 2^30]; u and v wrapped or clamped.
    const uint32_t* locate(float& u, float& v, int32_t& qs, int32_t& qt);
    void convert(int su, int sv, uint32_t* slot);
    void convert_bezier(int su, int sv, uint32_t* slot);
    // Pole `at` in homogeneous coordinates w (P - O), w (w only if rational) into h.
    void homogeneous(int at, const float* O, float* h) const;
    // The slot's header after its coefficients: exponents, origin, 2^30 over the spans' lengths.
    void write_head(uint32_t* slot, int su, int sv, const float* O, uint32_t exps) const;
    // The Bézier patch's coordinates at (qs, qt), and (ds, dt not null) their last
    // differences in s and t (the derivatives over the degrees).
    void bezier(const uint32_t* slot, int32_t qs, int32_t qt, int32_t* out, int32_t* ds, int32_t* dt) const;

    uint32_t* memory_ = nullptr;
    uint32_t slots_ = 0, slot_words_ = 0, conversions_ = 0;
    int pu_ = 0, pv_ = 0, nu_ = 0, nv_ = 0;
    bool rational_ = false, u_periodic_ = false, v_periodic_ = false;
    bool bezier_ = false; // a degree over kMaxPatchDegree: Bézier form
    const float *uk_ = nullptr, *vk_ = nullptr, *poles_ = nullptr, *weights_ = nullptr;
    int last_su_ = -1, last_sv_ = -1; // the span of the last point (the next is often there too)
    const uint32_t* last_ = nullptr;  // and its patch
};

} // namespace facet::geom
