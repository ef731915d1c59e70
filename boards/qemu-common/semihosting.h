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
    SysExitExtended = 0x20,
};

uint32_t call(uint32_t op, const void* arg);

[[noreturn]] void exit(int code);

// Host file I/O relative to QEMU's working directory. Returns a handle, or -1.
int open_for_write(const char* path);
// Returns false unless every byte was written.
bool write(int handle, const void* data, size_t size);
void close(int handle);

} // namespace facet::semihosting
