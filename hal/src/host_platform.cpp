// What the boards provide on the target, for host builds: the instruction markers (no-ops
// without QEMU) and the assert hook (report and abort, so tests and tools fail loudly).
#include "hal/measure.h"
#include "hal/status.h"

#include <cstdio>
#include <cstdlib>

extern "C" void facet_mark_begin(void) {}
extern "C" void facet_mark_end(void) {}

namespace facet {
[[noreturn]] void assert_failed(const char* scope, const char* what, const char* file, int line) {
    std::fprintf(stderr, "facet assert [%s] %s at %s:%d\n", scope, what, file, line);
    std::abort();
}
} // namespace facet
