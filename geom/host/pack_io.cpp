#include "pack_io.h"

#include "file_io.h"

#include "hal/print.h"

#include "geom/pack_file.h"
#include "geom/pack_format.h"

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

bool load_pack_bytes(const std::vector<uint8_t>& file, LoadedPack& out, std::string& error) {
    out = LoadedPack{};
    out.file_bytes = uint32_t(file.size());
    switch (pack_file_kind(file.data(), uint32_t(file.size()))) {
    case PackFileKind::Unknown:
        error = "not a facet pack (neither FPK1 nor FPZ1)";
        return false;
    case PackFileKind::Pack:
        // Pack::open checks the size against the header and says so.
        out.words.resize((file.size() + 3) / 4);
        if (!file.empty()) std::memcpy(out.words.data(), file.data(), file.size());
        out.bytes = uint32_t(file.size());
        return true;
    case PackFileKind::Deflated: break;
    }
    pack::DeflatedHead h{};
    if (file.size() >= sizeof h) std::memcpy(&h, file.data(), sizeof h);
    if (file.size() >= sizeof h && uint64_t(sizeof h) + h.stream_bytes < file.size()) {
        error = std::to_string(file.size() - sizeof h - h.stream_bytes) +
                " bytes follow the deflated pack (appended or not one pack)";
        return false;
    }
    if (h.pack_bytes > pack::kMaxBytes) {
        error = "the pack would be larger than the 64 MiB limit";
        return false;
    }
    out.words.resize((size_t(h.pack_bytes) + 3) / 4);
    out.deflated = true;
    const Result r = inflate_pack_file({file.data(), file.size()}, {reinterpret_cast<uint8_t*>(out.words.data()), h.pack_bytes}, out.bytes);
    if (!r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        error = std::string("cannot inflate: ") + text;
        return false;
    }
    return true;
}

bool load_pack_file(const std::string& path, LoadedPack& out, std::string& error) {
    std::vector<uint8_t> file;
    // A pack is at most kMaxBytes; a deflated one is smaller (or barely larger: a header).
    if (!host::read_file(path, uint64_t(pack::kMaxBytes) + 4096, file, error)) return false;
    if (!load_pack_bytes(file, out, error)) {
        error = path + ": " + error;
        return false;
    }
    return true;
}

} // namespace facet::geom
