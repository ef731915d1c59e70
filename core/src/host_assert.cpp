// The assert hook (core/status.h) for host builds: report and abort, so tests and tools fail
// loudly. On the boards, boards/common/runtime.cpp reports it on the console and halts.
#include "core/status.h"

#include <cstdio>
#include <cstdlib>

namespace facet {
[[noreturn]] void assert_failed(const char* scope, const char* what, const char* file, int line) {
    std::fprintf(stderr, "facet assert [%s] %s at %s:%d\n", scope, what, file, line);
    std::abort();
}
} // namespace facet
