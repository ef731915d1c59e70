// The overlay's annotations list (overlay.h): the model's PMI, by kind, in the parts list's panel.
#include "annotations.h"
#include "core/format.h"
#include "overlay.h"
#include "overlay_style.h"
#include "render/text.h"

namespace facet::module {
namespace {

using namespace overlay_style;

// Each kind's ink on the dark panel (annotations.cpp's colours, lighter).
constexpr Rgb565 kKindInk[pack::kAnnotationKinds] = {rgb565(130, 175, 255), rgb565(255, 130, 130), rgb565(120, 220, 140),
                                                     rgb565(225, 185, 130)};
constexpr const char* kKindLabel[pack::kAnnotationKinds] = {"DIM", "TOL", "DAT", "NOTE"};

} // namespace

bool Overlay::has_pmi() const { return annotating_ && annotating_->listed_count() > 0; }

void Overlay::set_pmi(bool open) {
    pmi_open_ = open && has_pmi();
    if (pmi_open_) parts_open_ = models_open_ = false;
    pmi_first_row_ = 0;
}

uint32_t Overlay::pmi_rows() const {
    const int32_t rows = (parts_panel().height - 2 * kRow - kPartsFooter) / kRow;
    return rows > 0 ? uint32_t(rows) : 0;
}

void Overlay::scroll_pmi(int32_t rows) {
    if (has_pmi()) pmi_first_row_ = scrolled(pmi_first_row_, rows, annotating_->listed_count(), pmi_rows());
}

void Overlay::list_tab(const render::Target& t, const Area& p, const char* label) const {
    const int32_t x = p.width - 2 * kScrollW - kTabW;
    render::fill_rect(t, x + 1, p.y + 1, kTabW - 2, kRow - 2, kButton);
    render::draw_text(t, x + (kTabW - render::text_width(label)) / 2, p.y + (kRow - render::kGlyphHeight) / 2, label, kText);
}

bool Overlay::tab_hit(int16_t x, int16_t y) const {
    const Area p = parts_panel();
    const int32_t left = p.width - 2 * kScrollW - kTabW;
    return y >= p.y && y < p.y + kRow && x >= left && x < left + kTabW;
}

// "PMI n" and the PARTS tab; the kinds; a row per annotation listed; SHOW, HIDE.
void Overlay::pmi_list(const render::Target& t) const {
    const Area p = parts_panel();
    if (p.height < 2 * kRow + kPartsFooter) return;
    const Annotating& a = *annotating_;
    char text[128];
    format(text, sizeof text, "PMI {}", a.listed_count());
    list_head(t, p, text);
    list_tab(t, p, "PARTS");
    const int32_t quarter = p.width / 4, ky = p.y + kRow;
    for (uint32_t k = 0; k < pack::kAnnotationKinds; ++k) {
        const int32_t x = p.x + int32_t(k) * quarter, w = k == 3 ? p.width - 3 * quarter : quarter;
        const bool on = (a.shown() >> k) & 1u;
        render::fill_rect(t, x + 1, ky + 1, w - 2, kRow - 2, on ? kButtonOn : kButton);
        render::draw_text(t, x + (w - render::text_width(kKindLabel[k])) / 2, ky + (kRow - render::kGlyphHeight) / 2, kKindLabel[k],
                          on ? kText : kDim);
    }
    const geom::Annotations& pmi = *a.annotations();
    uint32_t i = a.nth_listed(pmi_first_row_);
    for (uint32_t r = 0; r < pmi_rows() && i < a.count(); ++r, i = a.next_listed(i + 1)) {
        const int32_t y = ky + kRow + int32_t(r) * kRow;
        if (i == a.chosen()) render::fill_rect(t, p.x, y, p.width - 1, kRow, kButtonOn);
        format(text, sizeof text, "{}", pmi.text(i));
        render::cut_text(text, (p.width - 8) / render::kCellWidth);
        const bool shown = (a.shown() >> pmi[i].kind) & 1u;
        render::draw_text(t, p.x + 4, y + (kRow - render::kGlyphHeight) / 2, text, shown ? kKindInk[pmi[i].kind] : kDim);
    }
    static constexpr const char* kLabels[2] = {"SHOW ALL", "HIDE ALL"};
    const int32_t half = p.width / 2, y = p.y + p.height - kPartsFooter;
    for (int k = 0; k < 2; ++k) {
        const int32_t x = p.x + k * half, w = k ? p.width - half : half;
        render::fill_rect(t, x + 1, y + 1, w - 2, kPartsFooter - 2, kButton);
        render::draw_text(t, x + (w - render::text_width(kLabels[k])) / 2, y + (kPartsFooter - render::kGlyphHeight) / 2, kLabels[k], kText);
    }
}

Overlay::PartsHit Overlay::pmi_at(int16_t x, int16_t y) const {
    PartsHit h;
    if (!pmi_open() || list_hit(x, y, h)) {
        if (h.kind == PartsHit::Kind::Panel && tab_hit(x, y)) h.kind = PartsHit::Kind::Tab;
        return h;
    }
    const Area p = parts_panel();
    if (y >= p.y + p.height - kPartsFooter) {
        h.kind = x < p.width / 2 ? PartsHit::Kind::ShowAll : PartsHit::Kind::HideAll;
        return h;
    }
    const int32_t dy = y - p.y - kRow;
    if (dy < kRow) { // the kinds
        const int32_t quarter = p.width / 4;
        h.kind = PartsHit::Kind::KindToggle, h.part = uint32_t(x / quarter < 3 ? x / quarter : 3);
        return h;
    }
    const uint32_t row = uint32_t(dy - kRow) / uint32_t(kRow);
    if (row >= pmi_rows()) return h;
    const uint32_t i = annotating_->nth_listed(pmi_first_row_ + row);
    if (i < annotating_->count()) h.kind = PartsHit::Kind::Row, h.part = i;
    return h;
}

} // namespace facet::module
