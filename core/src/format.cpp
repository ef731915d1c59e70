#include "core/format.h"

namespace facet::fmt_detail {
namespace {

void put(Sink& s, char c) {
    ++s.total;
    if (s.len == s.cap) {
        if (!s.flush) return; // truncating sink: drop
        s.flush(s.to, s.buf, s.len);
        s.len = 0;
    }
    s.buf[s.len++] = c;
}

void put_str(Sink& s, const char* str) {
    if (!str) str = "(null)";
    while (*str) put(s, *str++);
}

// Unsigned value in base 10 or 16 with at least `min_digits` digits.
void put_unsigned(Sink& s, uint64_t v, unsigned base, unsigned min_digits) {
    char digits[24];
    unsigned n = 0;
    do {
        const unsigned d = static_cast<unsigned>(v % base);
        digits[n++] = static_cast<char>(d < 10 ? '0' + d : 'a' + d - 10);
        v /= base;
    } while (v);
    while (n < min_digits && n < sizeof digits) digits[n++] = '0';
    while (n) put(s, digits[--n]);
}

uint64_t magnitude(int64_t v) {
    return v < 0 ? ~static_cast<uint64_t>(v) + 1 : static_cast<uint64_t>(v);
}

void put_place(Sink& s, const Place& p) {
    put_str(s, p.kind);
    if (p.index != Place::kNoIndex) {
        put(s, ' ');
        put_unsigned(s, p.index, 10, 1);
    }
}

void put_result(Sink& s, const Result& r) {
    if (r.ok()) {
        put_str(s, "ok");
        return;
    }
    if (r.where.kind) {
        put_place(s, r.where);
        if (r.at.kind) {
            put_str(s, ", ");
            put_place(s, r.at);
        }
        put_str(s, ": ");
    }
    put_str(s, r.what && *r.what ? r.what : status_name(r.status));
}

void put_arg(Sink& s, const Arg& a) {
    switch (a.kind) {
    case Arg::Kind::Signed:
        if (a.i < 0) put(s, '-');
        put_unsigned(s, magnitude(a.i), 10, 1);
        break;
    case Arg::Kind::Unsigned: put_unsigned(s, a.u, 10, 1); break;
    case Arg::Kind::String: put_str(s, a.s); break;
    case Arg::Kind::Result: put_result(s, *a.r); break;
    case Arg::Kind::Hex:
        put_str(s, "0x");
        put_unsigned(s, a.u, 16, a.digits);
        break;
    case Arg::Kind::Fixed: {
        uint64_t scale = 1;
        for (unsigned i = 0; i < a.digits; ++i) scale *= 10;
        const uint64_t m = magnitude(a.i);
        if (a.i < 0) put(s, '-');
        put_unsigned(s, m / scale, 10, 1);
        if (a.digits) {
            put(s, '.');
            put_unsigned(s, m % scale, 10, a.digits);
        }
        break;
    }
    }
}

} // namespace

void format_args(Sink& s, const char* fmt, const Arg* args, size_t count) {
    size_t next = 0;
    for (const char* p = fmt; *p; ++p) {
        if (p[0] == '{' && p[1] == '{') {
            put(s, '{');
            ++p;
        } else if (p[0] == '}' && p[1] == '}') {
            put(s, '}');
            ++p;
        } else if (p[0] == '{' && p[1] == '}') {
            if (next < count) put_arg(s, args[next++]);
            else put_str(s, "{?}"); // more placeholders than arguments: visible, not UB
            ++p;
        } else {
            put(s, *p);
        }
    }
}

} // namespace facet::fmt_detail

namespace facet {

size_t describe(const Result& r, char* buf, size_t size) { return format(buf, size, "{}", r); }

} // namespace facet
