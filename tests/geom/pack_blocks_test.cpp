// Blocked packs: an index and blocks made from a whole pack, read with the device's code (the
// index in place, each block decoded alone, in pieces or at once), joined back into the same
// whole pack for the host tools; every corruption of the index refused with its place.
#include "geom/bounds.h"
#include "geom/pack.h"
#include "geom/pack_file.h"
#include "geom/pack_index.h"
#include "pack_blocks.h"
#include "pack_io.h"
#include "pack_writer.h"

#include "core/format.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::pack;

namespace {

using Bytes = std::vector<uint8_t>;

// `n` boxes of different sizes, each a shell of 6 planar faces, each placed twice, named; box
// b's edge b % 12 marked smooth (SmoothEdges: its faces meeting tangentially, as if rounded).
Bytes boxes_pack(int n, const Needs* needs = nullptr) {
    PackWriter w;
    w.set_model_name("boxes");
    if (needs) w.set_needs(*needs);
    for (int b = 0; b < n; ++b) {
        const float s = 5.0f + float(b);
        uint32_t v[8];
        for (int i = 0; i < 8; ++i) v[i] = w.add_vertex(s * (i & 1), s * ((i >> 1) & 1), s * ((i >> 2) & 1));
        const int ends[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        uint32_t e[12];
        for (int i = 0; i < 12; ++i) e[i] = w.add_edge({kStraight, 0, s, v[ends[i][0]], v[ends[i][1]], 1e-7f, 0});
        w.set_smooth_edge(e[b % 12]);
        // Each side's loop: the four edges between its corners (k-th side: bit k/2 fixed).
        const int sides[6][4] = {{0, 5, 1, 4}, {2, 7, 3, 6}, {0, 9, 2, 8}, {1, 11, 3, 10}, {4, 10, 6, 8}, {5, 11, 7, 9}};
        const uint32_t colour = w.add_colour({uint8_t(40 * b), 120, 200, 255});
        const uint32_t first_face = w.face_count();
        for (int f = 0; f < 6; ++f) {
            const float z = (f & 1) ? s : 0;
            const uint32_t surf = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, z + float(f))});
            const uint32_t first = w.coedge_count();
            for (int k = 0; k < 4; ++k) w.add_coedge(Coedge::make(e[sides[f][k]], k >= 2, Seam::None));
            const uint32_t loop = w.add_loop({first, 4});
            w.add_face({surf, loop, 1, kNoIndex, f == 0 ? colour : kNoIndex, 0, {0, 0, 0}, {0, 0}, {s, s}});
        }
        const uint32_t shell = w.add_shell({first_face, 6, colour, 1});
        w.name_shell(shell, "box " + std::to_string(b));
        for (int k = 0; k < 2; ++k) {
            const uint32_t i = w.add_instance({shell, {1, 0, 0, 30.0f * float(b), 0, 1, 0, 40.0f * float(k), 0, 0, 1, 0}});
            w.name_instance(i, "box " + std::to_string(b) + (k ? " right" : " left"));
        }
    }
    return w.finish();
}

struct Aligned {
    std::vector<uint32_t> words;
    uint32_t size;
    explicit Aligned(const Bytes& b) : words((b.size() + 3) / 4 + 1), size(uint32_t(b.size())) {
        if (!b.empty()) std::memcpy(words.data(), b.data(), b.size());
    }
    const void* data() const { return words.data(); }
    uint8_t* bytes() { return reinterpret_cast<uint8_t*>(words.data()); }
};

std::string text(const Result& r) {
    char buf[200];
    describe(r, buf, sizeof buf);
    return buf;
}

Bytes blocked(const Bytes& whole_bytes, BlockOptions options = {}) {
    Aligned a(whole_bytes);
    Pack whole;
    EXPECT_TRUE(whole.open(a.data(), a.size).ok());
    Bytes out;
    std::string error;
    EXPECT_TRUE(make_blocked(whole, {}, options, out, error)) << error;
    return out;
}

} // namespace

