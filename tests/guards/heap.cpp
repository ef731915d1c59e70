// Must fail to link: firmware may not allocate from a heap.
#include "hal/board.h"

#include <cstdlib>

int facet_main(facet::hal::Board&) {
    void* p = std::malloc(16);
    return p != nullptr;
}
