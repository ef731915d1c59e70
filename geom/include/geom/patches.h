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
// float, once per span) and evaluated in int32 as sums of the Bernstein basis (made once per
// parameter by its own de Casteljau triangle, then shared by every row). A surface the cache
// cannot take (not a B-spline, a degree over kMaxBezierDegree, too little memory for one patch)
// says so (usable() false) and the caller evaluates it in float.
#include "geom/eval.h"
#include "geom/pack.h"
#include "geom/vec.h"

#include <cstdint>
#include <span>

namespace facet::geom {

constexpr int kMaxPatchDegree = 7;   // up to this degree: power form, Horner
constexpr int kMaxBezierDegree = 15; // beyond it up to this one: Bézier form, Bernstein sums

class PatchCache {
    // The memory: word 0 the surface whose patches it holds (its first float + 1; 0: none),
    // then (power form, when there is room) kMatrixSlots span matrices per direction, each a
    // MatrixHead and (p + 1)^2 coefficients, then the patch slots, each a PatchHead and the
    // patch's coefficients (int32, coordinate after coordinate).
    // A span's matrix depends only on its degree and its knots relative to the span (SpanKnots):
    // the matrices are kept from surface to surface (one of another layout, or any other bytes,
    // fails its check word and is made again).
    struct PatchHead {
        uint32_t key;       // the spans, su << 16 | sv (kEmpty: a free slot)
        uint32_t exponents; // a signed byte per coordinate: coefficient = value 2^exponent
        float origin[3];    // the patch's first pole: its coordinates are relative to it
        float per_span[2];  // 2^30 over the u and the v span's length (local parameters)
    };
    // The knots a span's basis polynomials depend on, over the span [0, 1]: knots s - p + 1 to
    // s + p but the span's own two (0 and 1).
    struct SpanKnots {
        float at[2 * kMaxPatchDegree - 2];
    };
    struct MatrixHead {
        uint32_t check; // of the degree, the knots, the exponent and the coefficients
        int32_t exponent;
        SpanKnots knots;
    };
    static constexpr uint32_t kHead = sizeof(PatchHead) / 4;
    static constexpr uint32_t kMatrixHead = sizeof(MatrixHead) / 4;

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
    static constexpr uint32_t kMatrixSlots = 32;
    static constexpr uint32_t matrix_words(int p) { return kMatrixHead + uint32_t((p + 1) * (p + 1)); }
    static const int32_t* coefficients(const PatchHead* h) { return reinterpret_cast<const int32_t*>(h + 1); }
    static int32_t* coefficients(PatchHead* h) { return reinterpret_cast<int32_t*>(h + 1); }
    // Span `span`'s basis matrix in u (v false) or v and its exponent: from the memory's
    // matrices, made there if missing, or made in `local` when there are none.
    const int32_t* span_matrix(bool v, int span, int& e, int32_t* local);
    static uint32_t matrix_check(int p, const MatrixHead* head);
    const PatchHead* patch(int su, int sv);
    // The patch of (u, v) and the local parameters in [0, 2^30]; u and v wrapped or clamped.
    const PatchHead* locate(float& u, float& v, int32_t& qs, int32_t& qt);
    void convert(int su, int sv, PatchHead* slot);
    void convert_bezier(int su, int sv, PatchHead* slot);
    // Pole `at` in homogeneous coordinates w (P - O), w (w only if rational) into h.
    void homogeneous(int at, const float* O, float* h) const;
    // The slot's header after its coefficients: exponents, origin, 2^30 over the spans' lengths.
    void write_head(PatchHead* slot, int su, int sv, const float* O, uint32_t exps) const;
    // The Bézier patch's coordinates at (qs, qt), and (ds, dt not null) their last
    // differences in s and t (the derivatives over the degrees).
    void bezier(const PatchHead* slot, int32_t qs, int32_t qt, int32_t* out, int32_t* ds, int32_t* dt) const;

    uint32_t* memory_ = nullptr;
    uint32_t slots_ = 0, slot_words_ = 0, conversions_ = 0;
    int pu_ = 0, pv_ = 0, nu_ = 0, nv_ = 0;
    bool rational_ = false, u_periodic_ = false, v_periodic_ = false;
    bool bezier_ = false; // a degree over kMaxPatchDegree: Bézier form
    const float *uk_ = nullptr, *vk_ = nullptr, *poles_ = nullptr, *weights_ = nullptr;
    int last_su_ = -1, last_sv_ = -1; // the span of the last point (the next is often there too)
    // The spans' basis polynomials (power form) in fixed point, kMatrixSlots a direction in the
    // memory before the patches (a span's is shared by a row or column of patches): key,
    // exponent, (p + 1)^2 coefficients. Null when the memory has no room for them.
    uint32_t *mu_ = nullptr, *mv_ = nullptr;
    const PatchHead* last_ = nullptr; // and its patch
};

// Points of a B-spline curve in fixed point. In float, the basis functions take p (p + 1) / 2
// divisions a point (about 100 instructions each in soft float) and the sum as many again; here
// each knot span a point falls in is extracted to Bézier form once (as PatchCache does for
// surfaces of high degree, in float) into one of a few slots kept in the object, and a point is
// a Bernstein sum per coordinate in int32, one int-to-float conversion per coordinate and, if
// rational, one division. An edge's samples walk along it, so most points hit the last span:
// on the ARM926 this pays from the first few points of a span, cubics included.
class CurveSpans {
public:
    static constexpr int kSlots = 4;

    // Takes curve c of the pack (a 3D curve or a pcurve); usable() when it is a B-spline of a
    // degree from min_degree to kMaxBezierDegree. Forgets the last curve's spans.
    void bind(const Pack& pack, const pack::Curve& c, int min_degree = 1);
    bool usable() const { return usable_; }
    // The same values as eval_curve3 and eval_curve2 (within the fixed point's rounding: ~1e-8
    // of a span's extent). A 3D curve's, and a pcurve's position.
    Vec3 point(float t);
    Curve3Point point_and_derivative(float t);
    Vec2 point2(float t);

private:
    struct Slot {
        int32_t span;
        uint32_t exps;     // a signed byte per coordinate
        float origin[3];   // the span's first pole (x, y on a pcurve)
        float per_span;    // 2^30 over the span's length
        int32_t c[(kMaxBezierDegree + 1) * 4]; // Bézier points [i][d], homogeneous if rational
    };
    const Slot& slot_of(float& t, int32_t& q);
    void extract(int span, Slot& s) const;
    // The curve's coordinates (and, if diff, their last differences) at q in [0, 2^30].
    void bezier_at(const Slot& s, int32_t q, int32_t* out, int32_t* diff) const;
    // The coordinates at t, unscaled, relative to the span's origin (homogeneous if rational).
    const Slot& coordinates(float t, float* f);

    Slot slots_[kSlots];
    const float *knots_ = nullptr, *poles_ = nullptr, *weights_ = nullptr;
    int p_ = 0, n_ = 0, dim_ = 3, dims_ = 3; // dims_: dim_, and the weight if rational
    bool rational_ = false, periodic_ = false, usable_ = false;
    int last_ = -1; // the slot of the last point
};

} // namespace facet::geom
