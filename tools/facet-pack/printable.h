#pragma once
// Text from a file, made safe to print on a terminal: control characters (an escape sequence's
// ESC, a newline, a carriage return) and bytes that are no UTF-8 shown as \xNN; valid UTF-8
// (a name in Cyrillic or Greek) kept as it is.
#include <cstdint>
#include <cstdio>
#include <string>

namespace facet::packer {

inline std::string printable(const std::string& text) {
    std::string out;
    auto escape = [&](uint8_t b) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02X", b);
        out += hex;
    };
    for (size_t i = 0; i < text.size();) {
        const uint8_t b = uint8_t(text[i]);
        if (b >= 0x20 && b < 0x7F) {
            out += char(b), ++i;
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte, every follower 10xxxxxx, no C1 control.
        const int n = b >= 0xC2 && b <= 0xDF ? 2 : b >= 0xE0 && b <= 0xEF ? 3 : b >= 0xF0 && b <= 0xF4 ? 4 : 0;
        bool ok = n > 0 && i + size_t(n) <= text.size();
        for (int k = 1; ok && k < n; ++k) ok = (uint8_t(text[i + size_t(k)]) & 0xC0) == 0x80;
        if (ok && n == 2 && b == 0xC2 && uint8_t(text[i + 1]) < 0xA0) ok = false; // U+0080-U+009F: C1 controls
        if (!ok) {
            escape(b), ++i;
            continue;
        }
        out.append(text, i, size_t(n));
        i += size_t(n);
    }
    return out;
}

} // namespace facet::packer
