#pragma once
// Console: a byte stream to and from the user (a UART on the boards).
#include <cstddef>
#include <cstdint>

namespace facet::hal {

class Console {
public:
    // Writes all bytes; blocks until the transmitter has taken them.
    virtual void write(const char* data, size_t size) = 0;
    // Returns the next received byte, or -1 at once when none is waiting.
    virtual int read_byte() = 0;

protected:
    ~Console() = default;
};

} // namespace facet::hal
