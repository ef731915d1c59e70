#include "hal/board.h"
#include "hal/print.h"
#include "qemu/capture.h"
#include "semihosting.h"

namespace facet::qemu {

Status dump(const char* name, const Rgb565* pixels, uint16_t width, uint16_t height) {
    hal::Console& con = hal::board().console;
    char path[64];
    if (format(path, sizeof path, "{}.f565", name) >= sizeof path) return Status::OutOfRange;
    if (!pixels) {
        print(con, "dump {}: no pixels\n", name);
        return Status::NotFound;
    }
    const int fd = semihosting::open_for_write(path);
    if (fd < 0) {
        print(con, "dump {}: cannot open {} on the host\n", name, path);
        return Status::Io;
    }
    const uint8_t header[8] = {'F', '5', '6', '5', uint8_t(width), uint8_t(width >> 8), uint8_t(height), uint8_t(height >> 8)};
    // Both QEMU cores run little-endian: the pixels are already in F565 order.
    const bool ok = semihosting::write(fd, header, sizeof header) && semihosting::write(fd, pixels, size_t(width) * height * 2);
    semihosting::close(fd);
    if (!ok) return Status::Io;
    print(con, "@dump {} {}\n", name, path);
    return Status::Ok;
}

} // namespace facet::qemu
