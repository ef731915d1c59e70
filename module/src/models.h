#pragma once
// Several models on the device (Viewer::set_library): the library's table read in place, the
// memory its models are loaded into, the one open and the one the chooser asked for. Its own
// state; the Core loads the models (library.cpp) and the overlay lists them.
#include "facet/types.h"
#include "geom/library.h"

#include <cstdint>

namespace facet::module {

class Models {
public:
    // The library's table (checked); its models are loaded into `memory` (or, given none, the
    // workspace's end). A model open now is none of this library's.
    Result set(const void* data, uint32_t bytes, void* memory, uint32_t memory_bytes) {
        geom::Library lib;
        if (const Result r = lib.open(data, bytes); !r.ok()) return r;
        library_ = lib;
        memory_ = memory, memory_bytes_ = memory_bytes;
        open_ = kNone;
        return {};
    }
    const geom::Library& library() const { return library_; }
    uint32_t count() const { return library_.count(); }
    geom::Library::Entry entry(uint32_t index) const { return library_.entry(index); }
    void* memory() const { return memory_; }
    uint32_t memory_bytes() const { return memory_bytes_; }

    uint32_t open() const { return open_; } // the library's model open (kNone: none)
    void opened(uint32_t index) { open_ = index; }
    // A model loaded from outside the library (load()): none of it is open, none asked for.
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
    void* memory_ = nullptr;
    uint32_t memory_bytes_ = 0;
    uint32_t open_ = kNone, asked_ = kNone;
};

} // namespace facet::module
