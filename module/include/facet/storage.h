#pragma once
// facet: packs read from the product's own storage (a memory card, USB mass storage, SPI flash,
// a file of an RTOS filesystem) through callbacks, shaped as LVGL's lv_fs_drv_t and FatFs are:
// open a file by its path, read bytes at an offset, close it; open a folder, read its entries,
// close it. A product that registered an lv_fs_drv_t hands facet the same driver in a few lines
// (docs/module.md, "Your own storage").
//
// Reads may end at once (return Ok) or later (return Busy, then call Viewer::read_done() once,
// from any context: a DMA or card interrupt). The module reads a blocked pack's index first and
// then each block when the view needs it, into its own pack memory, one block at a time: it never
// holds the whole file. A read that fails (a card pulled: Io) leaves its block out (its parts
// drawn as their proxies, or boxes) until the storage is back (Viewer::storage_changed()).
#include "core/status.h"

#include <cstdint>

namespace facet {

// An entry of a folder: its name (UTF-8, 0-terminated), its size, and whether it is a folder.
constexpr uint32_t kStorageNameBytes = 96;
struct StorageEntry {
    char name[kStorageNameBytes];
    uint32_t bytes;
    bool folder;
};

struct Storage {
    void* user = nullptr; // handed to every callback (the product's driver or filesystem)
    // The file at `path` (UTF-8, '/' between folders, from the storage's root) opened: its
    // handle in *file and its size in *bytes. NotFound: no such file.
    Result (*open)(void* user, const char* path, void** file, uint32_t* bytes) = nullptr;
    // `bytes` bytes at `offset` of the file into `into` (4-byte aligned). Ok: they are there.
    // Busy: the read goes on; Viewer::read_done() says when it ends. Anything else: it failed.
    Result (*read)(void* user, void* file, uint32_t offset, void* into, uint32_t bytes) = nullptr;
    void (*close)(void* user, void* file) = nullptr;
    // A folder's entries, for the chooser (optional: without them only open_file() opens models).
    Result (*dir_open)(void* user, const char* path, void** dir) = nullptr;
    // The next entry into *entry; NotFound after the last.
    Result (*dir_read)(void* user, void* dir, StorageEntry* entry) = nullptr;
    void (*dir_close)(void* user, void* dir) = nullptr;
};

} // namespace facet
