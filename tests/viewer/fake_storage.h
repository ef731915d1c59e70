#pragma once
// A product's storage for the tests (facet/storage.h): files by path in a folder tree, read at
// once or later (deferred: a read returns Busy and ends `delay` clock ticks on, as a DMA
// transfer's interrupt would call read_done()), and pulled out like a card mid-read.
#include "facet/viewer.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace facet::test {

struct FakeStorage {
    std::map<std::string, std::vector<uint8_t>> files; // "/folder/name.fpk" -> bytes
    bool deferred = false;  // reads end later (tick())
    uint32_t delay = 3;     // ticks a deferred read takes
    bool present = true;    // the card is in
    Viewer* viewer = nullptr; // told read_done() (deferred)
    // What was read: the largest single read, and every byte read.
    uint64_t largest_read = 0, bytes_read = 0;
    uint32_t reads = 0, open_files = 0;
    int pull_after_reads = -1; // the card is pulled as this read begins (deferred: it never ends)

    struct Pending {
        const std::vector<uint8_t>* file = nullptr;
        uint32_t offset = 0, bytes = 0, left = 0;
        void* into = nullptr;
    } pending;

    Storage storage() {
        Storage s;
        s.user = this;
        s.open = [](void* u, const char* path, void** file, uint32_t* bytes) -> Result {
            auto& self = *static_cast<FakeStorage*>(u);
            if (!self.present) return Result::fail(Status::Io, "no card");
            auto it = self.files.find(path);
            if (it == self.files.end()) return Result::fail(Status::NotFound, "no such file");
            *file = &it->second, *bytes = uint32_t(it->second.size());
            ++self.open_files;
            return {};
        };
        s.read = [](void* u, void* file, uint32_t offset, void* into, uint32_t bytes) -> Result {
            auto& self = *static_cast<FakeStorage*>(u);
            const auto* f = static_cast<const std::vector<uint8_t>*>(file);
            ++self.reads;
            if (self.pull_after_reads == 0) self.present = false;
            if (self.pull_after_reads >= 0) --self.pull_after_reads;
            if (!self.present && !self.deferred) return Result::fail(Status::Io, "no card");
            if (uint64_t(offset) + bytes > f->size()) return Result::fail(Status::OutOfRange, "past the end");
            self.largest_read = std::max<uint64_t>(self.largest_read, bytes);
            self.bytes_read += bytes;
            if (!self.deferred) {
                std::memcpy(into, f->data() + offset, bytes);
                return {};
            }
            self.pending = {f, offset, bytes, self.delay, into};
            return Result::fail(Status::Busy, "reading");
        };
        s.close = [](void* u, void*) { --static_cast<FakeStorage*>(u)->open_files; };
        s.dir_open = [](void* u, const char* path, void** dir) -> Result {
            auto& self = *static_cast<FakeStorage*>(u);
            if (!self.present) return Result::fail(Status::Io, "no card");
            std::string folder = path;
            if (folder.empty() || folder.back() != '/') folder += '/';
            bool any = folder == "/";
            for (const auto& [name, bytes] : self.files) any = any || name.rfind(folder, 0) == 0;
            if (!any) return Result::fail(Status::NotFound, "no such folder");
            self.listing = {};
            for (const auto& [name, bytes] : self.files) {
                if (name.rfind(folder, 0) != 0) continue;
                const std::string rest = name.substr(folder.size());
                const size_t slash = rest.find('/');
                StorageEntry e{};
                std::snprintf(e.name, sizeof e.name, "%s", rest.substr(0, slash).c_str());
                e.folder = slash != std::string::npos;
                e.bytes = e.folder ? 0 : uint32_t(bytes.size());
                self.listing.push_back(e);
            }
            *dir = &self.listing;
            return {};
        };
        s.dir_read = [](void* u, void*, StorageEntry* e) -> Result {
            auto& self = *static_cast<FakeStorage*>(u);
            if (self.listed >= self.listing.size()) return Result::fail(Status::NotFound, "the end");
            *e = self.listing[self.listed++];
            return {};
        };
        s.dir_close = [](void* u, void*) { static_cast<FakeStorage*>(u)->listed = 0; };
        return s;
    }

    // Time passes (a clock read): a deferred read under way ends when its ticks are up.
    void tick() {
        if (!pending.file || --pending.left > 0) return;
        const Pending p = pending;
        pending = {};
        if (!present) return; // (pulled: it never ends; the module gives it up)
        std::memcpy(p.into, p.file->data() + p.offset, p.bytes);
        viewer->read_done(Status::Ok);
    }

    std::vector<StorageEntry> listing;
    size_t listed = 0;
};

} // namespace facet::test