TEST(PackBlocks, IndexReadsInPlaceAndEveryPartHasItsBlock) {
    BlockOptions small;
    small.block_bytes = 1500; // a box's pack is about 1 KB: two blocks of two, and one of one
    const Bytes file = blocked(boxes_pack(5), small);
    Aligned a(file);
    PackIndex index;
    ASSERT_TRUE(index.open(a.data(), a.size).ok());
    EXPECT_EQ(index.parts().size(), 5u);
    EXPECT_EQ(index.instances().size(), 10u);
    EXPECT_GT(index.blocks().size(), 1u);
    EXPECT_STREQ(index.model_name(), "boxes");
    EXPECT_STREQ(index.part_name(3), "box 3");
    EXPECT_STREQ(index.instance_name(7), "box 3 right");
    for (uint32_t p = 0; p < index.parts().size(); ++p) {
        const pack::Part& part = index.parts()[p];
        EXPECT_EQ(part.face_count, 6u);
        EXPECT_EQ(part.edge_count, 12u);
        EXPECT_EQ(part.closed, 1u);
        const float s = 5.0f + float(p);
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(part.box_min[k], 0.0f) << p;
            EXPECT_GE(part.box_max[k], s) << p;
        }
    }
    // Each block, decoded alone, is a pack of its parts' shells, in order.
    for (uint32_t b = 0; b < index.blocks().size(); ++b) {
        const pack::Block& k = index.blocks()[b];
        const auto stored = index.block_file(b);
        EXPECT_EQ(pack_file_kind(stored.data(), uint32_t(stored.size())), PackFileKind::Lzma);
        std::vector<uint32_t> out((k.pack_bytes + 3) / 4);
        auto probs = std::make_unique<LzmaProbs>();
        PackDecoder d;
        Result r = d.start(stored, {reinterpret_cast<uint8_t*>(out.data()), out.size() * 4}, *probs);
        int pieces = 0;
        while (r.status == Status::Busy) r = d.run(256), ++pieces;
        ASSERT_TRUE(r.ok()) << text(r);
        EXPECT_GT(pieces, 1) << "decoded a piece at a time";
        Pack p;
        ASSERT_TRUE(p.open(out.data(), d.pack_bytes()).ok());
        ASSERT_EQ(p.shells().size(), k.part_count);
        EXPECT_TRUE(p.instances().empty());
        for (uint32_t s = 0; s < k.part_count; ++s) EXPECT_EQ(p.shells()[s].face_count, 6u);
        EXPECT_EQ(p.edges().size(), 12u * k.part_count) << "each part's edges after the part before it";
        for (uint32_t s = 0; s < k.part_count; ++s) { // its smooth edge kept (which one: JoinedBackIsTheWholePack)
            uint32_t smooth = 0;
            for (uint32_t e = 12 * s; e < 12 * s + 12; ++e) smooth += p.smooth_edge(e);
            EXPECT_EQ(smooth, 1u) << b << " " << s;
        }
    }
    // Placed: the index's box holds every instance's box.
    EXPECT_LE(index.header().bbox_min[0], 0.0f);
    EXPECT_GE(index.header().bbox_max[0], 4 * 30.0f + 9.0f);
    EXPECT_GE(index.header().bbox_max[1], 40.0f + 9.0f);
}

