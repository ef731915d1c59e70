// The device's DEFLATE decoder against zlib's encoder: every block kind zlib writes inflates to
// the original bytes; truncated, corrupted and oversized streams get a status, never a write
// outside the output. And deflated pack files unpack in place.
#include "geom/inflate.h"
#include "geom/pack.h"
#include "geom/pack_file.h"
#include "pack_io.h"
#include "pack_writer.h"
#include "triangle_pack.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstddef>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

using Bytes = std::vector<uint8_t>;

// A raw DEFLATE stream of data by zlib with the given level and strategy.
Bytes zlib_deflate(const Bytes& data, int level, int strategy = Z_DEFAULT_STRATEGY) {
    z_stream z{};
    EXPECT_EQ(deflateInit2(&z, level, Z_DEFLATED, -15, 9, strategy), Z_OK);
    Bytes out(deflateBound(&z, uLong(data.size())) + 16);
    z.next_in = const_cast<Bytef*>(data.data());
    z.avail_in = uInt(data.size());
    z.next_out = out.data();
    z.avail_out = uInt(out.size());
    EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

// The inflater's code, and its reason in `why`.
Status run(const Bytes& stream, Bytes& out, uint32_t& written, const char*& why) {
    const Result r = inflate({stream.data(), stream.size()}, {out.data(), out.size()}, written);
    why = r.what;
    return r.status;
}
Status unpack(uint8_t* region, uint32_t capacity, uint32_t loaded, uint32_t& bytes, const char*& why) {
    const Result r = unpack_in_place(region, capacity, loaded, bytes);
    why = r.what;
    return r.status;
}

// Test inputs: noise (zlib stores it), text-like data with repeats (dynamic codes), a short
// string (fixed codes), a long run (overlapping copies), nothing at all, and skewed bytes
// (codes longer than the decoder's table).
std::vector<std::pair<std::string, Bytes>> inputs() {
    std::mt19937 rng(7);
    Bytes noise(70000);
    for (uint8_t& b : noise) b = uint8_t(rng());
    Bytes text;
    const char* words[] = {"cylinder ", "plane ", "B-spline ", "edge ", "loop ", "face ", "0.25 ", "-12.5 "};
    while (text.size() < 200000) {
        const char* w = words[rng() % 8];
        text.insert(text.end(), w, w + std::strlen(w));
    }
    const std::string hello = "facet: a short string";
    Bytes run(100000, 0xAB);
    run[500] = 1;
    // Skewed: byte k about twice as rare as byte k - 1, so that the codes run up to 15 bits
    // (past the decoder's 9-bit table: its bit-by-bit path).
    Bytes skewed(150000);
    for (uint8_t& b : skewed) {
        const uint32_t r = rng() | 1u << 24;
        b = uint8_t(__builtin_ctz(r) * 7 + (rng() % 3));
    }
    return {{"noise", noise}, {"text", text}, {"short", Bytes(hello.begin(), hello.end())}, {"run", run}, {"empty", {}},
            {"skewed", skewed}};
}

} // namespace

TEST(Inflate, EveryZlibBlockKindRoundTrips) {
    const std::pair<int, int> modes[] = {{9, Z_DEFAULT_STRATEGY}, {1, Z_DEFAULT_STRATEGY}, {0, Z_DEFAULT_STRATEGY},
                                         {9, Z_FIXED},            {9, Z_HUFFMAN_ONLY},     {9, Z_RLE}};
    for (const auto& [name, data] : inputs()) {
        for (const auto& [level, strategy] : modes) {
            const Bytes stream = zlib_deflate(data, level, strategy);
            Bytes out(data.size() + 10, 0xEE);
            uint32_t written = 0;
            const char* why = "";
            ASSERT_EQ(run(stream, out, written, why), Status::Ok) << name << " level " << level << " strategy " << strategy << ": " << why;
            ASSERT_EQ(written, data.size()) << name;
            EXPECT_TRUE(std::equal(data.begin(), data.end(), out.begin())) << name << " level " << level << " strategy " << strategy;
            EXPECT_EQ(out[data.size()], 0xEE) << "nothing written past the data";
        }
    }
}

