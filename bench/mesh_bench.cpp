// facet-bench-mesh: facet's on-device tessellation (geom/ + cdt/) side by side with Open
// CASCADE's BRepMesh_IncrementalMesh, on the same healed shapes, at the same linear deflection
// (0.1% and 1% of the bounding-box diagonal; angular 0.5 rad), measured by the same code:
//   max deviation  7 points per triangle (its centroid and the thirds of its edges, so chords
//                  of boundary edges count too) projected onto the face's exact surface (OCCT)
//   free / non-manifold edges, per part, after welding vertices at exactly equal positions;
//                  edges where two faces of the B-rep overlap apart (geom/host/mesh_topology.h)
//   small-angle share  triangles with an angle under 5 degrees
// Each distinct part (prototype) is meshed once by both, as a viewer would. A third row per
// deflection, facet@equal, is facet at the largest tolerance whose measured deviation does not
// exceed BRepMesh's measured deviation: the two meshes compared at equal measured deviation.
//
//   facet-bench-mesh MODEL.step... [--csv FILE]
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "mesh_topology.h"
#include "occt_to_pack.h"
#include "pack_writer.h"
#include "step_reader.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Precision.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

using namespace facet;

namespace {

struct Tri {
    float p[3][3];
    uint32_t face; // index into the face list the mesh is measured against
    uint32_t part; // which part (shell) it belongs to, for the topology
};

struct Measure {
    double ms = 0, max_deviation = 0, small_angle_share = 0, tolerance = 0;
    uint64_t triangles = 0, free_edges = 0, nonmanifold_edges = 0, overlap_edges = 0, faces_failed = 0;
};

// One projector per face, set up once (its search grid is the costly part on free-form faces).
class Projectors {
public:
    explicit Projectors(const std::vector<TopoDS_Shape>& faces)
        : faces_(faces), proj_(faces.size()), surf_(faces.size()), bounded_(faces.size()) {}
    double distance(uint32_t face, const gp_Pnt& p) {
        if (!proj_[face]) {
            surf_[face] = BRep_Tool::Surface(TopoDS::Face(faces_[face]));
            double u0, u1, v0, v1;
            surf_[face]->Bounds(u0, u1, v0, v1);
            if (Precision::IsInfinite(u0) || Precision::IsInfinite(u1) || Precision::IsInfinite(v0) || Precision::IsInfinite(v1)) {
                bounded_[face] = false; // elementary: solved in closed form, set up on each call
            } else {
                bounded_[face] = true;
                proj_[face] = std::make_unique<GeomAPI_ProjectPointOnSurf>();
                proj_[face]->Init(surf_[face], u0, u1, v0, v1);
            }
            if (!bounded_[face]) proj_[face] = std::make_unique<GeomAPI_ProjectPointOnSurf>();
        }
        if (!bounded_[face]) {
            GeomAPI_ProjectPointOnSurf once(p, surf_[face]);
            return once.NbPoints() > 0 ? once.LowerDistance() : 0.0;
        }
        proj_[face]->Perform(p);
        return proj_[face]->NbPoints() > 0 ? proj_[face]->LowerDistance() : 0.0;
    }

private:
    const std::vector<TopoDS_Shape>& faces_;
    std::vector<std::unique_ptr<GeomAPI_ProjectPointOnSurf>> proj_;
    std::vector<Handle(Geom_Surface)> surf_;
    std::vector<char> bounded_;
};

void measure(const std::vector<Tri>& tris, Projectors& proj, Measure& m) {
    m.triangles = tris.size();
    std::vector<geom::TopoTriangle> soup;
    soup.reserve(tris.size());
    uint64_t thin = 0;
    for (const Tri& t : tris) {
        geom::TopoTriangle& s = soup.emplace_back();
        s.group = t.part;
        s.face = t.face;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) s.p[k][c] = t.p[k][c];
        gp_Pnt P[3] = {{t.p[0][0], t.p[0][1], t.p[0][2]}, {t.p[1][0], t.p[1][1], t.p[1][2]}, {t.p[2][0], t.p[2][1], t.p[2][2]}};
        double minang = 180;
        for (int k = 0; k < 3; ++k) {
            gp_Vec a(P[k], P[(k + 1) % 3]), b(P[k], P[(k + 2) % 3]);
            if (a.Magnitude() > 0 && b.Magnitude() > 0) minang = std::min(minang, a.Angle(b) * 180 / M_PI);
            else minang = 0;
        }
        thin += minang < 5;
        // The centroid and the points at a third and two thirds of each edge.
        static constexpr double kW[7][3] = {{1. / 3, 1. / 3, 1. / 3}, {2. / 3, 1. / 3, 0}, {1. / 3, 2. / 3, 0}, {0, 2. / 3, 1. / 3},
                                            {0, 1. / 3, 2. / 3}, {1. / 3, 0, 2. / 3}, {2. / 3, 0, 1. / 3}};
        for (const auto& w : kW) {
            const gp_Pnt x(w[0] * P[0].XYZ() + w[1] * P[1].XYZ() + w[2] * P[2].XYZ());
            m.max_deviation = std::max(m.max_deviation, proj.distance(t.face, x));
        }
    }
    const geom::EdgeTopology topo = geom::edge_topology(soup);
    m.free_edges = topo.free;
    m.nonmanifold_edges = topo.nonmanifold;
    m.overlap_edges = topo.overlap;
    m.small_angle_share = tris.empty() ? 0 : double(thin) / double(tris.size());
}

