#include "file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace facet::host {

bool read_file(const std::string& path, uint64_t max_bytes, std::vector<uint8_t>& out, std::string& error) {
    out.clear();
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) {
        error = "cannot read " + path + ": " + std::strerror(errno);
        return false;
    }
    if (S_ISDIR(st.st_mode)) {
        error = path + " is a directory, not a file";
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        error = path + " is not a regular file";
        return false;
    }
    if (uint64_t(st.st_size) > max_bytes) {
        error = path + " is " + std::to_string(st.st_size) + " bytes, more than the " + std::to_string(max_bytes) +
                " this reads";
        return false;
    }
    const int fd = open(path.c_str(), O_RDONLY);
    if (fd < 0) {
        error = "cannot open " + path + ": " + std::strerror(errno);
        return false;
    }
    out.resize(size_t(st.st_size));
    size_t got = 0;
    while (got < out.size()) {
        const ssize_t n = read(fd, out.data() + got, out.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error = "cannot read " + path + (n < 0 ? std::string(": ") + std::strerror(errno) : ": it shrank while read");
            close(fd);
            out.clear();
            return false;
        }
        got += size_t(n);
    }
    close(fd);
    return true;
}

bool write_file(const std::string& path, const void* bytes, size_t size, std::string& error) {
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) {
        error = "cannot write " + path + ": " + std::strerror(errno);
        return false;
    }
    struct stat st {};
    const bool regular = fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    const char* p = static_cast<const char*>(bytes);
    size_t done = 0;
    int err = 0;
    while (done < size) {
        const ssize_t n = write(fd, p + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            err = n < 0 ? errno : ENOSPC;
            break;
        }
        done += size_t(n);
    }
    if (!err && regular && fsync(fd) != 0) err = errno;
    if (close(fd) != 0 && !err) err = errno;
    if (err) {
        error = "cannot write " + path + ": " + std::strerror(err) + " (" + std::to_string(done) + " of " +
                std::to_string(size) + " bytes written)";
        if (regular) unlink(path.c_str());
        return false;
    }
    return true;
}

bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

} // namespace facet::host
