// libFuzzer target for the pack file reader: any bytes in, plain, LZMA, deflated or blocked.
// unpack_in_place(), PackIndex::open(), PackDecoder and open() must return a status and, when
// they say Ok, every record the pack (or each block's pack) exposes must be readable within the
// buffer; so must the annotations' and the assembly tree's (geom/pmi.h, geom/tree.h).
#include "geom/pack.h"
#include "geom/pack_file.h"
#include "geom/pack_index.h"
#include "geom/pmi.h"
#include "geom/tree.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace facet;

namespace {

// The assembly tree's every record and name (a pack's or an index's).
template <typename Source>
uint64_t tree_sum(const Source& source) {
    geom::ProductTree tree;
    uint64_t sum = 0;
    if (!tree.open(source).ok() || !tree.count()) return 0; // (none: no node, no instance's node)
    for (uint32_t n = 0; n < tree.count(); ++n) sum += std::strlen(tree.name(n)) + std::strlen(tree.occurrence(n)) + tree.depth(n);
    for (uint32_t i = 0; i < source.instances().size(); ++i) sum += tree.node_of(i) + (tree.explode(i)[0] != 0);
    return sum;
}

uint64_t touch(const geom::Pack& pack) {
    uint64_t sum = 0;
    for (const auto& f : pack.faces()) {
        const auto& s = pack.surfaces()[f.surface];
        for (float v : pack.params(s.params, s.count)) sum += uint64_t(v != 0);
        for (uint32_t l = f.first_loop; l < f.first_loop + f.loop_count; ++l) {
            const auto& loop = pack.loops()[l];
            for (uint32_t c = loop.first_coedge; c < loop.first_coedge + loop.coedge_count; ++c) {
                const auto& e = pack.edges()[pack.coedges()[c].edge()];
                sum += pack.vertices()[e.v0].p[0] != 0;
                const uint32_t pc = pack.pcurve_of(f, c);
                if (pc != pack::kNoIndex) sum += pack.curves2()[pc].count;
            }
        }
    }
    geom::Annotations pmi;
    if (pmi.open(pack).ok()) {
        for (uint32_t i = 0; i < pmi.count(); ++i) {
            sum += std::strlen(pmi.text(i));
            for (uint32_t f : pmi.faces(i)) sum += pack.faces()[f].surface;
            for (const auto& l : pmi.polylines(i))
                for (const auto& p : pmi.points(l)) sum += p.d[0] != 0;
            sum += pmi.coarse_polylines(i).size();
        }
    }
    sum += tree_sum(pack);
    return sum;
}

// A blocked file: the index in place, then each block decoded (capped at 1 MiB) and read.
int blocked(const uint8_t* data, size_t size) {
    std::vector<uint32_t> file(size / 4 + 1);
    std::memcpy(file.data(), data, size);
    geom::PackIndex index;
    if (!index.open(file.data(), uint32_t(size)).ok()) return 0;
    uint64_t sum = index.parts().size() + index.instances().size() + tree_sum(index);
    geom::Annotations pmi; // (an index carries a blocked model's)
    if (pmi.open(index).ok())
        for (uint32_t i = 0; i < pmi.count(); ++i) sum += std::strlen(pmi.text(i)) + pmi.faces(i).size() + pmi.polylines(i).size();
    static geom::LzmaProbs probs;
    for (uint32_t b = 0; b < index.blocks().size(); ++b) {
        const uint32_t bytes = std::min<uint32_t>(index.blocks()[b].pack_bytes, 1u << 20);
        std::vector<uint32_t> out(bytes / 4 + 1);
        geom::PackDecoder d;
        Result r = d.start(index.block_file(b), {reinterpret_cast<uint8_t*>(out.data()), bytes}, probs);
        while (r.status == Status::Busy) r = d.run(64 * 1024);
        geom::Pack pack;
        if (r.ok() && pack.open(out.data(), d.pack_bytes()).ok()) sum += touch(pack);
    }
    return int(sum & 0);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (geom::pack_file_kind(data, uint32_t(size)) == geom::PackFileKind::Blocked) return blocked(data, size);
    // The region the device would load the file into: the file, then room for what it decodes
    // to (and an LZMA decoder's state) (capped, so a head claiming a huge pack is refused as too big, as on the device).
    uint32_t room = 0;
    if (geom::compressed(geom::pack_file_kind(data, uint32_t(size))) && size >= sizeof(pack::DeflatedHead)) {
        pack::DeflatedHead head; // an LzmaHead's sizes sit at the same places
        std::memcpy(&head, data, sizeof head);
        room = std::min<uint32_t>(head.pack_bytes, 1u << 20) + geom::kLzmaStateBytes + 3;
    }
    const uint32_t capacity = uint32_t(size) + room;
    std::vector<uint32_t> region(capacity / 4 + 1);
    std::memcpy(region.data(), data, size);
    auto* bytes = reinterpret_cast<uint8_t*>(region.data());
    // Half the time fix a plain pack's size and CRC so the fuzzer gets past them to the records.
    if (room == 0 && size >= sizeof(pack::Header) && (size & 1)) {
        auto* h = reinterpret_cast<pack::Header*>(bytes);
        h->total_bytes = uint32_t(size);
        h->crc32 = pack::crc32(bytes + sizeof(pack::Header), uint32_t(size - sizeof(pack::Header)));
    }
    uint32_t pack_bytes = 0;
    if (!geom::unpack_in_place(bytes, capacity, uint32_t(size), pack_bytes).ok()) return 0;
    geom::Pack pack;
    if (!pack.open(bytes, pack_bytes).ok()) return 0;
    return int(touch(pack) & 0);
}