void run_brepmesh(const std::vector<TopoDS_Shape>& prototypes, double deflection, Measure& m) {
    std::vector<TopoDS_Shape> faces;
    std::vector<Tri> tris;
    double ms = 0;
    for (uint32_t part = 0; part < prototypes.size(); ++part) {
        TopoDS_Shape shape = BRepBuilderAPI_Copy(prototypes[part]).Shape();
        BRepTools::Clean(shape);
        const auto t0 = std::chrono::steady_clock::now();
        BRepMesh_IncrementalMesh mesher(shape, deflection, false, 0.5, false);
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        for (TopExp_Explorer x(shape, TopAbs_FACE); x.More(); x.Next()) {
            const TopoDS_Face face = TopoDS::Face(x.Current());
            TopLoc_Location loc;
            Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
            if (tri.IsNull()) {
                ++m.faces_failed;
                continue;
            }
            const uint32_t fi = uint32_t(faces.size());
            faces.push_back(face);
            const gp_Trsf tr = loc.Transformation();
            for (int i = 1; i <= tri->NbTriangles(); ++i) {
                int n[3];
                tri->Triangle(i).Get(n[0], n[1], n[2]);
                Tri t{};
                t.face = fi;
                t.part = part;
                for (int k = 0; k < 3; ++k) {
                    const gp_Pnt p = tri->Node(n[k]).Transformed(tr);
                    t.p[k][0] = float(p.X()), t.p[k][1] = float(p.Y()), t.p[k][2] = float(p.Z());
                }
                tris.push_back(t);
            }
        }
    }
    Projectors proj(faces);
    measure(tris, proj, m);
    m.ms = ms;
    m.tolerance = deflection;
}

bool run_facet(const std::vector<uint8_t>& bytes, Projectors& proj, double deflection, Measure& m) {
    std::vector<uint32_t> aligned((bytes.size() + 3) / 4);
    std::memcpy(aligned.data(), bytes.data(), bytes.size());
    geom::Pack pack;
    if (!pack.open(aligned.data(), uint32_t(bytes.size())).ok()) return false;
    geom::TessOptions opt;
    opt.tolerance = float(deflection);
    const size_t ne = pack.edges().size();
    std::vector<uint32_t> ef(ne);
    std::vector<uint16_t> ec(ne);
    std::vector<float> et(ne * 256 + 1024);
    std::vector<geom::Vec3> ep(ne * 256 + 1024);
    // One face's storage as the device's, patches included: the comparison measures the
    // device's own path (fixed-point patches), not the float one.
    const geom::FaceCapacity capacity{31996, 4096, 4096, geom::kPatchCacheWords};
    std::vector<uint64_t> face_memory(geom::face_storage_bytes(capacity) / 8 + 1);
    geom::FaceStorage sc;
    if (!sc.bind(face_memory.data(), face_memory.size() * 8, capacity).ok()) return false;
    std::vector<geom::MeshVertex> mv(1 << 21);
    std::vector<uint32_t> mi(3u << 21);
    std::vector<Tri> tris;
    // Timed as the fastest of a few runs (a run is a few milliseconds).
    double best_ms = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
    tris.clear();
    m.faces_failed = 0;
    const auto t0 = std::chrono::steady_clock::now();
    geom::EdgeSamples samples{ef, ec, et, ep};
    if (!geom::sample_edges(pack, opt, samples).ok()) return false;
    for (uint32_t part = 0; part < pack.shells().size(); ++part) {
        const pack::Shell& sh = pack.shells()[part];
        geom::Mesh mesh{mv, mi, {}};
        std::vector<uint32_t> face_of;
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            const uint32_t before = mesh.triangle_count;
            geom::FaceStats st;
            if (!geom::tessellate_face(pack, f, samples, opt, sc, mesh, st).ok()) ++m.faces_failed;
            for (uint32_t t = before; t < mesh.triangle_count; ++t) face_of.push_back(f);
        }
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            Tri tr{};
            tr.face = face_of[t];
            tr.part = part;
            for (int k = 0; k < 3; ++k) {
                const geom::Vec3 p = mesh.vertices[mesh.indices[3 * t + k]].p;
                tr.p[k][0] = p.x, tr.p[k][1] = p.y, tr.p[k][2] = p.z;
            }
            tris.push_back(tr);
        }
    }
    best_ms = std::min(best_ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    measure(tris, proj, m);
    m.ms = best_ms;
    m.tolerance = deflection;
    return true;
}

} // namespace

