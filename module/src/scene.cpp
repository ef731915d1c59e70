#include "scene.h"


#include <cmath>

namespace facet::module {
namespace {

constexpr float kUnitsPerDiagonal = 1048576.0f; // 2^20: mesh quantum = diagonal / 2^20
constexpr uint32_t kDefaultRgb = 0x00CDBEB4;    // light warm grey (B,G,R bytes)

inline int32_t round_to_int(float v) { return int32_t(v + (v >= 0 ? 0.5f : -0.5f)); }

} // namespace

Result Scene::open(const geom::Pack& pack) {
    loaded_ = false;
    if (pack.faces().size() > mem_.faces.size()) {
        return Result::fail(Status::Full, "more faces than the workspace holds (Capacity::faces)",
                            {"faces", uint32_t(pack.faces().size())});
    }
    if (pack.edges().size() > mem_.samples.first.size()) {
        return Result::fail(Status::Full, "more edges than the workspace holds (Capacity::edges)",
                            {"edges", uint32_t(pack.edges().size())});
    }
    pack_ = pack;
    const pack::Header& h = pack_.header();
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        centre_[k] = 0.5f * (h.bbox_min[k] + h.bbox_max[k]);
        const float e = 0.5f * (h.bbox_max[k] - h.bbox_min[k]);
        r2 += e * e;
    }
    radius_ = own_radius_ = r2 > 0 ? std::sqrt(r2) : 1.0f;
    unit_ = 2 * radius_ / kUnitsPerDiagonal;
    totals_ = {};
    loaded_ = true;
    show_all();
    fit_bounds(false);
    return {};
}

namespace {

struct Box {
    int64_t lo[3] = {INT64_MAX, INT64_MAX, INT64_MAX}, hi[3] = {INT64_MIN, INT64_MIN, INT64_MIN};
    bool empty() const { return lo[0] > hi[0]; }
    void add(const int32_t p[3]) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = p[k] < lo[k] ? p[k] : lo[k];
            hi[k] = p[k] > hi[k] ? p[k] : hi[k];
        }
    }
};

} // namespace

void Scene::fit_bounds(bool sampled) {
    const auto shells = pack_.shells();
    const auto instances = pack_.instances();
    const auto faces = pack_.faces();
    const auto loops = pack_.loops();
    const auto coedges = pack_.coedges();
    const auto edges = pack_.edges();
    const float inv = 1.0f / unit_;
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t s = 0; s < shells.size(); ++s) {
        Box box;
        for (uint32_t f = shells[s].first_face; f < shells[s].first_face + shells[s].face_count && f < faces.size(); ++f) {
            const FaceInfo& info = mem_.faces[f];
            if (sampled && info.state == FaceState::Done) {
                for (uint32_t v = 0; v < info.vertex_count; ++v) box.add(mem_.vertices[info.first_vertex + v].p);
            }
            const pack::Face& F = faces[f];
            for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
                for (uint32_t c = loops[l].first_coedge; c < loops[l].first_coedge + loops[l].coedge_count; ++c) {
                    const uint32_t e = coedges[c].edge();
                    const uint32_t n = !sampled || mem_.samples.count.empty() ? 0 : mem_.samples.count[e];
                    if (n && !mem_.sample_q.empty()) {
                        const uint32_t first = mem_.samples.first[e];
                        for (uint32_t i = first; i < first + n; ++i) box.add(&mem_.sample_q[3 * i]);
                    } else { // not sampled yet: the edge's ends
                        for (const uint32_t vi : {edges[e].v0, edges[e].v1}) {
                            const float* q = pack_.vertices()[vi].p;
                            const float f[3] = {q[0] * inv, q[1] * inv, q[2] * inv};
                            if (!(std::fabs(f[0]) < 1e9f && std::fabs(f[1]) < 1e9f && std::fabs(f[2]) < 1e9f)) continue;
                            const int32_t p[3] = {int32_t(f[0]), int32_t(f[1]), int32_t(f[2])};
                            box.add(p);
                        }
                    }
                }
            }
        }
        if (box.empty()) continue;
        for (uint32_t i = 0; i < instances.size(); ++i) {
            const pack::Instance& inst = instances[i];
            if (inst.shell != s || !shown(i)) continue; // a hidden part is not framed
            for (int corner = 0; corner < 8; ++corner) {
                const float c[3] = {float(corner & 1 ? box.hi[0] : box.lo[0]) * unit_, float(corner & 2 ? box.hi[1] : box.lo[1]) * unit_,
                                    float(corner & 4 ? box.hi[2] : box.lo[2]) * unit_};
                for (int k = 0; k < 3; ++k) {
                    const float w = inst.m[4 * k] * c[0] + inst.m[4 * k + 1] * c[1] + inst.m[4 * k + 2] * c[2] + inst.m[4 * k + 3];
                    lo[k] = w < lo[k] ? w : lo[k];
                    hi[k] = w > hi[k] ? w : hi[k];
                }
            }
        }
    }
    if (!(lo[0] <= hi[0])) return; // nothing placed: the pack's own box stays
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        centre_[k] = 0.5f * (lo[k] + hi[k]);
        const float e = 0.5f * (hi[k] - lo[k]);
        r2 += e * e;
    }
    // The camera's scale from mesh units to view units must stay under one (camera.cpp): a
    // placed model far smaller than its shells' own spread is framed at 1/16 of that spread.
    const float floor = own_radius_ / 16;
    radius_ = std::sqrt(r2);
    if (!(radius_ > floor)) radius_ = floor;
}

