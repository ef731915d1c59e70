// Must fail to link: 33 MiB of static data cannot fit the 32 MiB RAM budget.
#include "hal/board.h"

namespace {
volatile uint8_t big[33u << 20];
}

int facet_main(facet::hal::Board&) {
    big[sizeof big - 1] = 1;
    return big[0];
}
