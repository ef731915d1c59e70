#pragma once
// The portable half of every board's reset path.
#include <cstdint>

namespace facet::runtime {

// Copies .data from its load address, zeroes .bss and runs the C++ constructors.
void init_memory();
// Paints the stack, runs facet_main, prints the report lines the host runner reads
// ("@stack ..."), and ends with facet_main's code (hal::exit: the board's).
[[noreturn]] void run_main();

} // namespace facet::runtime
