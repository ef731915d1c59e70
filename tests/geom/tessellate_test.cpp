// The tessellation's pieces (edge sampling, face loops, the CDT, refinement, normals) on shapes
// built in code (tests/geom/shapes.h, no Open CASCADE): a plate with holes (planar faces with
// holes, cylinder seams), a sphere (its poles), a torus (two seams), a trimmed B-spline sheet.
// Each mesh is checked for what it must be, not for what it was: watertight (or, open, bounded
// by its loops alone), the volume it encloses within area x tolerance of the exact one, every
// triangle within the tolerance of its surface, a triangle count between what the boundary
// needs and what the surface's curvature allows; and made in pieces it is the mesh made at once.
#include "geom/deviation.h"
#include "geom/face_storage.h"
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "mesh_topology.h"
#include "shapes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace facet;
using namespace facet::geom;
using namespace facet::test;

namespace {

struct Tessellated {
    std::vector<MeshVertex> vertices;
    std::vector<Vec2> uv;
    std::vector<uint32_t> indices;  // three per triangle
    std::vector<uint32_t> face_of;  // per triangle
    std::vector<uint32_t> first_vertex; // per face: its first vertex (then the next face's)
    std::vector<uint32_t> sample_first, sample_count; // per edge: its samples in `samples`
    std::vector<Vec3> samples;      // every edge sample's point
    uint32_t boundary_samples = 0;  // samples around the loops (each coedge's, its ends once)
    uint32_t untangled = 0, slivers = 0; // crossing loops' pieces dropped, slivers made (FaceStats)
};

// The pack's faces tessellated as the device does (its face storage, patches included), in
// pieces of `units` (0: each face at once). An empty string, or what failed.
std::string tessellate(const Pack& pack, float tolerance, uint32_t units, Tessellated& out) {
    TessOptions opt;
    opt.tolerance = tolerance;
    const size_t ne = pack.edges().size();
    std::vector<uint32_t> first(ne);
    std::vector<uint16_t> count(ne);
    std::vector<float> t(1 << 16);
    std::vector<Vec3> p(1 << 16);
    EdgeSamples samples{first, count, t, p};
    if (!sample_edges(pack, opt, samples).ok()) return "edge sampling failed";
    out.samples.assign(p.begin(), p.begin() + samples.used);
    out.sample_first.assign(first.begin(), first.end());
    out.sample_count.assign(count.begin(), count.end());
    for (const pack::Coedge& c : pack.coedges()) out.boundary_samples += count[c.edge()] ? count[c.edge()] - 1 : 0;
    const FaceCapacity capacity{};
    std::vector<uint64_t> memory(face_storage_bytes(capacity) / 8 + 1);
    FaceStorage storage;
    if (!storage.bind(memory.data(), memory.size() * 8, capacity).ok()) return "no face storage";
    std::vector<MeshVertex> mv(1 << 17);
    std::vector<uint32_t> mi(3 << 18);
    std::vector<Vec2> muv(1 << 17);
    Mesh mesh{mv, mi, muv};
    for (uint32_t f = 0; f < pack.faces().size(); ++f) {
        const uint32_t before = mesh.triangle_count;
        out.first_vertex.push_back(mesh.vertex_count);
        FaceJob job;
        job.start(pack, f, samples, opt, storage, mesh);
        Result r;
        while ((r = job.run(units ? units : UINT32_MAX)).status == Status::Busy) {
        }
        if (!r.ok()) return "face " + std::to_string(f) + ": " + r.what;
        out.untangled += job.stats().untangled, out.slivers += job.stats().slivers;
        out.face_of.insert(out.face_of.end(), mesh.triangle_count - before, f);
    }
    out.first_vertex.push_back(mesh.vertex_count);
    out.vertices.assign(mv.begin(), mv.begin() + mesh.vertex_count);
    out.uv.assign(muv.begin(), muv.begin() + mesh.vertex_count);
    out.indices.assign(mi.begin(), mi.begin() + 3 * mesh.triangle_count);
    return "";
}

// A shape's pack, opened from word-aligned memory it keeps (the pack reads it in place).
struct OpenedPack {
    std::vector<uint32_t> words;
    Pack pack;
    bool open(const Bytes& b) {
        words.assign(b.size() / 4 + 1, 0);
        std::memcpy(words.data(), b.data(), b.size());
        return pack.open(words.data(), uint32_t(b.size())).ok();
    }
};

struct Shape {
    const char* name;
    Bytes bytes;
    bool closed;
    double volume;     // exact (closed shapes)
    float curvature;   // the most the surface bends (1/mm): bounds the triangles refinement may add
    int holes;         // of the open sheet's face (its Euler characteristic: 1 - holes)
};

std::vector<Shape> shapes() {
    return {{"plate with holes", plate_with_holes(), true, plate_volume(), 1.0f / 8, 0},
            {"plate with holes 0.1 micron apart", plate_with_holes(kHolesAMicronApart), true, plate_volume(kHolesAMicronApart), 1.0f / 8, 0},
            {"sheet whose side hooks across its top", hooked_sheet(), false, 0, 0.01f, 0},
            {"sphere", sphere(), true, sphere_volume(), 1.0f / kSphereRadius, 0},
            {"torus", torus(), true, torus_volume(), 1.0f / kTorusMinor, 0},
            {"trimmed B-spline", trimmed_bspline(), false, 0, kBentPlateCurvature, 1}};
}

Vec3 corner(const Tessellated& m, uint32_t t, int k) { return m.vertices[m.indices[3 * t + k]].p; }

class Tessellation : public ::testing::TestWithParam<float> {};

} // namespace

