#include "pack_io.h"

#include "file_io.h"
#include "pack_blocks.h"

#include "core/format.h"

#include "geom/pack.h"
#include "geom/pack_file.h"
#include "geom/pack_format.h"
#include "geom/pack_index.h"
#include "geom/tessellate.h"

#include <lzma.h>
#include <zlib.h>

#include <cstring>

namespace facet::geom {

std::vector<uint8_t> deflate_pack(const std::vector<uint8_t>& pack) {
    z_stream z{};
    // Raw DEFLATE (negative window bits: no zlib wrapper), the largest window, best compression.
    if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) return {};
    std::vector<uint8_t> out(sizeof(pack::DeflatedHead) + deflateBound(&z, uLong(pack.size())));
    z.next_in = const_cast<Bytef*>(pack.data());
    z.avail_in = uInt(pack.size());
    z.next_out = out.data() + sizeof(pack::DeflatedHead);
    z.avail_out = uInt(out.size() - sizeof(pack::DeflatedHead));
    const int rc = deflate(&z, Z_FINISH);
    const uLong stream = z.total_out;
    deflateEnd(&z);
    if (rc != Z_STREAM_END) return {};
    out.resize(sizeof(pack::DeflatedHead) + stream);
    pack::DeflatedHead h{};
    std::memcpy(h.magic, pack::kDeflatedMagic, 4);
    h.pack_bytes = uint32_t(pack.size());
    h.stream_bytes = uint32_t(stream);
    std::memcpy(out.data(), &h, sizeof h);
    return out;
}

std::vector<uint8_t> lzma_pack(const std::vector<uint8_t>& pack) {
    // Raw LZMA1 at xz's best preset, without an end marker. lc 0, lp 2, pb 2: a pack is mostly 4-byte floats and
    // indices, so a byte's place in its word predicts it better than the byte before it.
    lzma_options_lzma opt;
    if (lzma_lzma_preset(&opt, 9 | LZMA_PRESET_EXTREME)) return {};
    opt.lc = 0;
    opt.lp = 2;
    opt.pb = 2;
    static_assert(kLzmaMaxLcLp >= 2, "the device's decoder holds lc + lp = 2");
    uint32_t dict = 4096;
    while (dict < pack.size() && dict < (64u << 20)) dict <<= 1; // the whole pack is the history
    opt.dict_size = dict;
    opt.ext_flags = 0; // LZMA1EXT without LZMA_LZMA1EXT_ALLOW_EOPM: no end marker, the head has the size
    const lzma_filter filters[] = {{LZMA_FILTER_LZMA1EXT, &opt}, {LZMA_VLI_UNKNOWN, nullptr}};
    std::vector<uint8_t> out(sizeof(pack::LzmaHead) + pack.size() + pack.size() / 2 + 4096);
    size_t written = 0;
    if (lzma_raw_buffer_encode(filters, nullptr, pack.data(), pack.size(), out.data() + sizeof(pack::LzmaHead), &written,
                               out.size() - sizeof(pack::LzmaHead)) != LZMA_OK) {
        return {};
    }
    out.resize(sizeof(pack::LzmaHead) + written);
    pack::LzmaHead h{};
    std::memcpy(h.magic, pack::kLzmaMagic, 4);
    h.pack_bytes = uint32_t(pack.size());
    h.stream_bytes = uint32_t(written);
    h.props = uint8_t((opt.pb * 5 + opt.lp) * 9 + opt.lc);
    std::memcpy(out.data(), &h, sizeof h);
    return out;
}

