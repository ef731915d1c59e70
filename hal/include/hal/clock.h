#pragma once
// Clock: monotonic ticks (never wraps in practice: 64 bits).
#include <cstdint>

namespace facet::hal {

class Clock {
public:
    virtual uint64_t ticks() = 0;
    virtual uint32_t ticks_per_second() const = 0;

protected:
    ~Clock() = default;
};

} // namespace facet::hal
