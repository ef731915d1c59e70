// What the i.MX RT1062 boot ROM reads from the QSPI flash before it runs anything of ours
// (IMXRT1060RM, chapter "System Boot"; the linker script places each at its offset):
//
//   +0x0000  FlexSPI NOR configuration block (FCB): how to read the flash
//   +0x1000  image vector table (IVT): where the entry, the boot data and the DCD are
//   +0x1020  boot data: the image's start and size
//   +0x1030  device configuration data (DCD): register writes the ROM makes first, here the
//            SDRAM controller (SEMC) bring-up, so the image may use SDRAM from its first line
//   +0x2000  the vector table (boards/cortex-m/vectors.cpp): SP and the reset handler
//
// tests/boards/evkb_image_test.py reads these back from the built image and checks each field
// and every DCD write against its own table.
#include <array>
#include <cstddef>
#include <cstdint>

extern "C" uint32_t __vectors_start[], __boot_hdr_start[];
extern "C" uint8_t __image_size[];

namespace {

// --- FlexSPI NOR configuration block (RM "FlexSPI NOR Configuration Block"; 512 bytes) ------
// For the EVKB's ISSI IS25WP064A (64 Mbit quad SPI NOR): quad I/O fast read (0xEB) with 6
// dummy cycles, the same configuration NXP's SDK and Zephyr boot this board with.

// A LUT instruction pair (RM, FlexSPI "Look Up Table"): opcode 15:10, pads 9:8, operand 7:0.
constexpr uint32_t lut(uint32_t op0, uint32_t pads0, uint32_t operand0, uint32_t op1, uint32_t pads1, uint32_t operand1) {
    return (op0 << 10 | pads0 << 8 | operand0) | (op1 << 10 | pads1 << 8 | operand1) << 16;
}
constexpr uint32_t kCmdSdr = 0x01, kRaddrSdr = 0x02, kWriteSdr = 0x08, kReadSdr = 0x09, kDummySdr = 0x0C, kStop = 0;
constexpr uint32_t k1Pad = 0, k4Pads = 2;

struct FlexspiNorConfig {
    uint32_t tag;                     // 0x000 'FCFB'
    uint32_t version;                 // 0x004 V1.4.0 ('V', 1, 4, 0)
    uint32_t reserved0;               // 0x008
    uint8_t read_sample_clk_src;      // 0x00C 1: loopback from the DQS pad
    uint8_t cs_hold_time;             // 0x00D
    uint8_t cs_setup_time;            // 0x00E
    uint8_t column_address_width;     // 0x00F
    uint8_t device_mode_cfg_enable;   // 0x010
    uint8_t device_mode_type;         // 0x011
    uint16_t wait_time_cfg_commands;  // 0x012
    uint32_t device_mode_seq;         // 0x014
    uint32_t device_mode_arg;         // 0x018
    uint8_t config_cmd_enable;        // 0x01C
    uint8_t config_mode_type[3];      // 0x01D
    uint32_t config_cmd_seqs[3];      // 0x020
    uint32_t reserved1;               // 0x02C
    uint32_t config_cmd_args[3];      // 0x030
    uint32_t reserved2;               // 0x03C
    uint32_t controller_misc_option;  // 0x040
    uint8_t device_type;              // 0x044 1: serial NOR
    uint8_t sflash_pad_type;          // 0x045 4: quad
    uint8_t serial_clk_freq;          // 0x046 6: 100 MHz (RT1060 encoding)
    uint8_t lut_custom_seq_enable;    // 0x047
    uint32_t reserved3[2];            // 0x048
    uint32_t sflash_a1_size;          // 0x050 bytes on port A, chip select 1
    uint32_t sflash_a2_size, sflash_b1_size, sflash_b2_size;
    uint32_t cs_pad_override, sclk_pad_override, data_pad_override, dqs_pad_override; // 0x060
    uint32_t timeout_ms;              // 0x070
    uint32_t command_interval;        // 0x074
    uint16_t data_valid_time[2];      // 0x078
    uint16_t busy_offset;             // 0x07C
    uint16_t busy_bit_polarity;       // 0x07E
    uint32_t lookup_table[64];        // 0x080 16 sequences of 4 words; sequence 0 is the read
    uint32_t lut_custom_seq[12];      // 0x180
    uint32_t reserved4[4];            // 0x1B0
    uint32_t page_size;               // 0x1C0
    uint32_t sector_size;             // 0x1C4
    uint8_t ipcmd_serial_clk_freq;    // 0x1C8
    uint8_t is_uniform_block_size;    // 0x1C9
    uint8_t reserved5[2];             // 0x1CA
    uint8_t serial_nor_type;          // 0x1CC
    uint8_t need_exit_no_cmd_mode, half_clk_for_non_read_cmd, need_restore_no_cmd_mode;
    uint32_t block_size;              // 0x1D0
    uint32_t reserved6[11];           // 0x1D4
};
static_assert(sizeof(FlexspiNorConfig) == 512, "the FCB is 512 bytes");
static_assert(offsetof(FlexspiNorConfig, sflash_pad_type) == 0x45 && offsetof(FlexspiNorConfig, sflash_a1_size) == 0x50 &&
                  offsetof(FlexspiNorConfig, lookup_table) == 0x80 && offsetof(FlexspiNorConfig, page_size) == 0x1C0 &&
                  offsetof(FlexspiNorConfig, block_size) == 0x1D0,
              "FCB field offsets (RM, FlexSPI NOR Configuration Block)");

constexpr FlexspiNorConfig make_fcb() {
    FlexspiNorConfig c{};
    c.tag = 0x42464346;     // "FCFB", little-endian
    c.version = 0x56010400; // V1.4.0
    c.read_sample_clk_src = 1;
    c.cs_hold_time = 3;
    c.cs_setup_time = 3;
    c.device_type = 1;
    c.sflash_pad_type = 4;
    c.serial_clk_freq = 6;
    c.sflash_a1_size = 8u * 1024 * 1024;
    // Sequence 0, read: 0xEB on one pad, 24-bit address on four, 6 dummy cycles, read on four.
    c.lookup_table[0] = lut(kCmdSdr, k1Pad, 0xEB, kRaddrSdr, k4Pads, 0x18);
    c.lookup_table[1] = lut(kDummySdr, k4Pads, 0x06, kReadSdr, k4Pads, 0x04);
    // For programmers that take their commands from the FCB: 1 read status (0x05), 3 write
    // enable (0x06), 5 sector erase (0x20), 8 block erase (0xD8), 9 page program (0x02),
    // 11 chip erase (0x60).
    c.lookup_table[4 * 1] = lut(kCmdSdr, k1Pad, 0x05, kReadSdr, k1Pad, 0x04);
    c.lookup_table[4 * 3] = lut(kCmdSdr, k1Pad, 0x06, kStop, k1Pad, 0);
    c.lookup_table[4 * 5] = lut(kCmdSdr, k1Pad, 0x20, kRaddrSdr, k1Pad, 0x18);
    c.lookup_table[4 * 8] = lut(kCmdSdr, k1Pad, 0xD8, kRaddrSdr, k1Pad, 0x18);
    c.lookup_table[4 * 9] = lut(kCmdSdr, k1Pad, 0x02, kRaddrSdr, k1Pad, 0x18);
    c.lookup_table[4 * 9 + 1] = lut(kWriteSdr, k1Pad, 0x04, kStop, k1Pad, 0);
    c.lookup_table[4 * 11] = lut(kCmdSdr, k1Pad, 0x60, kStop, k1Pad, 0);
    c.page_size = 256;
    c.sector_size = 4096;
    c.ipcmd_serial_clk_freq = 1;
    c.block_size = 64 * 1024;
    return c;
}

// --- Image vector table and boot data (RM "Image Vector Table and Boot Data") ---------------
// Pointers, so the linker fills the addresses in (a constant initializer, kept in flash).
struct ImageVectorTable {
    uint32_t header;           // tag 0xD1, length 0x0020 (big-endian), version 0x41
    const void* entry;         // the vector table: the ROM loads SP and PC from it
    uint32_t reserved1;
    const void* dcd;
    const void* boot_data;
    const void* self;
    uint32_t csf;              // no signature (HAB off)
    uint32_t reserved2;
};
struct BootData {
    const void* start;         // the image's first byte: the flash base
    const uint8_t* size;       // its size: __image_size, an address-valued linker symbol
    uint32_t plugin;           // 0: not a plugin
    uint32_t placeholder;
};
static_assert(sizeof(ImageVectorTable) == 32 && sizeof(BootData) == 16, "IVT 32 bytes, boot data 16");

// --- Device configuration data (RM "Device Configuration Data (DCD)") ------------------------
// Big-endian: a header (tag 0xD2, total length, version 0x41), then commands: write data (tag
// 0xCC, length, parameter 0x04 = 32-bit writes; address/value pairs) and check data (tag 0xCF,
// length 12, parameter 0x1C = 32-bit, until any of the mask bits is set; address, mask).
struct DcdCommand {
    bool check;          // false: write value to address; true: wait until (address & value) != 0
    uint32_t address, value;
};

// SEMC (RM chapter "Smart External Memory Controller (SEMC)") bring-up for the EVKB's 32 MiB
// SDRAM (ISSI IS42S16160J, 16-bit, on chip select 0 at 0x80000000), as NXP's SDK DCD for this
// board: clocks, the EMC pins, the controller, then the SDRAM's own initialisation through IP
// commands (precharge all, two auto-refreshes, mode register), each checked for IPCMDDONE.
constexpr uint32_t kSemc = 0x402F0000;
constexpr DcdCommand kDcd[] = {
    // CCM: every module clock on (CCGR0..6), PLL2 (528 MHz) enabled, its PFD2 = 528 x 18 / 29
    // = 327.7 MHz, CBCDR: SEMC_CLK_SEL 1 (alternate), SEMC_ALT_CLK_SEL 0 (PLL2 PFD2),
    // SEMC_PODF 1 (/2: 163.86 MHz), IPG_PODF 1, AHB_PODF 3 (the ROM's pace until ours).
    {false, 0x400FC068, 0xFFFFFFFF}, {false, 0x400FC06C, 0xFFFFFFFF}, {false, 0x400FC070, 0xFFFFFFFF},
    {false, 0x400FC074, 0xFFFFFFFF}, {false, 0x400FC078, 0xFFFFFFFF}, {false, 0x400FC07C, 0xFFFFFFFF},
    {false, 0x400FC080, 0xFFFFFFFF}, {false, 0x400D8030, 0x00002001}, {false, 0x400D8100, 0x101D101B},
    {false, 0x400FC014, 0x00010D40},
    // IOMUXC: GPIO_EMC_00..38 to their SEMC function (ALT0), GPIO_EMC_39 (SEMC_DQS) with SION
    // (the read strobe loops back through the pad), and all 40 pads: 0x110F9 (hysteresis,
    // keeper: PKE 1 PUE 0, SPEED 3: 200 MHz, DSE 7: R0/7, fast slew).
    {false, 0x401F8014, 0}, {false, 0x401F8018, 0}, {false, 0x401F801C, 0}, {false, 0x401F8020, 0},
    {false, 0x401F8024, 0}, {false, 0x401F8028, 0}, {false, 0x401F802C, 0}, {false, 0x401F8030, 0},
    {false, 0x401F8034, 0}, {false, 0x401F8038, 0}, {false, 0x401F803C, 0}, {false, 0x401F8040, 0},
    {false, 0x401F8044, 0}, {false, 0x401F8048, 0}, {false, 0x401F804C, 0}, {false, 0x401F8050, 0},
    {false, 0x401F8054, 0}, {false, 0x401F8058, 0}, {false, 0x401F805C, 0}, {false, 0x401F8060, 0},
    {false, 0x401F8064, 0}, {false, 0x401F8068, 0}, {false, 0x401F806C, 0}, {false, 0x401F8070, 0},
    {false, 0x401F8074, 0}, {false, 0x401F8078, 0}, {false, 0x401F807C, 0}, {false, 0x401F8080, 0},
    {false, 0x401F8084, 0}, {false, 0x401F8088, 0}, {false, 0x401F808C, 0}, {false, 0x401F8090, 0},
    {false, 0x401F8094, 0}, {false, 0x401F8098, 0}, {false, 0x401F809C, 0}, {false, 0x401F80A0, 0},
    {false, 0x401F80A4, 0}, {false, 0x401F80A8, 0}, {false, 0x401F80AC, 0}, {false, 0x401F80B0, 0x10},
    {false, 0x401F8204, 0x110F9}, {false, 0x401F8208, 0x110F9}, {false, 0x401F820C, 0x110F9},
    {false, 0x401F8210, 0x110F9}, {false, 0x401F8214, 0x110F9}, {false, 0x401F8218, 0x110F9},
    {false, 0x401F821C, 0x110F9}, {false, 0x401F8220, 0x110F9}, {false, 0x401F8224, 0x110F9},
    {false, 0x401F8228, 0x110F9}, {false, 0x401F822C, 0x110F9}, {false, 0x401F8230, 0x110F9},
    {false, 0x401F8234, 0x110F9}, {false, 0x401F8238, 0x110F9}, {false, 0x401F823C, 0x110F9},
    {false, 0x401F8240, 0x110F9}, {false, 0x401F8244, 0x110F9}, {false, 0x401F8248, 0x110F9},
    {false, 0x401F824C, 0x110F9}, {false, 0x401F8250, 0x110F9}, {false, 0x401F8254, 0x110F9},
    {false, 0x401F8258, 0x110F9}, {false, 0x401F825C, 0x110F9}, {false, 0x401F8260, 0x110F9},
    {false, 0x401F8264, 0x110F9}, {false, 0x401F8268, 0x110F9}, {false, 0x401F826C, 0x110F9},
    {false, 0x401F8270, 0x110F9}, {false, 0x401F8274, 0x110F9}, {false, 0x401F8278, 0x110F9},
    {false, 0x401F827C, 0x110F9}, {false, 0x401F8280, 0x110F9}, {false, 0x401F8284, 0x110F9},
    {false, 0x401F8288, 0x110F9}, {false, 0x401F828C, 0x110F9}, {false, 0x401F8290, 0x110F9},
    {false, 0x401F8294, 0x110F9}, {false, 0x401F8298, 0x110F9}, {false, 0x401F829C, 0x110F9},
    {false, 0x401F82A0, 0x110F9},
    // SEMC: MCR (BTO 0x10, DQS from the pad), bus masters' priorities, base registers: BR0 =
    // SDRAM CS0 at 0x80000000, 32 MiB, valid; the other chip selects as the SDK leaves them.
    {false, kSemc + 0x00, 0x10000004}, {false, kSemc + 0x08, 0x00000081}, {false, kSemc + 0x0C, 0x00000081},
    {false, kSemc + 0x10, 0x8000001B}, {false, kSemc + 0x14, 0x8200001B}, {false, kSemc + 0x18, 0x8400001B},
    {false, kSemc + 0x1C, 0x8600001B}, {false, kSemc + 0x20, 0x90000021}, {false, kSemc + 0x24, 0xA0000019},
    {false, kSemc + 0x28, 0xA8000017}, {false, kSemc + 0x2C, 0xA900001B}, {false, kSemc + 0x30, 0x00000021},
    // IOCR 0x79A8: the pins' chip-select muxing. SDRAMCR0 0xF31: 16-bit port, burst 8, 9 column
    // bits, CAS latency 3. SDRAMCR1..3: timings (precharge, active, refresh) for 163 MHz.
    {false, kSemc + 0x04, 0x000079A8}, {false, kSemc + 0x40, 0x00000F31}, {false, kSemc + 0x44, 0x00652922},
    {false, kSemc + 0x48, 0x00010920}, {false, kSemc + 0x4C, 0x50210A08}, {false, kSemc + 0x80, 0x00000021},
    {false, kSemc + 0x84, 0x00888888}, {false, kSemc + 0x94, 0x00000002}, {false, kSemc + 0x98, 0x00000000},
    // IP commands at 0x80000000 (IPCR0), key 0xA55A: precharge all (0xF)...
    {false, kSemc + 0x90, 0x80000000}, {false, kSemc + 0x9C, 0xA55A000F}, {true, kSemc + 0x3C, 0x00000001},
    // ...auto-refresh twice (0xC)...
    {false, kSemc + 0x90, 0x80000000}, {false, kSemc + 0x9C, 0xA55A000C}, {true, kSemc + 0x3C, 0x00000001},
    {false, kSemc + 0x90, 0x80000000}, {false, kSemc + 0x9C, 0xA55A000C}, {true, kSemc + 0x3C, 0x00000001},
    // ...mode register (0xA) = 0x33: burst length 8, CAS latency 3...
    {false, kSemc + 0xA0, 0x00000033}, {false, kSemc + 0x90, 0x80000000}, {false, kSemc + 0x9C, 0xA55A000A},
    {true, kSemc + 0x3C, 0x00000001},
    // ...and auto-refresh on (SDRAMCR3.REN).
    {false, kSemc + 0x4C, 0x50210A09},
};

// The DCD's bytes, built at compile time from kDcd: consecutive writes share one 0xCC command.
constexpr size_t dcd_bytes() {
    size_t n = 4;
    for (size_t i = 0; i < std::size(kDcd);) {
        if (kDcd[i].check) {
            n += 12, ++i;
            continue;
        }
        n += 4;
        while (i < std::size(kDcd) && !kDcd[i].check) n += 8, ++i;
    }
    return n;
}

constexpr std::array<uint8_t, dcd_bytes()> make_dcd() {
    std::array<uint8_t, dcd_bytes()> b{};
    size_t at = 0;
    auto u8 = [&](uint32_t v) { b[at++] = uint8_t(v); };
    auto be16 = [&](uint32_t v) { u8(v >> 8), u8(v); };
    auto be32 = [&](uint32_t v) { u8(v >> 24), u8(v >> 16), u8(v >> 8), u8(v); };
    u8(0xD2), be16(uint32_t(dcd_bytes())), u8(0x41);
    for (size_t i = 0; i < std::size(kDcd);) {
        if (kDcd[i].check) {
            u8(0xCF), be16(12), u8(0x1C), be32(kDcd[i].address), be32(kDcd[i].value);
            ++i;
            continue;
        }
        size_t j = i;
        while (j < std::size(kDcd) && !kDcd[j].check) ++j;
        u8(0xCC), be16(uint32_t(4 + 8 * (j - i))), u8(0x04);
        for (; i < j; ++i) be32(kDcd[i].address), be32(kDcd[i].value);
    }
    return b;
}

} // namespace

extern "C" {
__attribute__((section(".boot_hdr.conf"), used)) const FlexspiNorConfig facet_flexspi_config = make_fcb();

__attribute__((section(".boot_hdr.dcd_data"), used, aligned(4))) const std::array<uint8_t, dcd_bytes()> facet_dcd = make_dcd();
static_assert(dcd_bytes() <= 0x1000 - 0x30, "the DCD must end before the vector table");

__attribute__((section(".boot_hdr.boot_data"), used)) const BootData facet_boot_data = {
    __boot_hdr_start, __image_size, 0, 0xFFFFFFFF};

__attribute__((section(".boot_hdr.ivt"), used)) const ImageVectorTable facet_ivt = {
    0x412000D1, __vectors_start, 0, &facet_dcd, &facet_boot_data, &facet_ivt, 0, 0};
}
