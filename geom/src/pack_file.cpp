#include "geom/pack_file.h"

#include "geom/inflate.h"
#include "geom/unlzma.h"

#include <algorithm>
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
    if (std::memcmp(data, kLzmaMagic, 4) == 0) return PackFileKind::Lzma;
    if (std::memcmp(data, kBlockedMagic, 4) == 0) return PackFileKind::Blocked;
    return PackFileKind::Unknown;
}

namespace {

// A compressed file's head, read the same way for both kinds (their fields line up).
struct CompressedHead {
    uint32_t pack_bytes = 0, stream_bytes = 0;
    uint8_t props = 0;
    bool reserved_zero = false;
};
static_assert(sizeof(DeflatedHead) == sizeof(LzmaHead));

bool read_head(const void* data, uint32_t available, CompressedHead& h) {
    const PackFileKind k = pack_file_kind(data, available);
    if (!compressed(k) || available < sizeof(LzmaHead)) return false;
    if (k == PackFileKind::Deflated) {
        DeflatedHead d;
        std::memcpy(&d, data, sizeof d);
        h = {d.pack_bytes, d.stream_bytes, 0, d.reserved == 0};
    } else {
        LzmaHead l;
        std::memcpy(&l, data, sizeof l);
        h = {l.pack_bytes, l.stream_bytes, l.props, (l.reserved[0] | l.reserved[1] | l.reserved[2]) == 0};
    }
    return true;
}

} // namespace

uint32_t decoded_memory_bytes(const void* data, uint32_t available) {
    CompressedHead h;
    if (!read_head(data, available, h) || h.pack_bytes > kMaxBytes) return 0;
    const uint32_t extra = pack_file_kind(data, available) == PackFileKind::Lzma ? 3 + kLzmaStateBytes : 0;
    return h.pack_bytes + extra;
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
    case PackFileKind::Deflated:
    case PackFileKind::Lzma: {
        CompressedHead h;
        if (!read_head(data, available, h)) return 0;
        n = uint64_t(sizeof(LzmaHead)) + h.stream_bytes;
        break;
    }
    case PackFileKind::Blocked: {
        if (available < sizeof(IndexHeader)) return 0;
        IndexHeader h;
        std::memcpy(&h, data, sizeof h);
        n = h.total_bytes;
        break;
    }
    case PackFileKind::Unknown: return 0;
    }
    return n <= available ? uint32_t(n) : 0;
}

uint32_t stored_pack_bytes(const void* data, uint32_t available) {
    if (pack_file_kind(data, available) == PackFileKind::Pack) return pack_file_bytes(data, available);
    CompressedHead h;
    return read_head(data, available, h) && h.pack_bytes <= kMaxBytes ? h.pack_bytes : 0;
}

Result stored_pack_counts(const void* data, uint32_t available, PackCounts& out, LzmaProbs& probs, bool head_only) {
    out = {};
    // The head and the section table: decoded alone for a compressed file (its first bytes need
    // no more of the output than themselves).
    alignas(4) uint8_t head[sizeof(pack::Header) + 32 * sizeof(pack::SectionEntry) + sizeof(pack::Needs)];
    uint32_t have = 0;
    const PackFileKind kind = pack_file_kind(data, available);
    if (kind == PackFileKind::Pack) {
        have = available < sizeof head ? available : uint32_t(sizeof head);
        std::memcpy(head, data, have);
    } else if (kind == PackFileKind::Lzma) {
        CompressedHead h;
        if (!read_head(data, available, h) || (!head_only && uint64_t(sizeof(LzmaHead)) + h.stream_bytes > available)) {
            return Result::fail(Status::Corrupt, "the compressed head is cut short or the file truncated", kFile);
        }
        if (head_only) h.stream_bytes = std::min<uint32_t>(h.stream_bytes, available - uint32_t(sizeof(LzmaHead)));
        const uint32_t want = h.pack_bytes < sizeof head ? h.pack_bytes : uint32_t(sizeof head);
        LzmaDecoder d;
        const auto* in = static_cast<const uint8_t*>(data) + sizeof(LzmaHead);
        Result r = d.start({in, h.stream_bytes}, h.props, {head, want}, probs);
        while (r.status == Status::Busy) r = d.run(want);
        have = d.written(); // (a stream longer than the head is no fault here)
    } else if (kind == PackFileKind::Deflated) {
        CompressedHead h;
        if (!read_head(data, available, h) || (!head_only && uint64_t(sizeof(DeflatedHead)) + h.stream_bytes > available)) {
            return Result::fail(Status::Corrupt, "the compressed head is cut short or the file truncated", kFile);
        }
        if (head_only) h.stream_bytes = std::min<uint32_t>(h.stream_bytes, available - uint32_t(sizeof(DeflatedHead)));
        const uint32_t want = h.pack_bytes < sizeof head ? h.pack_bytes : uint32_t(sizeof head);
        const auto* in = static_cast<const uint8_t*>(data) + sizeof(DeflatedHead);
        const Result r = inflate({in, h.stream_bytes}, {head, want}, have);
        if (!r.ok() && r.status != Status::Full) return r; // (a stream longer than the head is no fault here)
    } else {
        return Result::fail(Status::Unsupported, "no pack's counts here (a blocked pack has its index)", kFile);
    }
    pack::Header h;
    if (have < sizeof h) return Result::fail(Status::Corrupt, "the pack's head is cut short", kFile);
    std::memcpy(&h, head, sizeof h);
    if (std::memcmp(h.magic, pack::kMagic, 4) != 0 || h.header_bytes != sizeof h) {
        return Result::fail(Status::Corrupt, "no pack head (FPK1) where the file says", kFile);
    }
    const uint32_t entries = (have - sizeof h) / sizeof(pack::SectionEntry);
    if (h.section_count > entries) return Result::fail(Status::Corrupt, "more sections than a pack has", kFile);
    for (uint32_t i = 0; i < h.section_count; ++i) {
        pack::SectionEntry e;
        std::memcpy(&e, head + sizeof h + i * sizeof e, sizeof e);
        if (e.id == uint32_t(pack::SectionId::Faces)) out.faces = e.count;
        if (e.id == uint32_t(pack::SectionId::Edges)) out.edges = e.count;
        if (e.id == uint32_t(pack::SectionId::Shells)) out.shells = e.count;
        if (e.id == uint32_t(pack::SectionId::Needs) && e.count == 1 && e.record_bytes == sizeof(pack::Needs) &&
            uint64_t(e.offset) + sizeof(pack::Needs) <= have) {
            std::memcpy(&out.needs, head + e.offset, sizeof out.needs);
            out.has_needs = true;
        }
    }
    return {};
}

