#include "pins.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {
using namespace iomuxc;

// Pad settings (RM, IOMUXC: SW_PAD_CTL_PAD fields), as NXP's SDK configures these pins:
//   UART: DSE 6 (R0/6), SPEED 2 (100 MHz), keeper on                               = 0x10B0
//   LCD:  DSE 6, SPEED 2, pull 100K up, hysteresis                                 = 0x1B0B0
//   I2C:  DSE 6, SPEED 2, open drain, keeper (PUS 22K up, unused: PUE 0; the bus has its own pull-ups) = 0xD8B0
//   GPIO: DSE 6, SPEED 2, keeper                                                    = 0x10B0
//   button: hysteresis, pull 100K up (SW8 shorts to ground)                         = 0x1B0A0
constexpr uint32_t kUart = pad(0, 6, 2, 0, 1, 0, 0, 0);
constexpr uint32_t kLcd = pad(0, 6, 2, 0, 1, 1, 2, 1);
constexpr uint32_t kI2c = pad(0, 6, 2, 1, 1, 0, 3, 0);
constexpr uint32_t kGpio = pad(0, 6, 2, 0, 1, 0, 0, 0);
constexpr uint32_t kButton = pad(0, 4, 2, 0, 1, 1, 2, 1);
static_assert(kUart == 0x10B0 && kLcd == 0x1B0B0 && kI2c == 0xD8B0 && kButton == 0x1B0A0, "SDK pad values");

constexpr uint32_t ad_b0(uint32_t n) { return kMuxAdB0 + 4 * n; }
constexpr uint32_t ad_b0_pad(uint32_t n) { return kPadAdB0 + 4 * n; }
constexpr uint32_t ad_b1(uint32_t n) { return kMuxAdB1 + 4 * n; }
constexpr uint32_t ad_b1_pad(uint32_t n) { return kPadAdB1 + 4 * n; }
constexpr uint32_t b0(uint32_t n) { return kMuxB0 + 4 * n; }
constexpr uint32_t b0_pad(uint32_t n) { return kPadB0 + 4 * n; }
constexpr uint32_t b1(uint32_t n) { return kMuxB1 + 4 * n; }
constexpr uint32_t b1_pad(uint32_t n) { return kPadB1 + 4 * n; }

constexpr PinSetting kPins[] = {
    {"LPUART1_TX GPIO_AD_B0_12", ad_b0(12), 2, ad_b0_pad(12), kUart, 0, 0},
    {"LPUART1_RX GPIO_AD_B0_13", ad_b0(13), 2, ad_b0_pad(13), kUart, 0, 0},
    // I2C pads with SION: the module reads the line it drives (open drain, clock stretching).
    {"LPI2C1_SCL GPIO_AD_B1_00", ad_b1(0), 3 | kSion, ad_b1_pad(0), kI2c, kLpi2c1SclSelect, 1},
    {"LPI2C1_SDA GPIO_AD_B1_01", ad_b1(1), 3 | kSion, ad_b1_pad(1), kI2c, kLpi2c1SdaSelect, 1},
    {"LCD_CLK GPIO_B0_00", b0(0), 0, b0_pad(0), kLcd, 0, 0},
    {"LCD_ENABLE GPIO_B0_01", b0(1), 0, b0_pad(1), kLcd, 0, 0},
    {"LCD_HSYNC GPIO_B0_02", b0(2), 0, b0_pad(2), kLcd, 0, 0},
    {"LCD_VSYNC GPIO_B0_03", b0(3), 0, b0_pad(3), kLcd, 0, 0},
    {"LCD_DATA00 GPIO_B0_04", b0(4), 0, b0_pad(4), kLcd, 0, 0},
    {"LCD_DATA01 GPIO_B0_05", b0(5), 0, b0_pad(5), kLcd, 0, 0},
    {"LCD_DATA02 GPIO_B0_06", b0(6), 0, b0_pad(6), kLcd, 0, 0},
    {"LCD_DATA03 GPIO_B0_07", b0(7), 0, b0_pad(7), kLcd, 0, 0},
    {"LCD_DATA04 GPIO_B0_08", b0(8), 0, b0_pad(8), kLcd, 0, 0},
    {"LCD_DATA05 GPIO_B0_09", b0(9), 0, b0_pad(9), kLcd, 0, 0},
    {"LCD_DATA06 GPIO_B0_10", b0(10), 0, b0_pad(10), kLcd, 0, 0},
    {"LCD_DATA07 GPIO_B0_11", b0(11), 0, b0_pad(11), kLcd, 0, 0},
    {"LCD_DATA08 GPIO_B0_12", b0(12), 0, b0_pad(12), kLcd, 0, 0},
    {"LCD_DATA09 GPIO_B0_13", b0(13), 0, b0_pad(13), kLcd, 0, 0},
    {"LCD_DATA10 GPIO_B0_14", b0(14), 0, b0_pad(14), kLcd, 0, 0},
    {"LCD_DATA11 GPIO_B0_15", b0(15), 0, b0_pad(15), kLcd, 0, 0},
    {"LCD_DATA12 GPIO_B1_00", b1(0), 0, b1_pad(0), kLcd, 0, 0},
    {"LCD_DATA13 GPIO_B1_01", b1(1), 0, b1_pad(1), kLcd, 0, 0},
    {"LCD_DATA14 GPIO_B1_02", b1(2), 0, b1_pad(2), kLcd, 0, 0},
    {"LCD_DATA15 GPIO_B1_03", b1(3), 0, b1_pad(3), kLcd, 0, 0},
    {"LCD_DISP/TOUCH_RST GPIO1_IO02 (GPIO_AD_B0_02)", ad_b0(2), 5, ad_b0_pad(2), kGpio, 0, 0},
    {"TOUCH_INT GPIO1_IO11 (GPIO_AD_B0_11)", ad_b0(11), 5, ad_b0_pad(11), kGpio, 0, 0},
    {"BACKLIGHT GPIO2_IO31 (GPIO_B1_15)", b1(15), 5, b1_pad(15), kGpio, 0, 0},
    {"USER_BUTTON GPIO5_IO00 (WAKEUP)", kSnvsMuxWakeup, 5, kSnvsPadWakeup, kButton, 0, 0},
};

} // namespace

const PinSetting* pin_settings(uint32_t& count) {
    count = sizeof kPins / sizeof kPins[0];
    return kPins;
}

void pins_init() {
    for (const PinSetting& p : kPins) {
        mmio::write(p.mux, p.mux_value);
        mmio::write(p.pad, p.pad_value);
        if (p.daisy) mmio::write(p.daisy, p.daisy_value);
    }
}

} // namespace facet::evkb
