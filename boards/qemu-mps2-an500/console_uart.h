#pragma once
// CMSDK APB UART0, polled.
#include "hal/console.h"

namespace facet::mps2 {

class CmsdkUart final : public hal::Console {
public:
    void init();
    void write(const char* data, size_t size) override;
    int read_byte() override;
};

} // namespace facet::mps2