int main(int argc, char** argv) {
    std::string csv;
    std::vector<std::string> models;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
        else models.push_back(argv[i]);
    }
    if (models.empty()) {
        std::fprintf(stderr, "usage: facet-bench-mesh MODEL.step... [--csv FILE]\n");
        return 2;
    }
    FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
    if (out) {
        std::fprintf(out, "model,impl,deflection,ms,triangles,max_deviation,free_edges,nonmanifold_edges,small_angle_share,"
                          "tolerance,faces_failed,overlap_edges\n");
    }
    std::printf("%-22s %-12s %10s %10s %9s %10s %11s %6s %6s %6s %6s %6s\n", "model", "impl", "deflection", "tolerance", "ms",
                "triangles", "max_dev", "free", "nonman", "overlap", "thin%", "failed");
    for (const std::string& path : models) {
        packer::StepModel model;
        std::string error;
        const std::string name = path.substr(path.find_last_of('/') + 1);
        if (!packer::read_step(path, model, error, true)) {
            std::printf("%-22s skipped: %s\n", name.c_str(), error.c_str());
            continue;
        }
        geom::PackWriter writer;
        packer::Stats stats;
        packer::Packer packer(writer, model.colours, stats);
        for (const packer::Part& p : model.parts) packer.add_occurrence(p.shape, p.closed);
        const std::vector<uint8_t> bytes = writer.finish();
        const pack::Header* h = reinterpret_cast<const pack::Header*>(bytes.data());
        const double diag = std::sqrt(std::pow(h->bbox_max[0] - h->bbox_min[0], 2) + std::pow(h->bbox_max[1] - h->bbox_min[1], 2) +
                                      std::pow(h->bbox_max[2] - h->bbox_min[2], 2));
        Projectors proj(packer.packed_faces);
        for (double frac : {0.001, 0.01}) {
            const double defl = frac * diag;
            Measure mf, mb;
            if (!run_facet(bytes, proj, defl, mf)) continue;
            run_brepmesh(packer.prototypes, defl, mb);
            // facet at equal measured deviation: the largest tolerance (a few secant steps on
            // tolerance ~ deviation) whose deviation stays within BRepMesh's, equal within float
            // noise (a plane meshed by both deviates by ~1e-7 of its size).
            const double target = std::max(mb.max_deviation, 1e-4 * defl);
            Measure eq = mf;
            bool met = mf.max_deviation <= target;
            double t = defl;
            Measure last = mf;
            for (int step = 0; step < 5 && last.max_deviation > 0; ++step) {
                const double ratio = target / last.max_deviation;
                if (last.max_deviation <= target && ratio < 1.03) break; // close enough below
                t *= last.max_deviation <= target ? ratio : 0.97 * ratio;
                // Searched within [deflection / 200, 10 x deflection]: BRepMesh far under its own
                // deflection (its angular limit) or a planar model (any tolerance gives the same
                // mesh) stop at the ends.
                const double clamped = std::clamp(t, defl / 200, 10 * defl);
                if (clamped != t && (t = clamped) == last.tolerance) break;
                Measure m;
                if (!run_facet(bytes, proj, t, m)) break;
                // Only a mesh as complete as facet's own at the deflection counts.
                // (Free edges are not compared: an open shell's boundary has more of them when it
                // is sampled finer.)
                const bool complete = m.faces_failed <= mf.faces_failed && m.nonmanifold_edges <= mf.nonmanifold_edges;
                if (complete && m.max_deviation <= target && (!met || m.tolerance > eq.tolerance)) eq = m, met = true;
                last = m;
            }
            const std::pair<const char*, const Measure*> rows[] = {{"facet", &mf}, {"brepmesh", &mb}, {met ? "facet@equal" : "facet@equal?", &eq}};
            for (const auto& [impl, m] : rows) {
                std::printf("%-22s %-12s %10.4f %10.4f %9.1f %10llu %11.4f %6llu %6llu %7llu %6.1f %6llu\n", name.c_str(), impl,
                            defl, m->tolerance, m->ms, (unsigned long long)m->triangles, m->max_deviation,
                            (unsigned long long)m->free_edges, (unsigned long long)m->nonmanifold_edges,
                            (unsigned long long)m->overlap_edges, 100 * m->small_angle_share, (unsigned long long)m->faces_failed);
                if (out) {
                    std::fprintf(out, "%s,%s,%.6f,%.3f,%llu,%.6f,%llu,%llu,%.4f,%.6f,%llu,%llu\n", name.c_str(), impl, defl, m->ms,
                                 (unsigned long long)m->triangles, m->max_deviation, (unsigned long long)m->free_edges,
                                 (unsigned long long)m->nonmanifold_edges, m->small_angle_share, m->tolerance,
                                 (unsigned long long)m->faces_failed, (unsigned long long)m->overlap_edges);
                }
            }
            std::fflush(stdout);
        }
    }
    if (out) std::fclose(out);
    return 0;
}
