// The drivers' mmio.h on the host: reads and writes of the register model (register_model.h).
#include "register_model.h"

#include "mmio.h"

namespace facet::evkb::test {
Model model;
} // namespace facet::evkb::test

namespace facet::evkb::mmio {
using test::model;
uint32_t read(uint32_t address) {
    uint32_t v = 0;
    if (model.read_hook && model.read_hook(address, v)) return v;
    return model.regs[address];
}
void write(uint32_t address, uint32_t value) {
    model.log.push_back({address, value});
    if (model.write_hook && model.write_hook(address, value)) return;
    model.regs[address] = value;
}
uint16_t read16(uint32_t address) { return uint16_t(read(address)); }
void write16(uint32_t address, uint16_t value) { write(address, value); }
void delay_us(uint32_t us) { model.delayed_us += us; }
} // namespace facet::evkb::mmio
