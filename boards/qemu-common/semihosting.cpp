#include "semihosting.h"

namespace facet::semihosting {

uint32_t call(uint32_t op, const void* arg) {
    register uint32_t r0 asm("r0") = op;
    register const void* r1 asm("r1") = arg;
#if defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M'
    asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
#else
    asm volatile("svc 0x123456" : "+r"(r0) : "r"(r1) : "memory");
#endif
    return r0;
}

[[noreturn]] void exit(int code) {
    // SYS_EXIT_EXTENDED: {reason = ADP_Stopped_ApplicationExit, exit code}; QEMU exits with it.
    const uint32_t block[2] = {0x20026, static_cast<uint32_t>(code)};
    call(SysExitExtended, block);
    for (;;) {
    }
}

namespace {
size_t length(const char* s) {
    size_t n = 0;
    while (s[n]) ++n;
    return n;
}
} // namespace

int open_for_write(const char* path) {
    const uint32_t block[3] = {reinterpret_cast<uintptr_t>(path), 6 /* "wb" */,
                               static_cast<uint32_t>(length(path))};
    return static_cast<int>(call(SysOpen, block));
}

bool write(int handle, const void* data, size_t size) {
    const uint32_t block[3] = {static_cast<uint32_t>(handle), reinterpret_cast<uintptr_t>(data),
                               static_cast<uint32_t>(size)};
    return call(SysWrite, block) == 0; // returns the number of bytes NOT written
}

int open_for_read(const char* path) {
    const uint32_t block[3] = {reinterpret_cast<uintptr_t>(path), 1 /* "rb" */, static_cast<uint32_t>(length(path))};
    return static_cast<int>(call(SysOpen, block));
}

int32_t length(int handle) {
    const uint32_t block[1] = {static_cast<uint32_t>(handle)};
    return static_cast<int32_t>(call(SysFlen, block));
}

bool seek(int handle, uint32_t at) {
    const uint32_t block[2] = {static_cast<uint32_t>(handle), at};
    return call(SysSeek, block) == 0;
}

bool read(int handle, void* into, size_t size) {
    const uint32_t block[3] = {static_cast<uint32_t>(handle), reinterpret_cast<uintptr_t>(into), static_cast<uint32_t>(size)};
    return call(SysRead, block) == 0; // returns the number of bytes NOT read
}

void close(int handle) {
    const uint32_t block[1] = {static_cast<uint32_t>(handle)};
    call(SysClose, block);
}

} // namespace facet::semihosting
