// The FAT reader (hal/fat.h) on card images made on the host the way a technician's PC makes them
// (dosfstools' mkfs.fat, mtools' mcopy and mmd): FAT32 and FAT16, with and without a partition
// table, long and Unicode names, subfolders, files over many clusters read byte for byte at any
// offset; and every bad card: exFAT, FAT12, no filesystem, a FAT whose chain loops or leaves the
// card, a file longer than its chain, a card pulled in the middle of a read.
#include "hal/fat.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::hal;

namespace {

// A card over an image file's bytes; pulled after `reads_left` reads (-1: never).
struct ImageCard final : Card {
    const std::vector<uint8_t>* image = nullptr; // (not copied: images are tens of MiB)
    int reads_left = -1;
    uint32_t reads = 0, sectors_read = 0;
    bool present() override { return reads_left != 0; }
    Result start() override { return image && image->size() >= kSectorBytes ? Result{} : Result::fail(Status::Io, "no card"); }
    uint32_t sectors() const override { return image ? uint32_t(image->size() / kSectorBytes) : 0; }
    Result read(uint32_t sector, uint32_t count, void* into) override {
        if (reads_left == 0) return Result::fail(Status::Io, "the card was pulled");
        if (reads_left > 0) --reads_left;
        if (uint64_t(sector) + count > sectors()) return Result::fail(Status::OutOfRange, "past the card's end");
        ++reads, sectors_read += count;
        std::memcpy(into, image->data() + size_t(sector) * kSectorBytes, size_t(count) * kSectorBytes);
        return {};
    }
};

// This run's folder for its images (removed when the program ends).
std::string dir() {
    static const struct Folder {
        std::string path;
        Folder() {
            std::string t = testing::TempDir() + "facet-fat-XXXXXX";
            std::vector<char> buf(t.begin(), t.end());
            buf.push_back(0);
            EXPECT_NE(mkdtemp(buf.data()), nullptr);
            path = buf.data();
        }
        ~Folder() { std::filesystem::remove_all(path); }
    } folder;
    return folder.path;
}

std::string tool(const char* name) { // (mkfs.fat lies in /usr/sbin, which a user's PATH may lack)
    for (const char* d : {"/usr/sbin/", "/sbin/", "/usr/bin/"}) {
        const std::string p = std::string(d) + name;
        if (std::ifstream(p).good()) return p;
    }
    return name;
}

void run(const std::string& cmd) { ASSERT_EQ(std::system((cmd + " >/dev/null 2>&1").c_str()), 0) << cmd; }

std::vector<uint8_t> read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
}
void write_file(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::vector<uint8_t> noise(size_t n, uint32_t seed) {
    std::mt19937 g(seed);
    std::vector<uint8_t> v(n);
    for (auto& b : v) b = uint8_t(g());
    return v;
}

// The files every image holds (their bytes known here).
struct Content {
    std::vector<uint8_t> big = noise(3'000'017, 1), small = noise(777, 2), nested = noise(70'000, 3);
};
const Content& content() {
    static const Content c;
    return c;
}

// An image: `mkfs` args (the FAT type, size), an MBR partition at 1 MiB when `partitioned`.
std::vector<uint8_t> make_image(const std::string& name, const std::string& fat, uint32_t mib, bool partitioned) {
    const std::string d = dir(), img = d + "/" + name + ".img";
    const Content& c = content();
    write_file(d + "/big.bin", c.big);
    write_file(d + "/small.bin", c.small);
    write_file(d + "/nested.bin", c.nested);
    std::remove(img.c_str());
    std::string at = img;
    if (partitioned) {
        std::vector<uint8_t> mbr(512, 0);
        const uint32_t start = 2048, count = mib * 2048 - start;
        uint8_t* p = mbr.data() + 446;
        p[4] = fat == "32" ? 0x0C : 0x0E;
        for (int k = 0; k < 4; ++k) p[8 + k] = uint8_t(start >> (8 * k)), p[12 + k] = uint8_t(count >> (8 * k));
        mbr[510] = 0x55, mbr[511] = 0xAA;
        write_file(img, mbr);
        run("truncate -s " + std::to_string(mib) + "M " + img);
        run(tool("mkfs.fat") + " -F " + fat + " --offset 2048 " + img + " " + std::to_string(count / 2));
        at = img + "@@1M";
    } else {
        run(tool("mkfs.fat") + " -F " + fat + " -C " + img + " " + std::to_string(mib * 1024));
    }
    const std::string m = " -i " + at + " ";
    run(tool("mmd") + m + "::/models ::/models/old ::/models/old/deeper");
    run(tool("mcopy") + m + d + "/big.bin '::/models/Valve body (rev 2).fpk'");
    run(tool("mcopy") + m + d + "/small.bin ::/models/A.FPK");
    run(tool("mcopy") + m + d + "/small.bin ::/readme.txt");
    run(tool("mcopy") + m + d + "/nested.bin '::/models/old/deeper/Zahnrad-grün.fpk'");
    // Enough files that the folder takes more than one cluster (copied in one call).
    const std::string many = d + "/many";
    std::filesystem::create_directories(many);
    std::string sources;
    for (int k = 0; k < 70; ++k) {
        const std::string f = many + "/part-number-" + std::to_string(k) + "-long-name.fpk";
        write_file(f, c.small);
        sources += " " + f;
    }
    run(tool("mcopy") + m + sources + " ::/models/");
    return read_file(img);
}

struct Images {
    std::vector<uint8_t> fat32 = make_image("fat32", "32", 64, false), fat16 = make_image("fat16", "16", 32, true),
                         fat32_mbr = make_image("fat32mbr", "32", 64, true);
};
const Images& images() {
    static const Images i;
    return i;
}

std::vector<std::string> names(fat::Volume& v, const char* path) {
    fat::Dir d;
    std::vector<std::string> out;
    if (!v.open_dir(path, d).ok()) return out;
    fat::Entry e;
    for (Result r = v.read_dir(d, e); r.ok(); r = v.read_dir(d, e)) out.push_back(std::string(e.name) + (e.folder ? "/" : ""));
    return out;
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

void expect_reads_everything(const std::vector<uint8_t>& image, fat::Kind kind) {
    ImageCard card;
    card.image = &image;
    ASSERT_TRUE(card.start().ok());
    fat::Volume v;
    const Result m = v.mount(card);
    ASSERT_TRUE(m.ok()) << m.what;
    EXPECT_EQ(v.kind(), kind);
    const auto root = names(v, "/");
    EXPECT_TRUE(has(root, "models/") && has(root, "readme.txt")) << root.size();
    const auto models = names(v, "/models");
    EXPECT_EQ(models.size(), 73u); // 70 numbered, the valve, A.FPK, old/
    EXPECT_TRUE(has(models, "Valve body (rev 2).fpk"));
    EXPECT_TRUE(has(models, "A.FPK"));
    EXPECT_TRUE(has(models, "old/"));
    EXPECT_TRUE(has(models, "part-number-69-long-name.fpk"));
    EXPECT_TRUE(has(names(v, "/models/old/deeper"), "Zahnrad-grün.fpk")) << "a Unicode long name, as UTF-8";

    const Content& c = content();
    fat::File f;
    ASSERT_TRUE(v.open("/MODELS/valve BODY (rev 2).fpk", f).ok()) << "names match without regard to case";
    EXPECT_EQ(f.bytes, c.big.size());
    std::vector<uint8_t> got(c.big.size());
    ASSERT_TRUE(v.read(f, 0, got.data(), f.bytes).ok());
    EXPECT_TRUE(got == c.big);
    // Pieces at odd offsets, backwards and forwards (a block at a time, as the module reads).
    std::mt19937 g(7);
    for (int k = 0; k < 200; ++k) {
        const uint32_t at = g() % f.bytes, n = std::min<uint32_t>(1 + g() % 200'000, f.bytes - at);
        std::vector<uint8_t> piece(n);
        ASSERT_TRUE(v.read(f, at, piece.data(), n).ok()) << at << "+" << n;
        ASSERT_EQ(std::memcmp(piece.data(), c.big.data() + at, n), 0) << at << "+" << n;
    }
    ASSERT_TRUE(v.open("/models/old/deeper/zahnrad-grün.fpk", f).ok());
    got.assign(f.bytes, 0);
    ASSERT_TRUE(v.read(f, 0, got.data(), f.bytes).ok());
    EXPECT_TRUE(got == c.nested);
    ASSERT_TRUE(v.open("models/a.fpk", f).ok());
    EXPECT_EQ(f.bytes, c.small.size());
    EXPECT_EQ(v.read(f, 700, got.data(), 100).status, Status::OutOfRange) << "past the end";
    EXPECT_EQ(v.open("/models/none.fpk", f).status, Status::NotFound);
    EXPECT_EQ(v.open("/readme.txt/x", f).status, Status::NotFound);
    fat::Dir d;
    EXPECT_EQ(v.open_dir("/readme.txt", d).status, Status::NotFound);
}

// The first cluster of a file's entry and where the entry lies (a byte offset in the image),
// found by its 8.3 name in the root of a FAT32 superfloppy image.
struct Found {
    size_t entry = 0;
    uint32_t cluster = 0;
    uint32_t fat_at = 0, data_at = 0, cluster_bytes = 0;
};
Found find_root_entry(const std::vector<uint8_t>& img, const char short_name[11]) {
    Found f;
    auto u16 = [&](size_t at) { return uint32_t(img[at] | (img[at + 1] << 8)); };
    auto u32 = [&](size_t at) { return u16(at) | (u16(at + 2) << 16); };
    const uint32_t spc = img[13], reserved = u16(14), fats = img[16], fat_sectors = u32(36), root = u32(44);
    f.fat_at = reserved * 512, f.data_at = (reserved + fats * fat_sectors) * 512, f.cluster_bytes = spc * 512;
    const size_t dir_at = f.data_at + size_t(root - 2) * f.cluster_bytes;
    for (size_t e = dir_at; e < dir_at + f.cluster_bytes; e += 32) {
        if (std::memcmp(&img[e], short_name, 11) == 0) {
            f.entry = e;
            f.cluster = (u16(e + 20) << 16) | u16(e + 26);
        }
    }
    return f;
}

Result mount(const std::vector<uint8_t>& image, fat::Volume& v, ImageCard& card) {
    card.image = &image;
    if (Result r = card.start(); !r.ok()) return r;
    return v.mount(card);
}

} // namespace

TEST(Fat, ReadsFat32WithoutAPartitionTable) { expect_reads_everything(images().fat32, fat::Kind::Fat32); }
TEST(Fat, ReadsFat32InAnMbrPartition) { expect_reads_everything(images().fat32_mbr, fat::Kind::Fat32); }
TEST(Fat, ReadsFat16InAnMbrPartition) { expect_reads_everything(images().fat16, fat::Kind::Fat16); }

// A file written at once lies in one run of clusters: read in a few large transfers, not a
// sector at a time.
TEST(Fat, AContiguousFileIsReadInLargeTransfers) {
    ImageCard card;
    fat::Volume v;
    ASSERT_TRUE(mount(images().fat32, v, card).ok());
    fat::File f;
    ASSERT_TRUE(v.open("/models/Valve body (rev 2).fpk", f).ok());
    std::vector<uint8_t> got(f.bytes);
    const uint32_t before = card.reads;
    ASSERT_TRUE(v.read(f, 0, got.data(), f.bytes).ok());
    // Its chain's FAT sectors (a FAT32 sector holds 128 entries), and its data in a few transfers.
    const uint32_t clusters = (f.bytes + v.cluster_bytes() - 1) / v.cluster_bytes();
    EXPECT_LE(card.reads - before, (clusters + 127) / 128 + 1 + 3);
}

TEST(Fat, BadCardsAreSaidWithTheirReason) {
    ImageCard card;
    fat::Volume v;
    // Nothing on it.
    const std::vector<uint8_t> zeros(1 << 20, 0);
    EXPECT_EQ(mount(zeros, v, card).status, Status::Unsupported);
    // exFAT (its boot sector's name; no exFAT tool in Debian's base set is needed for that).
    std::vector<uint8_t> exfat(1 << 20, 0);
    std::memcpy(&exfat[3], "EXFAT   ", 8);
    exfat[510] = 0x55, exfat[511] = 0xAA;
    Result r = mount(exfat, v, card);
    EXPECT_EQ(r.status, Status::Unsupported);
    EXPECT_NE(std::string(r.what).find("exFAT"), std::string::npos);
    // An MBR whose partition is NTFS or exFAT (type 7).
    std::vector<uint8_t> ntfs(1 << 20, 0);
    ntfs[446 + 4] = 0x07, ntfs[446 + 8] = 1, ntfs[510] = 0x55, ntfs[511] = 0xAA;
    EXPECT_EQ(mount(ntfs, v, card).status, Status::Unsupported);
    // FAT12 (a floppy-sized card).
    const std::string img12 = dir() + "/fat12.img";
    std::remove(img12.c_str());
    run(tool("mkfs.fat") + " -F 12 -C " + img12 + " 1440");
    const std::vector<uint8_t> fat12 = read_file(img12);
    r = mount(fat12, v, card);
    EXPECT_EQ(r.status, Status::Unsupported);
    EXPECT_NE(std::string(r.what).find("FAT12"), std::string::npos);
    // A boot sector whose counts lie (the FAT larger than the card).
    std::vector<uint8_t> lying = images().fat32;
    lying[36] = 0xFF, lying[37] = 0xFF, lying[38] = 0xFF, lying[39] = 0x00;
    EXPECT_EQ(mount(lying, v, card).status, Status::Corrupt);
    // An empty card reader: no card.
    const std::vector<uint8_t> none;
    EXPECT_EQ(mount(none, v, card).status, Status::Io);
}

TEST(Fat, ACorruptFatOrEntryIsFoundNotFollowed) {
    const std::vector<uint8_t>& good = images().fat32;
    const Found f = find_root_entry(good, "README  TXT");
    ASSERT_NE(f.entry, 0u);
    ASSERT_GE(f.cluster, 2u);
    auto set32 = [](std::vector<uint8_t>& img, size_t at, uint32_t v) {
        for (int k = 0; k < 4; ++k) img[at + k] = uint8_t(v >> (8 * k));
    };
    std::vector<uint8_t> buf(content().big.size());
    ImageCard card;
    fat::Volume v;
    fat::File file;
    // The file made longer than its chain (its size says 100 clusters; its chain ends after one).
    std::vector<uint8_t> longer = good;
    set32(longer, f.entry + 28, 100 * f.cluster_bytes);
    ASSERT_TRUE(mount(longer, v, card).ok());
    ASSERT_TRUE(v.open("/readme.txt", file).ok());
    Result r = v.read(file, 0, buf.data(), file.bytes);
    EXPECT_EQ(r.status, Status::Corrupt) << r.what;
    // Its chain looping onto itself (a longer loop is walked no further than the file's length,
    // and what it reads fails the pack's CRC).
    std::vector<uint8_t> loop = longer;
    set32(loop, f.fat_at + 4 * f.cluster, f.cluster);
    ASSERT_TRUE(mount(loop, v, card).ok());
    ASSERT_TRUE(v.open("/readme.txt", file).ok());
    r = v.read(file, 0, buf.data(), file.bytes);
    EXPECT_EQ(r.status, Status::Corrupt) << "a loop read as data";
    // Its chain leading past the card's clusters.
    std::vector<uint8_t> outside = longer;
    set32(outside, f.fat_at + 4 * f.cluster, 0x0FFFFFF0u);
    ASSERT_TRUE(mount(outside, v, card).ok());
    ASSERT_TRUE(v.open("/readme.txt", file).ok());
    EXPECT_EQ(v.read(file, 0, buf.data(), file.bytes).status, Status::Corrupt);
    // Its entry's first cluster past the card's.
    std::vector<uint8_t> bad_entry = good;
    bad_entry[f.entry + 20] = 0xFF, bad_entry[f.entry + 21] = 0x0F;
    ASSERT_TRUE(mount(bad_entry, v, card).ok());
    EXPECT_EQ(v.open("/readme.txt", file).status, Status::Corrupt);
    // A cluster marked bad inside the chain.
    std::vector<uint8_t> marked = longer;
    set32(marked, f.fat_at + 4 * f.cluster, 0x0FFFFFF7u);
    ASSERT_TRUE(mount(marked, v, card).ok());
    ASSERT_TRUE(v.open("/readme.txt", file).ok());
    EXPECT_EQ(v.read(file, 0, buf.data(), file.bytes).status, Status::Corrupt);
}

// Random damage to the filesystem's first sectors and its FAT: every call ends, with Ok or a reason.
TEST(Fat, RandomDamageNeverHangsNorReadsOutside) {
    std::mt19937 g(11);
    std::vector<uint8_t> img = images().fat16;
    const size_t span = 2048 * 512 + 64 * 512; // the MBR, the boot sector, the FATs' start
    const std::vector<uint8_t> first(img.begin(), img.begin() + span);
    for (int k = 0; k < 300; ++k) {
        std::copy(first.begin(), first.end(), img.begin());
        for (int n = 0; n < 1 + int(g() % 8); ++n) img[g() % span] ^= uint8_t(1 + g() % 255);
        ImageCard card;
        fat::Volume v;
        if (!mount(img, v, card).ok()) continue;
        (void)names(v, "/");
        (void)names(v, "/models");
        fat::File f;
        std::vector<uint8_t> buf(content().big.size());
        if (v.open("/models/Valve body (rev 2).fpk", f).ok() && f.bytes <= buf.size()) (void)v.read(f, 0, buf.data(), f.bytes);
    }
}

TEST(Fat, ACardPulledMidReadIsIo) {
    ImageCard card;
    fat::Volume v;
    ASSERT_TRUE(mount(images().fat32, v, card).ok());
    fat::File f;
    ASSERT_TRUE(v.open("/models/Valve body (rev 2).fpk", f).ok());
    std::vector<uint8_t> buf(f.bytes);
    card.reads_left = 1; // the next read lands; the one after finds the card gone
    const Result r = v.read(f, 1000, buf.data(), 2'000'000);
    EXPECT_EQ(r.status, Status::Io) << r.what;
    EXPECT_EQ(v.open("/readme.txt", f).status, Status::Io);
}
