#pragma once
// ARM semihosting: the host services QEMU gives a guest started with
// -semihosting-config enable=on,target=native. A32 traps with SVC 0x123456, T32 with BKPT 0xAB.
#include <cstddef>
#include <cstdint>

namespace facet::semihosting {

enum Op : uint32_t {
    SysOpen = 0x01,
    SysClose = 0x02,
    SysWrite = 0x05,
    SysRead = 0x06,
    SysSeek = 0x0A,
    SysFlen = 0x0C,
    SysExitExtended = 0x20,
};

uint32_t call(uint32_t op, const void* arg);

[[noreturn]] void exit(int code);

// Host file I/O relative to QEMU's working directory. Returns a handle, or -1.
int open_for_write(const char* path);
// Returns false unless every byte was written.
bool write(int handle, const void* data, size_t size);
void close(int handle);
// Reading: a handle or -1; the file's length (-1: unknown); a seek to `at`; `size` bytes read at
// the handle's place (false unless every one was).
int open_for_read(const char* path);
int32_t length(int handle);
bool seek(int handle, uint32_t at);
bool read(int handle, void* into, size_t size);

} // namespace facet::semihosting
