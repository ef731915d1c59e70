#include "hal/fake.h"

#include <cstdio>
#include <cstdlib>

namespace facet::hal::fake {

int Console::read_byte() {
    if (input.empty()) return -1;
    const int c = static_cast<unsigned char>(input.front());
    input.erase(input.begin());
    return c;
}

Display::Display(uint16_t width, uint16_t height, uint8_t buffers)
    : width_(width), height_(height), buffers_(buffers)
    , draw_(size_t(width) * height, 0), shown_(size_t(width) * height, 0) {}

bool Display::in_range(uint16_t x, uint16_t y, uint16_t count) const {
    return count > 0 && y < height_ && x < width_ && uint32_t(x) + count <= width_;
}

Status Display::push_span(uint16_t x, uint16_t y, const Rgb565* px, uint16_t count) {
    if (!px || !in_range(x, y, count)) {
        ++rejected;
        return Status::OutOfRange;
    }
    Rgb565* row = &draw_[size_t(y) * width_ + x];
    for (uint16_t i = 0; i < count; ++i) row[i] = px[i];
    ++spans;
    pixels += count;
    return Status::Ok;
}

Status Display::fill_span(uint16_t x, uint16_t y, uint16_t count, Rgb565 colour) {
    if (!in_range(x, y, count)) {
        ++rejected;
        return Status::OutOfRange;
    }
    Rgb565* row = &draw_[size_t(y) * width_ + x];
    for (uint16_t i = 0; i < count; ++i) row[i] = colour;
    ++spans;
    pixels += count;
    return Status::Ok;
}

Status Display::flip() {
    ++flips;
    if (buffers_ == 2) std::swap(draw_, shown_);
    return Status::Ok;
}

bool Input::poll(InputEvent& event) {
    if (queue.empty()) return false;
    event = queue.front();
    queue.pop_front();
    return true;
}

bool write_f565(const std::string& path, const std::vector<Rgb565>& pixels, uint16_t width,
                uint16_t height) {
    if (pixels.size() != size_t(width) * height) return false;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const uint8_t header[8] = {'F', '5', '6', '5', uint8_t(width), uint8_t(width >> 8),
                               uint8_t(height), uint8_t(height >> 8)};
    bool ok = std::fwrite(header, 1, sizeof header, f) == sizeof header;
    for (Rgb565 p : pixels) {
        const uint8_t b[2] = {uint8_t(p), uint8_t(p >> 8)};
        ok = ok && std::fwrite(b, 1, 2, f) == 2;
    }
    return std::fclose(f) == 0 && ok;
}

} // namespace facet::hal::fake
