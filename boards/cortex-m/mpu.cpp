#include "mpu.h"

namespace facet::cortex_m {
namespace {

// MPU_RASR fields (ARMv7-M ARM, "MPU Region Attribute and Size Register").
constexpr uint32_t kEnable = 1u << 0;
constexpr uint32_t size_field(uint32_t log2) { return (log2 - 1) << 1; } // region = 2^(SIZE+1)
constexpr uint32_t kB = 1u << 16, kC = 1u << 17;
constexpr uint32_t tex(uint32_t t) { return t << 19; }
constexpr uint32_t ap(uint32_t a) { return a << 24; }
constexpr uint32_t kXn = 1u << 28;
constexpr uint32_t kApNone = 0, kApReadWrite = 3, kApReadOnly = 6;
constexpr uint32_t kValid = 1u << 4; // MPU_RBAR: the region number is in this write

// Memory type and access ("Memory region attribute encoding", TEX/C/B): device TEX=2 C=0 B=0
// (non-shareable device); normal write-back read/write-allocate TEX=1 C=1 B=1; normal
// write-through no write-allocate TEX=0 C=1 B=0; normal non-cacheable TEX=1 C=0 B=0. Shareable
// (S) stays 0: the Cortex-M7 does not cache shareable memory.
uint32_t attributes(Memory kind) {
    switch (kind) {
    case Memory::Device: return tex(2) | ap(kApReadWrite) | kXn;
    case Memory::Code: return tex(0) | kC | ap(kApReadOnly);
    case Memory::Tcm: return tex(1) | ap(kApReadWrite);
    case Memory::Data: return tex(1) | kC | kB | ap(kApReadWrite) | kXn;
    case Memory::Scanout: return tex(0) | kC | ap(kApReadWrite) | kXn;
    case Memory::NoAccess: return tex(1) | ap(kApNone) | kXn;
    }
    return ap(kApNone) | kXn;
}

} // namespace

uint32_t plan(const Range* ranges, uint32_t count, MpuRegion* out, uint32_t max) {
    if (count > max || count > kMaxMpuRegions) return 0;
    for (uint32_t i = 0; i < count; ++i) {
        const uint64_t begin = ranges[i].base, end = begin + ranges[i].bytes;
        if (ranges[i].bytes == 0) return 0;
        // The smallest aligned block of 2^log2 bytes (32 bytes at least) holding the range.
        uint32_t log2 = 5;
        while (log2 < 32 && ((begin >> log2) << log2) + (uint64_t(1) << log2) < end) ++log2;
        const uint64_t block = uint64_t(1) << log2, base = (begin >> log2) << log2;
        uint32_t srd = 0;
        if (log2 >= 8) { // subregions exist from 256-byte regions up
            const uint64_t sub = block / 8;
            for (uint32_t s = 0; s < 8; ++s) {
                const uint64_t s0 = base + s * sub, s1 = s0 + sub;
                if (s1 <= begin || s0 >= end) srd |= 1u << s;
            }
        }
        out[i].rbar = uint32_t(base) | kValid | i;
        out[i].rasr = attributes(ranges[i].kind) | (srd << 8) | size_field(log2) | kEnable;
    }
    return count;
}

uint32_t region_size(const MpuRegion& r) {
    const uint32_t log2 = ((r.rasr >> 1) & 0x1F) + 1;
    return log2 >= 32 ? 0 : 1u << log2; // 0: the whole 4 GiB
}

bool covers(const MpuRegion& r, uint32_t address) {
    if (!(r.rasr & kEnable)) return false;
    const uint64_t size = region_size(r) ? region_size(r) : (uint64_t(1) << 32);
    const uint64_t base = r.rbar & ~uint32_t(0x1F) & uint32_t(~(size - 1));
    if (address < base || address >= base + size) return false;
    if (size < 256) return true;
    const uint32_t s = uint32_t((address - base) / (size / 8));
    return !((r.rasr >> 8) & (1u << s));
}

} // namespace facet::cortex_m
