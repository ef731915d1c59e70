#pragma once
// A whole pack's edges sampled on the host (the mesher, the packer's proxies): the pool of
// samples grows, four times at a time, until it holds them (up to kMostSamples).
#include "geom/tessellate.h"

#include <cstdint>
#include <vector>

namespace facet::geom {

struct EdgePool {
    static constexpr size_t kMostSamples = size_t(1) << 26;
    std::vector<uint32_t> first;
    std::vector<uint16_t> count;
    std::vector<float> t;
    std::vector<Vec3> p;
    EdgeSamples samples{}; // (views of the vectors above)

    // Every edge sampled, starting from a pool of `start` samples: Ok, or the last try's failure
    // (Full when even the largest pool is short).
    Result sample(const Pack& pack, const TessOptions& opt, size_t start) {
        first.assign(pack.edges().size(), 0), count.assign(pack.edges().size(), 0);
        for (size_t pool = start;; pool *= 4) {
            t.assign(pool, 0.0f), p.assign(pool, Vec3{});
            samples = EdgeSamples{first, count, t, p};
            const Result r = sample_edges(pack, opt, samples);
            if (r.ok() || r.status != Status::Full || pool > kMostSamples) return r;
        }
    }
};

} // namespace facet::geom
