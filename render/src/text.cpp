#include "render/text.h"

namespace facet::render {
namespace {

struct GlyphRange {
    uint32_t first, last, glyph; // code points first..last take glyphs glyph...
};
#include "font_5x8.inc"

// A code point's glyph: the replacement mark (the last range's) for one the font lacks.
const uint8_t* glyph_of(uint32_t c) {
    for (const GlyphRange& r : kGlyphRanges) {
        if (c >= r.first && c <= r.last) return kGlyphs[r.glyph + (c - r.first)];
    }
    return kGlyphs[kGlyphRanges[sizeof kGlyphRanges / sizeof kGlyphRanges[0] - 1].glyph];
}

// The rectangle's part within the target's band and screen.
bool clip(const Target& t, int32_t& x, int32_t& y, int32_t& w, int32_t& h) {
    if (x < 0) w += x, x = 0;
    if (y < t.y0) h -= t.y0 - y, y = t.y0;
    if (x + w > t.width) w = t.width - x;
    if (y + h > t.y0 + t.rows) h = t.y0 + t.rows - y;
    return w > 0 && h > 0;
}

} // namespace

void fill_pixels(Rgb565* p, uint32_t n, Rgb565 c) {
    // Two pixels per word store, eight words per round: the odd pixel at each end on its own.
    using Pair = uint32_t __attribute__((may_alias, aligned(4)));
    if ((reinterpret_cast<uintptr_t>(p) & 2) && n) *p++ = c, --n;
    Pair* w = reinterpret_cast<Pair*>(p);
    const uint32_t pair = uint32_t(c) * 0x00010001u;
    uint32_t words = n / 2;
    for (; words >= 8; words -= 8, w += 8) w[0] = w[1] = w[2] = w[3] = w[4] = w[5] = w[6] = w[7] = pair;
    while (words--) *w++ = pair;
    if (n & 1) *reinterpret_cast<Rgb565*>(w) = c;
}

void copy_pixels(Rgb565* to, const Rgb565* from, uint32_t n) {
    using Word = uint32_t __attribute__((may_alias, aligned(4)));
    if (((reinterpret_cast<uintptr_t>(to) ^ reinterpret_cast<uintptr_t>(from)) & 2) == 0) {
        if ((reinterpret_cast<uintptr_t>(to) & 2) && n) *to++ = *from++, --n;
        Word* w = reinterpret_cast<Word*>(to);
        const Word* r = reinterpret_cast<const Word*>(from);
        uint32_t words = n / 2;
        for (; words >= 8; words -= 8, w += 8, r += 8) {
            const uint32_t a = r[0], b = r[1], c = r[2], d = r[3], e = r[4], f = r[5], g = r[6], h = r[7];
            w[0] = a, w[1] = b, w[2] = c, w[3] = d, w[4] = e, w[5] = f, w[6] = g, w[7] = h;
        }
        while (words--) *w++ = *r++;
        to = reinterpret_cast<Rgb565*>(w), from = reinterpret_cast<const Rgb565*>(r);
        n &= 1;
    }
    while (n--) *to++ = *from++;
}

uint32_t next_code_point(const char*& text) {
    const auto* s = reinterpret_cast<const uint8_t*>(text);
    const uint32_t b = s[0];
    uint32_t length, c, least;
    if (b < 0x80) length = 1, c = b, least = 0;
    else if ((b & 0xE0) == 0xC0) length = 2, c = b & 0x1F, least = 0x80;
    else if ((b & 0xF0) == 0xE0) length = 3, c = b & 0x0F, least = 0x800;
    else if ((b & 0xF8) == 0xF0) length = 4, c = b & 0x07, least = 0x10000;
    else { // a continuation byte, or no UTF-8 lead byte: one mark for it
        text += 1;
        return kReplacement;
    }
    for (uint32_t k = 1; k < length; ++k) {
        if ((s[k] & 0xC0) != 0x80) { // cut short (by the string's end too): one mark for the bytes read
            text += k;
            return kReplacement;
        }
        c = (c << 6) | (s[k] & 0x3F);
    }
    text += length;
    // Overlong forms, UTF-16 surrogates and code points past Unicode's: no character.
    return c < least || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF ? kReplacement : c;
}

int32_t text_length(const char* text) {
    int32_t n = 0;
    while (*text) (void)next_code_point(text), ++n;
    return n;
}

void cut_text(char* text, int32_t characters) {
    const char* at = text;
    for (int32_t k = 0; k < characters && *at; ++k) (void)next_code_point(at);
    text[at - text] = 0;
}

int32_t text_width(const char* text, int32_t scale) {
    const int32_t n = text_length(text);
    return n ? (n * kCellWidth - 1) * scale : 0;
}

int32_t draw_text(const Target& t, int32_t x, int32_t y, const char* text, Rgb565 colour, int32_t scale) {
    const int32_t top = t.y0, bottom = t.y0 + t.rows;
    for (; *text; x += kCellWidth * scale) {
        if (x >= t.width) { // the rest is off the screen: only the advance counts
            return x + text_length(text) * kCellWidth * scale;
        }
        const uint32_t c = next_code_point(text);
        if (y >= bottom || y + kGlyphHeight * scale <= top || x + kGlyphWidth * scale <= 0) continue;
        const uint8_t* glyph = glyph_of(c);
        // Each glyph row `scale` screen rows high, each set bit `scale` pixels wide (no
        // division per pixel: the ARM926 has no divide instruction).
        for (int32_t gr = 0; gr < kGlyphHeight; ++gr) {
            const uint8_t bits = glyph[gr];
            if (!bits) continue;
            for (int32_t py = y + gr * scale, end = py + scale; py < end; ++py) {
                if (py < top || py >= bottom) continue;
                Rgb565* row = t.row(py);
                for (int32_t gc = 0; gc < kGlyphWidth; ++gc) {
                    if (!((bits >> (4 - gc)) & 1)) continue;
                    for (int32_t px = x + gc * scale, stop = px + scale; px < stop; ++px)
                        if (px >= 0 && px < t.width) row[px] = colour;
                }
            }
        }
    }
    return x;
}

void fill_rect(const Target& t, int32_t x, int32_t y, int32_t w, int32_t h, Rgb565 colour) {
    if (!clip(t, x, y, w, h)) return;
    for (int32_t r = y; r < y + h; ++r) fill_pixels(t.row(r) + x, uint32_t(w), colour);
}

void dim_rect(const Target& t, int32_t x, int32_t y, int32_t w, int32_t h, Rgb565 colour) {
    if (!clip(t, x, y, w, h)) return;
    // Halve both and add: the low bit of each channel dropped first (no carry between them).
    const uint32_t half = (uint32_t(colour) & 0xF7DEu) >> 1;
    for (int32_t r = y; r < y + h; ++r) {
        Rgb565* p = t.row(r) + x;
        for (int32_t i = 0; i < w; ++i) p[i] = Rgb565(((uint32_t(p[i]) & 0xF7DEu) >> 1) + half);
    }
}

} // namespace facet::render
