// libFuzzer target for the pack reader: any bytes in; open() must return a status and, when
// it says Ok, every record it exposes must be readable within the buffer.
#include "geom/pack.h"

#include <cstdint>
#include <cstring>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<uint32_t> aligned((size + 3) / 4 + 1);
    std::memcpy(aligned.data(), data, size);
    facet::geom::Pack pack;
    facet::geom::PackProblem problem;
    // Half the time fix the CRC so the fuzzer gets past it to the record checks.
    if (size >= sizeof(facet::pack::Header) && (size & 1)) {
        auto* h = reinterpret_cast<facet::pack::Header*>(aligned.data());
        h->total_bytes = uint32_t(size);
        const auto* bytes = reinterpret_cast<const uint8_t*>(aligned.data());
        h->crc32 = facet::pack::crc32(bytes + sizeof(facet::pack::Header), uint32_t(size - sizeof(facet::pack::Header)));
    }
    if (pack.open(aligned.data(), uint32_t(size), problem) != facet::Status::Ok) return 0;
    uint64_t sum = 0;
    for (const auto& f : pack.faces()) {
        const auto& s = pack.surfaces()[f.surface];
        for (float v : pack.params(s.params, s.count)) sum += uint64_t(v != 0);
        for (uint32_t l = f.first_loop; l < f.first_loop + f.loop_count; ++l) {
            const auto& loop = pack.loops()[l];
            for (uint32_t c = loop.first_coedge; c < loop.first_coedge + loop.coedge_count; ++c) {
                const auto& e = pack.edges()[pack.coedges()[c].edge];
                sum += pack.vertices()[e.v0].p[0] != 0;
            }
        }
    }
    return int(sum & 0);
}