// Every shape at three tolerances: the properties the mesh must have.
TEST_P(Tessellation, ShapesAreWatertightWithinToleranceAndSized) {
    const float tol = GetParam();
    for (const Shape& s : shapes()) {
        SCOPED_TRACE(std::string(s.name) + " at " + std::to_string(tol) + " mm");
        OpenedPack opened;
        ASSERT_TRUE(opened.open(s.bytes));
        const Pack& pack = opened.pack;
        Tessellated m;
        ASSERT_EQ(tessellate(pack, tol, 0, m), "");
        const uint32_t triangles = uint32_t(m.face_of.size());
        ASSERT_GT(triangles, 0u);

        // Topology: welded at exactly equal positions (the shared edge samples), no free edge
        // on a closed solid; on the open sheet, free edges only along its loops.
        std::vector<TopoTriangle> topo(triangles);
        double area = 0, volume = 0;
        for (uint32_t t = 0; t < triangles; ++t) {
            topo[t].group = 0, topo[t].face = m.face_of[t];
            const Vec3 a = corner(m, t, 0), b = corner(m, t, 1), c = corner(m, t, 2);
            for (int k = 0; k < 3; ++k) {
                const Vec3 q = corner(m, t, k);
                topo[t].p[k][0] = q.x, topo[t].p[k][1] = q.y, topo[t].p[k][2] = q.z;
            }
            const Vec3 n = cross(b - a, c - a);
            area += 0.5 * std::sqrt(double(dot(n, n)));
            volume += double(dot(a, cross(b, c))) / 6; // the divergence theorem, outward winding
        }
        std::set<std::tuple<float, float, float>> on_loops;
        for (const Vec3& q : m.samples) on_loops.insert({q.x, q.y, q.z});
        uint32_t inner_free = 0;
        const EdgeTopology e = edge_topology(topo, [&](const BadEdge& bad) {
            if (bad.triangles.size() == 1 && (!on_loops.count({bad.a[0], bad.a[1], bad.a[2]}) ||
                                              !on_loops.count({bad.b[0], bad.b[1], bad.b[2]}))) {
                ++inner_free;
            }
        });
        EXPECT_EQ(e.nonmanifold, 0u);
        if (s.closed) {
            EXPECT_EQ(e.free, 0u) << "watertight";
            // Chords and flat triangles cut inside or outside the curved surfaces by at most the
            // tolerance: the enclosed volume is the solid's within area x tolerance.
            EXPECT_NEAR(volume, s.volume, area * tol) << "outward and closed: its volume";
        } else {
            EXPECT_EQ(inner_free, 0u) << "free edges only along the loops";
            EXPECT_EQ(e.free, m.boundary_samples) << "every chord of every loop, once";
            // Euler characteristic of the welded mesh: a disc with `holes` holes.
            std::map<std::tuple<float, float, float>, uint32_t> id;
            std::set<std::pair<uint32_t, uint32_t>> edges;
            for (uint32_t t = 0; t < triangles; ++t) {
                uint32_t v[3];
                for (int k = 0; k < 3; ++k) v[k] = id.emplace(std::make_tuple(topo[t].p[k][0], topo[t].p[k][1], topo[t].p[k][2]), uint32_t(id.size())).first->second;
                for (int k = 0; k < 3; ++k) edges.insert({std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])});
            }
            EXPECT_EQ(int64_t(id.size()) - int64_t(edges.size()) + int64_t(triangles), 1 - s.holes);
        }

        // Every triangle within the tolerance of its face's surface (the shapes' edges lie on
        // their surfaces exactly: no B-rep gap to allow for; a float's rounding does).
        float worst = 0;
        for (uint32_t t = 0; t < triangles; ++t) {
            const Vec3 p[3] = {corner(m, t, 0), corner(m, t, 1), corner(m, t, 2)};
            const Vec2 uv[3] = {m.uv[m.indices[3 * t]], m.uv[m.indices[3 * t + 1]], m.uv[m.indices[3 * t + 2]]};
            worst = std::max(worst, triangle_deviation(pack, m.face_of[t], p, uv, 4));
        }
        EXPECT_LE(worst, tol * 1.001f + 1e-5f) << "the measured deviation";

        // At least what the loops need (a polygon of n chords takes n - 2 triangles, a hole
        // two more); at most four times what the curvature allows: triangles whose sides
        // L sag by L^2 k / 8 = tol cover the area in about area / (0.43 L^2), plus the
        // boundary's own.
        const double L2 = 8 * double(tol) / s.curvature;
        const double most = 4 * (area / (0.43 * L2) + m.boundary_samples);
        EXPECT_GE(double(triangles), double(m.boundary_samples) - 2 * pack.faces().size());
        EXPECT_LE(double(triangles), most) << "triangles for an area of " << area << " mm^2";

        // In pieces (the device's way: a bounded amount of work at a time), the same mesh.
        Tessellated pieces;
        ASSERT_EQ(tessellate(pack, tol, 7, pieces), "");
        ASSERT_EQ(pieces.indices, m.indices);
        ASSERT_EQ(pieces.vertices.size(), m.vertices.size());
        EXPECT_EQ(std::memcmp(pieces.vertices.data(), m.vertices.data(), m.vertices.size() * sizeof(MeshVertex)), 0);
    }
}