Result PackDecoder::start(std::span<const uint8_t> file, std::span<uint8_t> out, LzmaProbs& probs) {
    *this = PackDecoder{};
    kind_ = pack_file_kind(file.data(), uint32_t(file.size()));
    auto fail = [&](Result r) { return result_ = r.within(kFile); };
    if (reinterpret_cast<uintptr_t>(out.data()) & 3) return fail(Result::fail(Status::OutOfRange, "the memory for the pack is not 4-byte aligned"));
    switch (kind_) {
    case PackFileKind::Unknown:
    case PackFileKind::Blocked: return fail(Result::fail(Status::Corrupt, "not a pack (neither FPK1, FPX1 nor FPZ1)"));
    case PackFileKind::Pack: {
        pack_bytes_ = pack_file_bytes(file.data(), uint32_t(file.size()));
        if (pack_bytes_ == 0) return fail(Result::fail(Status::Corrupt, "the pack is longer than its bytes (truncated)"));
        if (pack_bytes_ > out.size()) return fail(Result::fail(Status::Full, "the pack does not fit its memory"));
        stream_ = file.first(pack_bytes_), out_ = out;
        return result_ = Result::fail(Status::Busy, "copying");
    }
    case PackFileKind::Deflated:
    case PackFileKind::Lzma: break;
    }
    CompressedHead h;
    if (!read_head(file.data(), uint32_t(file.size()), h)) return fail(Result::fail(Status::Corrupt, "the compressed head is cut short"));
    if (uint64_t(sizeof(LzmaHead)) + h.stream_bytes > file.size()) {
        return fail(Result::fail(Status::Corrupt, "the compressed pack is shorter than its head says (truncated)"));
    }
    if (h.pack_bytes > kMaxBytes) return fail(Result::fail(Status::Corrupt, "the pack would be larger than the 64 MiB limit"));
    if (!h.reserved_zero) return fail(Result::fail(Status::Corrupt, "the compressed head's reserved field is not 0"));
    if (h.pack_bytes > out.size()) return fail(Result::fail(Status::Full, "the decoded pack does not fit its memory"));
    pack_bytes_ = h.pack_bytes;
    stream_ = file.subspan(sizeof(LzmaHead), h.stream_bytes), out_ = out.first(h.pack_bytes);
    if (kind_ == PackFileKind::Lzma) {
        const Result r = lzma_.start(stream_, h.props, out_, probs);
        if (r.status != Status::Busy) return fail(r);
    }
    return result_ = Result::fail(Status::Busy, "decoding");
}

Result PackDecoder::finish(const Result& r, uint32_t written) {
    if (r.status == Status::Busy) return result_ = r;
    if (!r.ok()) return result_ = r.within(kFile);
    if (written != pack_bytes_) return result_ = Result::fail(Status::Corrupt, "the decoded pack is shorter than its head says", kFile);
    return result_ = {};
}

