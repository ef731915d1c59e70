// The device's LZMA decoder against liblzma's encoder: every input and every lc/lp/pb the table
// holds decodes to the original bytes; truncated, corrupt, oversized and trailing streams get a
// status, never a read or write outside their buffers (the ASan build checks every access). And
// LZMA pack files (facet-pack's default) unpack in place and through the host loader.
#include "geom/pack.h"
#include "geom/pack_file.h"
#include "geom/unlzma.h"
#include "pack_io.h"
#include "pack_writer.h"
#include "triangle_pack.h"

#include <gtest/gtest.h>
#include <lzma.h>

#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

using Bytes = std::vector<uint8_t>;

uint8_t props_of(uint32_t lc, uint32_t lp, uint32_t pb) { return uint8_t((pb * 5 + lp) * 9 + lc); }

// A raw LZMA1 stream of data by liblzma; with `marker` an end marker after the data (plain
// LZMA1), without (LZMA1EXT, as facet-pack writes).
Bytes xz_encode(const Bytes& data, uint32_t preset, uint32_t lc, uint32_t lp, uint32_t pb, bool marker = false) {
    lzma_options_lzma opt;
    EXPECT_FALSE(lzma_lzma_preset(&opt, preset));
    opt.lc = lc, opt.lp = lp, opt.pb = pb;
    opt.ext_flags = 0;
    const lzma_filter filters[] = {{marker ? LZMA_FILTER_LZMA1 : LZMA_FILTER_LZMA1EXT, &opt}, {LZMA_VLI_UNKNOWN, nullptr}};
    Bytes out(data.size() + data.size() / 2 + 1024);
    size_t n = 0;
    EXPECT_EQ(lzma_raw_buffer_encode(filters, nullptr, data.data(), data.size(), out.data(), &n, out.size()), LZMA_OK);
    out.resize(n);
    return out;
}

struct Decoded {
    Status status;
    const char* why;
    uint32_t written;
};

Decoded decode(const Bytes& stream, uint8_t props, Bytes& out) {
    auto probs = std::make_unique<LzmaProbs>();
    uint32_t written = 0;
    const Result r = unlzma({stream.data(), stream.size()}, props, {out.data(), out.size()}, *probs, written);
    return {r.status, r.what, written};
}

// Noise (literals all the way), text with repeats (matches and rep matches), float data as a
// pack holds it, a short string, a long run (overlapping copies) and one byte.
std::vector<std::pair<std::string, Bytes>> inputs() {
    std::mt19937 rng(3);
    Bytes noise(40000);
    for (uint8_t& b : noise) b = uint8_t(rng());
    Bytes text;
    const char* words[] = {"cylinder ", "plane ", "B-spline ", "edge ", "loop ", "face ", "0.25 ", "-12.5 "};
    while (text.size() < 120000) {
        const char* w = words[rng() % 8];
        text.insert(text.end(), w, w + std::strlen(w));
    }
    Bytes floats;
    for (int i = 0; i < 30000; ++i) {
        const float f = float(i % 97) * 0.125f + float(rng() % 5) * 1e-3f;
        const uint8_t* p = reinterpret_cast<const uint8_t*>(&f);
        floats.insert(floats.end(), p, p + 4);
    }
    const std::string hello = "facet: a short string";
    Bytes run(60000, 0xAB);
    run[300] = 1;
    return {{"noise", noise}, {"text", text}, {"floats", floats}, {"short", Bytes(hello.begin(), hello.end())},
            {"run", run}, {"one", Bytes{42}}};
}

} // namespace

TEST(Unlzma, LiblzmaStreamsRoundTrip) {
    const uint32_t settings[][3] = {{0, 2, 2}, {0, 0, 0}, {2, 0, 2}, {1, 1, 0}, {0, 1, 4}};
    for (const auto& [name, data] : inputs()) {
        for (uint32_t preset : {0u, 6u, 9u | LZMA_PRESET_EXTREME}) {
            for (const auto& s : settings) {
                const Bytes stream = xz_encode(data, preset, s[0], s[1], s[2]);
                Bytes out(data.size());
                const Decoded d = decode(stream, props_of(s[0], s[1], s[2]), out);
                ASSERT_EQ(d.status, Status::Ok) << name << " preset " << preset << " lc/lp/pb " << s[0] << s[1] << s[2] << ": " << d.why;
                ASSERT_EQ(d.written, data.size());
                EXPECT_EQ(out, data) << name << " preset " << preset;
            }
        }
    }
}

TEST(Unlzma, TruncatedStreamsAndTrailingBytesAreRefused) {
    for (const auto& [name, data] : inputs()) {
        const Bytes stream = xz_encode(data, 6, 0, 2, 2);
        for (size_t n = 0; n < stream.size(); n += 1 + stream.size() / 200) {
            const Bytes cut(stream.begin(), stream.begin() + long(n));
            Bytes out(data.size());
            EXPECT_EQ(decode(cut, props_of(0, 2, 2), out).status, Status::Corrupt) << name << " cut at " << n;
        }
        Bytes longer = stream;
        longer.push_back(0);
        Bytes out(data.size());
        const Decoded d = decode(longer, props_of(0, 2, 2), out);
        EXPECT_EQ(d.status, Status::Corrupt) << name;
        EXPECT_STREQ(d.why, "bytes follow the end of the LZMA stream") << name;
    }
}