TEST(PackBlocks, JoinedBackIsTheWholePack) {
    for (const BlockStore store : {BlockStore::Lzma, BlockStore::Deflated, BlockStore::Plain}) {
        BlockOptions o;
        o.store = store;
        o.block_bytes = 2500;
        const Needs needs{400, 900, 800, 200, 500, 450};
        const Bytes whole = boxes_pack(4, &needs);
        const Bytes file = blocked(whole, o);
        { // the whole model's Needs in the index
            Aligned f(file);
            PackIndex index;
            ASSERT_TRUE(index.open(f.data(), f.size).ok());
            ASSERT_NE(index.needs(), nullptr);
            EXPECT_EQ(std::memcmp(index.needs(), &needs, sizeof needs), 0);
        }
        LoadedPack joined;
        std::string error;
        ASSERT_TRUE(load_pack_bytes(file, joined, error)) << error;
        EXPECT_EQ(joined.kind, PackFileKind::Blocked);
        Pack a, b;
        Aligned w(whole);
        ASSERT_TRUE(a.open(w.data(), w.size).ok());
        ASSERT_TRUE(b.open(joined.data(), joined.bytes).ok());
        EXPECT_EQ(a.faces().size(), b.faces().size());
        EXPECT_EQ(a.edges().size(), b.edges().size());
        EXPECT_EQ(a.vertices().size(), b.vertices().size());
        EXPECT_EQ(a.shells().size(), b.shells().size());
        ASSERT_EQ(a.instances().size(), b.instances().size());
        for (size_t i = 0; i < a.instances().size(); ++i) {
            EXPECT_EQ(a.instances()[i].shell, b.instances()[i].shell);
            EXPECT_EQ(std::memcmp(a.instances()[i].m, b.instances()[i].m, sizeof a.instances()[i].m), 0);
            EXPECT_STREQ(a.instance_name(uint32_t(i)), b.instance_name(uint32_t(i)));
        }
        for (uint32_t s = 0; s < a.shells().size(); ++s) EXPECT_STREQ(a.shell_name(s), b.shell_name(s));
        EXPECT_STREQ(a.model_name(), b.model_name());
        ASSERT_NE(b.needs(), nullptr);
        EXPECT_EQ(std::memcmp(a.needs(), b.needs(), sizeof needs), 0);
        for (size_t f = 0; f < a.faces().size(); ++f) {
            const uint32_t ca = a.faces()[f].colour, cb = b.faces()[f].colour;
            ASSERT_EQ(ca == kNoIndex, cb == kNoIndex) << f;
            if (ca != kNoIndex) {
                EXPECT_EQ(std::memcmp(&a.colours()[ca], &b.colours()[cb], 4), 0) << f;
            }
        }
        // The same geometry: each coedge's edge ends at the same points (vertices are renumbered
        // in the order the faces first use them).
        ASSERT_EQ(a.coedges().size(), b.coedges().size());
        for (size_t c = 0; c < a.coedges().size(); ++c) {
            const Edge &ea = a.edges()[a.coedges()[c].edge()], &eb = b.edges()[b.coedges()[c].edge()];
            EXPECT_EQ(std::memcmp(a.vertices()[ea.v0].p, b.vertices()[eb.v0].p, 12), 0) << c;
            EXPECT_EQ(std::memcmp(a.vertices()[ea.v1].p, b.vertices()[eb.v1].p, 12), 0) << c;
            EXPECT_EQ(a.coedges()[c].reversed(), b.coedges()[c].reversed());
            EXPECT_EQ(a.smooth_edge(a.coedges()[c].edge()), b.smooth_edge(b.coedges()[c].edge())) << c;
        }
    }
}

TEST(PackBlocks, ShellBoxesHoldTheirCurvesAndSurfaces) {
    // A box's shell: its corners. (The curved shapes' boxes are checked in the tessellation tests.)
    const Bytes whole = boxes_pack(2);
    Aligned w(whole);
    Pack p;
    ASSERT_TRUE(p.open(w.data(), w.size).ok());
    const Box3 b = shell_box(p, 1);
    for (int k = 0; k < 3; ++k) {
        EXPECT_FLOAT_EQ(b.lo[k], 0);
        EXPECT_FLOAT_EQ(b.hi[k], 6);
    }
}

