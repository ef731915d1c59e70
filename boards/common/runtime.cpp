#include "runtime.h"

#include "hal/board.h"
#include "hal/print.h"
#include "stack.h"

// Linker-script symbols shared by every facet board script.
extern "C" {
extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
}

namespace facet::runtime {

void init_memory() {
    if (static_cast<uint32_t*>(__data_load) != static_cast<uint32_t*>(__data_start)) {
        const uint32_t* src = __data_load;
        for (uint32_t* dst = __data_start; dst < __data_end;) *dst++ = *src++;
    }
    for (uint32_t* p = __bss_start; p < __bss_end;) *p++ = 0;
    for (auto f = __init_array_start; f < __init_array_end; ++f) (*f)();
}

[[noreturn]] void run_main() {
    stack::paint();
    hal::Board& board = hal::board();
    const int code = facet_main(board);
    print(board.console, "@stack used {} of {} bytes\n", stack::size() - stack::unused(),
          stack::size());
    print(board.console, "@exit {}\n", code);
    hal::exit(code);
}

} // namespace facet::runtime

namespace facet {

[[noreturn]] void assert_failed(const char* scope, const char* what, const char* file, int line) {
    print(hal::board().console, "\n*** facet assert [{}] {} at {}:{}\n", scope, what, file, line);
    hal::exit(70);
}

} // namespace facet

// The C++ runtime hooks a bare-metal program may reference.
extern "C" {
void* __dso_handle = nullptr;
[[noreturn]] void __cxa_pure_virtual() { facet::assert_failed("c++", "pure virtual call", "", 0); }
[[noreturn]] void abort() { facet::assert_failed("c++", "abort", "", 0); }
}
