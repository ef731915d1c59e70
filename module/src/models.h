#pragma once
// Several models on the device, as the chooser lists them: a library's (Viewer::set_library: its
// table read in place) or a storage folder's pack files (Viewer::set_storage: listed once, each
// with its size and face count). Its own state: the memory the models are loaded into, the one
// open and the one the chooser asked for; the Core opens them (library.cpp, storage.cpp) and the
// overlay lists them.
#include "facet/storage.h"
#include "facet/types.h"
#include "geom/library.h"

#include <cstdint>

namespace facet::module {

class Models {
public:
    static constexpr uint32_t kMaxListed = 48;  // a storage folder's pack files listed (the rest counted: unlisted())
    static constexpr uint32_t kFolderBytes = 96; // the folder's path

    // A storage folder's pack file, or a model of a library file in it, as listed.
    struct Listed {
        char name[kStorageNameBytes];          // the file's
        char model[pack::kLibraryNameBytes];   // a library's model's name ("" for a file of its own)
        uint32_t offset, bytes;                // the model file within the file (0, the file's size)
        uint32_t faces;                        // kNone: its head does not say (it says why when opened)
        bool library;                          // a library's model (offset, bytes), or a library
        bool unreadable;                       // whose table does not read (said when opened)
    };

    // The library's table (checked); its models are loaded into `memory` (or, given none, the
    // workspace's end). A model open now is none of this library's.
    Result set(const void* data, uint32_t bytes, void* memory, uint32_t memory_bytes) {
        geom::Library lib;
        if (const Result r = lib.open(data, bytes); !r.ok()) return r;
        clear();
        library_ = lib;
        memory_ = memory, memory_bytes_ = memory_bytes;
        return {};
    }
    // A storage folder's files, listed from here on (add() each; the folder's path kept:
    // "/" the root, a leading '/' added when it has none).
    Result set_folder(const char* folder, void* memory, uint32_t memory_bytes);
    // A file of the folder listed (false past kMaxListed: counted in unlisted()).
    bool add(const Listed& file);
    void clear() {
        library_ = {}, listed_ = unlisted_ = 0, folder_[0] = 0, open_ = asked_ = kNone;
    }

    bool on_storage() const { return folder_[0] != 0; }
    const char* folder() const { return folder_; }
    void set_faces(uint32_t index, uint32_t faces) { files_[index].faces = faces; }
    // The storage went away: nothing listed (the folder kept, for when it is back).
    void emptied() { listed_ = unlisted_ = 0, open_ = asked_ = kNone; }
    uint32_t count() const { return on_storage() ? listed_ : library_.count(); }
    uint32_t unlisted() const { return unlisted_; }
    const char* name(uint32_t index) const { return on_storage() ? files_[index].name : library_.entry(index).name; }
    const Listed& listed(uint32_t index) const { return files_[index]; } // on_storage()
    geom::Library::Entry entry(uint32_t index) const { return library_.entry(index); } // a library's
    // A listed file's path on the storage: the folder's, '/', its name (false: it does not fit).
    bool path(uint32_t index, char* out, uint32_t bytes) const { return folder_path(files_[index].name, out, bytes); }
    bool folder_path(const char* name, char* out, uint32_t bytes) const;
    void* memory() const { return memory_; }
    uint32_t memory_bytes() const { return memory_bytes_; }

    uint32_t open() const { return open_; } // the model open (kNone: none)
    void opened(uint32_t index) { open_ = index; }
    // A model loaded from outside the list (load()): none of it is open, none asked for.
    void forget() { open_ = asked_ = kNone; }
    // The chooser asked for a model (opened at the next step, outside the input's handling).
    void ask(uint32_t index) {
        if (index != open_) asked_ = index;
    }
    // The model asked for, once (kNone: none).
    uint32_t take_asked() {
        const uint32_t m = asked_;
        asked_ = kNone;
        return m;
    }

private:
    geom::Library library_;
    char folder_[kFolderBytes] = {};
    Listed files_[kMaxListed] = {};
    uint32_t listed_ = 0, unlisted_ = 0;
    void* memory_ = nullptr;
    uint32_t memory_bytes_ = 0;
    uint32_t open_ = kNone, asked_ = kNone;
};

} // namespace facet::module
