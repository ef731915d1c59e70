#pragma once
// A small, allocation-free formatter for the target (newlib-nano's snprintf pulls in malloc).
//
//   format(buffer, sizeof buffer, "{}.png", name);   // always NUL-terminated, truncates
//   print(console, "faces {}/{} ({} bytes)\n", done, total, bytes);   // hal/print.h
//   print(console, "fault at {}\n", hex(address));
//
// "{}" takes the next argument; "{{" and "}}" are literal braces. Integers of any width,
// bool, const char*, hex(x), fixed(value, decimals) (an integer scaled by 10^decimals), a
// Status (its name) and a Result ("face 12, loop 3: its loops cross in (u,v)").
#include "core/status.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace facet {

struct Hex {
    uint64_t value;
    uint8_t digits; // minimum digits, zero padded
};
constexpr Hex hex(uint64_t value, uint8_t digits = 8) { return {value, digits}; }

struct Fixed {
    int64_t value;   // the number times 10^decimals
    uint8_t decimals;
};
constexpr Fixed fixed(int64_t value, uint8_t decimals) { return {value, decimals}; }

namespace fmt_detail {

struct Arg {
    enum class Kind : uint8_t { Signed, Unsigned, String, Hex, Fixed, Result } kind;
    uint8_t digits;
    union {
        int64_t i;
        uint64_t u;
        const char* s;
        const facet::Result* r;
    };
};

template <typename T>
Arg make_arg(const T& v) {
    Arg a{};
    if constexpr (std::is_same_v<T, Hex>) {
        a.kind = Arg::Kind::Hex;
        a.u = v.value;
        a.digits = v.digits;
    } else if constexpr (std::is_same_v<T, Fixed>) {
        a.kind = Arg::Kind::Fixed;
        a.i = v.value;
        a.digits = v.decimals;
    } else if constexpr (std::is_same_v<T, Result>) {
        a.kind = Arg::Kind::Result;
        a.r = &v;
    } else if constexpr (std::is_same_v<T, Status>) {
        a.kind = Arg::Kind::String;
        a.s = status_name(v);
    } else if constexpr (std::is_same_v<T, bool>) {
        a.kind = Arg::Kind::String;
        a.s = v ? "true" : "false";
    } else if constexpr (std::is_enum_v<T>) {
        a.kind = Arg::Kind::Signed;
        a.i = static_cast<int64_t>(v);
    } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
        a.kind = Arg::Kind::Signed;
        a.i = v;
    } else if constexpr (std::is_integral_v<T>) {
        a.kind = Arg::Kind::Unsigned;
        a.u = v;
    } else {
        static_assert(std::is_convertible_v<T, const char*>, "print: unsupported argument type");
        a.kind = Arg::Kind::String;
        a.s = v;
    }
    return a;
}

// Output sink: a fixed buffer that may be flushed (to a console: hal/print.h) when full.
struct Sink {
    char* buf;
    size_t cap;
    size_t len;
    size_t total;                                  // characters produced, including any dropped or flushed
    void (*flush)(void* to, const char*, size_t);  // null: truncate into buf
    void* to;
};

void format_args(Sink& sink, const char* fmt, const Arg* args, size_t count);

} // namespace fmt_detail

// "where, at: what" (or "what" alone) -- a Result as one line of text, without its code.
size_t describe(const Result& r, char* buf, size_t size);

// Formats into `buf` (always NUL-terminated when size > 0; a null `buf` is size 0). Returns the
// length the full result would have, so a caller can detect truncation (result >= size).
template <typename... Args>
size_t format(char* buf, size_t size, const char* fmt, const Args&... args) {
    if (!buf) size = 0; // no buffer: the length alone (as snprintf(NULL, 0, ...))
    fmt_detail::Arg list[sizeof...(Args) + 1] = {fmt_detail::make_arg(args)...};
    fmt_detail::Sink sink{buf, size ? size - 1 : 0, 0, 0, nullptr, nullptr};
    fmt_detail::format_args(sink, fmt, list, sizeof...(Args));
    if (size) buf[sink.len] = '\0';
    return sink.total;
}

} // namespace facet
