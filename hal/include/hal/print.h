#pragma once
// print(): the formatter (core/format.h) onto a console, in pieces of a small buffer.
//
//   print(console, "faces {}/{} ({} bytes)\n", done, total, bytes);
#include "core/format.h"
#include "hal/console.h"

namespace facet {

namespace fmt_detail {
inline void to_console(void* console, const char* data, size_t size) { static_cast<hal::Console*>(console)->write(data, size); }
} // namespace fmt_detail

template <typename... Args>
void print(hal::Console& console, const char* fmt, const Args&... args) {
    fmt_detail::Arg list[sizeof...(Args) + 1] = {fmt_detail::make_arg(args)...};
    char buf[96];
    fmt_detail::Sink sink{buf, sizeof buf, 0, 0, fmt_detail::to_console, &console};
    fmt_detail::format_args(sink, fmt, list, sizeof...(Args));
    if (sink.len) console.write(buf, sink.len);
}

} // namespace facet