TEST(Unlzma, EndMarkerBeforeTheEndAndShortOutputAreRefused) {
    const Bytes data = inputs()[1].second;
    // An end marker where the output is not yet complete (it expects one byte more).
    const Bytes marked = xz_encode(data, 6, 0, 2, 2, true);
    Bytes out(data.size() + 1);
    Decoded d = decode(marked, props_of(0, 2, 2), out);
    EXPECT_EQ(d.status, Status::Corrupt);
    EXPECT_STREQ(d.why, "the stream ends before the output is complete");
    // The output one byte short: the stream does not end where the output does.
    const Bytes plain = xz_encode(data, 6, 0, 2, 2);
    out.assign(data.size() - 1, 0);
    d = decode(plain, props_of(0, 2, 2), out);
    EXPECT_EQ(d.status, Status::Corrupt);
    EXPECT_LE(d.written, out.size());
}

TEST(Unlzma, PropertiesBeyondTheTableAreRefused) {
    const Bytes data = inputs()[3].second;
    const Bytes stream = xz_encode(data, 6, 3, 0, 2);
    Bytes out(data.size());
    Decoded d = decode(stream, props_of(3, 0, 2), out);
    EXPECT_EQ(d.status, Status::Unsupported);
    EXPECT_STREQ(d.why, "literal context bits (lc + lp) beyond what the decoder holds");
    d = decode(stream, 225, out);
    EXPECT_EQ(d.status, Status::Corrupt);
    EXPECT_STREQ(d.why, "bad properties byte");
    const Bytes not_zero{1, 0, 0, 0, 0, 0};
    d = decode(not_zero, props_of(0, 2, 2), out);
    EXPECT_EQ(d.status, Status::Corrupt);
    EXPECT_STREQ(d.why, "the stream does not start as a range coder's does");
}

TEST(Unlzma, CorruptStreamsGetAStatusAndStayInBounds) {
    // Flipped bits anywhere: a status, or (if the damage still decodes) some output, always
    // within the buffer.
    const Bytes data = inputs()[2].second;
    const Bytes stream = xz_encode(data, 6, 0, 2, 2);
    std::mt19937 rng(5);
    int refused = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Bytes bad = stream;
        for (int k = 0; k < 3; ++k) bad[1 + rng() % (bad.size() - 1)] ^= uint8_t(1u << (rng() % 8));
        Bytes out(data.size());
        const Decoded d = decode(bad, props_of(0, 2, 2), out);
        if (d.status != Status::Ok) {
            ++refused;
            EXPECT_STRNE(d.why, "");
        }
        EXPECT_LE(d.written, out.size());
    }
    EXPECT_GT(refused, 250); // the clean-end check catches nearly all damage
}

using test::triangle_pack;

TEST(PackFile, LzmaPackUnpacksInPlaceAndLoads) {
    const Bytes plain = triangle_pack();
    const Bytes file = lzma_pack(plain);
    ASSERT_FALSE(file.empty());
    EXPECT_EQ(pack_file_kind(file.data(), uint32_t(file.size())), PackFileKind::Lzma);
    EXPECT_EQ(pack_file_bytes(file.data(), uint32_t(file.size())), file.size());
    EXPECT_EQ(decoded_memory_bytes(file.data(), uint32_t(file.size())), plain.size() + 3 + kLzmaStateBytes);

    // A region just large enough for the pack, the file and the decoder's state, the file at
    // its start, as the device loads it.
    const uint32_t capacity = uint32_t(plain.size() + file.size() + kLzmaStateBytes + 3);
    std::vector<uint32_t> region(capacity / 4 + 1);
    std::memcpy(region.data(), file.data(), file.size());
    auto* bytes = reinterpret_cast<uint8_t*>(region.data());
    uint32_t n = 0;
    Result r = unpack_in_place(bytes, capacity, capacity, n);
    ASSERT_TRUE(r.ok()) << r.what;
    ASSERT_EQ(n, plain.size());
    EXPECT_EQ(std::memcmp(bytes, plain.data(), n), 0);
    Pack p;
    r = p.open(bytes, n);
    ASSERT_TRUE(r.ok()) << r.what;
    EXPECT_EQ(p.faces().size(), 1u);

    // One byte short: refused, with the reason.
    std::memcpy(region.data(), file.data(), file.size());
    r = unpack_in_place(bytes, capacity - 1, capacity - 1, n);
    EXPECT_EQ(r.status, Status::Full);
    EXPECT_STREQ(r.what, "the pack and its compressed form together do not fit the pack memory");

    // The host loader (facet-pack --check, facet-mesh) decodes with the same code.
    LoadedPack loaded;
    std::string error;
    ASSERT_TRUE(load_pack_bytes(file, loaded, error)) << error;
    EXPECT_EQ(loaded.kind, PackFileKind::Lzma);
    EXPECT_EQ(loaded.bytes, plain.size());
    EXPECT_EQ(std::memcmp(loaded.data(), plain.data(), plain.size()), 0);

    // Cut short, a reserved byte set, bytes appended: each refused with its reason.
    Bytes cut = file;
    cut.resize(cut.size() - 1);
    EXPECT_FALSE(load_pack_bytes(cut, loaded, error));
    EXPECT_NE(error.find("truncated"), std::string::npos) << error;
    Bytes reserved = file;
    reserved[13] = 1; // LzmaHead::reserved[0]
    EXPECT_FALSE(load_pack_bytes(reserved, loaded, error));
    EXPECT_NE(error.find("reserved field is not 0"), std::string::npos) << error;
    Bytes longer = file;
    longer.push_back(0);
    EXPECT_FALSE(load_pack_bytes(longer, loaded, error));
    EXPECT_EQ(error, "1 bytes follow the compressed pack (appended or not one pack)");
}
