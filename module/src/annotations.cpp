// A model's annotations over the view (annotations.h).
#include "annotations.h"

#include "core/format.h"
#include "render/text.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace facet::module {
namespace {

// Each kind's colour, as drawings colour them apart: dimensions blue, tolerances red, datums
// green, notes brown; the one chosen in the highlight colour (the picked faces').
constexpr Rgb565 kKindColour[pack::kAnnotationKinds] = {rgb565(20, 70, 190), rgb565(190, 30, 40), rgb565(20, 130, 60),
                                                        rgb565(110, 70, 30)};
constexpr Rgb565 kChosenColour = rgb565(230, 30, 190);
constexpr int32_t kMostAcross = 1 << 24; // sub-pixels: a sphere's size on the screen is measured up to it
constexpr Rgb565 kLabelPaper = rgb565(250, 250, 245), kLabelEdge = rgb565(150, 150, 160);

// Halfway to the background's light grey: a presentation seen from behind.
constexpr Rgb565 faded(Rgb565 c) {
    const uint32_t r = (c >> 11) & 31, g = (c >> 5) & 63, b = c & 31;
    return Rgb565((((r + 25) / 2) << 11) | (((g + 51) / 2) << 5) | ((b + 26) / 2));
}

} // namespace

// 1 / unit as m * 2^e, m in [2^31, 2^32): a point in mm to mesh units by integer arithmetic on
// its float's bits (the ARM926 has no FPU: soft float's division and rounding would cost some
// thousand instructions a point, the presentation's thousands of points a frame).
Annotating::UnitScale Annotating::unit_scale(float unit) {
    int e = 0;
    const float f = std::frexp(1.0f / unit, &e); // [0.5, 1)
    return {uint32_t(double(f) * 4294967296.0), e - 32};
}

bool Annotating::to_units(float x, const UnitScale& s, int32_t& q) {
    uint32_t bits;
    std::memcpy(&bits, &x, 4);
    const int32_t exponent = int32_t((bits >> 23) & 255);
    if (exponent == 0) return q = 0, true; // (zero, or a subnormal: under a mesh unit)
    if (exponent == 255) return false;
    const uint64_t product = uint64_t((bits & 0x7FFFFFu) | 0x800000u) * s.m; // x = mantissa 2^(exponent - 150)
    const int32_t shift = 150 - exponent - s.e;                           // q = product >> shift
    if (shift <= 0) return false; // (2^32 mesh units or more)
    if (shift >= 64) return q = 0, true;
    const uint64_t v = (product + (uint64_t(1) << (shift - 1))) >> shift; // rounded half up
    if (v >= (1u << 30)) return false; // 2^30 mesh units or more: left out (it would overflow)
    q = bits >> 31 ? -int32_t(v) : int32_t(v);
    return true;
}

bool Annotating::quantize(const float p[3], const UnitScale& s, int32_t q[3]) {
    return to_units(p[0], s, q[0]) && to_units(p[1], s, q[1]) && to_units(p[2], s, q[2]);
}

bool Annotating::project(const float p[3], const Transform& t, const UnitScale& unit, Projected& out) {
    int32_t q[3];
    if (!quantize(p, unit, q)) return false;
    t.project(q, out);
    return !out.out;
}

bool Annotating::faces_away(uint32_t i, const Transform& t, const UnitScale& unit) const {
    const pack::Annotation& a = (*pmi_)[i];
    int32_t q[3];
    if (!(a.flags & pack::kHasPlane) || !quantize(a.anchor, unit, q)) return false;
    // The normal in view space (the transform's rotation rows on it), and the way from the
    // anchor to the eye: (0, 0, 1) in a parallel view, (-x, -y, d) in a perspective one.
    const float* n = a.normal;
    const float nx = float(t.a[0]) * n[0] + float(t.a[1]) * n[1] + float(t.a[2]) * n[2];
    const float ny = float(t.a[3]) * n[0] + float(t.a[4]) * n[1] + float(t.a[5]) * n[2];
    const float nz = float(t.a[6]) * n[0] + float(t.a[7]) * n[1] + float(t.a[8]) * n[2];
    if (t.ortho) return nz < 0;
    int32_t x, y, d;
    t.to_view(q, x, y, d);
    return -nx * float(x) - ny * float(y) + nz * float(d) < 0;
}

