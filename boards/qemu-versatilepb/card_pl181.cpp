// The SD card behind the PL181 (card_pl181.h). Registers from the PrimeCell PL181 TRM (ARM DDI
// 0172); the commands and the CSD from the SD Physical Layer Simplified Specification.
#include "card_pl181.h"

#include "memory_map.h"

namespace facet::versatilepb {
namespace {

constexpr uintptr_t kPower = kPl181 + 0x00, kClock = kPl181 + 0x04, kArgument = kPl181 + 0x08, kCommand = kPl181 + 0x0C;
constexpr uintptr_t kResponse0 = kPl181 + 0x14, kDataTimer = kPl181 + 0x24, kDataLength = kPl181 + 0x28;
constexpr uintptr_t kDataCtrl = kPl181 + 0x2C, kStatus = kPl181 + 0x34, kClear = kPl181 + 0x38, kFifo = kPl181 + 0x80;
constexpr uintptr_t kSysMci = kSysRegs + 0x48; // SYS_MCI: bit 0, a card in MMCI0's slot

// Command register: the index, a response expected (long: 136 bits), the state machine enabled.
constexpr uint32_t kResponse = 1u << 6, kLong = 1u << 7, kEnable = 1u << 10;
constexpr uint32_t kNone = 0, kShort = kResponse, kLongResponse = kResponse | kLong;
// Status register.
constexpr uint32_t kCmdCrcFail = 1u << 0, kDataCrcFail = 1u << 1, kCmdTimeout = 1u << 2, kDataTimeout = 1u << 3;
constexpr uint32_t kRxOverrun = 1u << 5, kCmdRespEnd = 1u << 6, kCmdSent = 1u << 7, kDataEnd = 1u << 8;
constexpr uint32_t kStartBitErr = 1u << 9, kRxHalfFull = 1u << 15, kRxFull = 1u << 17, kRxAvailable = 1u << 21;
constexpr uint32_t kClearAll = 0x7FF;
constexpr uint32_t kDataErrors = kDataCrcFail | kDataTimeout | kRxOverrun | kStartBitErr;
// Data control: enabled, from the card, 512-byte blocks (2^9).
constexpr uint32_t kDataEnable = 1u << 0, kFromCard = 1u << 1, kBlock512 = 9u << 4;
constexpr uint32_t kMaxTransfer = 65535 / hal::Card::kSectorBytes; // DataLength is 16 bits: 127 sectors
constexpr uint32_t kPolls = 1'000'000;

constexpr Place kCard{"card"};
Result io(const char* what) { return Result::fail(Status::Io, what, kCard); }

} // namespace

// The card-detect line where the board wires it; without it (QEMU leaves SYS_MCI low), whether
// a card answers: a started one its status (CMD13), another the interface condition (CMD8).
bool Pl181Card::present() {
    if (reg(kSysMci) & 1u) return true;
    const bool answers = started_ ? command(13, rca_, kShort).ok() : command(0, 0, kNone).ok() && command(8, 0x1AA, kShort).ok();
    if (!answers) started_ = false; // (one put back is started again)
    return answers;
}

Result Pl181Card::command(uint32_t index, uint32_t argument, uint32_t response, bool crc_ok) {
    reg(kClear) = kClearAll;
    reg(kArgument) = argument;
    reg(kCommand) = index | response | kEnable;
    const uint32_t done = response ? kCmdRespEnd : kCmdSent;
    for (uint32_t k = 0; k < kPolls; ++k) {
        const uint32_t s = reg(kStatus);
        if (s & kCmdTimeout) return io("the card did not answer a command");
        if ((s & kCmdCrcFail) && !crc_ok) return io("a command's answer failed its CRC");
        if (s & (done | (crc_ok ? kCmdCrcFail : 0))) {
            for (int i = 0; i < 4; ++i) resp_[i] = reg(kResponse0 + 4 * i);
            return {};
        }
    }
    return io("the controller never ended a command");
}

Result Pl181Card::start() {
    started_ = false, sectors_ = 0;
    if (!present()) return io("no card in the slot");
    reg(kPower) = 0x03;       // on
    reg(kClock) = 1u << 8;    // the card's clock enabled
    if (Result r = command(0, 0, kNone); !r.ok()) return r; // GO_IDLE_STATE
    // SEND_IF_COND: a version 2 card echoes the check pattern (and may be high capacity).
    const bool v2 = command(8, 0x1AA, kShort).ok() && (resp_[0] & 0xFFF) == 0x1AA;
    bool ready = false;
    for (uint32_t k = 0; k < 100000 && !ready; ++k) {
        if (Result r = command(55, 0, kShort); !r.ok()) return r;                              // APP_CMD
        if (Result r = command(41, v2 ? 0x40FF8000u : 0x00FF8000u, kShort, true); !r.ok()) return r; // SD_SEND_OP_COND (3.3 V)
        ready = resp_[0] & 0x80000000u;
    }
    if (!ready) return io("the card never left its power-up");
    block_addressed_ = v2 && (resp_[0] & 0x40000000u);
    if (Result r = command(2, 0, kLongResponse); !r.ok()) return r; // ALL_SEND_CID
    if (Result r = command(3, 0, kShort); !r.ok()) return r;        // SEND_RELATIVE_ADDR
    rca_ = resp_[0] & 0xFFFF0000u;
    if (Result r = command(9, rca_, kLongResponse); !r.ok()) return r; // SEND_CSD: its size
    // resp_[0] holds bits 127-96 of the CSD, resp_[1] 95-64, resp_[2] 63-32.
    if ((resp_[0] >> 30) == 1) { // CSD 2.0: (C_SIZE + 1) * 512 KiB
        const uint32_t c_size = ((resp_[1] & 0x3F) << 16) | (resp_[2] >> 16);
        sectors_ = (c_size + 1) * 1024;
    } else { // CSD 1.0: (C_SIZE + 1) * 2^(C_SIZE_MULT + 2) blocks of 2^READ_BL_LEN bytes
        const uint32_t read_bl_len = (resp_[1] >> 16) & 0xF;
        const uint32_t c_size = ((resp_[1] & 0x3FF) << 2) | (resp_[2] >> 30);
        const uint32_t mult = (resp_[2] >> 15) & 0x7;
        const uint64_t bytes = uint64_t(c_size + 1) << (mult + 2 + read_bl_len);
        sectors_ = uint32_t(bytes / kSectorBytes);
    }
    if (sectors_ == 0) return io("the card states no size");
    if (Result r = command(7, rca_, kShort); !r.ok()) return r; // SELECT_CARD
    if (!block_addressed_) {
        if (Result r = command(16, kSectorBytes, kShort); !r.ok()) return r; // SET_BLOCKLEN
    }
    started_ = true;
    return {};
}

// The FIFO emptied into `out` as the controller fills it (QEMU refills it when the status is read).
Result Pl181Card::read_data(uint32_t* out, uint32_t words) {
    uint32_t idle = 0;
    while (words > 0) {
        const uint32_t s = reg(kStatus);
        if (s & kDataErrors) return io("a data transfer from the card failed");
        if (!(s & kRxAvailable)) {
            if (++idle > kPolls) return io("the card stopped sending data");
            continue;
        }
        idle = 0;
        uint32_t n = (s & kRxFull) ? 16 : (s & kRxHalfFull) ? 8 : 1;
        if (n > words) n = words;
        for (uint32_t i = 0; i < n; ++i) *out++ = reg(kFifo);
        words -= n;
    }
    for (uint32_t k = 0; k < kPolls; ++k) {
        if (reg(kStatus) & kDataEnd) return {};
    }
    return io("the data transfer never ended");
}

Result Pl181Card::read(uint32_t sector, uint32_t count, void* into) {
    if (!started_ || !present()) return io("no card (pulled, or not started)");
    if (uint64_t(sector) + count > sectors_) return Result::fail(Status::OutOfRange, "a read past the card's end", kCard);
    auto* out = static_cast<uint32_t*>(into);
    while (count > 0) {
        const uint32_t n = count < kMaxTransfer ? count : kMaxTransfer;
        reg(kClear) = kClearAll;
        reg(kDataTimer) = 0xFFFFFFFFu;
        reg(kDataLength) = n * kSectorBytes;
        reg(kDataCtrl) = kDataEnable | kFromCard | kBlock512;
        const uint32_t address = block_addressed_ ? sector : sector * kSectorBytes;
        if (Result r = command(n == 1 ? 17 : 18, address, kShort); !r.ok()) return r; // READ_SINGLE / READ_MULTIPLE_BLOCK
        Result r = read_data(out, n * kSectorBytes / 4);
        if (n > 1) { // STOP_TRANSMISSION (said even after a failed transfer)
            const Result stop = command(12, 0, kShort);
            if (r.ok()) r = stop;
        }
        if (!r.ok()) {
            started_ = present() && started_;
            return r;
        }
        out += n * kSectorBytes / 4, sector += n, count -= n;
    }
    return {};
}

} // namespace facet::versatilepb
