#pragma once
// A pack file on the product's storage (facet/storage.h), open for the module's reads: one read
// at a time, asked of the storage in transfers of at most kChunkBytes, each ended at once by
// the storage or later by Viewer::read_done() (any context). The loader waits for a read (load()
// is one call); the swapper polls one between its pieces of work, a transfer a piece, so a
// block read from a storage that answers at once still takes a bounded time a piece.
#include "facet/storage.h"
#include "presenter.h" // (kDoneStore, kDoneLoad)

#include <atomic>
#include <cstdint>

namespace facet::module {

class Reader {
public:
    static constexpr uint32_t kChunkBytes = 32768;   // a transfer asked of the storage
    static constexpr uint32_t kWaitUs = 5'000'000;   // a transfer not ended in this is given up
    static constexpr uint32_t kWaitPolls = 1u << 26; // (without a clock: polls)

    struct Clock {
        uint32_t (*now_us)(void* user) = nullptr;
        void* user = nullptr;
    };

    // The file at `path` of `storage` (the one before closed), its reads timed by `clock`.
    // NotFound, Io, OutOfRange (a storage without open, read and close).
    Result open(const Storage& storage, const char* path, const Clock& clock);
    void close();
    bool is_open() const { return file_ != nullptr || opened_; }
    uint32_t bytes() const { return bytes_; } // the window's (the whole file's unless window())
    uint32_t size() const { return size_; }   // the whole file's
    // Reads from here on within [offset, offset + length) of the file (a library's model: a file
    // inside it), offsets counted from its start. False when it lies past the file's end.
    bool window(uint32_t offset, uint32_t length);

    // A read begun (its first transfer asked): Ok when the bytes are there, Busy while it goes
    // on (poll()), else why not. Bytes past the file's end are Corrupt (the pack says more than
    // the file holds).
    Result start(uint32_t offset, void* into, uint32_t bytes);
    // The read under way: its transfer looked at, and when it has ended the next one asked;
    // Busy until the last has ended, then its result (once). A transfer not ended in kWaitUs on
    // the clock (kWaitPolls polls without one) is given up: Io, and the file with it (a transfer
    // the storage may still end must not land in memory the module reuses).
    Result poll();
    // A read to its end (start(), then poll() until it ends or is given up).
    Result read(uint32_t offset, void* into, uint32_t bytes);
    bool reading() const { return left_ > 0 || pending_; }
    // No transfer of the storage's under way (another file may be read meanwhile).
    bool idle() const { return !pending_ || (done_.load(kDoneLoad) & kDoneBit); }

    // The storage's word that the read under way ended (any context: one store).
    void done(Status status) {
        std::atomic_signal_fence(std::memory_order_seq_cst);
        done_.store(uint32_t(status) | kDoneBit, kDoneStore);
    }
    // The storage went away (a card pulled): the file is forgotten (not closed: its driver may
    // be gone), a read under way ends with Io.
    void lost();

private:
    static constexpr uint32_t kDoneBit = 0x80000000u;
    uint32_t now() const { return clock_.now_us ? clock_.now_us(clock_.user) : 0; }
    Storage storage_{};
    Clock clock_{};
    Result transfer(); // the next transfer asked: Ok (the read is done), Busy, or why not
    uint32_t started_us_ = 0, polls_ = 0; // the transfer under way's
    uint32_t at_ = 0, left_ = 0, asked_ = 0; // the read under way: its next offset, bytes left, the transfer's bytes
    uint8_t* into_ = nullptr;
    void* file_ = nullptr;
    bool opened_ = false; // (a storage may hand a null handle)
    uint32_t bytes_ = 0, size_ = 0, base_ = 0; // the window's size, the file's, the window's start
    bool pending_ = false;
    std::atomic<uint32_t> done_{0};
};

} // namespace facet::module
