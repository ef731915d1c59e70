// Edge sampling: every edge once, into a pool both of its faces read (watertight by
// construction), as few samples as keep every chord within the tolerance of the curve and
// every turn of the tangent within the angle.
#include "geom/params.h"
#include "face_internal.h"
#include "geom/fmath.h"

#include <algorithm>
#include <cmath>

namespace facet::geom {

using namespace facet::pack;

float detail::max_arc_angle(float r, float tol) {
    if (!(r > 0) || tol >= 2 * r) return 4 * kPi;
    const float s = sqrt_f(tol / (2 * r)); // sin(a/4)
    return 4 * atan2_f(s, sqrt_f(1 - s * s));
}

namespace {

// Appends (t, p) to the pool; false when it is full.
struct Pool {
    EdgeSamples& out;
    bool emit(float t, Vec3 p) {
        if (out.used >= out.t.size() || out.used >= out.p.size()) return false;
        out.t[out.used] = t;
        out.p[out.used] = p;
        ++out.used;
        return true;
    }
};

Vec3 vertex(const Pack& pack, uint32_t i) {
    const float* p = pack.vertices()[i].p;
    return {p[0], p[1], p[2]};
}

// A circular arc: the fewest equal steps that keep both the chord's sag and the turn within
// bounds. Ends are the exact pack vertices.
// `arc`: detail::max_arc_angle(r, tol) (EdgeSampler::circle_arc).
bool sample_circle(const Pack& pack, const Curve& C, const Edge& E, const TessOptions& opt, float arc, Pool& pool) {
    const Circle3Params& circle = params<Circle3Params>(pack, C);
    const float r = circle.radius;
    const float span = std::fabs(E.t1 - E.t0);
    const float step = std::min(arc, opt.max_angle);
    const float pieces = std::ceil(span / step);
    const uint32_t n = pieces < 1 ? 1u : (pieces > 4096 ? 4096u : uint32_t(pieces));
    pool.out.work += 1 + n / 16; // a rotation per sample
    if (!pool.emit(E.t0, vertex(pack, E.v0))) return false;
    // cos and sin of the angle step by step (a rotation per sample): no trigonometry per point.
    const Vec3 O = vec3(circle.origin), X = vec3(circle.x), Y = vec3(circle.y);
    const float dt = (E.t1 - E.t0) / float(n);
    float c, s, cd, sd;
    sincos_f(E.t0, s, c);
    sincos_f(dt, sd, cd);
    for (uint32_t k = 1; k < n; ++k) {
        const float cn = c * cd - s * sd;
        s = s * cd + c * sd;
        c = cn;
        if (!pool.emit(E.t0 + dt * float(k), O + (X * c + Y * s) * r)) return false;
    }
    return pool.emit(E.t1, vertex(pack, E.v1));
}

// How a B-spline edge's chord stands for it, from its poles (the curve lies in their convex
// hull, and its tangents in the cone of its control polygon's legs). Straight: every pole
// within tol/16 of the line through the edge's ends (STEP writers and healing make lines of
// them, seams often). Within: every pole within kChordAim of the tolerance of that line, and
// every leg within half of the angle (its cosine given) of the chord's direction: the curve
// then strays from its chord by less than the tolerance and its tangent turns by no more than
// the angle, all an edge sampled more finely would be held to (an edge small on the screen:
// its ends are enough).
// Either way the poles' positions along the line must be monotonic (variation diminishing: the
// curve then never turns back).
constexpr float kChordAim = 0.95f; // as the adaptive pieces' sag aims (EdgeSampler::tol2_: its square)
enum class Chord : uint8_t { Curved, Straight, Within };
Chord chord_of(const Pack& pack, const Curve& C, Vec3 a, Vec3 b, float tol, float cos_half_angle) {
    const BSplineCurveView B = bspline(pack, C);
    const int n = B.n;
    const float* poles = B.poles;
    const Vec3 d = b - a;
    const float len2 = dot(d, d);
    if (!(len2 > 0)) return Chord::Curved;
    const float near2 = (tol / 16) * (tol / 16), within2 = (kChordAim * tol) * (kChordAim * tol);
    const float cos2 = cos_half_angle * cos_half_angle;
    float last = -1e30f, most2 = 0;
    bool up = true, down = true, legs_up = true, legs_down = true; // (legs: each within the half angle, that way)
    bool weighted = true; // a rational curve's weights all positive (else its tangents leave the legs' cone)
    for (int i = 0; B.rational && i < n; ++i) weighted = weighted && B.weights[i] > 0;
    Vec3 prev{};
    for (int i = 0; i < n; ++i) {
        const Vec3 p = Vec3{poles[3 * i], poles[3 * i + 1], poles[3 * i + 2]} - a;
        const float along = dot(p, d) / len2;
        most2 = std::max(most2, length2(p - d * along));
        if (most2 > within2) return Chord::Curved;
        if (i > 0) {
            up = up && along >= last, down = down && along <= last;
            const Vec3 leg = p - prev;
            const float l = dot(leg, d), turn2 = cos2 * dot(leg, leg) * len2; // l^2 >= turn2: within the half angle
            legs_up = legs_up && l >= 0 && l * l >= turn2;
            legs_down = legs_down && l <= 0 && l * l >= turn2;
        }
        last = along, prev = p;
    }
    if (most2 <= near2) return up || down ? Chord::Straight : Chord::Curved;
    return weighted && ((up && legs_up) || (down && legs_down)) ? Chord::Within : Chord::Curved;
}

// Drops samples closer than min_gap to the sample kept before them (the edge's ends always
// stay): features far below the tolerance gain nothing from them, and a face's CDT grid could
// not tell them apart (clean_loops would then have to drop them in that face only). A sample
// where the edge turns by more than half the angle stays however near: a circle smaller than
// the tolerance keeps the sides the angle gives it, so that its face's loops still go round it
// the right way (a 270-degree bend of 2 mm with its ends alone is a chord the other way round).
void thin_out(EdgeSamples& out, uint32_t first, float min_gap, float cos_half_angle) {
    const float gap2 = min_gap * min_gap;
    const uint32_t last = out.used - 1;
    uint32_t kept = first;
    for (uint32_t i = first + 1; i < last; ++i) {
        if (length2(out.p[i] - out.p[kept]) < gap2 &&
            !detail::turns_more(out.p[i] - out.p[kept], out.p[i + 1] - out.p[i], cos_half_angle)) {
            continue;
        }
        ++kept;
        out.t[kept] = out.t[i];
        out.p[kept] = out.p[i];
    }
    if (kept > first && length2(out.p[last] - out.p[kept]) < gap2) --kept; // too near the end
    ++kept;
    out.t[kept] = out.t[last];
    out.p[kept] = out.p[last];
    out.used = kept + 1;
}

} // namespace

void EdgeSampler::start(const Pack& pack, const TessOptions& opt, EdgeSamples& out, uint32_t e) {
    pack_ = &pack, out_ = &out, edge_ = e;
    top_ = 0;
    const Edge& E = pack.edges()[e];
    // A thin face's two sides must not cross: its edges' sag stays under their limit.
    opt_ = opt;
    if (E.max_sag > 0 && E.max_sag < opt.tolerance) opt_.tolerance = E.max_sag;
    opt_.tolerance *= detail::kAim;
    start_ = out.used;
    out.first[e] = out.used;
    adaptive_ = false;
    result_ = Result::fail(Status::Busy, "sampling");
    Pool pool{out};
    const Vec3 a = vertex(pack, E.v0), b = vertex(pack, E.v1);
    bool room = true;
    if (E.curve == kNoIndex) { // degenerate: a single point
        room = pool.emit(E.t0, a) && pool.emit(E.t1, a);
    } else if (E.curve == kStraight) {
        room = pool.emit(E.t0, a) && pool.emit(E.t1, b);
    } else {
        const Curve& C = pack.curves3()[E.curve];
        switch (CurveType(C.type)) {
        case CurveType::Line: room = pool.emit(E.t0, a) && pool.emit(E.t1, b); break;
        case CurveType::Circle:
            room = sample_circle(pack, C, E, opt_, circle_arc(params<Circle3Params>(pack, C).radius), pool);
            break;
        case CurveType::BSpline:
            if (chord_of(pack, C, a, b, opt_.tolerance, angle_cosines().half) != Chord::Curved) room = pool.emit(E.t0, a) && pool.emit(E.t1, b);
            else adaptive_ = true;
            break;
        default: adaptive_ = true; break;
        }
    }
    if (!room) {
        result_ = Result::fail(Status::Full, "more edge samples than the pool holds", {"edge", e});
        return;
    }
    if (!adaptive_) {
        finish();
        return;
    }
    // Any other curve, adaptively: a piece whose points leave its chord by more than the
    // tolerance (less a margin), or whose end tangents turn by more than the angle, is cut in k
    // equal pieces, k from the sag (which falls with the square of the length). Starts from 4
    // pieces, so a closed curve (ends equal) and an S-bend are seen. The sag is measured at
    // three points of a piece, which need not be where the curve strays furthest from the
    // chord: aim 5% under the tolerance.
    curve_ = &pack.curves3()[E.curve];
    tol2_ = 0.9025f * opt_.tolerance * opt_.tolerance;
    cos_max_ = angle_cosines().whole;
    // The work of an evaluation: a B-spline's grows with the square of its degree (its basis
    // and derivative in soft float on the ARM926; in fixed point, CurveSpans, about an eighth).
    eval_ = 1;
    spans_.bind(pack, *curve_);
    if (CurveType(curve_->type) == CurveType::BSpline) {
        const uint32_t degree = uint32_t(bspline(pack, *curve_).p);
        eval_ = 1 + (degree + 1) * (degree + 1) / (spans_.usable() ? 16 : 2);
    }
    if (!pool.emit(E.t0, a)) {
        result_ = Result::fail(Status::Full, "more edge samples than the pool holds", {"edge", e});
        return;
    }
    const float t0 = E.t0, t1 = E.t1;
    for (int k = 4; k >= 1; --k) {
        const float t = k == 4 ? t1 : t0 + (t1 - t0) * float(k) / 4;
        stack_[top_++] = {t, eval(t)};
    }
    left_ = eval(t0);
    tl_ = t0;
    min_piece_ = 1e-6f * (std::fabs(t1 - t0) + 1e-6f);
    out.work += 5 * eval_;
}

Result EdgeSampler::run(uint32_t units) {
    if (result_.status != Status::Busy) return result_;
    EdgeSamples& out = *out_;
    const Pack& pack = *pack_;
    const Edge& E = pack.edges()[edge_];
    constexpr uint32_t kMaxSamples = 4000;
    Pool pool{out};
    const uint32_t work0 = out.work;
    while (top_) {
        if (out.work - work0 >= units) return result_; // Busy: the rest next time
        const Piece right = stack_[top_ - 1];
        // The sag at a quarter, half and three quarters of the piece: where the curvature
        // changes along it, the furthest point is off its middle.
        const Vec3 chord = right.p.p - left_.p;
        const float len2 = dot(chord, chord);
        float sag2 = 0;
        out.work += 3 * eval_;
        for (int q = 1; q <= 3; ++q) {
            const Vec3 off = eval_point(tl_ + (right.t - tl_) * 0.25f * float(q)) - left_.p;
            const float along = len2 > 0 ? dot(off, chord) / len2 : 0;
            sag2 = std::max(sag2, length2(off - chord * along));
        }
        const bool turned = detail::turns_more(left_.d, right.p.d, cos_max_);
        const bool room = right.t - tl_ > min_piece_ && out.used - start_ < kMaxSamples;
        const int limit = std::min(16, kStack - top_ + 1); // pieces the stack has room for
        if ((sag2 > tol2_ || turned) && room && limit >= 2) {
            // k pieces: sag / k^2 <= tol, at least 2.
            int k = 2;
            if (sag2 > 4 * tol2_) { // (in float first: the ratio is huge on a corrupt curve)
                const float pieces = std::ceil(sqrt_f(sqrt_f(sag2 / tol2_)) * 1.05f);
                k = pieces < float(limit) ? int(pieces) : limit;
            }
            k = std::clamp(k, 2, limit);
            --top_; // the right end goes back on top of the new pieces
            out.work += uint32_t(k - 1) * eval_;
            for (int j = k; j >= 1; --j) {
                const float t = j == k ? right.t : tl_ + (right.t - tl_) * float(j) / float(k);
                stack_[top_++] = {t, j == k ? right.p : eval(t)};
            }
            continue;
        }
        --top_;
        if (!pool.emit(right.t, top_ == 0 ? vertex(pack, E.v1) : right.p.p)) {
            result_ = Result::fail(Status::Full, "more edge samples than the pool holds", {"edge", edge_});
            return result_;
        }
        tl_ = right.t;
        left_ = right.p;
    }
    finish();
    return result_;
}

// The cosines of opt_.max_angle and of its half, and a circle's largest arc for opt_.tolerance
// (a cosine, a square root, an arc tangent: hundreds of instructions each in soft float), kept
// for the last arguments.
const EdgeSampler::AngleCosines& EdgeSampler::angle_cosines() {
    const float angle = opt_.max_angle, half = angle / 2;
    return cosines_({angle}, [&] { return AngleCosines{cos_f(angle), half < kPi / 2 ? cos_f(half) : 0}; });
}

float EdgeSampler::circle_arc(float r) {
    const float tol = opt_.tolerance;
    return arc_({r, tol}, [&] { return detail::max_arc_angle(r, tol); });
}

Curve3Point EdgeSampler::eval(float t) { return spans_.usable() ? spans_.point_and_derivative(t) : eval_curve3(*pack_, *curve_, t); }
Vec3 EdgeSampler::eval_point(float t) { return spans_.usable() ? spans_.point(t) : eval_curve3_point(*pack_, *curve_, t); }

void EdgeSampler::finish() {
    EdgeSamples& out = *out_;
    if (out.used - start_ > 2) thin_out(out, start_, opt_.tolerance / 16, angle_cosines().half);
    if (out.used - start_ > 0xFFFF) {
        result_ = Result::fail(Status::Full, "more than 65,535 samples on one edge", {"edge", edge_});
        return;
    }
    out.count[edge_] = uint16_t(out.used - start_);
    result_ = {};
}

Result sample_edges(const Pack& pack, const TessOptions& opt, EdgeSamples& out, uint32_t begin, uint32_t end) {
    const auto edges = pack.edges();
    if (begin == 0) out.used = 0;
    if (!(opt.tolerance > 0 && opt.tolerance <= kMaxMagnitude) || !(opt.max_angle > 0)) {
        return Result::fail(Status::OutOfRange, "the tolerance and the angle must be positive");
    }
    if (out.first.size() < edges.size() || out.count.size() < edges.size()) {
        return Result::fail(Status::Full, "more edges than the sample index holds", {"edges", uint32_t(edges.size())});
    }
    if (end > edges.size()) end = uint32_t(edges.size());
    EdgeSampler sampler;
    for (uint32_t e = begin; e < end; ++e) {
        sampler.start(pack, opt, out, e);
        if (Result r = sampler.run(UINT32_MAX); !r.ok()) return r;
    }
    return {};
}

Result sample_edges(const Pack& pack, const TessOptions& opt, EdgeSamples& out) {
    return sample_edges(pack, opt, out, 0, uint32_t(pack.edges().size()));
}

} // namespace facet::geom