void Annotating::candidate(const Transform& t, const UnitScale& unit, uint32_t i) {
    Projected at;
    if (!project((*pmi_)[i].anchor, t, unit, at)) return; // (its anchor off the view: no label)
    ++wanted_;
    if (candidates_ == kMaxLabels) return; // (counted as left out when placed)
    candidates_list_[candidates_++] = {int16_t(at.s.x / render::subpixel::kPerPixel), int16_t(at.s.y / render::subpixel::kPerPixel), 0, 0, i};
}

uint32_t Annotating::polylines(render::Rasterizer& raster, const Frame& f, uint32_t i) {
    const pack::Annotation& a = (*pmi_)[i];
    const Transform& t = f.t;
    // Its sphere on the screen: off the view (or the band), nothing; its size picks the
    // polylines (the coarse ones where a pixel spans more than they stray) and its label.
    int32_t centre[3], radius;
    if (!quantize(a.centre, f.unit, centre) || !to_units(a.radius, f.unit, radius)) return 1;
    if (!t.visible(centre, radius + 1, f.screen)) return 1;
    // Its strokes too small to read: its outline alone, and its text on a label.
    const bool unreadable = too_small(f, i);
    if (unreadable && ((a.flags & pack::kSemantic) || a.kind == uint8_t(pack::AnnotationKind::Note))) candidate(t, f.unit, i);
    if (!t.visible(centre, radius + 1, f.rows)) return 1; // (its label may reach into the band)
    Projected at_centre;
    const int32_t across = t.across(centre, radius, kMostAcross, at_centre);
    const bool coarse = across >= 0 && float(across) < f.coarse_below * a.radius;
    const Rgb565 colour = i == chosen_ ? kChosenColour : faces_away(i, t, f.unit) ? faded(kKindColour[a.kind]) : kKindColour[a.kind];
    uint32_t work = 1;
    const auto lines = (coarse ? pmi_->coarse_polylines(i) : pmi_->polylines(i)).first(unreadable ? a.outline_count : a.polyline_count);
    // Its points: its sphere's centre plus the steps so far, times the step (mesh units, Q16).
    const int64_t step16 = (int64_t(radius) << 16) / pack::kStepUnits;
    for (const pack::Polyline& l : lines) {
        Projected prev{}, cur{};
        bool have = false;
        int32_t at[3] = {0, 0, 0};
        for (const pack::PmiStep& s : pmi_->points(l)) {
            int32_t q[3];
            for (int k = 0; k < 3; ++k) at[k] += s.d[k], q[k] = centre[k] + int32_t((at[k] * step16) >> 16);
            t.project(q, cur);
            const bool in = !cur.out;
            if (in) {
                cur.s.z = 0; // over the model, whatever lies nearer
                if (have) (void)raster.line(prev.s, cur.s, colour, 0);
                prev = cur;
            }
            have = in;
        }
        work += 1 + l.point_count / 64;
    }
    return work;
}

int32_t Annotating::across_screen(const Frame& f, const float centre_mm[3], float radius_mm) {
    int32_t centre[3], radius;
    Projected c;
    if (!quantize(centre_mm, f.unit, centre) || !to_units(radius_mm, f.unit, radius)) return -1;
    return f.t.across(centre, radius, kMostAcross, c);
}

bool Annotating::too_small(const Frame& f, uint32_t i) const {
    const int32_t across = across_screen(f, (*pmi_)[i].anchor, (*pmi_)[i].stroke / 2); // (its strokes at its anchor)
    return across >= 0 && across < kReadablePixels * render::subpixel::kPerPixel;
}

uint32_t Annotating::draw(render::Rasterizer& raster, const Transform& t, Rows rows, Rows screen, float mesh_unit, float diagonal_mm,
                          uint32_t from, uint32_t units, uint32_t& spent) {
    spent = 0;
    const uint32_t n = count();
    if (from == 0) candidates_ = 0, wanted_ = 0;
    if (!drawing()) {
        placed_ = 0, left_out_ = 0;
        return n + 1;
    }
    // The coarse polylines where a pixel spans more than they stray: across (sub-pixels) under
    // 2 radius / (kCoarsePolylines diagonal) pixels.
    const Frame f{t, rows, screen, unit_scale(mesh_unit), 2.0f * float(render::subpixel::kPerPixel) / (pack::kCoarsePolylines * diagonal_mm)};
    uint32_t i = from;
    for (; i < n && spent < units; ++i) {
        const pack::Annotation& a = (*pmi_)[i];
        if (!kind_shown(i) || a.drawn_by != kNone) { // (one drawn by another: drawn there)
            spent += (i & 7) == 7; // (an eighth of a unit a record passed)
            continue;
        }
        if (a.polyline_count) spent += polylines(raster, f, i);
        else if (a.flags & pack::kSemantic) candidate(t, f.unit, i), ++spent; // no presentation: placed at its faces
    }
    if (i < n) return i;
    labels(raster);
    spent += 1 + placed_ / 8;
    return n + 1;
}

