// A pack file on the product's storage, read one read at a time (reader.h).
#include "reader.h"

namespace facet::module {
namespace {
constexpr Place kStorage{"storage"};
} // namespace

Result Reader::open(const Storage& storage, const char* path, const Clock& clock) {
    close();
    if (!storage.open || !storage.read || !storage.close) {
        return Result::fail(Status::OutOfRange, "the storage has no open, read or close callback", kStorage);
    }
    if (!path || !*path) return Result::fail(Status::OutOfRange, "no file's path", kStorage);
    void* file = nullptr;
    uint32_t bytes = 0;
    if (Result r = storage.open(storage.user, path, &file, &bytes); !r.ok()) {
        return r.status == Status::Busy ? Result::fail(Status::Io, "the storage's open() said Busy (open is synchronous)", kStorage) : r;
    }
    storage_ = storage, clock_ = clock, file_ = file, opened_ = true, bytes_ = size_ = bytes, base_ = 0;
    return {};
}

bool Reader::window(uint32_t offset, uint32_t length) {
    if (offset > size_ || length > size_ - offset) return false;
    base_ = offset, bytes_ = length;
    return true;
}

void Reader::close() {
    if (opened_ && !pending_) storage_.close(storage_.user, file_);
    file_ = nullptr, opened_ = false, bytes_ = size_ = base_ = 0, pending_ = false, left_ = 0;
}

void Reader::lost() {
    file_ = nullptr, opened_ = false, bytes_ = 0;
    if (pending_) done(Status::Io);
}

Result Reader::start(uint32_t offset, void* into, uint32_t bytes) {
    if (!opened_) return Result::fail(Status::Io, "the file is gone (the storage was removed)", kStorage);
    if (reading()) return Result::fail(Status::Busy, "a read is under way", kStorage);
    if (uint64_t(offset) + bytes > bytes_) return Result::fail(Status::Corrupt, "the pack reads past the end of its file (truncated)", kStorage);
    at_ = offset, left_ = bytes, into_ = static_cast<uint8_t*>(into);
    return left_ ? transfer() : Result{};
}

Result Reader::transfer() {
    if (!opened_) {
        left_ = 0;
        return Result::fail(Status::Io, "the file is gone (the storage was removed)", kStorage);
    }
    asked_ = left_ < kChunkBytes ? left_ : kChunkBytes;
    done_.store(0, kDoneStore);
    started_us_ = now(), polls_ = 0;
    const Result r = storage_.read(storage_.user, file_, base_ + at_, into_, asked_);
    if (r.status == Status::Busy) {
        pending_ = true;
        return r;
    }
    if (!r.ok()) {
        left_ = 0;
        return r;
    }
    at_ += asked_, into_ += asked_, left_ -= asked_;
    return left_ ? Result::fail(Status::Busy, "a read is under way", kStorage) : Result{};
}

Result Reader::poll() {
    if (!pending_) return left_ ? transfer() : Result{};
    const uint32_t d = done_.load(kDoneLoad);
    if (!(d & kDoneBit)) {
        const bool late = clock_.now_us ? now() - started_us_ > kWaitUs : ++polls_ > kWaitPolls;
        if (!late) return Result::fail(Status::Busy, "a read is under way", kStorage);
        pending_ = false, left_ = 0;
        file_ = nullptr, opened_ = false;
        return Result::fail(Status::Io, "the storage did not end a read in 5 s", kStorage);
    }
    pending_ = false;
    const Status s = Status(int32_t(d & ~kDoneBit));
    if (s != Status::Ok) {
        left_ = 0;
        return Result::fail(s == Status::Busy ? Status::Io : s, "the storage's read failed", kStorage);
    }
    at_ += asked_, into_ += asked_, left_ -= asked_;
    return left_ ? Result::fail(Status::Busy, "a read is under way", kStorage) : Result{};
}

Result Reader::read(uint32_t offset, void* into, uint32_t bytes) {
    Result r = start(offset, into, bytes);
    while (r.status == Status::Busy) r = poll();
    return r;
}

} // namespace facet::module
