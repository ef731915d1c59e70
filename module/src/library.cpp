// Several models on the device: a library read in place, one of its models open at a time in
// the memory load() uses, and the chooser of facet's interface (Action::Models).
#include "core.h"

namespace facet {

uint32_t library_count(const void* data, uint32_t bytes) {
    geom::Library lib;
    return lib.open(data, bytes).ok() ? lib.count() : 0;
}

Result library_model(const void* data, uint32_t bytes, uint32_t index, LibraryModel& out) {
    out = {nullptr, 0, ""};
    geom::Library lib;
    if (const Result r = lib.open(data, bytes); !r.ok()) return module::public_result(r);
    if (index >= lib.count()) return Result::fail(Status::OutOfRange, "no such model in the library", {"model", index});
    const geom::Library::Entry e = lib.entry(index);
    out = {e.file, e.bytes, e.name};
    return {};
}

Result Core::set_library(const void* data, uint32_t bytes, void* memory, uint32_t memory_bytes) {
    if (const Result r = models_.set(data, bytes, memory, memory_bytes); !r.ok()) return r;
    presenter_.overlay().set_library(&models_);
    return {};
}

// Model `index` of the list loaded: a library's in place, a storage folder's through it.
Result Core::load_listed(uint32_t index) {
    if (!models_.on_storage()) {
        const geom::Library::Entry e = models_.entry(index);
        return load(e.file, e.bytes, models_.memory(), models_.memory_bytes());
    }
    char path[sizeof open_path_];
    if (!models_.path(index, path, sizeof path)) return Result::fail(Status::OutOfRange, "the file's path is too long", {"model", index});
    const module::Models::Listed& l = models_.listed(index);
    if (l.unreadable) return Result::fail(Status::Corrupt, "a library whose table does not read (its CRC or an entry)", {"model", index});
    return l.library ? open_file(path, models_.memory(), models_.memory_bytes(), l.offset, l.bytes)
                     : open_file(path, models_.memory(), models_.memory_bytes());
}

Result Core::open_model(uint32_t index) {
    if (models_.count() == 0) return Result::fail(Status::NotFound, "no library or storage folder with models is set");
    if (index >= models_.count()) return Result::fail(Status::OutOfRange, "no such model in the list", {"model", index});
    const uint32_t before = models_.open();
    const Result r = load_listed(index);
    if (r.ok()) {
        models_.opened(index);
        presenter_.overlay().set_models(false, index);
        return r;
    }
    Event failed{};
    failed.kind = Event::Kind::ModelFailed;
    failed.model.index = index;
    failed.why = r;
    emit(failed);
    presenter_.overlay().mark_broken(index); // (the person holding it sees it in the chooser)
    // The model open before comes back (its file is intact; load() dropped it).
    if (before != kNone && before != index && load_listed(before).ok()) models_.opened(before);
    presenter_.overlay().set_models(true, models_.open()); // (the chooser stays for another)
    presenter_.invalidate();
    return r;
}

// A tap on the chooser: a row opens its model at the next step, the header's buttons scroll
// (true: the tap was the chooser's).
bool Core::tap_models(int16_t x, int16_t y) {
    using Kind = module::Overlay::PartsHit::Kind;
    module::Overlay& o = presenter_.overlay();
    const module::Overlay::PartsHit h = o.models_at(x, y);
    switch (h.kind) {
    case Kind::None: return false;
    case Kind::Row:
        models_.ask(h.part);
        return true;
    case Kind::Up: o.scroll_models(-int32_t(o.model_rows()) + 1); break;
    case Kind::Down: o.scroll_models(int32_t(o.model_rows()) - 1); break;
    default: return true;
    }
    presenter_.redraw(); // (the chooser alone)
    return true;
}

void Core::toggle_models() {
    module::Overlay& o = presenter_.overlay();
    o.set_models(!o.models_open(), models_.open());
    presenter_.redraw(); // (the chooser alone)
}

void Viewer::unload() { static_cast<Core*>(this)->unload(); }
Result Viewer::set_library(const void* library, uint32_t bytes, void* memory, uint32_t memory_bytes) {
    return module::public_result(static_cast<Core*>(this)->set_library(library, bytes, memory, memory_bytes));
}
Result Viewer::open_model(uint32_t index) { return module::public_result(static_cast<Core*>(this)->open_model(index)); }
uint32_t Viewer::model_index() const { return static_cast<const Core*>(this)->model_index(); }

} // namespace facet
