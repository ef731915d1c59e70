// The host's card image through semihosting (card_semihosted.h).
#include "card_semihosted.h"

#include "semihosting.h"

namespace facet::qemu {
namespace {
constexpr Place kCard{"semihosted card"};
} // namespace

bool SemihostedCard::present() {
    if (!looked_) looked_ = true, handle_ = semihosting::open_for_read(kPath);
    return handle_ >= 0;
}

Result SemihostedCard::start() {
    if (!present()) return Result::fail(Status::Io, "no card image (facet-card.img) beside QEMU", kCard);
    const int32_t bytes = semihosting::length(handle_);
    if (bytes < int32_t(kSectorBytes)) return Result::fail(Status::Io, "the card image's length is unknown or under a sector", kCard);
    sectors_ = uint32_t(bytes) / kSectorBytes;
    return {};
}

Result SemihostedCard::read(uint32_t sector, uint32_t count, void* into) {
    if (!present() || sectors_ == 0) return Result::fail(Status::Io, "no card", kCard);
    if (sector > sectors_ || count > sectors_ - sector) return Result::fail(Status::OutOfRange, "past the card's end", kCard);
    if (!semihosting::seek(handle_, sector * kSectorBytes) || !semihosting::read(handle_, into, size_t(count) * kSectorBytes)) {
        return Result::fail(Status::Io, "the host did not read the card image", kCard);
    }
    return {};
}

} // namespace facet::qemu
