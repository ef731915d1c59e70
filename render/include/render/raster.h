#pragma once
// Span rasterizer: triangles and lines into caller-owned RGB565 pixels and a 16-bit depth
// buffer, for the whole screen or for a band of its rows (partial rendering: a board without
// room for full frames draws the screen band after band, with the same pixels).
//
// Screen space, y down. Vertex positions are sub-pixels (render/subpixel.h: 28.4 fixed point);
// pixel (x, y) is sampled at its centre. Coverage follows the top-left rule, so triangles
// sharing an edge never draw a pixel twice and never leave a gap. Depth is a 16-bit z-buffer
// (0 nearest). Shading is Gouraud: a shade index (how lit the surface is) is interpolated per
// pixel and the triangle's palette colours it, one table look-up per pixel (a lit CAD face is
// its colour times its lighting, so one interpolant does the work of three). Integer
// arithmetic only.
#include "core/pixel.h"
#include "core/status.h"
#include "render/subpixel.h"

#include <cstddef>
#include <cstdint>

namespace facet::render {

namespace detail {
struct PixelBox; // raster_internal.h
}

struct ScreenVertex {
    int32_t x, y;     // sub-pixels (render/subpixel.h)
    uint16_t z;       // depth, 0 = nearest
    uint8_t shade;    // palette index: 0 darkest, 255 brightest
};

// A triangle's doubled signed area on the screen (sub-pixels squared): with y down, positive
// when a, b, c turn clockwise on the screen (a back face: front faces turn counter-clockwise).
inline int64_t doubled_area(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    return int64_t(b.x - a.x) * (c.y - a.y) - int64_t(b.y - a.y) * (c.x - a.x);
}

// The colours of one material from dark (0) to fully lit (255), then a few copies of the
// brightest: an interpolated shade may overshoot its vertices' by a rounding unit or two, and
// the rasterizer indexes without clamping where that is all it can do.
struct Palette {
    static constexpr int kPad = 16;
    uint32_t colour[256 + kPad]; // RGB565 values, one word each (a shifted word load per pixel)
};

// The palette of a colour under light: shade s gives (r, g, b) * s / 255.
void make_palette(Palette& out, uint8_t r, uint8_t g, uint8_t b);

// Positions must satisfy |x|, |y| <= kGuardBand (sub-pixels) so every product stays in 64 bits
// (render/subpixel.h); triangles beyond it are refused with OutOfRange (clipping happens
// before the rasterizer).
constexpr int32_t kGuardBand = subpixel::kGuardPixels * subpixel::kPerPixel;

enum class Cull : uint8_t { None, Back };

// Where the rasterizer draws: rows [y0, y0 + rows) of a width x height screen. `pixels` and
// `depth` hold those rows, row after row (rows * width entries each), in the caller's memory.
// Everything outside the band is clipped, exactly: a triangle drawn band by band covers the
// same pixels with the same values as drawn into the whole screen at once.
struct Target {
    Rgb565* pixels = nullptr;
    uint16_t* depth = nullptr;
    uint16_t width = 0, height = 0; // the screen
    uint16_t y0 = 0, rows = 0;      // the band (0, height: the whole screen)

    Rgb565* row(int32_t y) const { return pixels + size_t(y - y0) * width; } // y within the band
};

struct RasterStats {
    uint32_t triangles = 0;   // triangles that reached scan conversion
    uint32_t culled = 0;      // back-facing or zero-area
    uint32_t spans = 0;       // spans shaded one at a time: clamped or stippled ones, and the rows
                              // of a larger triangle far from the origin (the common paths, in
                              // place a chunk of rows or a small triangle at once, count none)
    uint32_t pixels = 0;      // pixels depth-tested, drawn or hidden (what the spans cost)
};

class Rasterizer {
public:
    Rasterizer() = default;
    explicit Rasterizer(const Target& target) { set_target(target); }
    // Draws into `target` from now on (a band, a buffer); stats carry on.
    void set_target(const Target& target) { t_ = target; }
    const Target& target() const { return t_; }

    void clear_depth(); // the band's depth: all far
    // Screen-door transparency: triangles then cover every other pixel (a checkerboard, the
    // same on every band), so what lies behind shows through the rest. Lines are not affected.
    void set_stipple(bool on) { stipple_ = on; }
    // Draws one triangle coloured from `palette`. Front faces are counter-clockwise as seen
    // on the screen. OutOfRange (nothing drawn) if a vertex is outside the guard band.
    Status draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const Palette& palette,
                Cull cull = Cull::Back);

    // Whether everything the triangle could cover in the band is already nearer than all of it
    // (its nearest corner, less a margin for rounding): drawing it would change no pixel. It
    // reads the depth of its box until one entry is farther: for a face likely hidden (a back
    // face seen through a section), a fraction of what drawing it costs.
    bool hidden(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) const;

    // Draws a one-pixel line from a to b (pixel centres nearest the ends, every pixel on the
    // way: a DDA along the longer axis) in one colour. Depth-tested like triangles, but pulled
    // `bias` units toward the eye first, so an edge of a surface shows on that surface (CAD
    // edges over faces); it writes its depth, so faces drawn later behind it keep it.
    // OutOfRange (nothing drawn) if an end is outside the guard band.
    Status line(const ScreenVertex& a, const ScreenVertex& b, Rgb565 colour, uint16_t bias);
    // One pixel, c's, as line(c, c) draws it (a face too small for its triangles or edges).
    Status point(const ScreenVertex& c, Rgb565 colour, uint16_t bias);
    // A surface's outline (where it turns from facing the eye to facing away): like line(), but
    // each pixel is depth-tested against its neighbour one pixel beyond the outline (`beyond`:
    // the side away from the surface, 0 right, 1 down, 2 left, 3 up), not against itself: there
    // the surface is edge-on, and the pixel itself is mostly covered by the surface's own nearer
    // part. Only a pixel whose neighbour is outside the band (or the screen) is tested against
    // itself. It writes its depth where it is nearer.
    Status outline(const ScreenVertex& a, const ScreenVertex& b, Rgb565 colour, uint16_t bias, uint8_t beyond);
    // A square `size` pixels a side (1 to kMaxSplat) around c's pixel, at c's depth, each pixel
    // depth-tested and drawn in one colour where nearer: a surface too small on the screen for
    // its triangles, while the view moves. OutOfRange (nothing drawn) outside the guard band.
    static constexpr int32_t kMaxSplat = 6;
    Status splat(const ScreenVertex& c, int32_t size, Rgb565 colour);

    RasterStats stats;

private:
    struct Interp; // one interpolated attribute (raster.cpp)
    // A larger triangle (positive area) over its box's pixels in the band.
    void scan(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2, const detail::PixelBox& box);
    // Rows of the triangle; kColumns: its columns (v0, v1, v2 with x and y swapped, two of them
    // swapped back to a positive area; rows and columns swapped likewise).
    template <typename T, bool kColumns>
    void scan_rows(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2, int32_t row0,
                   int32_t row1, int32_t col0, int32_t col1, bool clamp);
    void scan_small(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2, int32_t row0,
                    int32_t row1, int32_t col0, int32_t col1);
    void shade(int32_t y, int32_t lo, int32_t hi, const Interp* at, bool clamp);
    void gradients(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2, int32_t oy,
                   Interp at[]) const;
    void small_gradients(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int64_t area2, int32_t oy,
                         bool clamp, Interp at[]) const;
    static constexpr int kAttributes = 2; // depth, shade

    const Palette* palette_ = nullptr; // the triangle being drawn's
    bool stipple_ = false;
    Target t_;
};

} // namespace facet::render