TEST(Inflate, TruncatedStreamsAreRefused) {
    for (const auto& [name, data] : inputs()) {
        if (data.empty()) continue;
        const Bytes stream = zlib_deflate(data, 9);
        for (size_t n = 0; n < stream.size(); n += 1 + stream.size() / 300) {
            const Bytes cut(stream.begin(), stream.begin() + long(n));
            Bytes out(data.size());
            uint32_t written = 0;
            const char* why = "";
            EXPECT_NE(run(cut, out, written, why), Status::Ok) << name << " cut at " << n;
        }
    }
}

TEST(Inflate, OutputTooSmallIsFull) {
    for (const auto& [name, data] : inputs()) {
        if (data.size() < 2) continue;
        for (int level : {0, 9}) {
            const Bytes stream = zlib_deflate(data, level);
            Bytes out(data.size() - 1);
            uint32_t written = 0;
            const char* why = "";
            EXPECT_EQ(run(stream, out, written, why), Status::Full) << name;
            EXPECT_STREQ(why, "the inflated data is larger than its space");
        }
    }
}

TEST(Inflate, CorruptStreamsGetAStatusAndStayInBounds) {
    // Flipped bits anywhere: a status or (if the damage still decodes) some output, always
    // within the buffer (the ASan build checks every access).
    const Bytes data = inputs()[1].second;
    const Bytes stream = zlib_deflate(data, 9);
    std::mt19937 rng(11);
    int refused = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Bytes bad = stream;
        for (int k = 0; k < 3; ++k) bad[rng() % bad.size()] ^= uint8_t(1u << (rng() % 8));
        Bytes out(data.size());
        uint32_t written = 0;
        const char* why = "";
        const Status st = run(bad, out, written, why);
        if (st != Status::Ok) {
            ++refused;
            EXPECT_STRNE(why, "");
        }
        EXPECT_LE(written, out.size());
    }
    EXPECT_GT(refused, 0);
}

TEST(Inflate, HandMadeBadStreams) {
    struct Case {
        const char* name;
        Bytes stream;
        const char* why;
    };
    const Case cases[] = {
        // BFINAL 1, BTYPE 11.
        {"reserved block type", {0x07}, "an invalid block type"},
        // Stored: LEN 5, NLEN not its complement.
        {"stored length check", {0x01, 0x05, 0x00, 0x00, 0x00}, "a stored block's length check fails"},
        // Fixed: literal 'a' (code 0x91, 8 bits), then length 3 (code 257: 0000001) distance 2
        // (code 1: 00001): reaches two back with one byte written.
        {"copy before the start", {0x4b, 0x04, 0x42, 0x00}, "a copy reaches back before the start"},
        {"empty", {}, "the DEFLATE stream ends early"},
    };
    for (const Case& c : cases) {
        Bytes out(64);
        uint32_t written = 0;
        const char* why = "";
        EXPECT_EQ(run(c.stream, out, written, why), Status::Corrupt) << c.name;
        EXPECT_STREQ(why, c.why) << c.name;
    }
}

using test::triangle_pack;

TEST(PackFile, DeflatedPackUnpacksInPlace) {
    const Bytes plain = triangle_pack();
    const Bytes file = deflate_pack(plain);
    ASSERT_FALSE(file.empty());
    EXPECT_EQ(pack_file_kind(file.data(), uint32_t(file.size())), PackFileKind::Deflated);
    EXPECT_EQ(pack_file_bytes(file.data(), uint32_t(file.size())), file.size());

    // A region just large enough for both, the file at its start, as the device loads it.
    const uint32_t capacity = uint32_t(plain.size() + file.size());
    std::vector<uint32_t> region(capacity / 4 + 1);
    std::memcpy(region.data(), file.data(), file.size());
    auto* bytes = reinterpret_cast<uint8_t*>(region.data());
    uint32_t n = 0;
    const char* why = "";
    ASSERT_EQ(unpack(bytes, capacity, capacity, n, why), Status::Ok) << why;
    ASSERT_EQ(n, plain.size());
    EXPECT_EQ(std::memcmp(bytes, plain.data(), n), 0);
    Pack p;
    const Result problem = p.open(bytes, n);
    ASSERT_TRUE(problem.ok()) << problem.what;
    EXPECT_EQ(p.faces().size(), 1u);

    // One byte short of room for both: refused, with the reason.
    std::memcpy(region.data(), file.data(), file.size());
    EXPECT_EQ(unpack(bytes, capacity - 1, capacity - 1, n, why), Status::Full);
    EXPECT_STREQ(why, "the pack and its compressed form together do not fit the pack memory");
}

