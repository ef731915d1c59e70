// facet-mesh: pack -> triangles with the device's geom/ and cdt/ code, written as STL, OBJ or
// PLY, with a report: faces, failed faces (and why), triangles, the deviation from the exact
// surfaces, free and non-manifold edges, the share of thin triangles, time.
//
//   facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM]
#include "geom/pack.h"
#include "geom/tessellate.h"

#include <algorithm>
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
    float tolerance = 0;
    bool quiet = false, per_face = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "--stl" || a == "--obj" || a == "--ply") && i + 1 < argc) format = a.substr(2), out = argv[++i];
        else if (a == "--json" && i + 1 < argc) json = argv[++i];
        else if (a == "--tolerance" && i + 1 < argc) tolerance = std::strtof(argv[++i], nullptr);
        else if (a == "--quiet") quiet = true;
        else if (a == "--faces") per_face = true;
        else if (a[0] != '-') in = argv[i];
        else return die("usage: facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM]");
    }
    if (!in) return die("usage: facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM]");
    std::ifstream f(in, std::ios::binary);
    if (!f) return die(std::string("cannot open ") + in);
    std::vector<char> bytes((std::istreambuf_iterator<char>(f)), {});
    std::vector<uint32_t> aligned((bytes.size() + 3) / 4);
    std::memcpy(aligned.data(), bytes.data(), bytes.size());
    Pack pack;
    PackProblem problem;
    if (pack.open(aligned.data(), uint32_t(bytes.size()), problem) != Status::Ok) return die(std::string(in) + ": " + problem.message);

    TessOptions opt;
    opt.tolerance = tolerance > 0 ? tolerance : default_tolerance(pack);
    const auto t_start = std::chrono::steady_clock::now();

    // Edge samples (once per edge, shared by every face and instance).
    const size_t ne = pack.edges().size();
    std::vector<uint32_t> ef(ne);
    std::vector<uint16_t> ec(ne);
    std::vector<float> et(ne * 64 + 1024);
    std::vector<Vec3> ep(ne * 64 + 1024);
    EdgeSamples samples{ef, ec, et, ep};
    if (sample_edges(pack, opt, samples) != Status::Ok) return die("edge sample pool full");

    // Per-face scratch: the device's 16-bit CDT arena at its largest.
    constexpr size_t kV = 32000;
    std::vector<cdt::Vertex<uint16_t>> av(kV);
    std::vector<cdt::Triangle<uint16_t>> at(cdt::triangles_for(kV));
    std::vector<uint16_t> aw(cdt::work_for(kV)), ao(kV), am(kV), ai(kV);
    std::vector<uint32_t> ak(kV);
    std::vector<cdt::Point> lp(kV), ip(kV);
    std::vector<uint32_t> ls(4096), mesh_of(kV);
    std::vector<Vec2> uvs(kV);
    std::vector<Vec3> xyz(kV);
    std::vector<uint8_t> pinned(kV);
    std::vector<uint64_t> passed(cdt::triangles_for(kV));
    FaceScratch sc{{av, at, aw, ao, am, ai, ak}, lp, ls, ip, uvs, pinned, xyz, mesh_of, passed};

    // Mesh per shell, then placed per instance.
    std::vector<MeshVertex> mv(1 << 22);
    std::vector<uint32_t> mi(3u << 22);
    std::vector<Vec2> muv(1 << 22);
    Output o;
    uint32_t faces = 0, failed = 0;
    double max_dev = 0;
    std::map<std::string, uint32_t> reasons;
    std::vector<int> shell_done(pack.shells().size(), 0);
    std::map<uint32_t, double> face_dev;
    for (const pack::Instance& inst : pack.instances()) {
        const pack::Shell& sh = pack.shells()[inst.shell];
        Mesh mesh{mv, mi, muv};
        std::vector<uint32_t> tri_face;
        for (uint32_t fi = sh.first_face; fi < sh.first_face + sh.face_count; ++fi) {
            const uint32_t before = mesh.triangle_count;
            const FaceResult r = tessellate_face(pack, fi, samples, opt, sc, mesh);
            const bool first_time = !shell_done[inst.shell];
            if (first_time) ++faces;
            if (!ok(r.status)) {
                if (first_time) {
                    ++failed;
                    ++reasons[r.reason];
                    if (!quiet) std::fprintf(stderr, "facet-mesh: face %u not triangulated: %s (%s)\n", fi, r.reason, status_name(r.status));
                }
                continue;
            }
            for (uint32_t t = before; t < mesh.triangle_count; ++t) tri_face.push_back(fi);
            if (per_face && first_time) {
                std::printf("face %u: surface type %u, %u points, %u triangles\n", fi,
                            pack.surfaces()[pack.faces()[fi].surface].type, r.points, r.triangles);
            }
        }
        shell_done[inst.shell] = 1;
        // Deviation: each triangle's centroid against the surface at its interpolated (u,v).
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            const uint32_t* id = &mesh.indices[3 * t];
            const pack::Face& F = pack.faces()[tri_face[t]];
            const pack::Surface& S = pack.surfaces()[F.surface];
            const Vec3 c = (mesh.vertices[id[0]].p + mesh.vertices[id[1]].p + mesh.vertices[id[2]].p) * (1.0f / 3);
            const Vec2 guess = (mesh.uv[id[0]] + mesh.uv[id[1]] + mesh.uv[id[2]]) * (1.0f / 3);
            const bool wraps = !is_elementary(S) && u_periodic(S) && (std::fabs(mesh.uv[id[0]].x - mesh.uv[id[1]].x) > 3 ||
                                                                      std::fabs(mesh.uv[id[1]].x - mesh.uv[id[2]].x) > 3);
            if (!wraps) {
                Vec2 uv;
                const double d = surface_deviation(pack, tri_face[t], c, guess, uv);
                max_dev = std::max(max_dev, d);
                face_dev[tri_face[t]] = std::max(face_dev[tri_face[t]], d);
            }
        }
        const uint32_t base = uint32_t(o.p.size());
        for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
            o.p.push_back(place(inst.m, mesh.vertices[v].p));
            o.n.push_back(turn(inst.m, mesh.vertices[v].n));
        }
        for (uint32_t k = 0; k < mesh.triangle_count * 3; ++k) o.tri.push_back(base + mesh.indices[k]);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();

    // Topology of the welded mesh: vertices equal to the bit are one.
    std::map<std::tuple<float, float, float>, uint32_t> weld;
    std::vector<uint32_t> id(o.p.size());
    for (size_t i = 0; i < o.p.size(); ++i) id[i] = weld.emplace(std::make_tuple(o.p[i].x, o.p[i].y, o.p[i].z), uint32_t(weld.size())).first->second;
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    uint32_t thin = 0;
    for (size_t t = 0; t + 2 < o.tri.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            uint32_t a = id[o.tri[t + k]], b = id[o.tri[t + (k + 1) % 3]];
            if (a > b) std::swap(a, b);
            ++uses[{a, b}];
        }
        const Vec3 A = o.p[o.tri[t]], B = o.p[o.tri[t + 1]], C = o.p[o.tri[t + 2]];
        const float ang[3] = {std::acos(std::clamp(dot(normalized(B - A), normalized(C - A)), -1.0f, 1.0f)),
                              std::acos(std::clamp(dot(normalized(A - B), normalized(C - B)), -1.0f, 1.0f)),
                              std::acos(std::clamp(dot(normalized(A - C), normalized(B - C)), -1.0f, 1.0f))};
        if (std::min({ang[0], ang[1], ang[2]}) < 5.0f * 3.14159265f / 180) ++thin;
    }
    uint32_t free_edges = 0, nonmanifold = 0;
    for (auto& [e, n] : uses) {
        if (e.first == e.second) continue;
        free_edges += n == 1;
        nonmanifold += n > 2;
    }
    const uint32_t ntri = uint32_t(o.tri.size() / 3);
    const double thin_share = ntri ? double(thin) / ntri : 0;
    if (!out.empty()) {
        const bool okw = format == "stl" ? write_stl(out, o) : format == "obj" ? write_obj(out, o) : write_ply(out, o);
        if (!okw) return die("cannot write " + out);
    }
    std::printf("%s: %u faces, %u failed, %u triangles, max deviation %.4f mm (tolerance %.4f), free edges %u, "
                "non-manifold edges %u, thin (<5 deg) %.1f%%, %.1f ms\n",
                in, faces, failed, ntri, max_dev, opt.tolerance, free_edges, nonmanifold, 100 * thin_share, ms);
    for (auto& [r, n] : reasons) std::printf("  %u faces: %s\n", n, r.c_str());
    if (!quiet) {
        for (auto& [fi, d] : face_dev) {
            if (d > opt.tolerance) {
                std::printf("  face %u (surface type %u): deviation %.4f mm over the tolerance\n", fi,
                            pack.surfaces()[pack.faces()[fi].surface].type, d);
            }
        }
    }
    if (!json.empty()) {
        std::ofstream j(json);
        j << "{\"faces\": " << faces << ", \"faces_failed\": " << failed << ", \"triangles\": " << ntri
          << ", \"max_deviation\": " << max_dev << ", \"tolerance\": " << opt.tolerance << ", \"free_edges\": " << free_edges
          << ", \"nonmanifold_edges\": " << nonmanifold << ", \"small_angle_share\": " << thin_share << ", \"ms\": " << ms << "}\n";
    }
    return 0;
}
