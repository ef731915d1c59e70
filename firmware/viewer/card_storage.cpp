// The memory card as the module's storage (card_storage.h).
#include "card_storage.h"

#include <cstring>

namespace facet::firmware {
namespace {
constexpr Place kCard{"card"};
} // namespace

Result CardStorage::mount(hal::Card& card) {
    card_ = &card;
    present_ = card.present();
    for (bool& o : open_) o = false;
    dir_open_ = false;
    volume_.unmount();
    if (!present_) return Result::fail(Status::Io, "no card in the slot", kCard);
    if (Result r = card.start(); !r.ok()) return r;
    return volume_.mount(card);
}

Storage CardStorage::storage() {
    Storage s;
    s.user = this;
    s.open = [](void* user, const char* path, void** file, uint32_t* bytes) -> Result {
        auto& self = *static_cast<CardStorage*>(user);
        for (uint32_t i = 0; i < kFiles; ++i) {
            if (self.open_[i]) continue;
            if (Result r = self.volume_.open(path, self.files_[i]); !r.ok()) return r;
            if (self.files_[i].folder) return Result::fail(Status::NotFound, "a folder, not a file", kCard);
            self.open_[i] = true;
            *file = &self.files_[i], *bytes = self.files_[i].bytes;
            return {};
        }
        return Result::fail(Status::Full, "four files are open on the card already", kCard);
    };
    s.read = [](void* user, void* file, uint32_t offset, void* into, uint32_t bytes) -> Result {
        auto& self = *static_cast<CardStorage*>(user);
        return self.volume_.read(*static_cast<hal::fat::File*>(file), offset, into, bytes);
    };
    s.close = [](void* user, void* file) {
        auto& self = *static_cast<CardStorage*>(user);
        self.open_[static_cast<hal::fat::File*>(file) - self.files_] = false;
    };
    s.dir_open = [](void* user, const char* path, void** dir) -> Result {
        auto& self = *static_cast<CardStorage*>(user);
        if (self.dir_open_) return Result::fail(Status::Full, "a folder is being listed already", kCard);
        if (Result r = self.volume_.open_dir(path, self.dir_); !r.ok()) return r;
        self.dir_open_ = true;
        *dir = &self.dir_;
        return {};
    };
    s.dir_read = [](void* user, void*, StorageEntry* out) -> Result {
        auto& self = *static_cast<CardStorage*>(user);
        for (;;) {
            if (Result r = self.volume_.read_dir(self.dir_, self.entry_); !r.ok()) return r;
            const size_t n = std::strlen(self.entry_.name);
            if (n >= sizeof out->name) continue; // (a name longer than the module's paths take: not listed)
            std::memcpy(out->name, self.entry_.name, n + 1);
            out->bytes = self.entry_.bytes, out->folder = self.entry_.folder;
            return {};
        }
    };
    s.dir_close = [](void* user, void*) { static_cast<CardStorage*>(user)->dir_open_ = false; };
    return s;
}

bool CardStorage::poll(Viewer& viewer, Result& why) {
    why = {};
    if (!card_ || card_->present() == present_) return false;
    present_ = !present_;
    if (!present_) {
        volume_.unmount();
        for (bool& o : open_) o = false; // (their handles are gone with the card)
        dir_open_ = false;
        why = viewer.storage_changed(false);
        return true;
    }
    if (Result r = mount(*card_); !r.ok()) {
        why = r;
        return true;
    }
    why = viewer.storage_changed(true);
    return true;
}

} // namespace facet::firmware
