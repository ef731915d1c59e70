// facet-mesh: pack -> triangles with the device's geom/ and cdt/ code, written as STL, OBJ or
// PLY, with a report: faces, failed faces (and why), triangles, the deviation from the exact
// surfaces, free and non-manifold edges, the share of thin triangles, time.
//
//   facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM] [--angle RAD] [--faces]
//              [--pieces UNITS]
// --pieces: each face tessellated in pieces of UNITS (geom::FaceJob), as the device does; the
// mesh must be the very one made at once.
//
// Measured once per shell (a part placed several times is one mesh): the deviation on a
// barycentric grid in every triangle and along its edges (geom/deviation.h); the topology
// after welding the shell's vertices at exactly equal positions: a free edge has one triangle,
// a non-manifold edge more than two. A closed shell (a solid) is watertight when it has
// neither and no face failed.
#include "geom/deviation.h"
#include "hal/print.h"
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "mesh_topology.h"
#include "pack_io.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

struct Output {
    std::vector<Vec3> p, n;
    std::vector<uint32_t> tri;
    std::vector<uint32_t> tri_shell_face; // per triangle: (instance, face) for deviation
};

int die(const std::string& m) {
    std::fprintf(stderr, "facet-mesh: error: %s\n", m.c_str());
    return 1;
}

Vec3 place(const float* m, Vec3 p) {
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}
Vec3 turn(const float* m, Vec3 n) {
    return normalized({m[0] * n.x + m[1] * n.y + m[2] * n.z, m[4] * n.x + m[5] * n.y + m[6] * n.z,
                       m[8] * n.x + m[9] * n.y + m[10] * n.z});
}

bool write_stl(const std::string& path, const Output& o) {
    std::ofstream f(path, std::ios::binary);
    char header[80] = "facet-mesh";
    f.write(header, 80);
    const uint32_t n = uint32_t(o.tri.size() / 3);
    f.write(reinterpret_cast<const char*>(&n), 4);
    for (uint32_t t = 0; t < n; ++t) {
        const Vec3 a = o.p[o.tri[3 * t]], b = o.p[o.tri[3 * t + 1]], c = o.p[o.tri[3 * t + 2]];
        const Vec3 nn = normalized(cross(b - a, c - a));
        const float rec[12] = {nn.x, nn.y, nn.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
        f.write(reinterpret_cast<const char*>(rec), 48);
        const uint16_t attr = 0;
        f.write(reinterpret_cast<const char*>(&attr), 2);
    }
    return bool(f);
}

bool write_obj(const std::string& path, const Output& o) {
    std::ofstream f(path);
    f << "# facet-mesh\n";
    for (size_t i = 0; i < o.p.size(); ++i) f << "v " << o.p[i].x << ' ' << o.p[i].y << ' ' << o.p[i].z << '\n';
    for (size_t i = 0; i < o.n.size(); ++i) f << "vn " << o.n[i].x << ' ' << o.n[i].y << ' ' << o.n[i].z << '\n';
    for (size_t t = 0; t + 2 < o.tri.size(); t += 3)
        f << "f " << o.tri[t] + 1 << "//" << o.tri[t] + 1 << ' ' << o.tri[t + 1] + 1 << "//" << o.tri[t + 1] + 1 << ' '
          << o.tri[t + 2] + 1 << "//" << o.tri[t + 2] + 1 << '\n';
    return bool(f);
}

bool write_ply(const std::string& path, const Output& o) {
    std::ofstream f(path);
    f << "ply\nformat ascii 1.0\nelement vertex " << o.p.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << o.tri.size() / 3 << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (size_t i = 0; i < o.p.size(); ++i)
        f << o.p[i].x << ' ' << o.p[i].y << ' ' << o.p[i].z << ' ' << o.n[i].x << ' ' << o.n[i].y << ' ' << o.n[i].z << '\n';
    for (size_t t = 0; t + 2 < o.tri.size(); t += 3) f << "3 " << o.tri[t] << ' ' << o.tri[t + 1] << ' ' << o.tri[t + 2] << '\n';
    return bool(f);
}

} // namespace

