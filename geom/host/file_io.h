#pragma once
// Files on the host, every failure said: a read takes only a regular file of bounded size (a
// directory, /dev/zero or a FIFO is refused, not read forever); a write checks every byte, the
// flush and the close (a full disk, /dev/full, a closed pipe), and fsyncs a regular file so a
// full disk shows before the tool says it is done.
#include <cstdint>
#include <string>
#include <vector>

namespace facet::host {

bool read_file(const std::string& path, uint64_t max_bytes, std::vector<uint8_t>& out, std::string& error);

// Writes `bytes` to `path` (created or truncated). On failure a partial regular file is removed.
bool write_file(const std::string& path, const void* bytes, size_t size, std::string& error);
inline bool write_file(const std::string& path, const std::string& text, std::string& error) {
    return write_file(path, text.data(), text.size(), error);
}

// True when both paths name the same existing file (hard links and symlinks included).
bool same_file(const std::string& a, const std::string& b);

} // namespace facet::host
