// The QEMU boards' Capture (hal/capture.h): qemu::capture and qemu::dump (the runner's
// screenshot protocol), as a driver the board hands out with its others.
#include "qemu/capture.h"

namespace facet::qemu {
namespace {

class RunnerCapture final : public hal::Capture {
public:
    Status shot(const char* name) override { return capture(name); }
    Status dump(const char* name, const Rgb565* pixels, uint16_t width, uint16_t height) override {
        return qemu::dump(name, pixels, width, height);
    }
} runner_capture;

} // namespace

hal::Capture& runner() { return runner_capture; }

} // namespace facet::qemu
