#pragma once
// One status enum for every fallible call in facet (Ok = 0, like pico-sdk and Zephyr).
#include <cstdint>

namespace facet {

enum class [[nodiscard]] Status : int32_t {
    Ok = 0,
    OutOfRange,   // a coordinate, index or size outside the stated limits
    Full,         // a fixed-capacity store has no room; the store is still valid
    Corrupt,      // input data failed validation
    Unsupported,  // valid input that this build does not handle
    NotFound,
    Busy,
    Degenerate,   // geometrically degenerate input (zero area, zero length)
    Crossing,     // two constraints cross
    Io,           // a transfer to or from the host failed
};

constexpr const char* status_name(Status s) {
    switch (s) {
    case Status::Ok: return "Ok";
    case Status::OutOfRange: return "OutOfRange";
    case Status::Full: return "Full";
    case Status::Corrupt: return "Corrupt";
    case Status::Unsupported: return "Unsupported";
    case Status::NotFound: return "NotFound";
    case Status::Busy: return "Busy";
    case Status::Degenerate: return "Degenerate";
    case Status::Crossing: return "Crossing";
    case Status::Io: return "Io";
    }
    return "?";
}

constexpr bool ok(Status s) { return s == Status::Ok; }

// Broken invariants (not bad input) go to one hook that the board or test decides about
// (modm_assert style). `scope` names the module, `what` the invariant.
[[noreturn]] void assert_failed(const char* scope, const char* what, const char* file, int line);

} // namespace facet

#define FACET_ASSERT(scope, cond)                                                                  \
    do {                                                                                           \
        if (!(cond)) ::facet::assert_failed(scope, #cond, __FILE__, __LINE__);                     \
    } while (0)