TEST(PackBlocks, EveryCorruptionOfTheIndexIsRefusedWithItsPlace) {
    const Bytes good = blocked(boxes_pack(3));
    PackIndex index;
    {
        Aligned a(good);
        ASSERT_TRUE(index.open(a.data(), a.size).ok());
    }
    auto refused = [&](Bytes bad, const char* what) {
        Aligned a(bad);
        PackIndex i;
        const Result r = i.open(a.data(), a.size);
        EXPECT_EQ(r.status, Status::Corrupt) << what;
        return text(r);
    };
    // Every byte of the index flipped: refused (the CRC, or the header's own checks).
    Aligned g(good);
    PackIndex gi;
    ASSERT_TRUE(gi.open(g.data(), g.size).ok());
    const uint32_t index_bytes = gi.header().index_bytes;
    for (uint32_t at = 0; at < index_bytes; ++at) {
        Bytes bad = good;
        bad[at] ^= 0x5A;
        refused(bad, ("byte " + std::to_string(at)).c_str());
    }
    // Cut short anywhere before the end: refused.
    for (uint32_t n : {0u, 10u, 63u, 64u, index_bytes - 1, uint32_t(good.size()) - 1}) {
        refused(Bytes(good.begin(), good.begin() + n), "truncated");
    }
    // A record made wrong and the CRC made right again: the place is named.
    auto recrc = [](Bytes& b) {
        IndexHeader h;
        std::memcpy(&h, b.data(), sizeof h);
        h.crc32 = crc32(b.data() + kIndexCrcFrom, h.index_bytes - kIndexCrcFrom);
        std::memcpy(b.data(), &h, sizeof h);
    };
    auto section = [&](const Bytes& b, IndexSectionId id) {
        IndexHeader h;
        std::memcpy(&h, b.data(), sizeof h);
        for (uint32_t i = 0; i < h.section_count; ++i) {
            SectionEntry e;
            std::memcpy(&e, b.data() + sizeof h + i * sizeof e, sizeof e);
            if (e.id == uint32_t(id)) return e.offset;
        }
        return 0u;
    };
    {
        Bytes bad = good;
        pack::Part part;
        const uint32_t at = section(bad, IndexSectionId::Parts) + 2 * sizeof part;
        std::memcpy(&part, bad.data() + at, sizeof part);
        part.block = 7;
        std::memcpy(bad.data() + at, &part, sizeof part);
        recrc(bad);
        EXPECT_EQ(refused(bad, "part's block"), "index section Parts record 2: the part's block does not hold it");
    }
    {
        Bytes bad = good;
        Instance inst;
        const uint32_t at = section(bad, IndexSectionId::Instances) + 5 * sizeof inst;
        std::memcpy(&inst, bad.data() + at, sizeof inst);
        inst.shell = 3;
        std::memcpy(bad.data() + at, &inst, sizeof inst);
        recrc(bad);
        EXPECT_EQ(refused(bad, "instance's part"), "index section Instances record 5: part index out of range");
    }
    {
        Bytes bad = good;
        pack::Block block;
        const uint32_t at = section(bad, IndexSectionId::Blocks);
        std::memcpy(&block, bad.data() + at, sizeof block);
        block.stored_bytes = uint32_t(bad.size());
        std::memcpy(bad.data() + at, &block, sizeof block);
        recrc(bad);
        EXPECT_EQ(refused(bad, "block past the end"),
                  "index section Blocks record 0: the block lies outside the file, overlaps the one before it or is empty");
    }
}

TEST(PackBlocks, ACorruptBlockIsRefusedWhenDecodedAndTheOthersStillRead) {
    BlockOptions o;
    o.block_bytes = 1500;
    Bytes file = blocked(boxes_pack(3), o);
    Aligned a(file);
    PackIndex index;
    ASSERT_TRUE(index.open(a.data(), a.size).ok());
    ASSERT_GE(index.blocks().size(), 2u);
    // The first block's stream damaged in the file: the index still reads (it has its own CRC).
    const uint32_t at = index.blocks()[0].offset + 40;
    a.bytes()[at] ^= 0xFF;
    PackIndex again;
    ASSERT_TRUE(again.open(a.data(), a.size).ok());
    auto decode = [&](uint32_t b) {
        const pack::Block& k = again.blocks()[b];
        std::vector<uint32_t> out((k.pack_bytes + 3) / 4);
        auto probs = std::make_unique<LzmaProbs>();
        PackDecoder d;
        Result r = d.start(again.block_file(b), {reinterpret_cast<uint8_t*>(out.data()), out.size() * 4}, *probs);
        while (r.status == Status::Busy) r = d.run(4096);
        Pack p;
        if (r.ok()) r = p.open(out.data(), d.pack_bytes());
        return r;
    };
    EXPECT_FALSE(decode(0).ok());
    for (uint32_t b = 1; b < again.blocks().size(); ++b) EXPECT_TRUE(decode(b).ok()) << b;
}

TEST(PackBlocks, TooSmallAMemoryForTheBlockIsFull) {
    const Bytes file = blocked(boxes_pack(1));
    Aligned a(file);
    PackIndex index;
    ASSERT_TRUE(index.open(a.data(), a.size).ok());
    std::vector<uint32_t> out(16);
    auto probs = std::make_unique<LzmaProbs>();
    PackDecoder d;
    const Result r = d.start(index.block_file(0), {reinterpret_cast<uint8_t*>(out.data()), out.size() * 4}, *probs);
    EXPECT_EQ(r.status, Status::Full);
    EXPECT_EQ(d.run(1000).status, Status::Full) << "and says so again";
}
