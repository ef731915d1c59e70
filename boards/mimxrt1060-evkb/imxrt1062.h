#pragma once
// i.MX RT1062 registers this board uses. Every address and field from the i.MX RT1060
// Processor Reference Manual (IMXRT1060RM, Rev. 3), by chapter and register name; the same
// facts NXP's SDK (MIMXRT1062.h, fsl_iomuxc.h) and NuttX (arch/arm/src/imxrt/hardware) state.
#include <cstdint>

namespace facet::evkb {

// --- Clock Controller Module (RM chapter "Clock Controller Module (CCM)") -------------------
namespace ccm {
constexpr uint32_t kBase = 0x400FC000;
constexpr uint32_t kCacrr = kBase + 0x10;  // ARM_PODF 2:0
constexpr uint32_t kCbcdr = kBase + 0x14;  // SEMC_CLK_SEL 6, SEMC_ALT_CLK_SEL 7, IPG_PODF 9:8,
                                           // AHB_PODF 12:10, SEMC_PODF 18:16, PERIPH_CLK_SEL 25
constexpr uint32_t kCbcmr = kBase + 0x18;  // PERIPH_CLK2_SEL 13:12, PRE_PERIPH_CLK_SEL 19:18, LCDIF_PODF 25:23
constexpr uint32_t kCscmr1 = kBase + 0x1C; // PERCLK_PODF 5:0, PERCLK_CLK_SEL 6, USDHC1_CLK_SEL 16 (0: PLL2 PFD2)
constexpr uint32_t kCscdr1 = kBase + 0x24; // UART_CLK_PODF 5:0, UART_CLK_SEL 6, USDHC1_PODF 13:11
constexpr uint32_t kCscdr2 = kBase + 0x38; // LCDIF_PRED 14:12, LCDIF_PRE_CLK_SEL 17:15,
                                           // LPI2C_CLK_SEL 18, LPI2C_CLK_PODF 24:19
constexpr uint32_t kCdhipr = kBase + 0x48; // handshake busy: SEMC 0, AHB 1, PERIPH2 3, PERIPH 5, ARM 16
constexpr uint32_t kCcgr0 = kBase + 0x68;  // clock gates CCGR0..CCGR6 at 0x68..0x80
constexpr uint32_t ccgr(uint32_t n) { return kCcgr0 + 4 * n; }
} // namespace ccm

// --- CCM analog: the PLLs (RM "CCM Analog Memory Map/Register Definition") ----------------
namespace analog {
constexpr uint32_t kBase = 0x400D8000;
constexpr uint32_t kPllArm = kBase + 0x00;    // DIV_SELECT 6:0, POWERDOWN 12, ENABLE 13, BYPASS 16, LOCK 31
constexpr uint32_t kPllVideo = kBase + 0xA0;  // DIV_SELECT 6:0, POWERDOWN 12, ENABLE 13, BYPASS 16,
                                              // POST_DIV_SELECT 20:19 (0: /4, 1: /2, 2: /1), LOCK 31
constexpr uint32_t kPllVideoNum = kBase + 0xB0;
constexpr uint32_t kPllVideoDenom = kBase + 0xC0;
constexpr uint32_t kMisc2 = kBase + 0x170;    // VIDEO_DIV 31:30 (0: /1, 1: /2, 3: /4)
constexpr uint32_t kPfd528 = kBase + 0x100;   // PLL2's PFDs: PFD2_FRAC 21:16 (528 MHz x 18 / FRAC)
constexpr uint32_t kPowerdown = 1u << 12, kEnable = 1u << 13, kBypass = 1u << 16, kLock = 1u << 31;
} // namespace analog

// --- DCDC converter (RM chapter "DCDC Converter (DCDC)") ------------------------------------
namespace dcdc {
constexpr uint32_t kReg0 = 0x40080000; // STS_DC_OK 31
constexpr uint32_t kReg3 = 0x4008000C; // TRG 4:0: VDD_SOC = 0.8 V + TRG x 25 mV
} // namespace dcdc

// --- Watchdogs (RM chapters "Watchdog Timer (WDOG)", "Watchdog Timer (RTWDOG)") -------------
namespace wdog {
constexpr uint32_t kWdog1Wcr = 0x400B8000; // 16-bit WCR: WDE bit 2
constexpr uint32_t kWdog2Wcr = 0x400D0000;
constexpr uint32_t kRtwdogCs = 0x400BC000;    // EN 7, UPDATE 5, CMD32EN 13, ULK 11, RCS 10
constexpr uint32_t kRtwdogCnt = 0x400BC004;   // write 0xD928C520 to unlock
constexpr uint32_t kRtwdogToval = 0x400BC008;
} // namespace wdog

// --- IOMUX controller (RM chapter "IOMUX Controller (IOMUXC)") ------------------------------
// A pad's mux register takes the ALT function (and SION, bit 4); its pad control register the
// electrical settings: SRE 0, DSE 5:3, SPEED 7:6, ODE 11, PKE 12, PUE 13, PUS 15:14, HYS 16.
namespace iomuxc {
constexpr uint32_t kMuxAdB0 = 0x401F80BC, kPadAdB0 = 0x401F82AC; // GPIO_AD_B0_00
constexpr uint32_t kMuxAdB1 = 0x401F80FC, kPadAdB1 = 0x401F82EC; // GPIO_AD_B1_00
constexpr uint32_t kMuxB0 = 0x401F813C, kPadB0 = 0x401F832C;     // GPIO_B0_00
constexpr uint32_t kMuxB1 = 0x401F817C, kPadB1 = 0x401F836C;     // GPIO_B1_00
constexpr uint32_t kMuxSdB0 = 0x401F81BC, kPadSdB0 = 0x401F83AC; // GPIO_SD_B0_00
constexpr uint32_t kLpi2c1SclSelect = 0x401F84CC;                 // daisy chain inputs
constexpr uint32_t kLpi2c1SdaSelect = 0x401F84D0;
constexpr uint32_t kSnvsMuxWakeup = 0x400A8000, kSnvsPadWakeup = 0x400A8018; // IOMUXC_SNVS
constexpr uint32_t kSion = 1u << 4;
constexpr uint32_t pad(uint32_t sre, uint32_t dse, uint32_t speed, uint32_t ode, uint32_t pke, uint32_t pue,
                       uint32_t pus, uint32_t hys) {
    return sre | (dse << 3) | (speed << 6) | (ode << 11) | (pke << 12) | (pue << 13) | (pus << 14) | (hys << 16);
}
} // namespace iomuxc

// --- GPIO (RM chapter "General Purpose Input/Output (GPIO)") --------------------------------
namespace gpio {
constexpr uint32_t kGpio1 = 0x401B8000, kGpio2 = 0x401BC000, kGpio5 = 0x400C0000;
constexpr uint32_t kDr = 0x00, kGdir = 0x04, kPsr = 0x08;
} // namespace gpio

// --- LPUART (RM chapter "Low Power Universal Asynchronous Receiver/Transmitter (LPUART)") ----
namespace lpuart {
constexpr uint32_t kLpuart1 = 0x40184000;
constexpr uint32_t kGlobal = 0x08; // RST 1
constexpr uint32_t kBaud = 0x10;   // SBR 12:0, BOTHEDGE 17, OSR 28:24 (oversampling OSR + 1)
constexpr uint32_t kStat = 0x14;   // TDRE 23, TC 22, RDRF 21, OR 19, NF 18, FE 17, PF 16 (w1c)
constexpr uint32_t kCtrl = 0x18;   // RE 18, TE 19
constexpr uint32_t kData = 0x1C;
constexpr uint32_t kTdre = 1u << 23, kRdrf = 1u << 21, kErrors = 0xFu << 16;
constexpr uint32_t kRe = 1u << 18, kTe = 1u << 19, kBothEdge = 1u << 17;
} // namespace lpuart

// --- GPT (RM chapter "General Purpose Timer (GPT)") ------------------------------------------
namespace gpt {
constexpr uint32_t kGpt1 = 0x401EC000;
constexpr uint32_t kCr = 0x00;  // EN 0, ENMOD 1, CLKSRC 8:6 (5: 24 MHz crystal), FRR 9, EN_24M 10, SWR 15
constexpr uint32_t kPr = 0x04;  // PRESCALER 11:0 (divide by PRESCALER + 1), PRESCALER24M 15:12
constexpr uint32_t kCnt = 0x24;
} // namespace gpt

// --- eLCDIF (RM chapter "Enhanced LCD Interface (eLCDIF)") ------------------------------------
// Registers with SET/CLR/TOG aliases at +4/+8/+C.
namespace lcdif {
constexpr uint32_t kBase = 0x402B8000;
constexpr uint32_t kCtrl = kBase + 0x00, kCtrlSet = kBase + 0x04, kCtrlClr = kBase + 0x08;
constexpr uint32_t kCtrl1 = kBase + 0x10, kCtrl1Clr = kBase + 0x18;
constexpr uint32_t kCtrl2 = kBase + 0x20;
constexpr uint32_t kTransferCount = kBase + 0x30; // V_COUNT 31:16, H_COUNT 15:0
constexpr uint32_t kCurBuf = kBase + 0x40, kNextBuf = kBase + 0x50;
constexpr uint32_t kVdctrl0 = kBase + 0x70; // VSYNC_PULSE_WIDTH 17:0, VSYNC_PULSE_WIDTH_UNIT 20,
                                            // VSYNC_PERIOD_UNIT 21, ENABLE_POL 24, DOTCLK_POL 25,
                                            // HSYNC_POL 26, VSYNC_POL 27, ENABLE_PRESENT 28
constexpr uint32_t kVdctrl1 = kBase + 0x80; // VSYNC_PERIOD
constexpr uint32_t kVdctrl2 = kBase + 0x90; // HSYNC_PERIOD 17:0, HSYNC_PULSE_WIDTH 31:18
constexpr uint32_t kVdctrl3 = kBase + 0xA0; // VERTICAL_WAIT_CNT 15:0, HORIZONTAL_WAIT_CNT 27:16
constexpr uint32_t kVdctrl4 = kBase + 0xB0; // DOTCLK_H_VALID_DATA_CNT 17:0, SYNC_SIGNALS_ON 18
// CTRL: RUN 0, MASTER 5, WORD_LENGTH 9:8 (0: 16 bits), LCD_DATABUS_WIDTH 11:10 (0: 16 bits),
// DOTCLK_MODE 17, BYPASS_COUNT 19, CLKGATE 30, SFTRST 31. CTRL1: CUR_FRAME_DONE_IRQ 9,
// BYTE_PACKING_FORMAT 19:16. CTRL2: OUTSTANDING_REQS 23:21.
constexpr uint32_t kRun = 1u << 0, kMaster = 1u << 5, kDotclkMode = 1u << 17, kBypassCount = 1u << 19;
constexpr uint32_t kClkgate = 1u << 30, kSftrst = 1u << 31;
constexpr uint32_t kCurFrameDone = 1u << 9;
} // namespace lcdif

// --- LPI2C (RM chapter "Low Power Inter-Integrated Circuit (LPI2C)") ------------------------
namespace lpi2c {
constexpr uint32_t kLpi2c1 = 0x403F0000;
constexpr uint32_t kMcr = 0x10;    // MEN 0, RST 1, RTF 8, RRF 9
constexpr uint32_t kMsr = 0x14;    // TDF 0, RDF 1, EPF 8, SDF 9, NDF 10, ALF 11, FEF 12, PLTF 13, MBF 24, BBF 25 (w1c 8..13)
constexpr uint32_t kMcfgr1 = 0x24; // PRESCALE 2:0
constexpr uint32_t kMcfgr2 = 0x28; // BUSIDLE 11:0, FILTSCL 19:16, FILTSDA 27:24
constexpr uint32_t kMccr0 = 0x48;  // CLKLO 5:0, CLKHI 13:8, SETHOLD 21:16, DATAVD 29:24
constexpr uint32_t kMfsr = 0x5C;   // TXCOUNT 2:0, RXCOUNT 18:16
constexpr uint32_t kMtdr = 0x60;   // DATA 7:0, CMD 10:8
constexpr uint32_t kMrdr = 0x70;   // DATA 7:0, RXEMPTY 14
constexpr uint32_t kMen = 1u << 0, kRst = 1u << 1, kRtf = 1u << 8, kRrf = 1u << 9;
constexpr uint32_t kTdf = 1u << 0, kSdf = 1u << 9, kNdf = 1u << 10, kAlf = 1u << 11, kFef = 1u << 12, kPltf = 1u << 13;
constexpr uint32_t kMbf = 1u << 24;
constexpr uint32_t kRxEmpty = 1u << 14;
// MTDR commands (CMD field).
constexpr uint32_t kCmdTransmit = 0u << 8, kCmdReceive = 1u << 8, kCmdStop = 2u << 8, kCmdStart = 4u << 8;
} // namespace lpi2c

} // namespace facet::evkb
