#pragma once
// The assembly the blocked-pack tests share: shapes built in code, one part each, whole and
// blocked.
#include "../geom/shapes.h"
#include "pack_blocks.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace facet::test {

// Four shapes (a plate with holes, a sphere, a torus, a trimmed B-spline patch), one part each,
// in a row 150 mm apart.
inline Bytes assembly() {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<geom::Pack> packs(4);
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(packs[k].open(shapes[k].data(), uint32_t(shapes[k].size())).ok());
    return combine_packs(packs, 150.0f);
}

// The blocked form of `whole`, a part a block, every part's box the whole pack's (so the two
// forms have one box, one default tolerance and one mesh quantum: the same mesh).
inline Bytes blocked(const Bytes& whole, geom::BlockStore store = geom::BlockStore::Lzma) {
    geom::Pack p;
    EXPECT_TRUE(p.open(whole.data(), uint32_t(whole.size())).ok());
    const pack::Header& h = p.header();
    std::vector<geom::PartBox> boxes(p.shells().size());
    for (geom::PartBox& b : boxes)
        for (int k = 0; k < 3; ++k) b.min[k] = h.bbox_min[k], b.max[k] = h.bbox_max[k];
    Bytes out;
    std::string error;
    EXPECT_TRUE(make_blocked(p, boxes, {1, store}, out, error)) << error;
    return out;
}

} // namespace facet::test