void Annotating::labels(render::Rasterizer& raster) {
    const render::Target& target = raster.target();
    placed_ = 0;
    // The chosen one first (it always shows), then in the file's order; one that would cover
    // one placed already is left out.
    auto place = [&](const Label& c) {
        const char* text = pmi_->text(c.annotation);
        const int16_t w = int16_t(render::text_width(text) + 4), h = int16_t(render::kLineHeight + 1);
        const Label box{int16_t(c.x - w / 2), int16_t(c.y - h / 2), w, h, c.annotation};
        for (uint32_t k = 0; k < placed_; ++k) {
            const Label& o = placed_labels_[k];
            if (box.x < o.x + o.w && o.x < box.x + box.w && box.y < o.y + o.h && o.y < box.y + box.h) return;
        }
        placed_labels_[placed_++] = box;
    };
    for (uint32_t k = 0; k < candidates_; ++k)
        if (candidates_list_[k].annotation == chosen_) place(candidates_list_[k]);
    for (uint32_t k = 0; k < candidates_; ++k)
        if (candidates_list_[k].annotation != chosen_) place(candidates_list_[k]);
    left_out_ = wanted_ - placed_;
    for (uint32_t k = 0; k < placed_; ++k) {
        const Label& b = placed_labels_[k];
        const uint8_t kind = (*pmi_)[b.annotation].kind;
        const Rgb565 ink = b.annotation == chosen_ ? kChosenColour : kKindColour[kind];
        render::fill_rect(target, b.x, b.y, b.w, b.h, kLabelEdge);
        render::fill_rect(target, b.x + 1, b.y + 1, b.w - 2, b.h - 2, kLabelPaper);
        render::draw_text(target, b.x + 2, b.y + 1, pmi_->text(b.annotation), ink);
    }
}

uint32_t Annotating::label_at(int16_t x, int16_t y) const {
    for (uint32_t k = placed_; k-- > 0;) {
        const Label& b = placed_labels_[k];
        if (x >= b.x && x < b.x + b.w && y >= b.y && y < b.y + b.h) return b.annotation;
    }
    return kNone;
}

bool Annotating::listed(uint32_t i) const {
    const uint8_t flags = (*pmi_)[i].flags;
    return (flags & pack::kSemantic) && !(flags & pack::kRepeat); // (a presentation alone says no values)
}

uint32_t Annotating::of_face(uint32_t f, uint32_t* out, uint32_t max) const {
    uint32_t n = 0;
    for (uint32_t i = 0; i < count(); ++i) {
        if (!listed(i) || !pmi_->applies_to(i, f)) continue;
        if (n < max) out[n] = i;
        ++n;
    }
    return n;
}

void Annotating::face_line(uint32_t f, char* line, uint32_t bytes) const {
    if (!bytes) return;
    line[0] = 0;
    constexpr uint32_t kMost = 8;
    uint32_t ids[kMost];
    const uint32_t n = of_face(f, ids, kMost);
    if (!n) return;
    size_t at = 0;
    auto add = [&](const char* a, const char* b) { at = std::min<size_t>(bytes - 1, at + format(line + at, bytes - at, "{}{}", a, b)); };
    add("PMI:", "");
    for (uint32_t k = 0; k < n && k < kMost; ++k) add(k ? " \u00B7 " : " ", pmi_->text(ids[k]));
    // A character the line's end cut into is dropped whole (its lead byte and what follows).
    size_t end = std::strlen(line), lead = end;
    while (lead > 0 && (static_cast<unsigned char>(line[lead - 1]) & 0xC0) == 0x80) --lead;
    if (lead > 0) {
        const unsigned char c = static_cast<unsigned char>(line[lead - 1]);
        const size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
        if (end - (lead - 1) < length) line[lead - 1] = 0;
    }
}

} // namespace facet::module
