// facet-mesh: pack -> triangles with the device's geom/ and cdt/ code, written as STL, OBJ or
// PLY, with a report: faces, failed faces (and why), triangles, the deviation from the exact
// surfaces, free and non-manifold edges, the share of thin triangles, time.
//
//   facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM | --finer N] [--angle RAD] [--faces]
//              [--pieces UNITS] [--face-points N] [--quiet]
// --pieces: each face tessellated in pieces of UNITS (geom::FaceJob), as the device does; the
// mesh must be the very one made at once. --face-points: the CDT arena's capacity in points
// (default and most: 32,760, the 16-bit arena), to try a device's smaller one.
//
// Exit codes: 0 a complete mesh within the tolerance; 1 error (bad input, a failed write);
// 2 usage; 5 incomplete mesh (a face failed or a closed shell is not watertight); 6 a face
// strays further from its surface than the tolerance plus the B-rep's own gap there (its
// edges' tolerance: a file whose curves miss its surfaces). With 5 or 6 the outputs are written.
//
// Measured once per shell (a part placed several times is one mesh): the deviation on a
// barycentric grid in every triangle and along its edges (geom/deviation.h); the topology
// after welding the shell's vertices at exactly equal positions: a free edge has one triangle,
// a non-manifold edge more than two. A closed shell (a solid) is watertight when it has
// neither and no face failed.
#include "geom/deviation.h"
#include "geom/measure.h"
#include "core/format.h"
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "file_io.h"
#include "mesh_topology.h"
#include "edge_pool.h"
#include "pack_io.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
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

