#include "clocks.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {
using namespace mmio;

// CCM_CBCDR / CCM_CBCMR fields (RM, CCM register descriptions).
constexpr uint32_t kPeriphClkSel = 1u << 25;
constexpr uint32_t kPeriphClk2PodfMask = 7u << 27;
constexpr uint32_t kAhbPodfMask = 7u << 10, kIpgPodfMask = 3u << 8;
constexpr uint32_t kPeriphClk2SelMask = 3u << 12, kPrePeriphClkSelMask = 3u << 18, kLcdifPodfMask = 7u << 23;
constexpr uint32_t kArmPodfBusy = 1u << 16, kAhbPodfBusy = 1u << 1, kPeriphClkSelBusy = 1u << 5;

// PLL_USB1 (PLL3, 480 MHz: the source of pll3_80m and pll3_60m): POWER 12, ENABLE 13,
// EN_USB_CLKS 6, BYPASS 16, LOCK 31 (RM, CCM Analog: CCM_ANALOG_PLL_USB1).
constexpr uint32_t kPllUsb1 = analog::kBase + 0x10;
constexpr uint32_t kUsb1Power = 1u << 12, kUsb1Enable = 1u << 13, kUsb1EnUsbClks = 1u << 6;

} // namespace

void clocks_init(const ClockPlan& p) {
    // 1. VDD_SOC for 600 MHz (the datasheet's overdrive run point), then wait for the DCDC.
    modify(dcdc::kReg3, 0x1F, p.vdd_soc_trg);
    wait(dcdc::kReg0, 1u << 31, 1u << 31);

    // 2. Run the core from the 24 MHz oscillator (periph_clk2) while the ARM PLL changes.
    modify(ccm::kCbcmr, kPeriphClk2SelMask, 1u << 12);  // PERIPH_CLK2_SEL: osc_clk
    modify(ccm::kCbcdr, kPeriphClk2PodfMask, 0);       // PERIPH_CLK2_PODF: /1
    modify(ccm::kCbcdr, kPeriphClkSel, kPeriphClkSel); // PERIPH_CLK_SEL: periph_clk2
    wait(ccm::kCdhipr, kPeriphClkSelBusy, 0);

    // 3. ARM PLL: bypassed while it locks, then switched in (Fout = 24 MHz x 100 / 2 = 1200 MHz).
    write(analog::kPllArm, analog::kBypass | analog::kEnable | (p.arm_div_select & 0x7F));
    wait(analog::kPllArm, analog::kLock, analog::kLock);
    write(analog::kPllArm, analog::kEnable | (p.arm_div_select & 0x7F));

    // 4. Dividers: core = PLL1 / 2, AHB = core, IPG = AHB / 4.
    write(ccm::kCacrr, p.arm_podf & 7);
    wait(ccm::kCdhipr, kArmPodfBusy, 0);
    modify(ccm::kCbcdr, kAhbPodfMask, (p.ahb_podf & 7) << 10);
    wait(ccm::kCdhipr, kAhbPodfBusy, 0);
    modify(ccm::kCbcdr, kIpgPodfMask, (p.ipg_podf & 3) << 8);

    // 5. Back to the PLL: pre_periph = PLL1 (PRE_PERIPH_CLK_SEL 3), periph = pre_periph.
    modify(ccm::kCbcmr, kPrePeriphClkSelMask, 3u << 18);
    modify(ccm::kCbcdr, kPeriphClkSel, 0);
    wait(ccm::kCdhipr, kPeriphClkSelBusy, 0);

    // 6. PLL3 (480 MHz) on, for the UART and LPI2C roots (the ROM normally leaves it running).
    if (!(read(kPllUsb1) & analog::kLock) || (read(kPllUsb1) & analog::kBypass)) {
        write(kPllUsb1, kUsb1Power | kUsb1Enable | kUsb1EnUsbClks | analog::kBypass);
        wait(kPllUsb1, analog::kLock, analog::kLock);
        write(kPllUsb1, kUsb1Power | kUsb1Enable | kUsb1EnUsbClks);
    }

    // 7. Peripheral roots: PERCLK = IPG (GPT, PIT), UART = pll3_80m, LPI2C = pll3_60m / 6.
    modify(ccm::kCscmr1, 0x7F, p.perclk_podf & 0x3F);                   // PERCLK_CLK_SEL 0: ipg
    modify(ccm::kCscdr1, 0x7F, p.uart_podf & 0x3F);                     // UART_CLK_SEL 0: pll3_80m
    modify(ccm::kCscdr2, (1u << 18) | (0x3Fu << 19), (p.lpi2c_podf & 0x3F) << 19); // LPI2C_CLK_SEL 0: pll3_60m

    // 8. Video PLL (PLL5) for the LCD: 24 MHz x 31 = 744 MHz (its 648..1300 MHz range), / 4 / 2
    //    = 93 MHz; LCDIF root = PLL5 / 5 / 2 = 9.3 MHz.
    write(analog::kPllVideoNum, 0);
    write(analog::kPllVideoDenom, 1);
    write(analog::kPllVideo, analog::kBypass | analog::kEnable | ((p.video_post_div & 3) << 19) |
                                 (p.video_div_select & 0x7F));
    modify(analog::kMisc2, 3u << 30, (p.video_misc2_div & 3) << 30);
    wait(analog::kPllVideo, analog::kLock, analog::kLock);
    write(analog::kPllVideo, analog::kEnable | ((p.video_post_div & 3) << 19) | (p.video_div_select & 0x7F));
    // LCDIF_PRE_CLK_SEL 2: PLL5; LCDIF_PRED; LCDIF_CLK_SEL 0: the pre-mux output.
    modify(ccm::kCscdr2, (7u << 15) | (7u << 12) | (7u << 9), (2u << 15) | ((p.lcdif_pred & 7) << 12));
    modify(ccm::kCbcmr, kLcdifPodfMask, (p.lcdif_podf & 7) << 23);

    // 9. Every module clock on (CCGR0..6 = all ones), as the DCD already did for the ROM.
    for (uint32_t n = 0; n < 7; ++n) write(ccm::ccgr(n), 0xFFFFFFFF);
}

} // namespace facet::evkb
