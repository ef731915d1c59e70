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

// A panel: scan-out (frames shown in place) unless told otherwise; areas written go into the
// frame shown, or into the panel's own memory.
class Display final : public hal::Display {
public:
    Display(uint16_t width, uint16_t height, bool scanout = true);

    DisplayInfo info() const override { return {width_, height_, PixelFormat::Rgb565, scanout_}; }
    Status show(Rgb565* frame) override;
    Status write(const Area& area, const Rgb565* pixels) override;
    const Rgb565* frame() const override { return shown_ ? shown_ : panel_.data(); }

    // What the panel shows now, as pixels.
    std::vector<Rgb565> front() const { return {frame(), frame() + size_t(width_) * height_}; }
    Rgb565 pixel(uint16_t x, uint16_t y) const { return frame()[size_t(y) * width_ + x]; }

    uint64_t writes = 0;     // accepted write() calls
    uint64_t pixels = 0;     // pixels written
    uint64_t rejected = 0;   // calls refused
    uint32_t shows = 0;

private:
    uint16_t width_, height_;
    bool scanout_;
    Rgb565* shown_ = nullptr;
    std::vector<Rgb565> panel_;
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