INSTANTIATE_TEST_SUITE_P(AtThreeTolerances, Tessellation, ::testing::Values(0.5f, 0.1f, 0.02f));

// Thin tori (a fillet's tube) from a tenth of a millimetre to past their tube's radius: few
// triangles across the tube at the coarser tolerances, where the deviation over a triangle is
// far from the cubic that refinement models on free-form surfaces (a side's sag across the
// tube is a quartic, or the peak is inside): every triangle within the tolerance, measured on
// a grid of twelfths. (Before refinement measured tori on its grid of sixths, these reached
// 1.10 to 1.16 times the tolerance.)
TEST(Tessellation, ThinToriAtCoarseTolerancesStayWithinThem) {
    for (auto [major, minor] : {std::pair{6.0f, 2.0f}, std::pair{12.0f, 1.0f}}) {
        OpenedPack opened;
        ASSERT_TRUE(opened.open(torus(major, minor)));
        for (float tol = 0.1f; tol < 3.0f; tol *= 1.13f) {
            SCOPED_TRACE("tube " + std::to_string(minor) + " mm about " + std::to_string(major) + " mm at " + std::to_string(tol) + " mm");
            Tessellated m;
            ASSERT_EQ(tessellate(opened.pack, tol, 0, m), "");
            float worst = 0;
            for (uint32_t t = 0; t < m.face_of.size(); ++t) {
                const Vec3 p[3] = {corner(m, t, 0), corner(m, t, 1), corner(m, t, 2)};
                const Vec2 uv[3] = {m.uv[m.indices[3 * t]], m.uv[m.indices[3 * t + 1]], m.uv[m.indices[3 * t + 2]]};
                worst = std::max(worst, triangle_deviation(opened.pack, m.face_of[t], p, uv, 12));
            }
            EXPECT_LE(worst, tol * 1.001f + 1e-5f) << "the measured deviation";
        }
    }
}

