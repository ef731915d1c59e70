// facet-bench-mesh: facet's on-device tessellation (geom/ + cdt/) side by side with Open
// CASCADE's BRepMesh_IncrementalMesh, on the same healed shapes, at the same linear deflection
// (0.1% and 1% of the bounding-box diagonal; angular 0.5 rad), measured by the same code:
//   max deviation  triangle centroids projected onto the face's exact surface (OCCT)
//   free / non-manifold edges after welding vertices at exactly equal positions
//   small-angle share  triangles with an angle under 5 degrees
// Each distinct part (prototype) is meshed once by both, as a viewer would.
//
//   facet-bench-mesh MODEL.step... [--csv FILE]
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "occt_to_pack.h"
#include "pack_writer.h"
#include "step_reader.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace facet;

namespace {

struct Tri {
    float p[3][3];
    uint32_t face; // index into the face list the mesh was measured against
};

struct Measure {
    double ms = 0, max_deviation = 0, small_angle_share = 0;
    uint64_t triangles = 0, free_edges = 0, nonmanifold_edges = 0, faces_failed = 0;
};

void measure(const std::vector<Tri>& tris, const std::vector<TopoDS_Shape>& faces, Measure& m) {
    m.triangles = tris.size();
    std::map<std::tuple<float, float, float>, uint32_t> weld;
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    uint64_t thin = 0;
    std::vector<Handle(Geom_Surface)> surf(faces.size());
    for (size_t f = 0; f < faces.size(); ++f) surf[f] = BRep_Tool::Surface(TopoDS::Face(faces[f]));
    for (const Tri& t : tris) {
        uint32_t id[3];
        for (int k = 0; k < 3; ++k) id[k] = weld.emplace(std::make_tuple(t.p[k][0], t.p[k][1], t.p[k][2]), uint32_t(weld.size())).first->second;
        for (int k = 0; k < 3; ++k) {
            uint32_t a = id[k], b = id[(k + 1) % 3];
            if (a > b) std::swap(a, b);
            if (a != b) ++uses[{a, b}];
        }
        gp_Pnt P[3] = {{t.p[0][0], t.p[0][1], t.p[0][2]}, {t.p[1][0], t.p[1][1], t.p[1][2]}, {t.p[2][0], t.p[2][1], t.p[2][2]}};
        double minang = 180;
        for (int k = 0; k < 3; ++k) {
            gp_Vec a(P[k], P[(k + 1) % 3]), b(P[k], P[(k + 2) % 3]);
            if (a.Magnitude() > 0 && b.Magnitude() > 0) minang = std::min(minang, a.Angle(b) * 180 / M_PI);
            else minang = 0;
        }
        thin += minang < 5;
        const gp_Pnt c((P[0].XYZ() + P[1].XYZ() + P[2].XYZ()) / 3);
        GeomAPI_ProjectPointOnSurf proj(c, surf[t.face]);
        if (proj.NbPoints() > 0) m.max_deviation = std::max(m.max_deviation, proj.LowerDistance());
    }
    for (auto& [e, n] : uses) {
        m.free_edges += n == 1;
        m.nonmanifold_edges += n > 2;
    }
    m.small_angle_share = tris.empty() ? 0 : double(thin) / double(tris.size());
}

void run_brepmesh(const std::vector<TopoDS_Shape>& prototypes, double deflection, Measure& m) {
    std::vector<TopoDS_Shape> faces;
    std::vector<Tri> tris;
    double ms = 0;
    for (const TopoDS_Shape& proto : prototypes) {
        TopoDS_Shape shape = BRepBuilderAPI_Copy(proto).Shape();
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
                for (int k = 0; k < 3; ++k) {
                    const gp_Pnt p = tri->Node(n[k]).Transformed(tr);
                    t.p[k][0] = float(p.X()), t.p[k][1] = float(p.Y()), t.p[k][2] = float(p.Z());
                }
                tris.push_back(t);
            }
        }
    }
    measure(tris, faces, m);
    m.ms = ms;
}