bool load_pack_bytes(const std::vector<uint8_t>& file, LoadedPack& out, std::string& error) {
    out = LoadedPack{};
    out.file_bytes = uint32_t(file.size());
    out.kind = pack_file_kind(file.data(), uint32_t(file.size()));
    switch (out.kind) {
    case PackFileKind::Unknown:
        error = "not a facet pack (neither FPB1, FPK1, FPX1 nor FPZ1)";
        return false;
    case PackFileKind::Blocked: {
        PackIndex index;
        if (!index.open(file.data(), uint32_t(file.size())).ok()) {
            error = "its index does not open";
            return false;
        }
        index.parts_box(out.box_min, out.box_max);
        std::vector<uint8_t> whole;
        if (!join_blocked({file.data(), file.size()}, whole, error)) return false;
        out.words.resize((whole.size() + 3) / 4);
        std::memcpy(out.words.data(), whole.data(), whole.size());
        out.bytes = uint32_t(whole.size());
        return true;
    }
    case PackFileKind::Pack:
        // Pack::open checks the size against the header and says so.
        out.words.resize((file.size() + 3) / 4);
        if (!file.empty()) std::memcpy(out.words.data(), file.data(), file.size());
        out.bytes = uint32_t(file.size());
        return true;
    case PackFileKind::Deflated:
    case PackFileKind::Lzma: break;
    }
    const uint32_t stated = pack_file_bytes(file.data(), uint32_t(file.size())); // 0: truncated, the decoder says so
    if (stated != 0 && stated < file.size()) {
        error = std::to_string(file.size() - stated) + " bytes follow the compressed pack (appended or not one pack)";
        return false;
    }
    const uint32_t memory = decoded_memory_bytes(file.data(), uint32_t(file.size()));
    if (memory == 0 && file.size() >= sizeof(pack::LzmaHead)) {
        error = "the pack would be larger than the 64 MiB limit";
        return false;
    }
    out.words.resize((size_t(memory) + 3) / 4);
    const Result r = decode_pack_file({file.data(), file.size()}, {reinterpret_cast<uint8_t*>(out.words.data()), out.words.size() * 4}, out.bytes);
    if (!r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        error = std::string("cannot decode: ") + text;
        return false;
    }
    out.words.resize((size_t(out.bytes) + 3) / 4); // the LZMA decoder's state after the pack is done with
    return true;
}

float model_tolerance(const LoadedPack& file, const Pack& pack) {
    return file.box_min[0] <= file.box_max[0] ? default_tolerance(file.box_min, file.box_max) : default_tolerance(pack);
}

bool load_pack_file(const std::string& path, LoadedPack& out, std::string& error) {
    std::vector<uint8_t> file;
    // A blocked pack is at most kMaxBlockedBytes; a whole one kMaxBytes (compressed: smaller,
    // or barely larger: a header).
    if (!host::read_file(path, uint64_t(pack::kMaxBlockedBytes), file, error)) return false;
    if (!load_pack_bytes(file, out, error)) {
        error = path + ": " + error;
        return false;
    }
    return true;
}

bool make_library(const std::vector<std::vector<uint8_t>>& files, std::vector<uint8_t>& out, std::string& error) {
    if (files.empty() || files.size() > pack::kMaxLibraryEntries) {
        error = "a library holds 1 to " + std::to_string(pack::kMaxLibraryEntries) + " models";
        return false;
    }
    const size_t table_end = sizeof(pack::LibraryHeader) + files.size() * sizeof(pack::LibraryEntry);
    std::vector<pack::LibraryEntry> table(files.size());
    size_t at = (table_end + 7) & ~size_t(7);
    for (size_t i = 0; i < files.size(); ++i) {
        LoadedPack loaded;
        Pack pack;
        if (!load_pack_bytes(files[i], loaded, error)) {
            error = "model " + std::to_string(i + 1) + ": " + error;
            return false;
        }
        if (const Result r = pack.open(loaded.data(), loaded.bytes); !r.ok()) {
            error = "model " + std::to_string(i + 1) + ": " + (r.what ? r.what : "not a sound pack");
            return false;
        }
        pack::LibraryEntry& e = table[i];
        std::memset(&e, 0, sizeof e);
        std::strncpy(e.name, pack.model_name(), sizeof e.name - 1); // (a longer name is cut)
        e.offset = uint32_t(at), e.bytes = uint32_t(files[i].size());
        at = (at + files[i].size() + 7) & ~size_t(7);
        if (at > pack::kMaxBlockedBytes) {
            error = "the library would be over " + std::to_string(pack::kMaxBlockedBytes >> 20) + " MiB";
            return false;
        }
    }
    out.assign(at, 0);
    pack::LibraryHeader h;
    std::memcpy(h.magic, pack::kLibraryMagic, 4);
    h.version = pack::kLibraryVersion, h.count = uint16_t(files.size()), h.total_bytes = uint32_t(at);
    h.crc32 = pack::crc32(table.data(), uint32_t(table.size() * sizeof table[0]));
    std::memcpy(out.data(), &h, sizeof h);
    std::memcpy(out.data() + sizeof h, table.data(), table.size() * sizeof table[0]);
    for (size_t i = 0; i < files.size(); ++i) std::memcpy(out.data() + table[i].offset, files[i].data(), files[i].size());
    return true;
}

} // namespace facet::geom