// Loops the CDT's grid cannot keep apart (geom/src/tangles.cpp), at every tolerance: the sheet
// whose side hooks back across its top drops the hook as slivers (the face is not lost), the
// plate whose holes are 0.1 micron apart stitches its two holes' loops where they touch in the
// grid (the shell stays closed: ShapesAreWatertightWithinToleranceAndSized checks both meshes).
TEST(Tessellation, LoopsThatCrossOrTouchInTheGridAreMeshedAllTheSame) {
    for (float tol : {1.0f, 0.1f, 0.01f}) {
        SCOPED_TRACE(std::to_string(tol) + " mm");
        OpenedPack hooked, thin;
        ASSERT_TRUE(hooked.open(hooked_sheet()));
        ASSERT_TRUE(thin.open(plate_with_holes(kHolesAMicronApart)));
        Tessellated a, b, c;
        ASSERT_EQ(tessellate(hooked.pack, tol, 0, a), "");
        EXPECT_EQ(a.untangled, 1u) << "the hook, one piece";
        EXPECT_EQ(a.slivers, 2u) << "its two points";
        ASSERT_EQ(tessellate(thin.pack, tol, 0, b), "");
        OpenedPack apart;
        ASSERT_TRUE(apart.open(plate_with_holes()));
        ASSERT_EQ(tessellate(apart.pack, tol, 0, c), "");
        EXPECT_GT(b.slivers, c.slivers) << "stitches where the holes touch (the cylinders' seams make slivers in both)";
        EXPECT_EQ(b.untangled, 0u);
    }
}

// A finer tolerance never gives fewer triangles (refinement only adds points where needed, and
// the edges are sampled at least as finely).
TEST(Tessellation, AFinerToleranceGivesNoFewerTriangles) {
    for (const Shape& s : shapes()) {
        OpenedPack opened;
        ASSERT_TRUE(opened.open(s.bytes));
        const Pack& pack = opened.pack;
        size_t last = 0;
        for (float tol : {1.0f, 0.3f, 0.1f, 0.03f}) {
            Tessellated m;
            ASSERT_EQ(tessellate(pack, tol, 0, m), "") << s.name;
            EXPECT_GE(m.face_of.size(), last) << s.name << " at " << tol << " mm";
            last = m.face_of.size();
        }
    }
}

