#pragma once
// The board's memory card as the module's storage (facet/storage.h): the card's FAT filesystem
// (hal/fat.h) behind the module's open, read and folder callbacks, a few files open at once.
// This is the glue a product writes for its own storage: each callback is a filesystem call.
//
//   CardStorage card;
//   if (card.mount(*board.card).ok()) viewer.set_storage(card.storage(), "/");
//   ... in the main loop: card.poll(viewer) notices a card pulled or put back.
#include "facet/viewer.h"
#include "hal/fat.h"

namespace facet::firmware {

class CardStorage {
public:
    // The card started and its filesystem mounted (Io: no card; Unsupported: exFAT, FAT12...).
    Result mount(hal::Card& card);
    bool mounted() const { return volume_.mounted(); }
    bool present() const { return present_; } // (as the last poll() found it)
    Storage storage();
    // A card pulled or put back since the last call: the viewer told (storage_changed()).
    // True when it changed; `why` is the viewer's answer (a card put back that cannot be read).
    bool poll(Viewer& viewer, Result& why);

private:
    static constexpr uint32_t kFiles = 4; // open at once (the model's, one being listed)
    hal::Card* card_ = nullptr;
    bool present_ = false;
    hal::fat::Volume volume_;
    hal::fat::File files_[kFiles];
    bool open_[kFiles] = {};
    hal::fat::Dir dir_;
    bool dir_open_ = false;
    hal::fat::Entry entry_; // (a long name: 769 bytes, not on the stack)
};

} // namespace facet::firmware
