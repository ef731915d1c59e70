// A read-only FAT16 / FAT32 reader (hal/fat.h). Layout from Microsoft's FAT specification (the
// BPB's fields, the cluster count that tells FAT12, 16 and 32 apart, the long-name entries and
// their checksum).
#include "hal/fat.h"

#include <cstring>

namespace facet::hal::fat {
namespace {

constexpr Place kCard{"card"};
constexpr uint32_t kEntryBytes = 32;
constexpr uint32_t kMaxDirEntries = 65536; // a folder's most (2 MiB of entries)
constexpr uint8_t kAttrLongName = 0x0F, kAttrVolume = 0x08, kAttrFolder = 0x10;

uint16_t u16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
uint32_t u32(const uint8_t* p) { return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24); }

Result corrupt(const char* what) { return Result::fail(Status::Corrupt, what, kCard); }

bool power_of_two(uint32_t n) { return n && !(n & (n - 1)); }

// A boot sector with a FAT BPB (not an MBR): a jump, 512-byte sectors, sane counts.
bool looks_like_bpb(const uint8_t* s) {
    return (s[0] == 0xEB || s[0] == 0xE9) && u16(s + 11) == 512 && power_of_two(s[13]) && u16(s + 14) > 0 && (s[16] == 1 || s[16] == 2);
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

bool same_name(const char* a, const char* b, size_t n) { // (b: n bytes, not terminated)
    for (size_t i = 0; i < n; ++i)
        if (!a[i] || lower(a[i]) != lower(b[i])) return false;
    return a[n] == 0;
}

// UCS-2 (with surrogate pairs) to UTF-8; false when it does not fit.
bool utf8(const uint16_t* s, uint32_t n, char* out, uint32_t bytes) {
    uint32_t o = 0;
    for (uint32_t i = 0; i < n; ++i) {
        uint32_t c = s[i];
        if (c >= 0xD800 && c < 0xDC00 && i + 1 < n && s[i + 1] >= 0xDC00 && s[i + 1] < 0xE000) {
            c = 0x10000 + ((c - 0xD800) << 10) + (s[++i] - 0xDC00);
        } else if (c >= 0xD800 && c < 0xE000) {
            c = 0xFFFD; // a lone surrogate
        }
        const uint32_t len = c < 0x80 ? 1 : c < 0x800 ? 2 : c < 0x10000 ? 3 : 4;
        if (o + len + 1 > bytes) return false;
        if (len == 1) {
            out[o++] = char(c);
        } else {
            static constexpr uint8_t kLead[] = {0, 0, 0xC0, 0xE0, 0xF0};
            out[o] = char(kLead[len] | (c >> (6 * (len - 1))));
            for (uint32_t k = 1; k < len; ++k) out[o + k] = char(0x80 | ((c >> (6 * (len - 1 - k))) & 0x3F));
            o += len;
        }
    }
    out[o] = 0;
    return true;
}

// An 8.3 name as "NAME.EXT" (lower case where the entry's NT flags say so).
void short_name(const uint8_t* e, char out[13]) {
    uint32_t o = 0;
    const bool base_lower = e[12] & 0x08, ext_lower = e[12] & 0x10;
    for (int i = 0; i < 8 && e[i] != ' '; ++i) {
        const char c = char(i == 0 && e[0] == 0x05 ? 0xE5 : e[i]);
        out[o++] = base_lower ? lower(c) : c;
    }
    if (e[8] != ' ') {
        out[o++] = '.';
        for (int i = 8; i < 11 && e[i] != ' '; ++i) out[o++] = ext_lower ? lower(char(e[i])) : char(e[i]);
    }
    out[o] = 0;
}

uint8_t checksum(const uint8_t* e) {
    uint8_t sum = 0;
    for (int i = 0; i < 11; ++i) sum = uint8_t(((sum & 1) << 7) + (sum >> 1) + e[i]);
    return sum;
}

} // namespace

Result Volume::sector(uint32_t lba) {
    if (lba == buf_lba_) return {};
    buf_lba_ = 0xFFFFFFFFu;
    if (Result r = card_->read(lba, 1, buf_); !r.ok()) return r;
    buf_lba_ = lba;
    return {};
}

Result Volume::mount(Card& card) {
    *this = Volume{};
    card_ = &card;
    if (card.sectors() == 0) return Result::fail(Status::Io, "the card is not started (or holds nothing)", kCard);
    if (Result r = sector(0); !r.ok()) return r;
    if (buf_[510] != 0x55 || buf_[511] != 0xAA) return Result::fail(Status::Unsupported, "no partition table or filesystem on the card (format it FAT32)", kCard);
    if (std::memcmp(buf_ + 3, "EXFAT   ", 8) == 0) return Result::fail(Status::Unsupported, "the card is exFAT: format it FAT32", kCard);
    if (std::memcmp(buf_ + 3, "NTFS    ", 8) == 0) return Result::fail(Status::Unsupported, "the card is NTFS: format it FAT32", kCard);
    if (!looks_like_bpb(buf_)) { // an MBR: its first FAT partition
        const uint8_t* found = nullptr;
        for (int i = 0; i < 4 && !found; ++i) {
            const uint8_t* p = buf_ + 446 + 16 * i;
            switch (p[4]) {
            case 0x04: case 0x06: case 0x0E: case 0x0B: case 0x0C: found = p; break;
            case 0x07: return Result::fail(Status::Unsupported, "the card's partition is exFAT or NTFS: format it FAT32", kCard);
            case 0xEE: return Result::fail(Status::Unsupported, "the card has a GPT partition table: give it an MBR and FAT32", kCard);
            default: break;
            }
        }
        if (!found) return Result::fail(Status::Unsupported, "no FAT16 or FAT32 partition on the card", kCard);
        part_lba_ = u32(found + 8);
        if (part_lba_ == 0 || part_lba_ >= card.sectors()) return corrupt("the partition starts outside the card");
        if (Result r = sector(part_lba_); !r.ok()) return r;
        if (std::memcmp(buf_ + 3, "EXFAT   ", 8) == 0) return Result::fail(Status::Unsupported, "the card is exFAT: format it FAT32", kCard);
        if (buf_[510] != 0x55 || buf_[511] != 0xAA || !looks_like_bpb(buf_)) return corrupt("the partition's boot sector is not a FAT one");
    }
    const uint8_t* b = buf_;
    sectors_per_cluster_ = b[13];
    const uint32_t reserved = u16(b + 14), fats = b[16], root_entries = u16(b + 17);
    const uint32_t total = u16(b + 19) ? u16(b + 19) : u32(b + 32);
    const uint32_t fat_sectors = u16(b + 22) ? u16(b + 22) : u32(b + 36);
    if (fat_sectors == 0 || total == 0) return corrupt("the boot sector gives no FAT or no size");
    const uint32_t root_sectors = (root_entries * kEntryBytes + Card::kSectorBytes - 1) / Card::kSectorBytes;
    const uint64_t meta = uint64_t(reserved) + uint64_t(fats) * fat_sectors + root_sectors;
    if (meta >= total) return corrupt("the FATs and the root folder leave no room for data");
    if (uint64_t(part_lba_) + total > card.sectors()) return corrupt("the filesystem is larger than the card");
    clusters_ = uint32_t((total - meta) / sectors_per_cluster_);
    if (clusters_ < 4085) return Result::fail(Status::Unsupported, "the card is FAT12: format it FAT32 (or FAT16)", kCard);
    kind_ = clusters_ < 65525 ? Kind::Fat16 : Kind::Fat32;
    const uint64_t fat_entries = uint64_t(fat_sectors) * Card::kSectorBytes / (kind_ == Kind::Fat16 ? 2 : 4);
    if (fat_entries < uint64_t(clusters_) + 2) {
        kind_ = Kind::None;
        return corrupt("the FAT is too small for the clusters");
    }
    fat_lba_ = part_lba_ + reserved;
    fat_sectors_ = fat_sectors;
    root_lba_ = fat_lba_ + fats * fat_sectors;
    root_entries_ = root_entries;
    data_lba_ = root_lba_ + root_sectors;
    if (kind_ == Kind::Fat32) {
        root_cluster_ = u32(b + 44);
        if (root_entries != 0 || !valid_cluster(root_cluster_)) {
            kind_ = Kind::None;
            return corrupt("the FAT32 root folder is not a cluster");
        }
    } else if (root_entries == 0) {
        kind_ = Kind::None;
        return corrupt("the FAT16 root folder has no entries");
    }
    return {};
}

Result Volume::next_cluster(uint32_t cluster, uint32_t& next) {
    const uint32_t width = kind_ == Kind::Fat16 ? 2 : 4, at = cluster * width;
    if (Result r = sector(fat_lba_ + at / Card::kSectorBytes); !r.ok()) return r;
    const uint8_t* p = buf_ + at % Card::kSectorBytes;
    const uint32_t v = kind_ == Kind::Fat16 ? u16(p) : (u32(p) & 0x0FFFFFFFu);
    const uint32_t end = kind_ == Kind::Fat16 ? 0xFFF8 : 0x0FFFFFF8u, bad = end - 1;
    if (v >= end) {
        next = 0;
        return {};
    }
    if (v == bad) return corrupt("a file's cluster is marked bad");
    if (!valid_cluster(v)) return corrupt("a cluster chain leads outside the card's clusters (or to a free one)");
    if (v == cluster) return corrupt("a cluster chain loops onto itself");
    next = v;
    return {};
}

Result Volume::cluster_at(File& f, uint32_t index, uint32_t& cluster) {
    uint32_t i = 0, c = f.first_cluster;
    if (f.at_cluster && f.at_index <= index) i = f.at_index, c = f.at_cluster;
    if (!valid_cluster(c)) return corrupt("a file's first cluster is outside the card's clusters");
    for (; i < index; ++i) {
        if (i >= clusters_) return corrupt("a cluster chain loops");
        uint32_t next = 0;
        if (Result r = next_cluster(c, next); !r.ok()) return r;
        if (next == 0) return Result::fail(Status::NotFound, "past the chain's end", kCard);
        c = next;
    }
    f.at_index = index, f.at_cluster = c;
    cluster = c;
    return {};
}

Result Volume::read(File& f, uint32_t offset, void* into, uint32_t bytes) {
    if (!mounted()) return Result::fail(Status::Io, "no card is mounted", kCard);
    if (uint64_t(offset) + bytes > f.bytes) return Result::fail(Status::OutOfRange, "a read past the file's end", kCard);
    auto* out = static_cast<uint8_t*>(into);
    const uint32_t cb = cluster_bytes();
    while (bytes > 0) {
        uint32_t cluster = 0;
        if (Result r = cluster_at(f, offset / cb, cluster); !r.ok()) {
            return r.status == Status::NotFound ? corrupt("a file's cluster chain is shorter than its size") : r;
        }
        const uint32_t within = offset % cb;
        const uint32_t lba = cluster_lba(cluster) + within / Card::kSectorBytes, in_sector = within % Card::kSectorBytes;
        if (in_sector == 0 && bytes >= Card::kSectorBytes && !(reinterpret_cast<uintptr_t>(out) & 3)) {
            // Whole sectors straight to the caller: the rest of this cluster, and on through the
            // clusters that follow it on the card (a file written at once lies in one run).
            uint32_t sectors = (cb - within) / Card::kSectorBytes;
            uint32_t want = bytes / Card::kSectorBytes;
            uint32_t last = cluster;
            while (sectors < want) {
                uint32_t next = 0;
                if (Result r = next_cluster(last, next); !r.ok()) return r;
                if (next != last + 1) break;
                last = next, sectors += sectors_per_cluster_;
                f.at_index += 1, f.at_cluster = next;
            }
            if (sectors > want) sectors = want;
            if (Result r = card_->read(lba, sectors, out); !r.ok()) return r;
            const uint32_t n = sectors * Card::kSectorBytes;
            out += n, offset += n, bytes -= n;
            continue;
        }
        if (Result r = sector(lba); !r.ok()) return r;
        uint32_t n = Card::kSectorBytes - in_sector;
        if (n > bytes) n = bytes;
        std::memcpy(out, buf_ + in_sector, n);
        out += n, offset += n, bytes -= n;
    }
    return {};
}

Result Volume::dir_entry(Dir& d, uint32_t index, uint32_t& at) {
    if (index >= kMaxDirEntries) return corrupt("a folder of more than 65,536 entries");
    uint32_t lba = 0;
    const uint32_t byte = index * kEntryBytes;
    if (d.fixed_root) {
        if (index >= root_entries_) return Result::fail(Status::NotFound, "the folder's end", kCard);
        lba = root_lba_ + byte / Card::kSectorBytes;
    } else {
        uint32_t cluster = 0;
        if (Result r = cluster_at(d.folder, byte / cluster_bytes(), cluster); !r.ok()) return r;
        lba = cluster_lba(cluster) + (byte % cluster_bytes()) / Card::kSectorBytes;
    }
    if (Result r = sector(lba); !r.ok()) return r;
    at = byte % Card::kSectorBytes;
    return {};
}

Result Volume::read_dir(Dir& d, Entry& out) {
    if (!mounted()) return Result::fail(Status::Io, "no card is mounted", kCard);
    uint16_t name[260];     // a long name gathered (UCS-2), from the entries before the short one
    uint32_t pieces = 0, expect = 0; // its pieces, and the sequence number the next one must have
    uint8_t sum = 0;
    for (;; ++d.entry) {
        uint32_t at = 0;
        if (Result r = dir_entry(d, d.entry, at); !r.ok()) return r;
        const uint8_t* e = buf_ + at;
        if (e[0] == 0x00) return Result::fail(Status::NotFound, "the folder's end", kCard);
        if (e[0] == 0xE5) { // deleted
            pieces = expect = 0;
            continue;
        }
        if ((e[11] & 0x3F) == kAttrLongName) {
            const uint32_t seq = e[0] & 0x1F;
            if (e[0] & 0x40) pieces = seq, expect = seq, sum = e[13];
            if (seq == 0 || seq != expect || e[13] != sum || pieces > 20) {
                pieces = expect = 0;
                continue;
            }
            static constexpr uint8_t kAt[13] = {1, 3, 5, 7, 9, 14, 16, 18, 20, 22, 24, 28, 30};
            for (int k = 0; k < 13; ++k) name[(seq - 1) * 13 + k] = u16(e + kAt[k]);
            --expect;
            continue;
        }
        const bool long_ok = pieces > 0 && expect == 0 && checksum(e) == sum;
        const uint32_t long_pieces = pieces;
        pieces = expect = 0;
        if (e[11] & kAttrVolume) continue;
        if (e[0] == '.' && (e[1] == ' ' || (e[1] == '.' && e[2] == ' '))) continue;
        out.folder = e[11] & kAttrFolder;
        out.bytes = out.folder ? 0 : u32(e + 28);
        uint32_t n = 0;
        while (long_ok && n < long_pieces * 13 && name[n] != 0 && name[n] != 0xFFFF) ++n;
        if (!long_ok || n == 0 || !utf8(name, n, out.name, sizeof out.name)) {
            char s[13];
            short_name(e, s);
            std::memcpy(out.name, s, sizeof s);
        }
        ++d.entry;
        return {};
    }
}

Result Volume::open_dir(const char* path, Dir& out) {
    File f;
    if (Result r = open(path, f); !r.ok()) return r;
    if (!f.folder) return Result::fail(Status::NotFound, "not a folder", kCard);
    out = {};
    out.folder = f;
    out.fixed_root = kind_ == Kind::Fat16 && f.first_cluster == 0;
    return {};
}

Result Volume::open(const char* path, File& out) {
    if (!mounted()) return Result::fail(Status::Io, "no card is mounted", kCard);
    if (!path) return Result::fail(Status::OutOfRange, "no path", kCard);
    // The root: FAT32's first cluster, FAT16's fixed area (cluster 0).
    File here{kind_ == Kind::Fat32 ? root_cluster_ : 0, 0, true, 0, 0};
    while (*path) {
        while (*path == '/') ++path;
        if (!*path) break;
        size_t n = 0;
        while (path[n] && path[n] != '/') ++n;
        if (!here.folder) return Result::fail(Status::NotFound, "a file where the path has a folder", kCard);
        Dir d{};
        d.folder = here;
        d.fixed_root = kind_ == Kind::Fat16 && here.first_cluster == 0;
        bool found = false;
        Entry e;
        for (;;) {
            const Result r = read_dir(d, e);
            if (r.status == Status::NotFound) break;
            if (!r.ok()) return r;
            // (its 8.3 name too: the entry before read_dir's step is in buf_)
            uint32_t at = 0;
            char s[13] = "";
            if (dir_entry(d, d.entry - 1, at).ok()) short_name(buf_ + at, s);
            if (!same_name(e.name, path, n) && !same_name(s, path, n)) continue;
            const uint8_t* entry = buf_ + at;
            const uint32_t first = (kind_ == Kind::Fat32 ? uint32_t(u16(entry + 20)) << 16 : 0) | u16(entry + 26);
            here = File{first, e.bytes, e.folder, 0, 0};
            if (here.folder && first == 0) here.first_cluster = kind_ == Kind::Fat32 ? root_cluster_ : 0; // (".." of the root's children)
            if ((here.bytes > 0 || (here.folder && here.first_cluster != 0)) && !valid_cluster(here.first_cluster)) {
                return corrupt("an entry's first cluster is outside the card's clusters");
            }
            found = true;
            break;
        }
        if (!found) return Result::fail(Status::NotFound, "no such file or folder on the card", kCard);
        path += n;
    }
    out = here;
    return {};
}

} // namespace facet::hal::fat