void Scene::set_shown(uint32_t i, bool on) {
    if (i >= kMaxHideable) return;
    if (on) hidden_[i >> 5] &= ~(1u << (i & 31));
    else hidden_[i >> 5] |= 1u << (i & 31);
}

void Scene::show_all() {
    for (uint32_t& w : hidden_) w = 0;
}

uint32_t Scene::shell_of(uint32_t f) const {
    const auto shells = pack_.shells();
    uint32_t s = 0;
    while (s + 1 < shells.size() && f >= shells[s].first_face + shells[s].face_count) ++s;
    return s;
}

uint32_t Scene::colour_of(uint32_t f) const {
    const pack::Face& F = pack_.faces()[f];
    const uint32_t ci = F.colour != pack::kNoIndex ? F.colour : pack_.shells()[shell_of(f)].colour;
    if (ci == pack::kNoIndex) return kDefaultRgb;
    const pack::Colour c = pack_.colours()[ci];
    return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16;
}

void Scene::quantize_samples(uint32_t from, uint32_t to) {
    const float inv = 1.0f / unit_;
    for (uint32_t i = from; i < to; ++i) {
        const geom::Vec3 p = mem_.samples.p[i];
        mem_.sample_q[3 * i] = round_to_int(p.x * inv);
        mem_.sample_q[3 * i + 1] = round_to_int(p.y * inv);
        mem_.sample_q[3 * i + 2] = round_to_int(p.z * inv);
    }
}

void Scene::reset_mesh(bool keep_peaks) {
    for (uint32_t f = 0; f < face_count(); ++f) mem_.faces[f] = {0, 0, 0, 0, 0, {0, 0, 0}, 0, FaceState::Pending, false};
    const Totals before = totals_;
    totals_ = {};
    totals_.faces = face_count();
    if (keep_peaks) {
        totals_.arena_peak_bytes = before.arena_peak_bytes;
        totals_.samples_peak = before.samples_peak, totals_.face_points_peak = before.face_points_peak;
        totals_.slivers_peak = before.slivers_peak, totals_.vertices_peak = before.vertices_peak;
        totals_.triangles_peak = before.triangles_peak;
    }
    if (mem_.samples.used > totals_.samples_peak) totals_.samples_peak = mem_.samples.used;
}