int main(int argc, char** argv) {
    const char* in = nullptr;
    std::string out, format, json;
    float tolerance = 0, angle = 0;
    bool quiet = false, per_face = false;
    uint32_t pieces = 0; // units per piece; 0: each face at once
    const char* usage = "usage: facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM] [--angle RAD] [--faces] [--pieces UNITS] [--quiet]";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "--stl" || a == "--obj" || a == "--ply") && i + 1 < argc) format = a.substr(2), out = argv[++i];
        else if (a == "--json" && i + 1 < argc) json = argv[++i];
        else if (a == "--tolerance" && i + 1 < argc) tolerance = std::strtof(argv[++i], nullptr);
        else if (a == "--angle" && i + 1 < argc) angle = std::strtof(argv[++i], nullptr);
        else if (a == "--quiet") quiet = true;
        else if (a == "--pieces" && i + 1 < argc) pieces = uint32_t(std::strtoul(argv[++i], nullptr, 10));
        else if (a == "--faces") per_face = true;
        else if (a[0] != '-' && !in) in = argv[i];
        else return die(usage);
    }
    if (!in) return die(usage);
    LoadedPack file;
    std::string error;
    if (!load_pack_file(in, file, error)) return die(std::string(in) + ": " + error);
    Pack pack;
    char text[200];
    if (const Result r = pack.open(file.data(), file.bytes); !r.ok()) {
        describe(r, text, sizeof text);
        return die(std::string(in) + ": " + text);
    }

    TessOptions opt;
    opt.tolerance = tolerance > 0 ? tolerance : default_tolerance(pack);
    if (angle > 0) opt.max_angle = angle;

    // Buffers: edge samples (once per edge, shared by every face and instance), the device's
    // 16-bit CDT arena at its largest, one shell's mesh.
    const size_t ne = pack.edges().size();
    std::vector<uint32_t> ef(ne);
    std::vector<uint16_t> ec(ne);
    std::vector<float> et(ne * 64 + 1024);
    std::vector<Vec3> ep(ne * 64 + 1024);
    constexpr size_t kV = 32000;
    std::vector<cdt::Vertex<uint16_t>> av(kV);
    std::vector<cdt::Triangle<uint16_t>> at(cdt::triangles_for(kV));
    std::vector<uint16_t> aw(cdt::work_for(kV)), ao(kV), am(kV), ai(kV);
    std::vector<uint32_t> ak(kV);
    std::vector<cdt::Point> lp(kV);
    std::vector<uint32_t> ls(4096), mesh_of(kV);
    std::vector<Vec2> uvs(kV);
    std::vector<Vec3> xyz(kV);
    std::vector<uint8_t> pinned(kV);
    std::vector<TriangleMeasure> measured(cdt::triangles_for(kV));
    std::vector<Sliver> slivers(4096);
    FaceScratch sc{{av, at, aw, ao, am, ai, ak}, lp, ls, uvs, pinned, xyz, mesh_of, measured, slivers};
    std::vector<MeshVertex> mv(1 << 22);
    std::vector<uint32_t> mi(3u << 22);
    std::vector<Vec2> muv(1 << 22);

    // Tessellate each shell once (timed: edge sampling and every face).
    struct ShellMesh {
        std::vector<MeshVertex> v;
        std::vector<Vec2> uv;
        std::vector<uint32_t> tri, face; // 3 indices per triangle; its face
    };
    std::vector<ShellMesh> shells(pack.shells().size());
    uint32_t faces = 0, failed = 0;
    std::map<std::string, uint32_t> reasons;
    std::vector<std::string> failures;
    const auto t_start = std::chrono::steady_clock::now();
    EdgeSamples samples{ef, ec, et, ep};
    if (const Result r = sample_edges(pack, opt, samples); !r.ok()) {
        describe(r, text, sizeof text);
        return die(std::string("edge sampling: ") + text);
    }
    for (uint32_t s = 0; s < pack.shells().size(); ++s) {
        const pack::Shell& sh = pack.shells()[s];
        Mesh mesh{mv, mi, muv};
        ShellMesh& out_shell = shells[s];
        for (uint32_t fi = sh.first_face; fi < sh.first_face + sh.face_count; ++fi) {
            const uint32_t before = mesh.triangle_count;
            FaceStats st;
            Result r;
            if (pieces) { // as the device: a piece at a time
                FaceJob job;
                job.start(pack, fi, samples, opt, sc, mesh);
                while ((r = job.run(pieces)).status == Status::Busy) {
                }
                st = job.stats();
            } else {
                r = tessellate_face(pack, fi, samples, opt, sc, mesh, st);
            }
            ++faces;
            if (!r.ok()) {
                ++failed;
                ++reasons[r.what];
                describe(r, text, sizeof text);
                failures.push_back(std::string(text) + " (" + status_name(r.status) + ")");
                continue;
            }
            for (uint32_t t = before; t < mesh.triangle_count; ++t) out_shell.face.push_back(fi);
            if (per_face) {
                std::printf("face %u: surface type %u, %u points, %u triangles\n", fi,
                            pack.surfaces()[pack.faces()[fi].surface].type, st.points, st.triangles);
            }
        }
        out_shell.v.assign(mv.begin(), mv.begin() + mesh.vertex_count);
        out_shell.uv.assign(muv.begin(), muv.begin() + mesh.vertex_count);
        out_shell.tri.assign(mi.begin(), mi.begin() + mesh.triangle_count * 3);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();

    // Measure each shell.
    double max_dev = 0;
    std::map<uint32_t, double> face_dev;
    uint32_t free_edges = 0, nonmanifold = 0, overlap = 0, thin = 0, shell_triangles = 0, closed = 0, watertight = 0;
    for (uint32_t s = 0; s < shells.size(); ++s) {
        const ShellMesh& m = shells[s];
        const uint32_t nt = uint32_t(m.tri.size() / 3);
        const uint32_t overlap_before = overlap;
        shell_triangles += nt;
        for (uint32_t t = 0; t < nt; ++t) {
            const uint32_t* id = &m.tri[3 * t];
            const Vec3 p[3] = {m.v[id[0]].p, m.v[id[1]].p, m.v[id[2]].p};
            const Vec2 uv[3] = {m.uv[id[0]], m.uv[id[1]], m.uv[id[2]]};
            const double d = triangle_deviation(pack, m.face[t], p, uv);
            max_dev = std::max(max_dev, d);
            face_dev[m.face[t]] = std::max(face_dev[m.face[t]], d);
            float ang[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
                const float la = length(a), lb = length(b);
                ang[k] = la > 0 && lb > 0 ? std::acos(std::clamp(dot(a, b) / (la * lb), -1.0f, 1.0f)) : 0.0f;
            }
            if (std::min({ang[0], ang[1], ang[2]}) < 5.0f * 3.14159265f / 180) ++thin;
        }
        std::vector<TopoTriangle> soup(nt);
        for (uint32_t t = 0; t < nt; ++t) {
            soup[t].group = 0;
            soup[t].face = m.face[t];
            for (int k = 0; k < 3; ++k) {
                const Vec3 q = m.v[m.tri[3 * t + k]].p;
                soup[t].p[k][0] = q.x, soup[t].p[k][1] = q.y, soup[t].p[k][2] = q.z;
            }
        }
        uint32_t listed = 0;
        const EdgeTopology topo = edge_topology(soup, [&](const BadEdge& e) {
            if (!per_face || listed++ >= 40) return;
            std::printf("  %s edge (%g %g %g)-(%g %g %g), faces", e.triangles.size() == 1 ? "free" : "non-manifold", e.a[0], e.a[1],
                        e.a[2], e.b[0], e.b[1], e.b[2]);
            for (uint32_t t : e.triangles) std::printf(" %u", m.face[t]);
            std::printf("\n");
        });
        const uint32_t fr = uint32_t(topo.free), nm = uint32_t(topo.nonmanifold);
        overlap += uint32_t(topo.overlap);
        free_edges += fr, nonmanifold += nm;
        if (pack.shells()[s].closed) {
            ++closed;
            const pack::Shell& sh = pack.shells()[s];
            bool all_faces = true;
            for (uint32_t fi = sh.first_face; fi < sh.first_face + sh.face_count; ++fi)
                all_faces = all_faces && std::find(m.face.begin(), m.face.end(), fi) != m.face.end();
            if (!fr && !nm && all_faces) ++watertight;
            else if (!quiet) std::fprintf(stderr, "facet-mesh: closed shell %u is not watertight: %u free, %u non-manifold edges%s\n", s, fr, nm, all_faces ? "" : ", a face failed");
            if (overlap > overlap_before && !quiet) {
                std::fprintf(stderr, "facet-mesh: closed shell %u: %u edges where two of its faces overlap in the B-rep\n", s,
                             overlap - overlap_before);
            }
        }
    }

    // The model: every instance of every shell, placed.
    Output o;
    for (const pack::Instance& inst : pack.instances()) {
        const ShellMesh& m = shells[inst.shell];
        const uint32_t base = uint32_t(o.p.size());
        for (const MeshVertex& v : m.v) {
            o.p.push_back(place(inst.m, v.p));
            o.n.push_back(turn(inst.m, v.n));
        }
        for (uint32_t k : m.tri) o.tri.push_back(base + k);
    }
    const uint32_t ntri = uint32_t(o.tri.size() / 3);
    float max_edge_tolerance = 0; // the B-rep's loosest edge
    for (const pack::Edge& e : pack.edges()) max_edge_tolerance = std::max(max_edge_tolerance, e.tolerance);
    const double thin_share = shell_triangles ? double(thin) / shell_triangles : 0;
    if (!out.empty()) {
        const bool okw = format == "stl" ? write_stl(out, o) : format == "obj" ? write_obj(out, o) : write_ply(out, o);
        if (!okw) return die("cannot write " + out);
    }
    std::printf("%s: %u faces, %u failed, %u triangles (%u per distinct part), max deviation %.4f mm (tolerance %.4f), "
                "free edges %u, non-manifold edges %u (+%u where faces overlap), closed shells watertight %u of %u, thin (<5 deg) %.1f%%, %.1f ms\n",
                in, faces, failed, ntri, shell_triangles, max_dev, opt.tolerance, free_edges, nonmanifold, overlap, watertight, closed,
                100 * thin_share, ms);
    for (auto& [r, n] : reasons) std::printf("  %u faces: %s\n", n, r.c_str());
    if (!quiet) {
        for (const std::string& f : failures) std::fprintf(stderr, "facet-mesh: %s\n", f.c_str());
        for (auto& [fi, d] : face_dev) {
            if (d > opt.tolerance) {
                // Where the B-rep itself is loose (its edges' own tolerance over the mesh's), the
                // edges' samples can be that far from the surface.
                const pack::Face& F = pack.faces()[fi];
                float loose = 0;
                for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l)
                    for (uint32_t c = pack.loops()[l].first_coedge; c < pack.loops()[l].first_coedge + pack.loops()[l].coedge_count; ++c)
                        loose = std::max(loose, pack.edges()[pack.coedges()[c].edge()].tolerance);
                std::printf("  face %u (surface type %u): deviation %.4f mm over the tolerance; its edges' B-rep tolerance %.4g mm\n", fi,
                            pack.surfaces()[F.surface].type, d, loose);
            }
        }
    }
    if (!json.empty()) {
        std::ofstream j(json);
        j << "{\"faces\": " << faces << ", \"faces_failed\": " << failed << ", \"triangles\": " << ntri
          << ", \"part_triangles\": " << shell_triangles << ", \"max_deviation\": " << max_dev
          << ", \"tolerance\": " << opt.tolerance << ", \"free_edges\": " << free_edges
          << ", \"nonmanifold_edges\": " << nonmanifold << ", \"overlap_edges\": " << overlap << ", \"closed_shells\": " << closed
          << ", \"watertight_closed_shells\": " << watertight << ", \"small_angle_share\": " << thin_share
          << ", \"max_edge_tolerance\": " << max_edge_tolerance << ", \"ms\": " << ms << "}\n";
    }
    return 0;
}
