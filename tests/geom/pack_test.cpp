// The pack reader refuses every kind of corruption with a status naming the bad record, and
// reads a valid pack in place.
#include "geom/pack.h"
#include "geom/pack_file.h"
#include "geom/params.h"
#include "pack_io.h"
#include "pack_writer.h"

#include "core/format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

using namespace facet;
using namespace facet::geom;
using namespace facet::pack;

namespace {

// A 10 mm cube: 6 planes, 12 edges (the first six straight, the others on line curves), 8
// vertices, 24 coedges; the first three faces carry line pcurves (optional on planes).
std::vector<uint8_t> cube_pack(std::initializer_list<uint32_t> smooth = {}, const Needs* needs = nullptr) {
    PackWriter w;
    if (needs) w.set_needs(*needs);
    const float s = 10;
    uint32_t v[8];
    for (int i = 0; i < 8; ++i) v[i] = w.add_vertex(s * (i & 1), s * ((i >> 1) & 1), s * ((i >> 2) & 1));
    const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    uint32_t e[12];
    for (int i = 0; i < 12; ++i) {
        const uint32_t a = v[edges[i][0]], b = v[edges[i][1]];
        const int ia = edges[i][0], ib = edges[i][1];
        const float o[3] = {s * (ia & 1), s * ((ia >> 1) & 1), s * ((ia >> 2) & 1)};
        const float d[3] = {s * ((ib & 1) - (ia & 1)), s * (((ib >> 1) & 1) - ((ia >> 1) & 1)), s * (((ib >> 2) & 1) - ((ia >> 2) & 1))};
        const uint32_t c = i < 6 ? kStraight : w.add_curve(pack::Line3Params{.origin = {o[0], o[1], o[2]}, .direction = {d[0] / s, d[1] / s, d[2] / s}});
        e[i] = w.add_edge({c, 0, s, a, b, 1e-7f, 0});
    }
    for (uint32_t i : smooth) w.set_smooth_edge(e[i]); // (as if those edges were rounded)
    // One face per side; pcurves are simple lines (the test only needs valid structure).
    const uint32_t colour = w.add_colour({200, 180, 40, 255});
    const uint32_t first_face = w.face_count();
    for (int f = 0; f < 6; ++f) {
        const uint32_t surf = w.add_surface(pack::PlaneParams{geom::axes_at(0, 0, 0)});
        const uint32_t first = w.coedge_count(), first_pcurve = f < 3 ? w.curve2_count() : kNoIndex;
        for (int k = 0; k < 4; ++k) {
            if (f < 3) w.add_curve(pack::Line2Params{.origin = {0, 0}, .direction = {1, 0}});
            w.add_coedge(Coedge::make(e[(f * 2 + k) % 12], k & 1, Seam::None));
        }
        const uint32_t loop = w.add_loop({first, 4});
        w.add_face({surf, loop, 1, first_pcurve, colour, 0, {0, 0, 0}, {0, 0}, {s, s}});
    }
    const uint32_t shell = w.add_shell({first_face, 6, kNoIndex, 1});
    w.add_instance({shell, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
    return w.finish();
}

// Aligned copy (the reader wants 4-byte alignment, as the device's load address gives).
struct Buf {
    std::vector<uint32_t> words;
    uint32_t size;
    explicit Buf(const std::vector<uint8_t>& b) : words((b.size() + 3) / 4), size(uint32_t(b.size())) {
        if (!b.empty()) std::memcpy(words.data(), b.data(), b.size()); // memcpy(null, ...) is UB even for 0 bytes
    }
    uint8_t* bytes() { return reinterpret_cast<uint8_t*>(words.data()); }
    Header& header() { return *reinterpret_cast<Header*>(bytes()); }
    SectionEntry& section(SectionId id) {
        SectionEntry* t = reinterpret_cast<SectionEntry*>(bytes() + sizeof(Header));
        for (uint32_t i = 0; i < header().section_count; ++i)
            if (t[i].id == uint32_t(id)) return t[i];
        throw std::runtime_error("no section");
    }
    template <typename T>
    T& record(SectionId id, uint32_t i) { return reinterpret_cast<T*>(bytes() + section(id).offset)[i]; }
    void reseal() { header().crc32 = crc32(bytes() + sizeof(Header), size - sizeof(Header)); }
    Result open(Pack& p) { return p.open(bytes(), size); }
};

// The section a refusal names (0: the header), and its text.
uint32_t section_of(const Result& r) {
    for (uint32_t id = 0; id <= uint32_t(SectionId::Colours); ++id)
        if (r.where.kind && std::string(r.where.kind) == section_place(id, 0).kind) return id;
    return 99;
}
std::string text(const Result& r) {
    char buf[160];
    describe(r, buf, sizeof buf);
    return buf;
}

} // namespace

TEST(Pack, ValidCubeReadsInPlace) {
    Buf b(cube_pack());
    Pack p;
    const Result problem = b.open(p);
    ASSERT_TRUE(problem.ok()) << text(problem);
    EXPECT_EQ(p.faces().size(), 6u);
    EXPECT_EQ(p.edges().size(), 12u);
    EXPECT_EQ(p.coedges().size(), 24u);
    EXPECT_EQ(p.edges()[0].curve, kStraight);
    EXPECT_EQ(p.coedges()[5].edge(), 3u);
    EXPECT_TRUE(p.coedges()[5].reversed());
    EXPECT_EQ(p.pcurve_of(p.faces()[2], 10), 10u) << "pcurves follow the face's coedges";
    EXPECT_EQ(p.pcurve_of(p.faces()[4], 17), kNoIndex);
    EXPECT_EQ(p.surfaces()[5].params, p.surfaces()[0].params) << "equal parameter blocks are stored once";
    EXPECT_EQ(p.header().bbox_max[2], 10.0f);
    EXPECT_EQ(reinterpret_cast<const uint8_t*>(p.faces().data()), b.bytes() + b.section(SectionId::Faces).offset) << "zero-copy";
}

// A pack's bytes moved elsewhere (the viewer compacts its decoded blocks): moved() reads every
// record where they now lie, as an open() there would, with no check again.
TEST(Pack, MovedBytesReadWhereTheyNowLie) {
    Buf a(cube_pack());
    Pack p;
    ASSERT_TRUE(a.open(p).ok());
    Buf b(cube_pack());
    Pack there;
    ASSERT_TRUE(b.open(there).ok());
    p.moved(b.bytes());
    EXPECT_EQ(&p.header(), &there.header());
    auto same = [](auto x, auto y) { return x.data() == y.data() && x.size() == y.size(); };
    EXPECT_TRUE(same(p.floats(), there.floats()));
    EXPECT_TRUE(same(p.surfaces(), there.surfaces()));
    EXPECT_TRUE(same(p.curves3(), there.curves3()));
    EXPECT_TRUE(same(p.curves2(), there.curves2()));
    EXPECT_TRUE(same(p.vertices(), there.vertices()));
    EXPECT_TRUE(same(p.edges(), there.edges()));
    EXPECT_TRUE(same(p.coedges(), there.coedges()));
    EXPECT_TRUE(same(p.loops(), there.loops()));
    EXPECT_TRUE(same(p.faces(), there.faces()));
    EXPECT_TRUE(same(p.shells(), there.shells()));
    EXPECT_TRUE(same(p.instances(), there.instances()));
    EXPECT_TRUE(same(p.colours(), there.colours()));
    EXPECT_STREQ(p.model_name(), there.model_name());
    EXPECT_EQ(p.shell_name(0), there.shell_name(0));
    Pack none;
    none.moved(b.bytes()); // (nothing open: nothing to move)
    EXPECT_TRUE(none.faces().empty());
}

TEST(Pack, CrcOfAKnownString) { EXPECT_EQ(crc32("123456789", 9), 0xCBF43926u); }

// Tangent edges (SmoothEdges): the bits the packer set read back edge by edge, none past the
// edges or in a pack without the section, where the bytes moved too; a table of another length
// than the edges need is refused, naming the section.
TEST(Pack, SmoothEdgesReadBackEdgeByEdgeAndATableOfTheWrongLengthIsRefused) {
    Buf plain(cube_pack()), marked(cube_pack({1, 7, 11})), other(cube_pack({2}));
    Pack p;
    ASSERT_TRUE(plain.open(p).ok());
    for (uint32_t e = 0; e < 12; ++e) EXPECT_FALSE(p.smooth_edge(e)) << e;
    EXPECT_THROW(plain.section(SectionId::SmoothEdges), std::runtime_error) << "written only when some edge is smooth";
    ASSERT_TRUE(marked.open(p).ok());
    for (uint32_t e = 0; e < 12; ++e) EXPECT_EQ(p.smooth_edge(e), e == 1 || e == 7 || e == 11) << e;
    EXPECT_FALSE(p.smooth_edge(12));
    EXPECT_FALSE(p.smooth_edge(1000));
    Pack q;
    ASSERT_TRUE(other.open(q).ok());
    p.moved(other.bytes()); // (the same layout: the other cube's bits, read where they lie)
    for (uint32_t e = 0; e < 12; ++e) EXPECT_EQ(p.smooth_edge(e), e == 2) << e;

    marked.section(SectionId::SmoothEdges).count = 0; // 12 edges take one word
    marked.reseal();
    const Result r = marked.open(p);
    EXPECT_EQ(r.status, Status::Corrupt);
    EXPECT_STREQ(r.what, "one bit per edge is needed");
    EXPECT_STREQ(r.where.kind, "section SmoothEdges word");
}

// What the model takes on a device (Needs, measured by the packer): read back as written, from
// the pack's head (stored_pack_counts, as facet::model_needs() reads it) and from the pack
// opened, where the bytes moved too; none in a pack without it. A record that is not one, or
// whose values no packer measures, is refused naming the section.
TEST(Pack, NeedsReadBackFromTheHeadAndTheWholeAndBadOnesAreRefused) {
    const Needs n{1200, 3400, 5600, 300, 700, 900};
    Buf with(cube_pack({}, &n)), without(cube_pack());
    Pack p;
    ASSERT_TRUE(with.open(p).ok());
    ASSERT_NE(p.needs(), nullptr);
    EXPECT_EQ(std::memcmp(p.needs(), &n, sizeof n), 0);
    EXPECT_EQ(with.section(SectionId::Needs).offset, sizeof(Header) + with.header().section_count * sizeof(SectionEntry))
        << "first after the table: in the pack's head";
    PackCounts counts;
    LzmaProbs probs;
    ASSERT_TRUE(stored_pack_counts(with.bytes(), with.size, counts, probs).ok());
    EXPECT_TRUE(counts.has_needs);
    EXPECT_EQ(std::memcmp(&counts.needs, &n, sizeof n), 0);
    EXPECT_EQ(counts.faces, 6u);
    for (const std::vector<uint8_t>& file : {lzma_pack(cube_pack({}, &n)), deflate_pack(cube_pack({}, &n))}) {
        const Buf f(file);
        ASSERT_TRUE(stored_pack_counts(f.words.data(), f.size, counts, probs).ok());
        EXPECT_TRUE(counts.has_needs);
        EXPECT_EQ(counts.needs.mesh_triangles, 5600u);
        EXPECT_EQ(counts.edges, 12u);
    }
    Buf other(cube_pack({}, &n));
    p.moved(other.bytes());
    EXPECT_EQ(reinterpret_cast<const uint8_t*>(p.needs()), other.bytes() + other.section(SectionId::Needs).offset);
    ASSERT_TRUE(without.open(p).ok());
    EXPECT_EQ(p.needs(), nullptr);
    ASSERT_TRUE(stored_pack_counts(without.bytes(), without.size, counts, probs).ok());
    EXPECT_FALSE(counts.has_needs);

    auto refused = [&](auto change, const char* what) {
        Buf b(cube_pack({}, &n));
        change(b);
        b.reseal();
        Pack q;
        const Result r = b.open(q);
        EXPECT_EQ(r.status, Status::Corrupt) << what;
        EXPECT_STREQ(r.what, what);
        EXPECT_STREQ(r.where.kind, "section Needs record");
    };
    refused([](Buf& b) { b.section(SectionId::Needs).count = 2; }, "the Needs section is not one record inside the pack");
    refused([](Buf& b) { b.section(SectionId::Needs).record_bytes = 28; }, "the Needs section is not one record inside the pack");
    refused([](Buf& b) { b.record<Needs>(SectionId::Needs, 0).coarse_vertices = 0xFFFFFFFFu; }, "a count of the Needs record is past 2^31");
}

TEST(Pack, TruncatedAtEverySizeIsRefused) {
    const std::vector<uint8_t> good = cube_pack();
    for (size_t n : {size_t(0), size_t(10), sizeof(Header) - 1, sizeof(Header), good.size() / 2, good.size() - 4}) {
        Buf b(std::vector<uint8_t>(good.begin(), good.begin() + long(n)));
        Pack p;
        const Result problem = b.open(p);
        EXPECT_EQ(problem.status, Status::Corrupt) << "size " << n;
        EXPECT_EQ(section_of(problem), 0u);
    }
}

TEST(Pack, BadMagicVersionAndCrc) {
    {
        Buf b(cube_pack());
        b.bytes()[0] = 'X';
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_STREQ(pr.what, "not a facet pack (bad magic)");
    }
    {
        Buf b(cube_pack());
        b.header().version = 9;
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_STREQ(pr.what, "unsupported version");
    }
    {
        Buf b(cube_pack());
        b.bytes()[b.size - 1] ^= 0x40; // flip one bit of the last record
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_STREQ(pr.what, "CRC mismatch");
    }
}

TEST(Pack, BadOffsetsAndRecordSizes) {
    {
        Buf b(cube_pack());
        b.section(SectionId::Faces).offset = b.size - 8; // runs past the end
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_EQ(section_of(pr), uint32_t(SectionId::Faces));
        EXPECT_STREQ(pr.what, "section lies outside the pack (bad offset or count)");
    }
    {
        Buf b(cube_pack());
        b.section(SectionId::Edges).offset += 2; // misaligned
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_STREQ(pr.what, "section offset is not 4-byte aligned");
    }
    {
        Buf b(cube_pack());
        b.section(SectionId::Loops).count = 0xFFFFFFF0u; // overflowing count
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
    }
    {
        Buf b(cube_pack());
        b.section(SectionId::Coedges).record_bytes = 16;
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_STREQ(pr.what, "record size does not match this reader");
    }
}

TEST(Pack, BadIndicesNameTheRecord) {
    struct Case {
        const char* name;
        void (*corrupt)(Buf&);
        SectionId section;
        uint32_t index;
    };
    const Case cases[] = {
        {"face surface", [](Buf& b) { b.record<pack::Face>(SectionId::Faces, 3).surface = 99; }, SectionId::Faces, 3},
        {"face loops", [](Buf& b) { b.record<pack::Face>(SectionId::Faces, 5).first_loop = 6; }, SectionId::Faces, 5},
        {"face colour", [](Buf& b) { b.record<pack::Face>(SectionId::Faces, 0).colour = 7; }, SectionId::Faces, 0},
        {"edge vertex", [](Buf& b) { b.record<Edge>(SectionId::Edges, 11).v1 = 8; }, SectionId::Edges, 11},
        {"edge curve", [](Buf& b) { b.record<Edge>(SectionId::Edges, 2).curve = 12; }, SectionId::Edges, 2},
        {"edge curve past kStraight", [](Buf& b) { b.record<Edge>(SectionId::Edges, 4).curve = kStraight - 1; }, SectionId::Edges, 4},
        {"coedge edge", [](Buf& b) { b.record<Coedge>(SectionId::Coedges, 23) = Coedge::make(12, false, Seam::None); }, SectionId::Coedges, 23},
        {"coedge seam", [](Buf& b) { b.record<Coedge>(SectionId::Coedges, 6) = Coedge::make(1, false, Seam(7)); }, SectionId::Coedges, 6},
        {"face pcurves", [](Buf& b) { b.record<pack::Face>(SectionId::Faces, 1).first_pcurve = 9; }, SectionId::Faces, 1},
        {"loop range", [](Buf& b) { b.record<Loop>(SectionId::Loops, 1).coedge_count = 40; }, SectionId::Loops, 1},
        {"empty loop", [](Buf& b) { b.record<Loop>(SectionId::Loops, 2).coedge_count = 0; }, SectionId::Loops, 2},
        {"shell faces", [](Buf& b) { b.record<Shell>(SectionId::Shells, 0).face_count = 7; }, SectionId::Shells, 0},
        {"instance shell", [](Buf& b) { b.record<Instance>(SectionId::Instances, 0).shell = 1; }, SectionId::Instances, 0},
        {"surface params", [](Buf& b) { b.record<pack::Surface>(SectionId::Surfaces, 2).count = 8; }, SectionId::Surfaces, 2},
        {"surface type", [](Buf& b) { b.record<pack::Surface>(SectionId::Surfaces, 1).type = 42; }, SectionId::Surfaces, 1},
        {"curve dim", [](Buf& b) { b.record<Curve>(SectionId::Curves3, 0).dim = 2; }, SectionId::Curves3, 0},
    };
    for (const Case& c : cases) {
        Buf b(cube_pack());
        c.corrupt(b);
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt) << c.name;
        EXPECT_EQ(section_of(pr), uint32_t(c.section)) << c.name << ": " << text(pr);
        EXPECT_EQ(pr.where.index, c.index) << c.name << ": " << text(pr);
        EXPECT_EQ(p.faces().size(), 0u) << "a refused pack exposes nothing";
    }
}

TEST(Pack, NanAndInfinityAnywhereAreRefused) {
    {
        Buf b(cube_pack());
        b.record<float>(SectionId::Floats, 5) = std::nanf("");
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_EQ(section_of(pr), uint32_t(SectionId::Floats));
        EXPECT_EQ(pr.where.index, 5u);
        EXPECT_EQ(text(pr), "section Floats record 5: a parameter is NaN, infinite or beyond +-1e8");
    }
    {
        Buf b(cube_pack());
        b.record<Vertex>(SectionId::Vertices, 7).p[1] = INFINITY;
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_EQ(section_of(pr), uint32_t(SectionId::Vertices));
    }
    {
        Buf b(cube_pack());
        b.record<float>(SectionId::Floats, 2) = 2e8f; // finite, but no CAD model's
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_EQ(pr.where.index, 2u);
    }
    {
        Buf b(cube_pack());
        b.record<Vertex>(SectionId::Vertices, 3).p[0] = 11; // outside the 10 mm box the header states
        b.reseal();
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
        EXPECT_STREQ(pr.what, "vertex outside the header's bounding box");
    }
    {
        Buf b(cube_pack());
        b.header().bbox_min[0] = std::nanf("");
        Pack p;
        const Result pr = b.open(p);
        EXPECT_EQ(pr.status, Status::Corrupt);
    }
}

TEST(Pack, BSplineHeadsAreChecked) {
    PackWriter w;
    // Degree 3, 4 poles, 8 knots, non-rational: 5 + 8 + 4*3 = 25 floats.
    std::vector<float> good = {3, 4, 8, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1};
    for (int i = 0; i < 12; ++i) good.push_back(float(i));
    w.add_bspline_curve(3, good);
    std::vector<float> bad = good;
    bad[2] = 9; // knot count inconsistent with poles + degree + 1
    w.add_bspline_curve(3, bad);
    Buf b(w.finish());
    Pack p;
    const Result pr = b.open(p);
    EXPECT_EQ(pr.status, Status::Corrupt);
    EXPECT_EQ(section_of(pr), uint32_t(SectionId::Curves3));
    EXPECT_EQ(pr.where.index, 1u);
}

// Knots that decrease or a weight that is not positive: no B-spline, and the span polynomials
// of the fixed-point patches would divide by a negative knot difference (found by the
// tessellation fuzzer). Each is refused and named; the same data in order passes.
TEST(Pack, BSplineKnotsMustNotDecreaseAndWeightsMustBePositive) {
    // Degree 1 x 1, 2 x 2 poles, 4 knots each way, rational: 9 + 8 + 4*4 floats.
    const std::vector<float> good = {1, 1, 2, 2, 4, 4, 1, 0, 0,  0, 0, 1, 1,  0, 0, 2, 2,
                                     0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0,  1, 1, 0.5f, 2};
    std::vector<float> knots = good, weight = good;
    knots[11] = -1; // u knots 0 0 -1 1
    weight[31] = 0;
    for (const auto& [floats, ok] : {std::pair{good, true}, std::pair{knots, false}, std::pair{weight, false}}) {
        PackWriter w;
        w.add_bspline_surface(floats);
        Buf b(w.finish());
        Pack p;
        const Result r = b.open(p);
        if (ok) {
            EXPECT_TRUE(r.ok()) << text(r);
            continue;
        }
        EXPECT_EQ(r.status, Status::Corrupt);
        EXPECT_EQ(section_of(r), uint32_t(SectionId::Surfaces));
        EXPECT_NE(text(r).find("knots decrease or a weight is not positive"), std::string::npos) << text(r);
    }
}

// A placement places a part whole: a rotation (or a rotation and a mirror), orthonormal within
// kPlacementTolerance, entries within +-1e8 (issue 49: one entry at 1e-38, a row of zeros, an
// entry of 1e7 passed and overflowed the view's arithmetic later).
TEST(Pack, APlacementThatIsNoRotationIsRefused) {
    auto with = [](auto change) {
        Buf b(cube_pack());
        change(b.record<Instance>(SectionId::Instances, 0).m);
        b.reseal();
        Pack p;
        return b.open(p);
    };
    for (const auto& change : std::initializer_list<void (*)(float*)>{
             [](float* m) { m[0] = 1e-38f; },                 // a squashed axis
             [](float* m) { m[4] = m[5] = m[6] = m[7] = 0; }, // a row of zeros
             [](float* m) { m[1] = 1e7f; },                   // sheared
             [](float* m) { m[0] = m[5] = m[10] = 2; },       // scaled twice
             [](float* m) { m[1] = 2e-4f; }}) {               // past the tolerance
        const Result r = with(change);
        EXPECT_EQ(r.status, Status::Corrupt);
        EXPECT_EQ(section_of(r), uint32_t(SectionId::Instances));
        EXPECT_EQ(text(r), "section Instances record 0: placement is no rotation (its rows are not unit vectors at right angles: "
                           "a part stretched or flattened)");
    }
    EXPECT_EQ(with([](float* m) { m[3] = std::nanf(""); }).status, Status::Corrupt);
    EXPECT_EQ(with([](float* m) { m[7] = 2e8f; }).status, Status::Corrupt) << "a translation beyond +-1e8";
    // Accepted: a turn (about z by 30 degrees), a mirror, float rounding, a far translation.
    EXPECT_TRUE(with([](float* m) {
                    const float c = 0.8660254f, s = 0.5f;
                    m[0] = c, m[1] = -s, m[4] = s, m[5] = c;
                }).ok());
    EXPECT_TRUE(with([](float* m) { m[0] = -1; }).ok()) << "a mirror";
    EXPECT_TRUE(with([](float* m) { m[1] = 5e-5f; }).ok()) << "within the tolerance";
    EXPECT_TRUE(with([](float* m) { m[3] = 9e7f; }).ok());
}

// A record is read as its own type only (params<T>: checked where assertions are on), and every
// caller takes a frame's sense from left_handed(), in floats, doubles and Q14 integers alike.
TEST(Params, ARecordIsReadAsItsOwnTypeOnly) {
    PackWriter w;
    const uint32_t cylinder = w.add_surface(CylinderParams{axes_at(0, 0, 0), 5});
    const uint32_t circle = w.add_curve(Circle2Params{.origin = {0, 0}, .x = {1, 0}, .y = {0, 1}, .radius = 2});
    (void)w.add_surface(PlaneParams{axes_at(0, 0, 1)});
    const std::vector<uint8_t> bytes = w.finish();
    Pack p;
    ASSERT_TRUE(p.open(bytes.data(), bytes.size()).ok());
    const Surface& s = p.surfaces()[cylinder];
    EXPECT_TRUE(holds<CylinderParams>(s));
    EXPECT_FALSE(holds<PlaneParams>(s));
    EXPECT_FALSE(holds<SphereParams>(s));
    EXPECT_EQ(params<CylinderParams>(p, s).radius, 5.0f);
    EXPECT_EQ(frame_of(p, s).z[2], 1.0f); // every elementary record's frame
    const Curve& c = p.curves2()[circle];
    EXPECT_TRUE(holds<Circle2Params>(c));
    EXPECT_FALSE(holds<Circle3Params>(c)); // (a 2D circle is no 3D one)
#ifndef NDEBUG
    EXPECT_DEATH((void)params<PlaneParams>(p, s), "holds<Params>");
#endif
}

TEST(Params, LeftHandedFramesInEveryArithmetic) {
    const float x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1}, minus_z[3] = {0, 0, -1};
    EXPECT_FALSE(left_handed(x, y, z));
    EXPECT_TRUE(left_handed(x, y, minus_z));
    EXPECT_TRUE(left_handed(Vec3{0, 1, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1})); // x and y swapped
    const int64_t qx[3] = {16384, 0, 0}, qy[3] = {0, 0, 16384}, qz[3] = {0, 16384, 0};
    EXPECT_TRUE(left_handed(qx, qy, qz)); // (1,0,0) x (0,0,1) = (0,-1,0): against z = (0,1,0)
    Frame f = axes_at(3, 4, 5);
    EXPECT_FALSE(left_handed(f));
    f.y[1] = -1;
    EXPECT_TRUE(left_handed(f));
}