TEST(PackFile, PlainPacksPassAndOtherBytesAreRefused) {
    const Bytes plain = triangle_pack();
    std::vector<uint32_t> region(plain.size() / 4 + 1);
    std::memcpy(region.data(), plain.data(), plain.size());
    uint32_t n = 0;
    const char* why = "";
    ASSERT_EQ(unpack(reinterpret_cast<uint8_t*>(region.data()), uint32_t(plain.size()), uint32_t(plain.size()), n, why), Status::Ok);
    EXPECT_EQ(n, plain.size());

    Bytes junk(64, 'x');
    EXPECT_EQ(unpack(junk.data(), 64, 64, n, why), Status::Corrupt);
    EXPECT_STREQ(why, "no pack here (neither FPK1, FPX1 nor FPZ1)");

    // A deflated file whose stream is cut short: its head promises more than is there.
    Bytes file = deflate_pack(plain);
    file.resize(file.size() - 3);
    LoadedPack loaded;
    std::string error;
    EXPECT_FALSE(load_pack_bytes(file, loaded, error));
    EXPECT_NE(error.find("truncated"), std::string::npos) << error;
}

// Reliability finding: bytes appended to a deflated pack, and non-zero reserved fields (which the
// CRC does not cover), were accepted. Each is refused with its reason.
TEST(PackFile, TrailingBytesAndReservedFieldsAreRefused) {
    const Bytes plain = triangle_pack();
    LoadedPack loaded;
    std::string error;

    Bytes file = deflate_pack(plain);
    ASSERT_TRUE(load_pack_bytes(file, loaded, error)) << error;
    Bytes longer = file;
    longer.insert(longer.end(), {'j', 'u', 'n', 'k'});
    EXPECT_FALSE(load_pack_bytes(longer, loaded, error));
    EXPECT_EQ(error, "4 bytes follow the compressed pack (appended or not one pack)");

    // The head made to cover the junk too: the decoder sees bytes after the last block.
    pack::DeflatedHead h;
    std::memcpy(&h, longer.data(), sizeof h);
    h.stream_bytes += 4;
    std::memcpy(longer.data(), &h, sizeof h);
    EXPECT_FALSE(load_pack_bytes(longer, loaded, error));
    EXPECT_NE(error.find("bytes follow the DEFLATE stream's last block"), std::string::npos) << error;

    Bytes reserved = file;
    reserved[12] = 1; // DeflatedHead::reserved
    EXPECT_FALSE(load_pack_bytes(reserved, loaded, error));
    EXPECT_NE(error.find("reserved field is not 0"), std::string::npos) << error;

    // A plain pack: appended bytes and non-zero flags or reserved words.
    Bytes padded = plain;
    padded.insert(padded.end(), 4, 0);
    std::vector<uint32_t> words(padded.size() / 4 + 1);
    std::memcpy(words.data(), padded.data(), padded.size());
    Pack p;
    Result r = p.open(words.data(), uint32_t(padded.size()));
    EXPECT_EQ(r.status, Status::Corrupt);
    EXPECT_STREQ(r.what, "size does not match the header (truncated or padded)");
    for (const size_t offset : {offsetof(pack::Header, flags), offsetof(pack::Header, reserved) + 8}) {
        Bytes changed = plain;
        changed[offset] = 0x80;
        std::memcpy(words.data(), changed.data(), changed.size());
        r = p.open(words.data(), uint32_t(changed.size()));
        EXPECT_EQ(r.status, Status::Corrupt) << offset;
        EXPECT_STREQ(r.what, "the header's flags or reserved fields are not 0");
    }
}
