#pragma once
// How facet reports errors, everywhere (cdt/, geom/, render/, the module, hal/ and the boards):
//
//   Status   the code: Ok = 0 and a few kinds of failure (like pico-sdk's and Zephyr's codes).
//            Low-level calls whose failure needs no more words than the code return it alone
//            (a CDT insertion, a rasterized triangle).
//   Result   the code, what went wrong (fixed text) and where (up to two places, outer
//            first: "face 12, loop 3"). Every call that can say why it failed returns one.
//
//   if (Result r = pack.open(data, size); !r.ok()) print(con, "pack: {}\n", r);
//       -> "pack: section Faces record 12: surface index out of range"
//
// Both are [[nodiscard]]: a failure is handled or passed on, never dropped.
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

// A place a problem was found: a kind of thing and which one ("face" 12, "section Faces
// record" 3). No kind: nowhere in particular; kNoIndex: the thing as a whole ("header").
struct Place {
    static constexpr uint32_t kNoIndex = 0xFFFFFFFFu;
    const char* kind = nullptr;
    uint32_t index = kNoIndex;
};

struct [[nodiscard]] Result {
    Status status = Status::Ok;
    const char* what = "";  // static text; "" when Ok
    Place where{};          // the outer place (a face, a pack record)
    Place at{};             // within it (a loop, a point)

    constexpr bool ok() const { return status == Status::Ok; }

    // A failure; `what` must outlive the result (a string literal).
    static constexpr Result fail(Status s, const char* what, Place where = {}, Place at = {}) {
        return Result{s, what, where, at};
    }
    // This result with an outer place put in front (a face's loop problem, seen from the face).
    constexpr Result within(Place outer) const {
        if (ok()) return *this;
        if (!where.kind) return Result{status, what, outer, at};
        return Result{status, what, outer, where};
    }
};

constexpr bool ok(const Result& r) { return r.ok(); }

// Broken invariants (not bad input) go to one hook that the board or test decides about
// (modm_assert style). `scope` names the module, `what` the invariant.
[[noreturn]] void assert_failed(const char* scope, const char* what, const char* file, int line);

} // namespace facet

#define FACET_ASSERT(scope, cond)                                                                  \
    do {                                                                                           \
        if (!(cond)) ::facet::assert_failed(scope, #cond, __FILE__, __LINE__);                     \
    } while (0)

// An invariant checked where assertions are on (the host's Debug and sanitizer builds: no
// NDEBUG), on paths whose exact instruction counts the targets' budgets hold.
#ifdef NDEBUG
#define FACET_DEBUG_ASSERT(scope, cond) ((void)0)
#else
#define FACET_DEBUG_ASSERT(scope, cond) FACET_ASSERT(scope, cond)
#endif
