#pragma once
// Host fakes of the hal drivers (cf. Zephyr display_dummy): they check bounds and record what
// they were given, for tests and host tools. Host only (they use the heap).
#include "hal/board.h"

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace facet::hal::fake {

class Console final : public hal::Console {
public:
    void write(const char* data, size_t size) override { output.append(data, size); }
    int read_byte() override;
    void type(const std::string& text) { input.append(text); }

    std::string output;
    std::string input;
};

class Clock final : public hal::Clock {
public:
    uint64_t ticks() override { return now += step; }
    uint32_t ticks_per_second() const override { return 1'000'000; }

    uint64_t now = 0;
    uint64_t step = 1; // each read advances the fake time
};

class Display final : public hal::Display {
public:
    Display(uint16_t width, uint16_t height, uint8_t buffers = 2);

    DisplayInfo info() const override { return {width_, height_, PixelFormat::Rgb565, buffers_}; }
    Status push_span(uint16_t x, uint16_t y, const Rgb565* pixels, uint16_t count) override;
    Status fill_span(uint16_t x, uint16_t y, uint16_t count, Rgb565 colour) override;
    Status flip() override;
    Rgb565* draw_buffer() override { return direct ? draw_.data() : nullptr; }

    bool direct = true; // offer the draw buffer for in-place writes (false: spans only)

    // The buffer last shown by flip() (or the only buffer for single-buffered displays).
    const std::vector<Rgb565>& front() const { return buffers_ == 1 ? draw_ : shown_; }
    const std::vector<Rgb565>& drawn() const { return draw_; } // the draw buffer
    Rgb565 pixel(uint16_t x, uint16_t y) const { return front()[size_t(y) * width_ + x]; }

    uint64_t spans = 0;      // accepted push/fill calls
    uint64_t pixels = 0;     // pixels written
    uint64_t rejected = 0;   // calls refused with OutOfRange
    uint32_t flips = 0;

private:
    bool in_range(uint16_t x, uint16_t y, uint16_t count) const;

    uint16_t width_, height_;
    uint8_t buffers_;
    std::vector<Rgb565> draw_, shown_;
};

class Input final : public hal::Input {
public:
    bool poll(InputEvent& event) override;
    std::deque<InputEvent> queue;
};

// Writes an image in facet's raw RGB565 format ("F565" magic, u16 width, u16 height, pixels,
// all little-endian) — the format the mps2 board dumps and tools/img.py converts to PNG.
bool write_f565(const std::string& path, const std::vector<Rgb565>& pixels, uint16_t width,
                uint16_t height);

} // namespace facet::hal::fake
