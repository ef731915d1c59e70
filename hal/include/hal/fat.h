#pragma once
// A read-only FAT16 / FAT32 reader for a memory card (hal/card.h): the card's first partition
// (an MBR's, or a card formatted without one), folders and long file names, files read at any
// offset. No heap: the Volume holds one sector of its own and a few numbers; Files and Dirs are
// small values the caller keeps.
//
//   hal::fat::Volume vol;
//   if (Result r = vol.mount(card); !r.ok()) print(con, "card: {}\n", r);   // exFAT: Unsupported
//   hal::fat::File f;
//   if (vol.open("/models/pump.fpk", f).ok()) r = vol.read(f, offset, buffer, bytes);
//
// Everything read from the card is checked before it is used: the boot sector's fields, every
// cluster number (in range, chains without loops, as long as the file), each directory entry.
// What fails says why (Corrupt, Unsupported: FAT12, exFAT, NTFS, sectors not 512 bytes; Io: the
// card's read failed; NotFound: no such file or folder).
#include "hal/card.h"

#include <cstdint>

namespace facet::hal::fat {

constexpr uint32_t kNameBytes = 256 * 3 + 1; // a long name's UTF-8 (255 UCS-2 characters)

// A file or folder found: its first cluster and size (the position of its last read kept, so
// reads going forward walk the cluster chain from there).
struct File {
    uint32_t first_cluster = 0, bytes = 0;
    bool folder = false;
    uint32_t at_index = 0, at_cluster = 0; // the chain's cluster number at_index (0: none yet)
};

// A folder being listed (the root of FAT16 is a fixed area of sectors, not a cluster chain).
struct Dir {
    File folder;
    uint32_t entry = 0; // the next entry's index
    bool fixed_root = false;
};

// An entry listed: its name (the long one when there is one, else 8.3 as "NAME.EXT"), size.
struct Entry {
    char name[kNameBytes];
    uint32_t bytes;
    bool folder;
};

enum class Kind : uint8_t { None, Fat16, Fat32 };

class Volume {
public:
    // The filesystem on `card` (started): Ok, or why it cannot be read.
    Result mount(Card& card);
    void unmount() { card_ = nullptr, kind_ = Kind::None; }
    bool mounted() const { return kind_ != Kind::None; }
    Kind kind() const { return kind_; }
    uint32_t cluster_bytes() const { return sectors_per_cluster_ * Card::kSectorBytes; }

    // The file or folder at `path` ('/' between names, from the root; names matched without
    // regard to ASCII case, long or 8.3).
    Result open(const char* path, File& out);
    // `bytes` bytes at `offset` into `into` (Corrupt: past the file's end, or its chain is short).
    Result read(File& f, uint32_t offset, void* into, uint32_t bytes);

    Result open_dir(const char* path, Dir& out);
    // The next entry (NotFound after the last; "." and "..", volume labels and deleted ones skipped).
    Result read_dir(Dir& d, Entry& out);

private:
    Result sector(uint32_t lba); // into buf_ (kept: the last one read)
    Result next_cluster(uint32_t cluster, uint32_t& next);
    // The cluster holding byte `offset` of f (walking its chain from f's last place or its start).
    Result cluster_at(File& f, uint32_t index, uint32_t& cluster);
    uint32_t cluster_lba(uint32_t cluster) const { return data_lba_ + (cluster - 2) * sectors_per_cluster_; }
    bool valid_cluster(uint32_t c) const { return c >= 2 && c < clusters_ + 2; }
    // Entry `index` of a folder, its sector read (the entry at buf_ + *at); NotFound past its end.
    Result dir_entry(Dir& d, uint32_t index, uint32_t& at);

    Card* card_ = nullptr;
    Kind kind_ = Kind::None;
    uint32_t part_lba_ = 0, fat_lba_ = 0, fat_sectors_ = 0, root_lba_ = 0, root_entries_ = 0, data_lba_ = 0;
    uint32_t sectors_per_cluster_ = 0, clusters_ = 0, root_cluster_ = 0;
    uint32_t buf_lba_ = 0xFFFFFFFFu;
    alignas(4) uint8_t buf_[Card::kSectorBytes] = {};
};

} // namespace facet::hal::fat
