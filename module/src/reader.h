#pragma once
// A pack file on the product's storage (facet/storage.h), open for the module's reads: one read
// at a time, ended at once by the storage or later by Viewer::read_done() (any context). The
// loader waits for a read (load() is one call: at most kWaitUs on the clock, or kWaitPolls
// polls without one); the swapper polls one between its pieces of work.
#include "facet/storage.h"
#include "presenter.h" // (kDoneStore, kDoneLoad)

#include <atomic>
#include <cstdint>

namespace facet::module {

class Reader {
public:
    static constexpr uint32_t kWaitUs = 5'000'000;   // a read the loader waits for
    static constexpr uint32_t kWaitPolls = 1u << 26; // (without a clock)

    struct Clock {
        uint32_t (*now_us)(void* user) = nullptr;
        void* user = nullptr;
    };

    // The file at `path` of `storage` (the one before closed), its reads timed by `clock`.
    // NotFound, Io, OutOfRange (a storage without open, read and close).
    Result open(const Storage& storage, const char* path, const Clock& clock);
    void close();
    bool is_open() const { return file_ != nullptr || opened_; }
    uint32_t bytes() const { return bytes_; }

    // A read begun: Ok when the bytes are there, Busy while it goes on (poll()), else why not.
    // Bytes past the file's end are Corrupt (the pack says more than the file holds).
    Result start(uint32_t offset, void* into, uint32_t bytes);
    // The read under way: Busy until the storage says it ended, then its result (once). One
    // that has not ended in kWaitUs on the clock (kWaitPolls polls without one) is given up: Io,
    // and the file with it (a read the storage may still end must not land in memory the module
    // reuses).
    Result poll();
    // A read to its end (start(), then poll() until it ends or is given up).
    Result read(uint32_t offset, void* into, uint32_t bytes);
    bool reading() const { return pending_; }
    // The read under way has ended (poll() then gives its result).
    bool ended() const { return !pending_ || (done_.load(kDoneLoad) & kDoneBit); }

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
    uint32_t started_us_ = 0, polls_ = 0; // the read under way's
    void* file_ = nullptr;
    bool opened_ = false; // (a storage may hand a null handle)
    uint32_t bytes_ = 0;
    bool pending_ = false;
    std::atomic<uint32_t> done_{0};
};

} // namespace facet::module
