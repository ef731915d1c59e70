#include "gpt.h"

#include "imxrt1062.h"
#include "mmio.h"

namespace facet::evkb {
namespace {
using namespace gpt;
constexpr uint32_t kEn = 1u << 0, kEnmod = 1u << 1, kFrr = 1u << 9, kEn24m = 1u << 10, kSwr = 1u << 15;
constexpr uint32_t kClksrcCrystal = 5u << 6; // CLKSRC 101: the 24 MHz crystal (ipg_clk_24M)
} // namespace

void GptClock::init() {
    const uint32_t g = kGpt1;
    mmio::write(g + kCr, 0);
    mmio::write(g + kCr, kSwr);
    mmio::wait(g + kCr, kSwr, 0);
    // 24 MHz / (PRESCALER24M + 1 = 1) / (PRESCALER + 1 = 24) = 1 MHz.
    mmio::write(g + kPr, (0u << 12) | 23u);
    mmio::write(g + kCr, kClksrcCrystal | kEn24m | kFrr | kEnmod);
    mmio::write(g + kCr, kClksrcCrystal | kEn24m | kFrr | kEnmod | kEn);
    last_ = mmio::read(g + kCnt);
    total_ = 0;
}

uint64_t GptClock::ticks() {
    const uint32_t now = mmio::read(kGpt1 + kCnt);
    total_ += now - last_;
    last_ = now;
    return total_;
}

} // namespace facet::evkb
