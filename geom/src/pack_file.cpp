#include "geom/pack_file.h"

#include "geom/inflate.h"

#include <cstring>

namespace facet::geom {

using namespace facet::pack;

namespace {
constexpr Place kFile{"pack file"};
} // namespace

PackFileKind pack_file_kind(const void* data, uint32_t available) {
    if (!data || available < 4) return PackFileKind::Unknown;
    if (std::memcmp(data, kMagic, 4) == 0) return PackFileKind::Pack;
    if (std::memcmp(data, kDeflatedMagic, 4) == 0) return PackFileKind::Deflated;
    return PackFileKind::Unknown;
}

uint32_t pack_file_bytes(const void* data, uint32_t available) {
    uint64_t n = 0;
    switch (pack_file_kind(data, available)) {
    case PackFileKind::Pack: {
        if (available < sizeof(Header)) return 0;
        Header h;
        std::memcpy(&h, data, sizeof h);
        n = h.total_bytes;
        break;
    }
    case PackFileKind::Deflated: {
        if (available < sizeof(DeflatedHead)) return 0;
        DeflatedHead h;
        std::memcpy(&h, data, sizeof h);
        n = uint64_t(sizeof h) + h.stream_bytes;
        break;
    }
    case PackFileKind::Unknown: return 0;
    }
    return n <= available ? uint32_t(n) : 0;
}

Result inflate_pack_file(std::span<const uint8_t> file, std::span<uint8_t> out, uint32_t& bytes) {
    bytes = 0;
    if (pack_file_kind(file.data(), uint32_t(file.size())) != PackFileKind::Deflated || file.size() < sizeof(DeflatedHead)) {
        return Result::fail(Status::Corrupt, "not a deflated pack", kFile);
    }
    DeflatedHead h;
    std::memcpy(&h, file.data(), sizeof h);
    if (uint64_t(sizeof h) + h.stream_bytes > file.size()) {
        return Result::fail(Status::Corrupt, "the deflated pack is shorter than its head says (truncated)", kFile);
    }
    if (h.pack_bytes > kMaxBytes) {
        return Result::fail(Status::Corrupt, "the pack would be larger than the 64 MiB limit", kFile);
    }
    if (h.reserved != 0) {
        return Result::fail(Status::Corrupt, "the deflated head's reserved field is not 0", kFile);
    }
    if (h.pack_bytes > out.size()) {
        return Result::fail(Status::Full, "the inflated pack does not fit its memory", kFile);
    }
    uint32_t written = 0;
    if (Result r = inflate(file.subspan(sizeof h, h.stream_bytes), out.first(h.pack_bytes), written); !r.ok()) return r.within(kFile);
    if (written != h.pack_bytes) {
        return Result::fail(Status::Corrupt, "the inflated pack is shorter than its head says", kFile);
    }
    bytes = written;
    return {};
}

Result unpack_in_place(uint8_t* region, uint32_t capacity, uint32_t loaded, uint32_t& bytes) {
    bytes = 0;
    if (loaded > capacity) loaded = capacity;
    const uint32_t file = pack_file_bytes(region, loaded);
    switch (pack_file_kind(region, loaded)) {
    case PackFileKind::Unknown:
        return Result::fail(Status::Corrupt, "no pack here (neither FPK1 nor FPZ1)", kFile);
    case PackFileKind::Pack:
        if (file == 0) {
            return Result::fail(Status::Corrupt, "the pack is larger than the memory it was loaded into, or truncated", kFile);
        }
        bytes = file;
        return {};
    case PackFileKind::Deflated: break;
    }
    if (file == 0) {
        return Result::fail(Status::Corrupt, "the deflated pack is larger than the memory it was loaded into, or truncated", kFile);
    }
    DeflatedHead h;
    std::memcpy(&h, region, sizeof h);
    if (uint64_t(h.pack_bytes) + file > capacity) {
        return Result::fail(Status::Full, "the pack and its deflated form together do not fit the pack memory", kFile);
    }
    // The stream to the end of the region, then inflated to the start: the two never overlap.
    uint8_t* moved = region + (capacity - file);
    std::memmove(moved, region, file);
    return inflate_pack_file({moved, file}, {region, capacity - file}, bytes);
}

} // namespace facet::geom
