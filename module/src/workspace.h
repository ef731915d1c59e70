#pragma once
// The workspace the application hands in, cut into the arrays the viewer needs. The same
// order of cuts measures the bytes a capacity needs (constexpr, so the public formula in
// facet/sizes.h is checked against it when the module is built) and lays the arrays out.
#include "facet/viewer.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace facet::module {

class Carver {
public:
    constexpr Carver() = default;                                    // measures only
    Carver(void* base, size_t bytes) : base_(static_cast<uint8_t*>(base)), room_(bytes) {}

    template <typename T>
    constexpr std::span<T> take(size_t count) {
        at_ = (at_ + alignof(T) - 1) / alignof(T) * alignof(T);
        const size_t start = at_;
        at_ += count * sizeof(T);
        if (!base_ || at_ > room_) return {};
        return {reinterpret_cast<T*>(base_ + start), count};
    }
    constexpr size_t used() const { return at_; }
    bool fits() const { return base_ && at_ <= room_; }

private:
    uint8_t* base_ = nullptr;
    size_t room_ = 0;
    size_t at_ = 0;
};

} // namespace facet::module