// Every sample of a face's drawn coedges (not a seam, not a pole) is a vertex of the face, the
// same bits: the edge drawn over the face and the face's own vertices are one set of points, as
// the face on the other side of the edge has them too (the painter's projection cache projects
// each once in a frame, module/src/painter.h; and the mesh is watertight along the edge).
TEST(Tessellation, BoundaryVerticesAreTheirEdgesSamples) {
    uint32_t checked = 0; // (a sphere's or a torus's face has no edge drawn: seams and poles)
    for (const Shape& s : shapes()) {
        for (float tol : {3.0f, 0.5f, 0.05f}) {
            SCOPED_TRACE(std::string(s.name) + " at " + std::to_string(tol) + " mm");
            OpenedPack opened;
            ASSERT_TRUE(opened.open(s.bytes));
            const Pack& pack = opened.pack;
            Tessellated m;
            ASSERT_EQ(tessellate(pack, tol, 0, m), "");
            auto bits = [](Vec3 a) {
                std::array<uint32_t, 3> b;
                std::memcpy(b.data(), &a, sizeof a);
                return b;
            };
            for (uint32_t f = 0; f < pack.faces().size(); ++f) {
                const pack::Face& F = pack.faces()[f];
                std::set<std::array<uint32_t, 3>> vertices;
                for (uint32_t v = m.first_vertex[f]; v < m.first_vertex[f + 1]; ++v) vertices.insert(bits(m.vertices[v].p));
                for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
                    const pack::Loop& L = pack.loops()[l];
                    for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
                        const pack::Coedge& C = pack.coedges()[c];
                        const uint32_t e = C.edge();
                        if (C.seam() != pack::Seam::None || pack.edges()[e].curve == pack::kNoIndex) continue; // no edge drawn
                        for (uint32_t k = 0; k < m.sample_count[e]; ++k, ++checked) {
                            EXPECT_TRUE(vertices.count(bits(m.samples[m.sample_first[e] + k])))
                                << "face " << f << ", edge " << e << ": sample " << k << " is no vertex of the face";
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 0u);
}

// A B-spline edge its chord stands for (every pole within the tolerance of it, running along
// it, each leg of the control polygon within half the angle of its direction) is its two
// vertices, whichever way the edge runs along its curve; a bulge past the tolerance, or legs
// turning more than the angle allows, samples it adaptively. Every sample lies on the curve
// and every chord within the tolerance of it.
TEST(EdgeSampling, AB_SplineItsChordStandsForIsItsTwoVertices) {
    // A cubic from (0, 0, 0) to (30, 0, 0), its middle poles at height h: the curve bulges 0.75 h.
    auto sampled = [](float h, float tolerance, float max_angle, bool reversed) {
        PackWriter w;
        std::vector<float> curve = {3, 4, 8, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1};
        for (float x : {0.0f, 10.0f, 20.0f, 30.0f}) curve.insert(curve.end(), {x, x == 0 || x == 30 ? 0.0f : h, 0});
        const uint32_t c = w.add_bspline_curve(3, curve);
        const uint32_t a = w.add_vertex(0, 0, 0), b = w.add_vertex(30, 0, 0);
        w.add_edge(reversed ? pack::Edge{c, 1, 0, b, a, 0, 0} : pack::Edge{c, 0, 1, a, b, 0, 0});
        OpenedPack opened;
        EXPECT_TRUE(opened.open(w.finish()));
        TessOptions opt;
        opt.tolerance = tolerance, opt.max_angle = max_angle;
        std::vector<uint32_t> first(1);
        std::vector<uint16_t> count(1);
        std::vector<float> t(4096);
        std::vector<Vec3> p(4096);
        EdgeSamples samples{first, count, t, p};
        EXPECT_TRUE(sample_edges(opened.pack, opt, samples).ok());
        std::vector<Vec3> out(p.begin(), p.begin() + count[0]);
        for (size_t k = 0; k + 1 < out.size(); ++k) { // each chord within the tolerance of the curve
            for (int q = 1; q < 8; ++q) {
                const float s = t[k] + (t[k + 1] - t[k]) * float(q) / 8, u = 1 - s;
                const Vec3 on{30 * (3 * u * u * s / 3 + 2 * 3 * u * s * s / 3 + s * s * s), 3 * u * s * h, 0}; // the cubic at s
                const Vec3 d = out[k + 1] - out[k], off = on - out[k];
                const float along = std::clamp(dot(off, d) / dot(d, d), 0.0f, 1.0f);
                EXPECT_LE(std::sqrt(length2(off - d * along)), tolerance * 1.001f) << "h " << h << " piece " << k;
            }
        }
        return out;
    };
    for (bool reversed : {false, true}) {
        const std::vector<Vec3> flat = sampled(0.5f, 1.0f, 1.0f, reversed); // bulge 0.375, poles 0.5 off: within 1 mm
        ASSERT_EQ(flat.size(), 2u) << (reversed ? "reversed" : "");
        EXPECT_EQ(flat[reversed ? 1 : 0].x, 0.0f);
        EXPECT_EQ(flat[reversed ? 0 : 1].x, 30.0f);
        EXPECT_GT(sampled(2.0f, 1.0f, 1.0f, reversed).size(), 2u) << "poles 2 mm off the chord: past 1 mm";
        EXPECT_GT(sampled(0.5f, 1.0f, 0.05f, reversed).size(), 2u) << "legs turning 2.9 degrees: past half of 0.05 rad";
    }
}