// The mesh as a binary STL, an OBJ or a PLY, in memory (the write is then checked as a whole).
std::string stl(const Output& o) {
    std::string f(80, '\0');
    std::memcpy(f.data(), "facet-mesh", 10);
    const uint32_t n = uint32_t(o.tri.size() / 3);
    f.append(reinterpret_cast<const char*>(&n), 4);
    for (uint32_t t = 0; t < n; ++t) {
        const Vec3 a = o.p[o.tri[3 * t]], b = o.p[o.tri[3 * t + 1]], c = o.p[o.tri[3 * t + 2]];
        const Vec3 nn = normalized(cross(b - a, c - a));
        const float rec[12] = {nn.x, nn.y, nn.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
        f.append(reinterpret_cast<const char*>(rec), 48);
        f.append(2, '\0'); // attribute bytes
    }
    return f;
}

std::string obj(const Output& o) {
    std::ostringstream f;
    f << "# facet-mesh\n";
    for (size_t i = 0; i < o.p.size(); ++i) f << "v " << o.p[i].x << ' ' << o.p[i].y << ' ' << o.p[i].z << '\n';
    for (size_t i = 0; i < o.n.size(); ++i) f << "vn " << o.n[i].x << ' ' << o.n[i].y << ' ' << o.n[i].z << '\n';
    for (size_t t = 0; t + 2 < o.tri.size(); t += 3)
        f << "f " << o.tri[t] + 1 << "//" << o.tri[t] + 1 << ' ' << o.tri[t + 1] + 1 << "//" << o.tri[t + 1] + 1 << ' '
          << o.tri[t + 2] + 1 << "//" << o.tri[t + 2] + 1 << '\n';
    return f.str();
}

std::string ply(const Output& o) {
    std::ostringstream f;
    f << "ply\nformat ascii 1.0\nelement vertex " << o.p.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << o.tri.size() / 3 << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (size_t i = 0; i < o.p.size(); ++i)
        f << o.p[i].x << ' ' << o.p[i].y << ' ' << o.p[i].z << ' ' << o.n[i].x << ' ' << o.n[i].y << ' ' << o.n[i].z << '\n';
    for (size_t t = 0; t + 2 < o.tri.size(); t += 3) f << "3 " << o.tri[t] << ' ' << o.tri[t + 1] << ' ' << o.tri[t + 2] << '\n';
    return f.str();
}

// A number for an option, all of the text, finite and within [lo, hi]; else a message.
bool number(const char* option, const char* text, double lo, double hi, double& out, std::string& error) {
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(out) || out < lo || out > hi) {
        std::ostringstream m;
        m << option << " " << text << ": a number from " << lo << " to " << hi << " is needed";
        error = m.str();
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    const char* in = nullptr;
    std::string out, format, json;
    double tolerance = 0, angle = 0, face_points = 32760, pieces = 0, finer = 0; // pieces: units per piece; 0: each face at once
    bool quiet = false, per_face = false;
    const char* usage = "usage: facet-mesh MODEL.fpk [--stl|--obj|--ply FILE] [--json REPORT] [--tolerance MM | --finer N] [--angle RAD] [--faces] "
                        "[--pieces UNITS] [--face-points N] [--quiet]";
    std::string error;
    auto bad = [&](const std::string& m) {
        std::fprintf(stderr, "facet-mesh: error: %s\n", m.c_str());
        return 2;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if ((a == "--stl" || a == "--obj" || a == "--ply") && has_value && out.empty()) format = a.substr(2), out = argv[++i];
        else if (a == "--json" && has_value && json.empty()) json = argv[++i];
        else if (a == "--tolerance" && has_value) {
            if (!number("--tolerance", argv[++i], 1e-9, 1e9, tolerance, error)) return bad(error + " (millimetres, more than 0)");
        } else if (a == "--finer" && has_value) { // the viewer's level of detail N steps finer
            if (!number("--finer", argv[++i], 0, 3, finer, error)) return bad(error);
            if (finer != std::floor(finer)) return bad("--finer: a whole number of steps, 0 to 3");
        } else if (a == "--angle" && has_value) {
            if (!number("--angle", argv[++i], 1e-3, 3.14159, angle, error)) return bad(error + " (radians)");
        } else if (a == "--pieces" && has_value) {
            if (!number("--pieces", argv[++i], 1, 1e9, pieces, error)) return bad(error);
        } else if (a == "--face-points" && has_value) {
            if (!number("--face-points", argv[++i], 16, 32760, face_points, error)) return bad(error);
        } else if (a == "--quiet") quiet = true;
        else if (a == "--faces") per_face = true;
        else if (!a.empty() && a[0] != '-' && !in) in = argv[i];
        else return bad(usage);
    }
    if (!in) return bad(usage);
    for (const std::string* o : {&out, &json}) {
        if (!o->empty() && host::same_file(in, *o)) return bad("the output " + *o + " is the pack itself: it would be overwritten");
    }
    if (!out.empty() && !json.empty() && (out == json || host::same_file(out, json))) return bad("the mesh and the report would be one file");
    LoadedPack file;
    if (!load_pack_file(in, file, error)) return die(error);
    Pack pack;
    char text[200];
    if (const Result r = pack.open(file.data(), file.bytes); !r.ok()) {
        describe(r, text, sizeof text);
        return die(std::string(in) + ": " + text);
    }

    TessOptions opt;
    const float default_tol = model_tolerance(file, pack); // the viewer's default (its box: the file's)
    opt.tolerance = tolerance > 0 ? float(tolerance) : default_tol;
    // The viewer's Finer key halves the tolerance, down to an eighth (the same float).
    for (int k = 0; k < int(finer); ++k) opt.tolerance *= 0.5f;
    if (angle > 0) opt.max_angle = float(angle);

    // Buffers: edge samples (once per edge, shared by every face and instance; the pool grows
    // until it holds them), the device's 16-bit CDT arena, one shell's mesh.
    const size_t ne = pack.edges().size();
    EdgePool edges;
    const auto t_start = std::chrono::steady_clock::now();
    if (const Result r = edges.sample(pack, opt, ne * 64 + 1024); !r.ok()) {
        describe(r, text, sizeof text);
        // Say which tolerance does work: the first of 4x, 16x, ... coarser that samples.
        std::string hint;
        for (float t = opt.tolerance * 4; r.status == Status::Full && t < 1e9f; t *= 4) {
            TessOptions o = opt;
            o.tolerance = t;
            EdgeSamples trial{edges.first, edges.count, edges.t, edges.p};
            if (sample_edges(pack, o, trial).ok()) {
                char h[120];
                std::snprintf(h, sizeof h, "; --tolerance %.4g mm samples every edge (the default is %.4g mm)", t, default_tol);
                hint = h;
                break;
            }
        }
        return die(std::string("edge sampling at --tolerance ") + std::to_string(opt.tolerance) + " mm: " + text + hint);
    }
    const EdgeSamples& samples = edges.samples;
    // One face's storage as the device's (its patches too: the same meshes), at this capacity.
    const FaceCapacity capacity{uint32_t(face_points), uint32_t(face_points), 4096, kPatchCacheWords};
    std::vector<uint64_t> face_memory(face_storage_bytes(capacity) / 8 + 1);
    FaceStorage sc;
    if (Result r = sc.bind(face_memory.data(), face_memory.size() * 8, capacity); !r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        return die(text);
    }
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
    std::set<uint32_t> failed_face;
    uint32_t full_faces = 0; // failed for want of room
    std::vector<std::string> failures;
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
                while ((r = job.run(uint32_t(pieces))).status == Status::Busy) {
                }
                st = job.stats();
            } else {
                r = tessellate_face(pack, fi, samples, opt, sc, mesh, st);
            }
            ++faces;
            if (!r.ok()) {
                ++failed;
                failed_face.insert(fi);
                full_faces += r.status == Status::Full;
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
    struct ThinCount {
        uint32_t triangles = 0, thin = 0;
    };
    std::map<uint8_t, ThinCount> by_type; // per surface type
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
            const uint8_t type = pack.surfaces()[pack.faces()[m.face[t]].surface].type;
            ++by_type[type].triangles;
            if (std::min({ang[0], ang[1], ang[2]}) < 5.0f * 3.14159265f / 180) ++thin, ++by_type[type].thin;
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
            // (A face may rightly have no triangle: one with no area at this tolerance. A whole
            // solid may not: no triangles have no free edges, and are no mesh of it.)
            bool all_faces = true;
            for (uint32_t fi = sh.first_face; fi < sh.first_face + sh.face_count; ++fi) all_faces = all_faces && !failed_face.count(fi);
            const bool empty = m.tri.empty();
            if (!fr && !nm && all_faces && !empty) ++watertight;
            else if (!quiet) {
                std::fprintf(stderr, "facet-mesh: closed shell %u is not watertight: %u free, %u non-manifold edges%s%s\n", s, fr, nm,
                             all_faces ? "" : ", a face failed", empty ? ", no triangles at all" : "");
            }
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
    // A face's allowance: the tolerance, plus how far the B-rep's own edges stray from its
    // surface (their tolerance: a file whose curves and surfaces disagree; the edges' samples
    // lie on the curves). Within it everywhere, the mesh is as close as the B-rep allows.
    auto looseness = [&](uint32_t fi) {
        const pack::Face& F = pack.faces()[fi];
        float loose = 0;
        for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l)
            for (uint32_t c = pack.loops()[l].first_coedge; c < pack.loops()[l].first_coedge + pack.loops()[l].coedge_count; ++c)
                loose = std::max(loose, pack.edges()[pack.coedges()[c].edge()].tolerance);
        return loose;
    };
    double worst_ratio = 0; // deviation / allowance, over the faces
    uint32_t loose_faces = 0, over_faces = 0;
    for (auto& [fi, d] : face_dev) {
        const float loose = looseness(fi);
        loose_faces += loose > opt.tolerance;
        const double ratio = d / (opt.tolerance + loose);
        worst_ratio = std::max(worst_ratio, ratio);
        over_faces += ratio > 1;
    }
    if (!out.empty()) {
        const std::string bytes = format == "stl" ? stl(o) : format == "obj" ? obj(o) : ply(o);
        if (!host::write_file(out, bytes, error)) return die(error);
    }
    std::printf("%s: %u faces, %u failed, %u triangles (%u per distinct part), max deviation %.4g mm (tolerance %.4g), "
                "free edges %u, non-manifold edges %u (+%u where faces overlap), closed shells watertight %u of %u, thin (<5 deg) %.1f%%, %.1f ms\n",
                in, faces, failed, ntri, shell_triangles, max_dev, opt.tolerance, free_edges, nonmanifold, overlap, watertight, closed,
                100 * thin_share, ms);
    for (auto& [r, n] : reasons) std::printf("  %u faces: %s\n", n, r.c_str());
    if (full_faces) {
        std::printf("  %u faces need more than one face's capacity (%zu points) at %.4g mm: a coarser --tolerance "
                    "meshes them (the default is %.4g mm)\n", full_faces, size_t(face_points), opt.tolerance, default_tol);
    }
    if (!quiet) {
        for (const std::string& f : failures) std::fprintf(stderr, "facet-mesh: %s\n", f.c_str());
        for (auto& [fi, d] : face_dev) {
            if (d > opt.tolerance) {
                const float loose = looseness(fi);
                std::printf("  face %u (surface type %u): deviation %.4g mm over the tolerance; its edges' B-rep tolerance %.4g mm: %s\n", fi,
                            pack.surfaces()[pack.faces()[fi].surface].type, d, loose,
                            d <= opt.tolerance + loose ? "within the two together (the B-rep's own gap)" : "OVER both together");
            }
        }
    }
    if (!json.empty()) {
        std::ostringstream j;
        j << "{\"faces\": " << faces << ", \"faces_failed\": " << failed << ", \"triangles\": " << ntri
          << ", \"part_triangles\": " << shell_triangles << ", \"max_deviation\": " << max_dev
          << ", \"tolerance\": " << opt.tolerance << ", \"free_edges\": " << free_edges
          << ", \"nonmanifold_edges\": " << nonmanifold << ", \"overlap_edges\": " << overlap << ", \"closed_shells\": " << closed
          << ", \"watertight_closed_shells\": " << watertight << ", \"small_angle_share\": " << thin_share
          << ", \"max_edge_tolerance\": " << max_edge_tolerance << ", \"deviation_ratio\": " << worst_ratio
          << ", \"loose_faces\": " << loose_faces << ", \"faces_over\": " << over_faces << ", \"ms\": " << ms
          << ", \"by_surface\": {";
        for (auto it = by_type.begin(); it != by_type.end(); ++it) {
            j << (it == by_type.begin() ? "" : ", ") << "\"" << surface_name(pack::SurfaceType(it->first)) << "\": {\"triangles\": " << it->second.triangles
              << ", \"thin\": " << it->second.thin << "}";
        }
        j << "}}\n";
        if (!host::write_file(json, j.str(), error)) return die(error);
    }
    if (failed || watertight < closed) {
        if (!quiet) std::fprintf(stderr, "facet-mesh: incomplete mesh: %u of %u faces failed, %u of %u closed shells not watertight (exit 5)\n", failed, faces, closed - watertight, closed);
        return 5;
    }
    if (over_faces) {
        if (!quiet) {
            std::fprintf(stderr, "facet-mesh: %u faces stray from their surfaces by more than the tolerance %.4g mm (and their B-rep's own gap): "
                         "up to %.4gx (exit 6)\n", over_faces, opt.tolerance, worst_ratio);
            // default_tolerance is 0.1% of the diagonal; the sweep (bench/sweep.py) holds from 0.02%.
            const float tested = 0.2f * default_tol;
            if (opt.tolerance < tested)
                std::fprintf(stderr, "  %.4g mm is finer than the tested range (from 0.02%% of the model's diagonal, %.4g mm here): "
                             "a face's (u,v) grid has 32,768 steps and its geometry is float32\n", opt.tolerance, tested);
        }
        return 6;
    }
    return 0;
}
