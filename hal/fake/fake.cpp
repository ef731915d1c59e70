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

Display::Display(uint16_t width, uint16_t height, bool scanout)
    : width_(width), height_(height), scanout_(scanout), panel_(size_t(width) * height, 0) {}

Status Display::show(Rgb565* frame) {
    if (!scanout_) {
        ++rejected;
        return Status::Unsupported;
    }
    if (!frame) {
        ++rejected;
        return Status::OutOfRange;
    }
    shown_ = frame;
    ++shows;
    return Status::Ok;
}

Status Display::write(const Area& area, const Rgb565* px) {
    const Status s = copy_area(shown_ ? shown_ : panel_.data(), width_, height_, area, px);
    if (!ok(s)) {
        ++rejected;
        return s;
    }
    ++writes;
    pixels += uint64_t(area.width) * area.height;
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
