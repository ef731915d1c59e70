// libFuzzer target for the pack reader through the storage interface (facet/storage.h): the
// input is a pack file on a product's storage (or, when it starts with no pack's magic, byte
// changes to a blocked pack of every surface kind made here, a part a block, so the runs reach
// the blocks), read as the module reads a card: listed (its face
// count from its head or index), opened (a blocked pack's index, then a block at a time, in
// transfers), zoomed into so that blocks left out are read in, and, by the input's size, with
// reads that end later (a DMA's interrupt) or a card pulled after some reads. Every call must
// return, nothing may read or write outside its buffers (ASan, UBSan) or wait for ever.
#include "../geom/shapes.h"
#include "../viewer/fake_storage.h"
#include "facet/viewer.h"
#include "pack_blocks.h"

#include <cstdint>
#include <cstring>
#include <vector>

using namespace facet;

namespace {

constexpr uint16_t kW = 64, kH = 48;
Rgb565 frames[2][kW * kH];
uint16_t depth[2][kW * kH];

// Four shapes (plate with holes, sphere, torus, trimmed B-spline), a part a block, LZMA.
const std::vector<uint8_t>& blocked() {
    static const std::vector<uint8_t> file = [] {
        const test::Bytes shapes[] = {test::plate_with_holes(), test::sphere(), test::torus(), test::trimmed_bspline()};
        std::vector<geom::Pack> packs(4);
        for (int k = 0; k < 4; ++k) (void)packs[k].open(shapes[k].data(), uint32_t(shapes[k].size()));
        const test::Bytes whole = geom::combine_packs(packs, 150.0f);
        geom::Pack p;
        test::Bytes out;
        std::string error;
        if (!p.open(whole.data(), uint32_t(whole.size())).ok() || !geom::make_blocked(p, {}, {1, geom::BlockStore::Lzma}, out, error)) return whole;
        return out;
    }();
    return file;
}

struct Run {
    test::FakeStorage card;
    uint32_t clock_us = 0;
};
Run* run_now = nullptr;

uint32_t now_us(void*) {
    run_now->card.tick();
    return run_now->clock_us += 2000;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // The workspace: the least a viewer takes and as much again for the model (blocks left out
    // in the smaller one, by the input's size).
    static std::vector<uint64_t> workspace(2 * FACET_WORKSPACE_BASE_BYTES / 8);
    Run r;
    run_now = &r;
    std::vector<uint8_t>& file = r.card.files["/models/a.fpk"];
    if (size >= 2 && data[0] == 'F' && data[1] == 'P') {
        file.assign(data, data + size);
    } else { // changes to the blocked pack: (offset 3 bytes, xor 1 byte) each
        file = blocked();
        for (size_t k = 0; k + 4 <= size; k += 4) {
            const uint32_t at = (uint32_t(data[k]) | uint32_t(data[k + 1]) << 8 | uint32_t(data[k + 2]) << 16) % uint32_t(file.size());
            file[at] ^= data[k + 3];
        }
        if (size % 4 == 3) file.resize(file.size() * data[size - 1] / 256); // (cut short)
        // Half the time the index's CRC made right again, so the runs reach its records and blocks.
        pack::IndexHeader h;
        if ((size & 16) && file.size() >= sizeof h) {
            std::memcpy(&h, file.data(), sizeof h);
            if (h.index_bytes >= pack::kIndexCrcFrom && h.index_bytes <= file.size()) {
                h.crc32 = pack::crc32(file.data() + pack::kIndexCrcFrom, h.index_bytes - pack::kIndexCrcFrom);
                std::memcpy(file.data(), &h, sizeof h);
            }
        }
    }
    r.card.deferred = size & 1;
    r.card.delay = 2;
    r.card.pull_after_reads = (size & 6) == 6 ? int(size % 13) : -1;
    Config cfg;
    cfg.display.width = kW, cfg.display.height = kH, cfg.display.band_lines = kH;
    cfg.display.buffers[0] = frames[0], cfg.display.buffers[1] = frames[1];
    cfg.display.depth[0] = depth[0], cfg.display.depth[1] = depth[1];
    cfg.display.flush = [](Viewer& v, void*, const Area&, const Rgb565*) { v.flush_done(); };
    cfg.now_us = now_us;
    cfg.interface = Interface::Off;
    const size_t bytes = (size & 8) ? workspace.size() * 8 : FACET_WORKSPACE_BASE_BYTES + 256 * 1024;
    Viewer* v = Viewer::create(cfg, workspace.data(), bytes);
    if (!v) return 0;
    r.card.viewer = v;
    if (!v->set_storage(r.card.storage(), "/models").ok() || !v->open_model(0).ok()) return 0;
    for (int round = 0; round < 4; ++round) {
        for (int k = 0; k < 3000 && v->step(20000) != Activity::Idle; ++k) {
        }
        v->wheel(2);
    }
    if (r.card.pull_after_reads < 0 && !r.card.present) {
        (void)v->storage_changed(false);
        r.card.present = true;
        (void)v->storage_changed(true);
        for (int k = 0; k < 3000 && v->step(20000) != Activity::Idle; ++k) {
        }
    }
    return 0;
}
