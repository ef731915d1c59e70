// facet-doc-figures: the figures the docs state about the storage plan, from the code that
// plans it (tests/tools/docs_figures_test.py checks each page says them).
#include "facet/sizes.h"
#include "geom/pack_file.h"

#include <cstdio>

int main() {
    std::printf("workspace_base_bytes %lu\n", static_cast<unsigned long>(FACET_WORKSPACE_BASE_BYTES));
    std::printf("workspace_default_bytes %lu\n", static_cast<unsigned long>(FACET_WORKSPACE_BYTES_DEFAULT));
    std::printf("lzma_state_bytes %u\n", static_cast<unsigned>(facet::geom::kLzmaStateBytes));
    return 0;
}