Result PackDecoder::run(uint32_t bytes) {
    if (result_.status != Status::Busy) return result_;
    switch (kind_) {
    case PackFileKind::Pack: {
        std::memmove(out_.data(), stream_.data(), pack_bytes_);
        return finish({}, pack_bytes_);
    }
    case PackFileKind::Deflated: {
        uint32_t written = 0;
        const Result r = inflate(stream_, out_, written);
        return finish(r, written);
    }
    case PackFileKind::Lzma: {
        const Result r = lzma_.run(bytes);
        return finish(r, lzma_.written());
    }
    default: return result_;
    }
}

namespace {

// Decodes the file (its head read into h) into out[0, h.pack_bytes); an LZMA file's decoder
// state is `probs`, somewhere outside both.
Result decode(std::span<const uint8_t> file, const CompressedHead& h, std::span<uint8_t> out, LzmaProbs* probs,
              uint32_t& bytes) {
    if (uint64_t(sizeof(LzmaHead)) + h.stream_bytes > file.size()) {
        return Result::fail(Status::Corrupt, "the compressed pack is shorter than its head says (truncated)", kFile);
    }
    if (h.pack_bytes > kMaxBytes) return Result::fail(Status::Corrupt, "the pack would be larger than the 64 MiB limit", kFile);
    if (!h.reserved_zero) return Result::fail(Status::Corrupt, "the compressed head's reserved field is not 0", kFile);
    if (h.pack_bytes > out.size()) return Result::fail(Status::Full, "the decoded pack does not fit its memory", kFile);
    const std::span<const uint8_t> stream = file.subspan(sizeof(LzmaHead), h.stream_bytes);
    uint32_t written = 0;
    const Result r = probs ? unlzma(stream, h.props, out.first(h.pack_bytes), *probs, written)
                           : inflate(stream, out.first(h.pack_bytes), written);
    if (!r.ok()) return r.within(kFile);
    if (written != h.pack_bytes) return Result::fail(Status::Corrupt, "the decoded pack is shorter than its head says", kFile);
    bytes = written;
    return {};
}

} // namespace

Result decode_pack_file(std::span<const uint8_t> file, std::span<uint8_t> out, uint32_t& bytes) {
    bytes = 0;
    CompressedHead h;
    if (!read_head(file.data(), uint32_t(file.size()), h)) return Result::fail(Status::Corrupt, "not a compressed pack", kFile);
    LzmaProbs* probs = nullptr;
    if (pack_file_kind(file.data(), uint32_t(file.size())) == PackFileKind::Lzma) {
        // The decoder's state right after the pack, 4-byte aligned (out's start must be).
        const uint64_t state_at = (uint64_t(h.pack_bytes) + 3) & ~uint64_t(3);
        if (state_at + kLzmaStateBytes > out.size() || (reinterpret_cast<uintptr_t>(out.data()) & 3)) {
            return Result::fail(Status::Full, "the pack and the LZMA decoder's state do not fit its memory", kFile);
        }
        probs = reinterpret_cast<LzmaProbs*>(out.data() + state_at);
    }
    return decode(file, h, out, probs, bytes);
}

Result unpack_in_place(uint8_t* region, uint32_t capacity, uint32_t loaded, uint32_t& bytes) {
    bytes = 0;
    if (loaded > capacity) loaded = capacity;
    const uint32_t file = pack_file_bytes(region, loaded);
    const PackFileKind kind = pack_file_kind(region, loaded);
    switch (kind) {
    case PackFileKind::Unknown:
    case PackFileKind::Blocked:
        return Result::fail(Status::Corrupt, "no pack here (neither FPK1, FPX1 nor FPZ1)", kFile);
    case PackFileKind::Pack:
        if (file == 0) {
            return Result::fail(Status::Corrupt, "the pack is larger than the memory it was loaded into, or truncated", kFile);
        }
        bytes = file;
        return {};
    case PackFileKind::Deflated:
    case PackFileKind::Lzma: break;
    }
    if (file == 0) {
        return Result::fail(Status::Corrupt, "the compressed pack is larger than the memory it was loaded into, or truncated", kFile);
    }
    CompressedHead h;
    (void)read_head(region, loaded, h); // readable: pack_file_bytes() read it
    const uint32_t state = kind == PackFileKind::Lzma ? kLzmaStateBytes + 3 : 0; // + its alignment
    if (uint64_t(h.pack_bytes) + file + state > capacity) {
        return Result::fail(Status::Full, "the pack and its compressed form together do not fit the pack memory", kFile);
    }
    // An LZMA decoder's state at the region's end, the file just before it, decoded to the
    // start: the three never overlap.
    const uint32_t state_at = state ? (capacity - kLzmaStateBytes) & ~3u : capacity;
    uint8_t* moved = region + (state_at - file);
    std::memmove(moved, region, file);
    LzmaProbs* probs = state ? reinterpret_cast<LzmaProbs*>(region + state_at) : nullptr;
    return decode({moved, file}, h, {region, state_at - file}, probs, bytes);
}

} // namespace facet::geom