void Scene::mark_failed(uint32_t f) {
    mem_.faces[f] = {0, 0, 0, 0, colour_of(f), {0, 0, 0}, 0, FaceState::Failed, false};
    ++totals_.failed;
}

Result Scene::append(uint32_t f, const geom::Mesh& fm, const geom::FaceStats& stats) {
    const uint32_t v0 = totals_.vertices, i0 = totals_.triangles * 3;
    if (v0 + fm.vertex_count > mem_.vertices.size() || i0 + fm.triangle_count * 3 > mem_.indices.size()) {
        return Result::fail(Status::Full, "the viewer's mesh is full (Capacity::mesh_vertices, mesh_triangles)");
    }
    if (fm.vertex_count > 0xFFFF) return Result::fail(Status::Full, "more than 65,535 vertices in one face");
    const float inv = 1.0f / unit_, limit = float(1 << 30);
    for (uint32_t v = 0; v < fm.vertex_count; ++v) {
        const geom::MeshVertex& mv = fm.vertices[v];
        DrawVertex& d = mem_.vertices[v0 + v];
        const float q[3] = {mv.p.x * inv, mv.p.y * inv, mv.p.z * inv};
        for (int k = 0; k < 3; ++k) {
            if (!(std::fabs(q[k]) < limit)) return Result::fail(Status::OutOfRange, "a vertex lies over 1000 diagonals from the model");
            d.p[k] = round_to_int(q[k]);
        }
        d.n[0] = int16_t(round_to_int(mv.n.x * 16384.0f));
        d.n[1] = int16_t(round_to_int(mv.n.y * 16384.0f));
        d.n[2] = int16_t(round_to_int(mv.n.z * 16384.0f));
        d.pad = 0;
    }
    for (uint32_t i = 0; i < fm.triangle_count * 3; ++i) mem_.indices[i0 + i] = uint16_t(fm.indices[i]);

    // The face's bounding sphere: its box's centre, and half the box's edges summed (no less
    // than half its diagonal).
    int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
    for (uint32_t v = 0; v < fm.vertex_count; ++v) {
        for (int k = 0; k < 3; ++k) {
            const int32_t c = mem_.vertices[v0 + v].p[k];
            lo[k] = c < lo[k] ? c : lo[k];
            hi[k] = c > hi[k] ? c : hi[k];
        }
    }
    int32_t centre[3] = {0, 0, 0}, radius = 0;
    if (fm.vertex_count) {
        for (int k = 0; k < 3; ++k) centre[k] = int32_t((int64_t(lo[k]) + hi[k]) / 2);
        radius = int32_t((int64_t(hi[0] - lo[0]) + (hi[1] - lo[1]) + (hi[2] - lo[2])) / 2 + 2);
    }
    const pack::Face& F = pack_.faces()[f];
    const bool planar = pack_.surfaces()[F.surface].type == uint8_t(pack::SurfaceType::Plane);
    mem_.faces[f] = {v0, fm.vertex_count, i0, fm.triangle_count, colour_of(f), {centre[0], centre[1], centre[2]}, radius,
                     FaceState::Done, planar};
    mem_.done_order[totals_.done++] = f;
    Totals& t = totals_;
    t.vertices += fm.vertex_count;
    t.triangles += fm.triangle_count;
    t.mesh_bytes = t.vertices * uint32_t(sizeof(DrawVertex)) + t.triangles * 3 * uint32_t(sizeof(uint16_t));
    const uint32_t arena = uint32_t(geom::face_arena_bytes(stats.points));
    if (arena > t.arena_peak_bytes) t.arena_peak_bytes = arena;
    if (stats.points > t.face_points_peak) t.face_points_peak = stats.points;
    if (stats.slivers > t.slivers_peak) t.slivers_peak = stats.slivers;
    if (t.vertices > t.vertices_peak) t.vertices_peak = t.vertices;
    if (t.triangles > t.triangles_peak) t.triangles_peak = t.triangles;
    return {};
}

} // namespace facet::module
