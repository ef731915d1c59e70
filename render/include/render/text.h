#pragma once
// Text and panels over the picture: facet's own 5 x 8 bitmap font (printable ASCII drawn in
// tools/font/make_font.py; Latin-1, Latin Extended-A, Greek and Cyrillic from the X11
// misc-fixed font Debian ships; compiled in: no font file at run time), filled and dimmed
// rectangles. Text is UTF-8 (as names come from the CAD system through the pack). Everything is clipped to the target's band, so an overlay is drawn band by band
// like the model.
#include "render/raster.h"

#include <cstdint>

namespace facet::render {

constexpr int32_t kGlyphWidth = 5, kGlyphHeight = 8; // pixels of a glyph (row 7: descenders)
constexpr int32_t kCellWidth = 6, kLineHeight = 10;  // a character's advance, a line's

// n pixels of one colour from p (two a word store).
void fill_pixels(Rgb565* p, uint32_t n, Rgb565 colour);
// n pixels (or 16-bit depths) from `from` to `to`, which do not overlap: eight words a round
// where both lie alike in their words.
void copy_pixels(Rgb565* to, const Rgb565* from, uint32_t n);

constexpr uint32_t kReplacement = 0xFFFD; // what the screen shows for a character the font lacks

// The next character of UTF-8 text, `text` moved past it: kReplacement for bytes that are no
// UTF-8 (a stray continuation byte, a sequence cut short, an overlong form, a surrogate), each
// such run one character. Not past the string's end (its NUL ends a cut sequence).
uint32_t next_code_point(const char*& text);
// Characters in UTF-8 text (as next_code_point() reads them).
int32_t text_length(const char* text);
// Ends `text` after its first `characters` characters (never inside one).
void cut_text(char* text, int32_t characters);
// The text's width in pixels at `scale` (1 or more: each font pixel scale x scale).
int32_t text_width(const char* text, int32_t scale = 1);
// Draws UTF-8 `text` with its top-left corner at (x, y) in `colour`, a cell a character; one
// the font lacks is drawn as the replacement mark. Returns the x after the last character.
int32_t draw_text(const Target& t, int32_t x, int32_t y, const char* text, Rgb565 colour, int32_t scale = 1);
// A rectangle filled with one colour, or the picture under it halved toward `colour` (a
// translucent panel: each channel (picture + colour) / 2).
void fill_rect(const Target& t, int32_t x, int32_t y, int32_t w, int32_t h, Rgb565 colour);
void dim_rect(const Target& t, int32_t x, int32_t y, int32_t w, int32_t h, Rgb565 colour);

} // namespace facet::render
