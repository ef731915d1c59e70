#include "hal/measure.h"

#include "hal/print.h"

namespace facet::hal {

void measure_begin(Console& console, const char* name) {
    print(console, "@begin {}\n", name);
    facet_mark_begin();
}

void measure_end(Console& console, const char* name) {
    facet_mark_end();
    print(console, "@end {}\n", name);
}

} // namespace facet::hal
