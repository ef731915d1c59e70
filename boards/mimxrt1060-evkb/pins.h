#pragma once
// The EVKB's pins facet uses (the board's schematic, MIMXRT1060-EVKB rev. B; the same
// assignments NXP's SDK pin_mux.c and Zephyr's mimxrt1060_evk-pinctrl.dtsi make):
//
//   GPIO_AD_B0_12/13   LPUART1 TX/RX (ALT2): the debug probe's virtual COM port
//   GPIO_AD_B1_00/01   LPI2C1 SCL/SDA (ALT3): the touch controller on the panel's FPC
//   GPIO_B0_00..B1_03  LCD CLK, ENABLE, HSYNC, VSYNC, DATA00..15 (ALT0): the 40-pin LCD FPC
//   GPIO_AD_B0_02      GPIO1_IO02 (ALT5): LCD DISP / touch RESET (shared on the connector)
//   GPIO_AD_B0_11      GPIO1_IO11 (ALT5): touch INT
//   GPIO_B1_15         GPIO2_IO31 (ALT5): backlight enable
//   WAKEUP             GPIO5_IO00 (ALT5): the user button SW8, active low
#include <cstdint>

namespace facet::evkb {

struct PinSetting {
    const char* name;
    uint32_t mux, mux_value;  // SW_MUX_CTL_PAD_*: ALT function (| SION)
    uint32_t pad, pad_value;  // SW_PAD_CTL_PAD_*
    uint32_t daisy, daisy_value; // *_SELECT_INPUT (0: none)
};

// The table pins_init() writes, in order.
const PinSetting* pin_settings(uint32_t& count);

void pins_init();

} // namespace facet::evkb
