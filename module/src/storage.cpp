// Models on the product's storage (facet/storage.h): a folder's pack files listed for the chooser
// (each one's size, and its face count from its head or index), one opened at a time through the
// Reader: a blocked pack's index read into the pack memory and its blocks as the view needs them
// (loader.h), another pack read whole into the pack memory and decoded there as a file the board
// loaded into it. A card pulled and put back (storage_changed()).
#include "core.h"

#include <algorithm>
#include <cstring>

namespace facet {
namespace {

constexpr Place kStorage{"storage"};

char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

// A pack file's name: *.fpk, or *.flb (a library), in any case (FAT's short names are upper case).
bool pack_name(const char* name, bool& library) {
    const size_t n = std::strlen(name);
    if (n < 5 || name[n - 4] != '.') return false;
    const char ext[3] = {lower(name[n - 3]), lower(name[n - 2]), lower(name[n - 1])};
    library = ext[0] == 'f' && ext[1] == 'l' && ext[2] == 'b';
    return library || (ext[0] == 'f' && ext[1] == 'p' && ext[2] == 'k');
}

// The faces a pack file on storage holds, from its first bytes (a blocked pack: its Parts
// records, read a few at a time); kNone when they do not say. Not validated: opening it does.
uint32_t listed_faces(module::Reader& r) {
    alignas(8) uint8_t head[1024];
    const uint32_t n = std::min<uint32_t>(sizeof head, r.bytes());
    if (!r.read(0, head, n).ok()) return kNone;
    switch (geom::pack_file_kind(head, n)) {
    case geom::PackFileKind::Unknown: return kNone;
    case geom::PackFileKind::Blocked: {
        pack::IndexHeader h;
        std::memcpy(&h, head, sizeof h);
        if (h.section_count > pack::kMaxSections || sizeof h + h.section_count * sizeof(pack::SectionEntry) > n) return kNone;
        for (uint32_t i = 0; i < h.section_count; ++i) {
            pack::SectionEntry s;
            std::memcpy(&s, head + sizeof h + i * sizeof s, sizeof s);
            if (s.id != uint32_t(pack::IndexSectionId::Parts) || s.record_bytes != sizeof(pack::Part)) continue;
            uint64_t faces = 0;
            constexpr uint32_t kChunk = sizeof head / sizeof(pack::Part);
            for (uint32_t p = 0; p < s.count; p += kChunk) {
                const uint32_t k = std::min(kChunk, s.count - p);
                if (!r.read(s.offset + p * uint32_t(sizeof(pack::Part)), head, k * uint32_t(sizeof(pack::Part))).ok()) return kNone;
                for (uint32_t j = 0; j < k; ++j) {
                    pack::Part part;
                    std::memcpy(&part, head + j * sizeof part, sizeof part);
                    faces += part.face_count;
                }
            }
            return faces < kNone ? uint32_t(faces) : kNone;
        }
        return kNone;
    }
    default: {
        geom::LzmaProbs probs; // (about 14 KB of stack, for an LZMA pack's head)
        geom::PackCounts counts;
        return geom::stored_pack_counts(head, n, counts, probs, true).ok() ? counts.faces : kNone;
    }
    }
}

// A library's models listed, each a row of its own (name, size, faces), after its table was read
// and checked (CRC, each entry inside the file); false when it does not read (the file is then
// one row that says so when opened).
bool list_library(module::Reader& r, module::Models::Listed row, module::Models& models) {
    pack::LibraryHeader h;
    alignas(8) uint8_t buf[16 * sizeof(pack::LibraryEntry)];
    if (r.bytes() < sizeof h || !r.read(0, &h, sizeof h).ok() || !geom::check_library_head(h, r.bytes()).ok()) return false;
    const uint32_t table_end = geom::library_table_end(h);
    uint32_t crc = 0; // (the table read twice: checked whole first, then listed)
    for (uint32_t at = sizeof h; at < table_end; at += sizeof buf) {
        const uint32_t n = std::min<uint32_t>(sizeof buf, table_end - at);
        if (!r.read(at, buf, n).ok()) return false;
        crc = pack::crc32(buf, n, crc);
    }
    if (crc != h.crc32) return false;
    for (uint32_t i = 0; i < h.count; ++i) {
        pack::LibraryEntry e;
        if (!r.read(uint32_t(sizeof h + i * sizeof e), &e, sizeof e).ok() || !geom::library_entry_sound(e, h)) return false;
    }
    for (uint32_t i = 0; i < h.count; ++i) {
        pack::LibraryEntry e;
        if (!r.window(0, r.size()) || !r.read(uint32_t(sizeof h + i * sizeof e), &e, sizeof e).ok()) return false;
        module::Models::Listed l = row;
        std::memcpy(l.model, e.name, sizeof l.model);
        l.offset = e.offset, l.bytes = e.bytes, l.faces = kNone, l.library = true, l.unreadable = false;
        if (r.window(e.offset, e.bytes)) l.faces = listed_faces(r);
        if (!models.add(l)) break; // (counted: unlisted())
    }
    return true;
}

} // namespace

namespace module {

Result Models::set_folder(const char* folder, void* memory, uint32_t memory_bytes) {
    const size_t n = folder ? std::strlen(folder) : 0;
    if (n + 2 > kFolderBytes) return Result::fail(Status::OutOfRange, "the folder's path is longer than 94 bytes", kStorage);
    clear();
    folder_[0] = '/'; // (the root: "/"; a folder without its leading '/' is from the root too)
    std::memcpy(folder_ + (n && folder[0] == '/' ? 0 : 1), folder, n + 1);
    memory_ = memory, memory_bytes_ = memory_bytes;
    return {};
}

bool Models::add(const Listed& file) {
    if (listed_ == kMaxListed) {
        ++unlisted_;
        return false;
    }
    files_[listed_++] = file;
    return true;
}

bool Models::folder_path(const char* name, char* out, uint32_t bytes) const {
    const size_t f = std::strlen(folder_), n = std::strlen(name);
    const bool slash = f > 0 && folder_[f - 1] != '/';
    if (f + slash + n + 1 > bytes) return false;
    std::memcpy(out, folder_, f);
    if (slash) out[f] = '/';
    std::memcpy(out + f + slash, name, n + 1);
    return true;
}

} // namespace module

Result Core::set_storage(const Storage& storage, const char* folder, void* memory, uint32_t memory_bytes) {
    if (!storage.open || !storage.read || !storage.close) {
        return Result::fail(Status::OutOfRange, "the storage has no open, read or close callback", kStorage);
    }
    if (Result r = models_.set_folder(folder, memory, memory_bytes); !r.ok()) return r;
    if (reader_.is_open() && std::memcmp(&storage, &storage_, sizeof storage) != 0) reader_.lost(); // (another storage: its files are not this one's)
    storage_ = storage;
    has_storage_ = storage_present_ = true;
    presenter_.overlay().set_library(&models_);
    return list_storage();
}

// The folder's pack files, in the order the storage gives them (a read under way for the open
// model is let end first: one read at a time).
Result Core::list_storage() {
    presenter_.overlay().set_library(&models_); // (marks cleared)
    presenter_.overlay().set_storage_gone(false);
    presenter_.invalidate();
    if (!storage_.dir_open || !storage_.dir_read || !storage_.dir_close) return {};
    // (the open model's transfer under way ended first: the storage does one at a time)
    for (uint32_t polls = 0; !reader_.idle(); ++polls) {
        if (polls > module::Reader::kWaitPolls) return Result::fail(Status::Io, "the storage did not end a read", kStorage);
    }
    char folder[module::Models::kFolderBytes];
    std::memcpy(folder, models_.folder(), sizeof folder);
    void* dir = nullptr;
    if (Result r = storage_.dir_open(storage_.user, folder, &dir); !r.ok()) return r;
    StorageEntry e;
    module::Reader file;
    lister_ = &file;
    char path[sizeof open_path_];
    for (;;) {
        const Result r = storage_.dir_read(storage_.user, dir, &e);
        if (r.status == Status::NotFound) break;
        if (!r.ok()) {
            lister_ = nullptr;
            storage_.dir_close(storage_.user, dir);
            return r;
        }
        e.name[kStorageNameBytes - 1] = 0;
        module::Models::Listed l{};
        bool library = false;
        if (e.folder || !pack_name(e.name, library)) continue;
        std::memcpy(l.name, e.name, sizeof l.name);
        l.bytes = e.bytes, l.faces = kNone, l.library = library;
        const bool opened = models_.folder_path(l.name, path, sizeof path) && file.open(storage_, path, clock()).ok();
        if (library && opened && list_library(file, l, models_)) {
            file.close();
            continue;
        }
        if (opened && !library) l.faces = listed_faces(file);
        if (opened) file.close();
        l.unreadable = library; // (a library whose table does not read: a row that says so when opened)
        models_.add(l);
    }
    lister_ = nullptr;
    storage_.dir_close(storage_.user, dir);
    for (uint32_t i = 0; open_path_[0] && i < models_.count(); ++i) { // (the model open, listed again)
        if (models_.path(i, path, sizeof path) && std::strcmp(path, open_path_) == 0 && models_.listed(i).offset == open_offset_) {
            models_.opened(i);
        }
    }
    return {};
}

Result Core::open_file(const char* path, void* memory, uint32_t memory_bytes, uint32_t offset, uint32_t length) {
    unload();
    if (!has_storage_) return Result::fail(Status::NotFound, "no storage is set (set_storage())", kStorage);
    if (!storage_present_) return Result::fail(Status::Io, "the storage is gone (storage_changed(false))", kStorage);
    if (!path || std::strlen(path) + 1 > sizeof open_path_) return Result::fail(Status::OutOfRange, "no path, or one longer than 190 bytes", kStorage);
    if (Result r = reader_.open(storage_, path, clock()); !r.ok()) return r;
    const bool in_library = length != kWhole;
    if (in_library && !reader_.window(offset, length)) {
        return Result::fail(Status::Corrupt, "the library's model lies past the end of its file", kStorage);
    }
    alignas(8) uint8_t head[sizeof(pack::IndexHeader)];
    const uint32_t file_bytes = reader_.bytes(), head_bytes = std::min<uint32_t>(sizeof head, file_bytes);
    if (Result r = reader_.read(0, head, head_bytes); !r.ok()) return r;
    if (geom::is_library(head, head_bytes)) { // (its models are the list's rows: set_storage(), open_model())
        return Result::fail(Status::Unsupported, "a library of several models: set_storage() lists them, open_model() opens one", kStorage);
    }
    const geom::PackFileKind kind = geom::pack_file_kind(head, head_bytes);
    if (kind == geom::PackFileKind::Unknown) return Result::fail(Status::Corrupt, "no pack here (neither FPK1, FPX1, FPZ1 nor FPB1)", {"pack file"});
    // What is read into memory: a blocked pack's index, another pack whole.
    uint32_t bytes = file_bytes;
    pack::IndexHeader h{};
    if (kind == geom::PackFileKind::Blocked) {
        std::memcpy(&h, head, sizeof h);
        if (head_bytes < sizeof h || h.index_bytes < sizeof h || h.index_bytes > file_bytes) {
            return Result::fail(Status::Corrupt, "the index's size is out of range (or the file truncated)", {"index header"});
        }
        bytes = h.index_bytes;
    }
    // At the end of the pack memory (the workspace's, given none), where load() decodes a file
    // lying in it.
    uint8_t* const lo = memory ? static_cast<uint8_t*>(memory) : model_start_;
    uint8_t* const hi = memory ? lo + memory_bytes : end_;
    const uintptr_t at = (reinterpret_cast<uintptr_t>(hi) - bytes) & ~uintptr_t(7);
    if (bytes > uintptr_t(hi - lo) || at < reinterpret_cast<uintptr_t>(lo)) {
        return Result::fail(Status::Full, "the pack memory cannot hold the file (or its index)", {"bytes needed", bytes});
    }
    auto* in = reinterpret_cast<uint8_t*>(at);
    if (kind != geom::PackFileKind::Blocked) work(Event::Kind::WorkBegin, Work::Unpack, 0);
    const Result read = reader_.read(0, in, bytes);
    if (kind != geom::PackFileKind::Blocked) work(Event::Kind::WorkEnd, Work::Unpack, 0);
    if (!read.ok()) return read;
    Result r;
    if (kind == geom::PackFileKind::Blocked) {
        r = open_pack(in, bytes, memory, memory_bytes, &reader_);
    } else {
        reader_.close(); // (read whole)
        r = open_pack(in, bytes, memory, memory_bytes, nullptr);
        pack_file_bytes_ = r.ok() ? file_bytes : 0;
    }
    if (!r.ok()) {
        unload();
        return r;
    }
    std::memcpy(open_path_, path, std::strlen(path) + 1);
    open_offset_ = offset, open_length_ = length;
    open_crc_ = kind == geom::PackFileKind::Blocked ? h.crc32 | 1u : 0; // (never 0 for a blocked pack)
    return {};
}

// The storage went away: the open model stays as it is (what is not read stays boxes), the
// chooser lists nothing. Back: the folder listed again, and the open model's file opened again
// when it is the same file (its index's CRC and size), its left-out blocks looked at again.
Result Core::storage_changed(bool present) {
    if (!has_storage_) return Result::fail(Status::NotFound, "no storage is set (set_storage())", kStorage);
    storage_present_ = present;
    if (!present) {
        reader_.lost();
        models_.emptied();
        presenter_.overlay().set_library(&models_);
        presenter_.overlay().set_storage_gone(true);
        presenter_.invalidate();
        return {};
    }
    Result listed = list_storage();
    if (open_crc_ && !reader_.is_open() && scene_.loaded()) { // (a blocked pack's: the others are read whole)
        if (Result r = reopen_storage_file(); !r.ok() && listed.ok()) listed = r;
    }
    return listed;
}

Result Core::reopen_storage_file() {
    module::Reader again;
    if (Result r = again.open(storage_, open_path_, clock()); !r.ok()) return r;
    if (open_length_ != kWhole && !again.window(open_offset_, open_length_)) return Result::fail(Status::NotFound, "the open model's file changed", kStorage);
    alignas(8) uint8_t head[sizeof(pack::IndexHeader)];
    pack::IndexHeader h;
    lister_ = &again; // (its read_done())
    const Result read = again.bytes() < sizeof h ? Result::fail(Status::Corrupt, "shorter than an index's header") : again.read(0, head, sizeof h);
    lister_ = nullptr;
    again.close();
    if (!read.ok()) return Result::fail(Status::Io, "the open model's file cannot be read again", kStorage);
    std::memcpy(&h, head, sizeof h);
    if ((h.crc32 | 1u) != open_crc_ || h.total_bytes != pack_file_bytes_) {
        return Result::fail(Status::NotFound, "the storage put back holds another file where the open model's was (its blocks stay boxes)", kStorage);
    }
    if (Result r = reader_.open(storage_, open_path_, clock()); !r.ok()) return r;
    if (open_length_ != kWhole) (void)reader_.window(open_offset_, open_length_);
    swapper_.storage_back();
    return {};
}

Result Viewer::set_storage(const Storage& storage, const char* folder, void* memory, uint32_t memory_bytes) {
    return module::public_result(static_cast<Core*>(this)->set_storage(storage, folder, memory, memory_bytes));
}
Result Viewer::open_file(const char* path) {
    Core& c = *static_cast<Core*>(this);
    return module::public_result(c.open_file(path, c.models().memory(), c.models().memory_bytes()));
}
uint32_t Viewer::model_count() const { return static_cast<const Core*>(this)->models().count(); }
Result Viewer::listed_model(uint32_t index, ListedModel& out) const {
    const module::Models& m = static_cast<const Core*>(this)->models();
    out = {"", 0, kNone};
    if (index >= m.count()) return Result::fail(Status::OutOfRange, "no such model in the list", {"model", index});
    if (m.on_storage()) { // (a library's model: its own name)
        const module::Models::Listed& l = m.listed(index);
        out = {l.library && !l.unreadable && l.model[0] ? l.model : l.name, l.bytes, l.faces};
    } else {
        out = {m.entry(index).name, m.entry(index).bytes, kNone};
    }
    return {};
}
void Viewer::read_done(Status status) { static_cast<Core*>(this)->read_done(status); }
Result Viewer::storage_changed(bool present) { return module::public_result(static_cast<Core*>(this)->storage_changed(present)); }

} // namespace facet