bool run_facet(const std::vector<uint8_t>& bytes, const std::vector<TopoDS_Shape>& packed_faces, double deflection, Measure& m) {
    std::vector<uint32_t> aligned((bytes.size() + 3) / 4);
    std::memcpy(aligned.data(), bytes.data(), bytes.size());
    geom::Pack pack;
    geom::PackProblem problem;
    if (pack.open(aligned.data(), uint32_t(bytes.size()), problem) != Status::Ok) return false;
    geom::TessOptions opt;
    opt.tolerance = float(deflection);
    const size_t ne = pack.edges().size();
    std::vector<uint32_t> ef(ne);
    std::vector<uint16_t> ec(ne);
    std::vector<float> et(ne * 256 + 1024);
    std::vector<geom::Vec3> ep(ne * 256 + 1024);
    constexpr size_t kV = 32000;
    std::vector<cdt::Vertex<uint16_t>> av(kV);
    std::vector<cdt::Triangle<uint16_t>> at(cdt::triangles_for(kV));
    std::vector<uint16_t> aw(cdt::work_for(kV)), ao(kV), am(kV), ai(kV);
    std::vector<uint32_t> ak(kV), ls(4096), mo(kV);
    std::vector<cdt::Point> lp(kV), ip(kV);
    std::vector<geom::Vec2> uv(kV);
    std::vector<geom::Vec3> xyz(kV);
    std::vector<uint8_t> pin(kV);
    std::vector<uint64_t> passed(cdt::triangles_for(kV));
    geom::FaceScratch sc{{av, at, aw, ao, am, ai, ak}, lp, ls, ip, uv, pin, xyz, mo, passed};
    std::vector<geom::MeshVertex> mv(1 << 21);
    std::vector<uint32_t> mi(3u << 21);
    std::vector<Tri> tris;
    const auto t0 = std::chrono::steady_clock::now();
    geom::EdgeSamples samples{ef, ec, et, ep};
    if (geom::sample_edges(pack, opt, samples) != Status::Ok) return false;
    for (const pack::Shell& sh : pack.shells()) {
        geom::Mesh mesh{mv, mi, {}};
        std::vector<uint32_t> face_of;
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            const uint32_t before = mesh.triangle_count;
            const geom::FaceResult r = geom::tessellate_face(pack, f, samples, opt, sc, mesh);
            if (!ok(r.status)) ++m.faces_failed;
            for (uint32_t t = before; t < mesh.triangle_count; ++t) face_of.push_back(f);
        }
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            Tri tr{};
            tr.face = face_of[t];
            for (int k = 0; k < 3; ++k) {
                const geom::Vec3 p = mesh.vertices[mesh.indices[3 * t + k]].p;
                tr.p[k][0] = p.x, tr.p[k][1] = p.y, tr.p[k][2] = p.z;
            }
            tris.push_back(tr);
        }
    }
    m.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    measure(tris, packed_faces, m);
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
    if (out) std::fprintf(out, "model,impl,deflection,ms,triangles,max_deviation,free_edges,nonmanifold_edges,small_angle_share,faces_failed\n");
    std::printf("%-22s %-9s %10s %9s %10s %11s %6s %6s %6s %6s\n", "model", "impl", "deflection", "ms", "triangles", "max_dev", "free", "nonman", "thin%", "failed");
    for (const std::string& path : models) {
        packer::StepModel model;
        std::string error;
        if (!packer::read_step(path, model, error, true)) {
            std::printf("%-22s skipped: %s\n", path.substr(path.find_last_of('/') + 1).c_str(), error.c_str());
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
        const std::string name = path.substr(path.find_last_of('/') + 1);
        for (double frac : {0.001, 0.01}) {
            const double defl = frac * diag;
            Measure mf, mb;
            if (!run_facet(bytes, packer.packed_faces, defl, mf)) continue;
            run_brepmesh(packer.prototypes, defl, mb);
            for (auto& [impl, m] : {std::pair<const char*, Measure&>{"facet", mf}, {"brepmesh", mb}}) {
                std::printf("%-22s %-9s %10.4f %9.1f %10llu %11.4f %6llu %6llu %6.1f %6llu\n", name.c_str(), impl, defl, m.ms,
                            (unsigned long long)m.triangles, m.max_deviation, (unsigned long long)m.free_edges,
                            (unsigned long long)m.nonmanifold_edges, 100 * m.small_angle_share, (unsigned long long)m.faces_failed);
                if (out) std::fprintf(out, "%s,%s,%.6f,%.3f,%llu,%.6f,%llu,%llu,%.4f,%llu\n", name.c_str(), impl, defl, m.ms,
                                      (unsigned long long)m.triangles, m.max_deviation, (unsigned long long)m.free_edges,
                                      (unsigned long long)m.nonmanifold_edges, m.small_angle_share, (unsigned long long)m.faces_failed);
            }
            std::fflush(stdout);
        }
    }
    if (out) std::fclose(out);
    return 0;
}
