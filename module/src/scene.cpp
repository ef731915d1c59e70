#include "scene.h"

#include "geom/fmath.h"

#include <cmath>

namespace facet::module {
namespace {

constexpr float kUnitsPerDiagonal = 1048576.0f; // 2^20: mesh quantum = diagonal / 2^20

// The sphere around a box (lo <= hi, mesh units): its centre, and half its diagonal rounded up
// (a unit for the centre's rounding, two more) -- as tight as a sphere holding the box can be,
// so a size on the screen is not overstated. False (no sphere) past 1e9 units.
bool sphere_around(const int32_t lo[3], const int32_t hi[3], int32_t centre[3], int32_t& radius) {
    float r2 = 0;
    for (int i = 0; i < 3; ++i) {
        centre[i] = int32_t((int64_t(lo[i]) + hi[i]) / 2);
        // (hi >= lo: the span fits 32 unsigned bits, and converts without the 64-bit routine)
        const float half = 0.5f * float(uint32_t(hi[i]) - uint32_t(lo[i])) + 1.0f;
        r2 += half * half;
    }
    const float r = std::sqrt(r2) + 2.0f;
    if (!(r < 1e9f)) return false;
    radius = int32_t(r);
    return true;
}

} // namespace

Result Scene::open(const geom::Pack& pack) {
    loaded_ = false;
    whole_ = {pack, 0, 0, 0, nullptr, 0, 0};
    blocks_ = {&whole_, 1};
    blocked_ = false;
    left_out_ = {};
    instances_ = pack.instances();
    faces_ = uint32_t(pack.faces().size()), edges_ = uint32_t(pack.edges().size()), parts_ = uint32_t(pack.shells().size());
    whole_.faces = faces_, whole_.edges = edges_;
    const pack::Header& h = pack.header();
    source_unit_mm_ = h.source_unit_mm;
    for (int k = 0; k < 3; ++k) box_min_[k] = h.bbox_min[k], box_max_[k] = h.bbox_max[k];
    if (Result r = annotations_.open(pack); !r.ok()) return r;
    if (Result r = tree_.open(pack); !r.ok()) return r;
    explode_ = 0;
    return start();
}

Result Scene::open(const geom::PackIndex& index, std::span<Block> blocks) {
    loaded_ = false;
    if (Result r = annotations_.open(index); !r.ok()) return r;
    if (Result r = tree_.open(index); !r.ok()) return r;
    explode_ = 0;
    const auto parts = index.parts();
    if (blocks.size() != index.blocks().size() || blocks.empty()) {
        return Result::fail(Status::OutOfRange, "the blocks given are not the index's");
    }
    uint32_t faces = 0, edges = 0;
    left_out_ = {};
    index_ = index;
    blocks_ = blocks;
    index.parts_box(box_min_, box_max_);
    for (uint32_t b = 0; b < blocks.size(); ++b) {
        const pack::Block& entry = index.blocks()[b];
        Block& block = blocks[b];
        const Place here{"block", b};
        block.first_face = faces, block.first_edge = edges, block.first_part = entry.first_part;
        uint64_t block_faces = 0, block_edges = 0;
        for (uint32_t s = 0; s < entry.part_count; ++s) {
            const pack::Part& part = parts[entry.first_part + s];
            block_faces += part.face_count, block_edges += part.edge_count;
        }
        if (faces + block_faces > UINT32_MAX / 2 || edges + block_edges > UINT32_MAX / 2) {
            return Result::fail(Status::Corrupt, "more faces or edges than a model can number", here);
        }
        block.faces = uint32_t(block_faces), block.edges = uint32_t(block_edges);
        faces += block.faces, edges += block.edges;
        if (block.left_out) {
            block.pack = {};
            tally_left_out(b, true);
        } else if (Result r = check_block(index, b); !r.ok()) {
            return r;
        }
    }
    blocked_ = true;
    instances_ = index.instances();
    faces_ = faces, edges_ = edges, parts_ = uint32_t(parts.size());
    source_unit_mm_ = index.header().source_unit_mm;
    return start();
}

// A block's pack against its parts in the index: its shells, faces and edges theirs.
Result Scene::check_block(const geom::PackIndex& index, uint32_t b) const {
    const pack::Block& entry = index.blocks()[b];
    const Block& block = blocks_[b];
    const geom::Pack& p = block.pack;
    const Place here{"block", b};
    if (p.shells().size() != entry.part_count || entry.part_count == 0) return Result::fail(Status::Corrupt, "its shells are not its parts", here);
    for (uint32_t s = 0; s < entry.part_count; ++s) {
        const pack::Part& part = index.parts()[entry.first_part + s];
        const pack::Shell& shell = p.shells()[s];
        if (shell.face_count != part.face_count || (shell.closed != 0) != (part.closed != 0)) {
            return Result::fail(Status::Corrupt, "a shell is not its part of the index", here);
        }
    }
    if (block.edges != p.edges().size() || block.faces != p.faces().size() ||
        p.faces().size() != p.shells().back().first_face + p.shells().back().face_count) {
        return Result::fail(Status::Corrupt, "its faces or edges are not its parts'", here);
    }
    return {};
}

void Scene::tally_left_out(uint32_t b, bool out) {
    const Block& block = blocks_[b];
    const uint32_t parts = index_.blocks()[b].part_count;
    if (out) ++left_out_.blocks, left_out_.parts += parts, left_out_.faces += block.faces, left_out_.edges += block.edges;
    else --left_out_.blocks, left_out_.parts -= parts, left_out_.faces -= block.faces, left_out_.edges -= block.edges;
}

Result Scene::start() {
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        centre_[k] = 0.5f * (box_min_[k] + box_max_[k]);
        const float e = 0.5f * (box_max_[k] - box_min_[k]);
        r2 += e * e;
    }
    radius_ = own_radius_ = r2 > 0 ? std::sqrt(r2) : 1.0f;
    unit_ = 2 * radius_ / kUnitsPerDiagonal;
    return {};
}

Result Scene::attach(const Memory& memory) {
    mem_ = memory;
    if (faces_ > mem_.faces.size()) {
        return Result::fail(Status::Full, "more faces than the workspace holds (Capacity::faces)", {"faces", faces_});
    }
    if (edges_ > mem_.samples.first.size()) {
        return Result::fail(Status::Full, "more edges than the workspace holds (Capacity::edges)", {"edges", edges_});
    }
    totals_ = {};
    loaded_ = true;
    show_all();
    fit_bounds(false);
    return {};
}

Part Scene::part(uint32_t s) const {
    const uint32_t b = find(s, &Block::first_part);
    const Block& block = blocks_[b];
    if (block.left_out) return {block.first_face, 0, b, index_.parts()[s].closed != 0};
    const pack::Shell& shell = block.pack.shells()[s - block.first_part];
    return {block.first_face + shell.first_face, shell.face_count, b, shell.closed != 0};
}

const char* Scene::part_name(uint32_t s) const {
    if (blocked_) return index_.part_name(s);
    return blocks_[0].pack.shell_name(s);
}

void Scene::block_box(uint32_t b, float lo[3], float hi[3]) const {
    const pack::Block* entry = blocked_ ? &index_.blocks()[b] : nullptr;
    for (int k = 0; k < 3; ++k) {
        lo[k] = entry ? entry->box_min[k] : centre_[k] - radius_;
        hi[k] = entry ? entry->box_max[k] : centre_[k] + radius_;
    }
}

bool Scene::part_box(uint32_t s, int32_t lo[3], int32_t hi[3]) const {
    if (!blocked_ || s >= index_.parts().size()) return false;
    const pack::Part& part = index_.parts()[s];
    const float inv = 1.0f / unit_;
    for (int k = 0; k < 3; ++k) {
        const float a = part.box_min[k] * inv, b = part.box_max[k] * inv;
        if (!(a <= b && std::fabs(a) < 1e9f && std::fabs(b) < 1e9f)) return false; // empty, or far off
        lo[k] = int32_t(std::floor(a)), hi[k] = int32_t(std::ceil(b));
    }
    return true;
}

bool Scene::part_corners(uint32_t s, int32_t corners[8][3]) const {
    int32_t lo[3], hi[3];
    if (!part_box(s, lo, hi)) return false;
    for (int c = 0; c < 8; ++c)
        for (int k = 0; k < 3; ++k) corners[c][k] = (c >> k) & 1 ? hi[k] : lo[k];
    return true;
}

bool Scene::part_sphere(uint32_t s, int32_t centre[3], int32_t& radius) const {
    int32_t lo[3], hi[3];
    return part_box(s, lo, hi) && sphere_around(lo, hi, centre, radius);
}

bool Scene::part_edges(uint32_t s, uint32_t& first, uint32_t& count) const {
    if (!blocked_) {
        first = 0, count = edges_;
        return parts_ == 1;
    }
    if (s >= parts_) return false;
    const Part p = part(s);
    const Block& block = blocks_[p.block];
    first = block.first_edge;
    if (block.left_out) { // none held
        count = 0;
        return true;
    }
    for (uint32_t k = block.first_part; k < s; ++k) first += index_.parts()[k].edge_count;
    count = index_.parts()[s].edge_count;
    return true;
}

void Scene::Box::add(const int32_t p[3]) {
    for (int k = 0; k < 3; ++k) {
        lo[k] = p[k] < lo[k] ? p[k] : lo[k];
        hi[k] = p[k] > hi[k] ? p[k] : hi[k];
    }
}

void Scene::Box::add(const Box& b) {
    for (int k = 0; k < 3; ++k) {
        lo[k] = b.lo[k] < lo[k] ? b.lo[k] : lo[k];
        hi[k] = b.hi[k] > hi[k] ? b.hi[k] : hi[k];
    }
}

void Scene::fit_bounds(bool sampled) {
    start_bounds(sampled);
    while (!bound(UINT32_MAX)) {
    }
}

void Scene::start_bounds(bool sampled) {
    bounds_ = {};
    bounds_.active = true;
    bounds_.sampled = sampled && !mem_.samples.count.empty() && !mem_.sample_q.empty();
    for (int k = 0; k < 3; ++k) bounds_.lo[k] = INFINITY, bounds_.hi[k] = -INFINITY;
}

// Part by part: its box in its own coordinates (a tessellated face's vertices, which hold its
// loops' samples; another face's samples, or before any sampling its edges' ends), then the
// box's corners through each of its instances.
bool Scene::bound(uint32_t points) {
    Bounds& b = bounds_;
    if (!b.active) return true;
    const float inv = 1.0f / unit_;
    while (b.part < parts_) {
        const Part part = this->part(b.part);
        const Block& block = blocks_[part.block];
        const geom::Pack& pack = block.pack;
        if (!b.in_part) {
            b.face = part.first_face, b.box = {}, b.in_part = true;
            Box box;
            if (block.left_out && part_box(b.part, box.lo, box.hi)) b.box = box;
        }
        for (; b.face < part.first_face + part.face_count; ++b.face) {
            if (points == 0) return false;
            const FaceInfo& info = mem_.faces[b.face];
            if (b.sampled && info.state == FaceState::Done) {
                for (uint32_t v = 0; v < info.vertex_count; ++v) b.box.add(mem_.vertices[info.first_vertex + v].p);
                points = points > info.vertex_count ? points - info.vertex_count : 0;
                continue;
            }
            const pack::Face& F = pack.faces()[b.face - block.first_face];
            Box face_box; // (its sampled edges': a face waiting for its mesh is given its sphere by it)
            bool all_sampled = b.sampled;
            for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
                const pack::Loop& L = pack.loops()[l];
                for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
                    const uint32_t local = pack.coedges()[c].edge(), e = block.first_edge + local;
                    const uint32_t n = b.sampled ? mem_.samples.count[e] : 0;
                    if (n) {
                        const uint32_t first = mem_.samples.first[e];
                        for (uint32_t i = first; i < first + n; ++i) face_box.add(&mem_.sample_q[3 * i]);
                        points = points > n ? points - n : 0;
                        continue;
                    }
                    all_sampled = false;
                    for (const uint32_t vi : {pack.edges()[local].v0, pack.edges()[local].v1}) { // not sampled yet: the ends
                        const float* q = pack.vertices()[vi].p;
                        const float f[3] = {q[0] * inv, q[1] * inv, q[2] * inv};
                        if (!(std::fabs(f[0]) < 1e9f && std::fabs(f[1]) < 1e9f && std::fabs(f[2]) < 1e9f)) continue;
                        const int32_t p[3] = {int32_t(f[0]), int32_t(f[1]), int32_t(f[2])};
                        b.box.add(p);
                    }
                    points = points > 8 ? points - 8 : 0;
                }
            }
            if (all_sampled && info.state == FaceState::Pending) set_edge_sphere(b.face, face_box);
            b.box.add(face_box);
        }
        const Box& box = b.box;
        if (!box.empty()) {
            for (uint32_t i = 0; i < instances_.size(); ++i) {
                pack::Instance scratch;
                const pack::Instance& inst = placed(i, scratch);
                if (inst.shell != b.part || !shown(i)) continue; // a hidden part is not framed
                for (int corner = 0; corner < 8; ++corner) {
                    const float c[3] = {float(corner & 1 ? box.hi[0] : box.lo[0]) * unit_, float(corner & 2 ? box.hi[1] : box.lo[1]) * unit_,
                                        float(corner & 4 ? box.hi[2] : box.lo[2]) * unit_};
                    for (int k = 0; k < 3; ++k) {
                        const float w = inst.m[4 * k] * c[0] + inst.m[4 * k + 1] * c[1] + inst.m[4 * k + 2] * c[2] + inst.m[4 * k + 3];
                        b.lo[k] = w < b.lo[k] ? w : b.lo[k];
                        b.hi[k] = w > b.hi[k] ? w : b.hi[k];
                    }
                }
            }
            points = points > 8 ? points - 8 : 0;
        }
        ++b.part, b.in_part = false;
    }
    b.active = false;
    const float *lo = b.lo, *hi = b.hi;
    if (!(lo[0] <= hi[0])) return true; // nothing placed: the pack's own box stays
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
    return true;
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
    const Block& b = block_of_face(f);
    const auto shells = b.pack.shells();
    const uint32_t local = f - b.first_face;
    uint32_t lo = 0, hi = uint32_t(shells.size()); // the last shell starting at or before the face
    while (hi - lo > 1) {
        const uint32_t mid = (lo + hi) / 2;
        if (shells[mid].first_face <= local) lo = mid;
        else hi = mid;
    }
    return b.first_part + lo;
}

uint32_t Scene::colour_of(uint32_t f) const {
    const Block& b = block_of_face(f);
    const geom::Pack& pack = b.pack;
    const pack::Face& F = pack.faces()[f - b.first_face];
    const uint32_t ci = F.colour != pack::kNoIndex ? F.colour : pack.shells()[shell_of(f) - b.first_part].colour;
    if (ci == pack::kNoIndex) return kDefaultRgb;
    const pack::Colour c = pack.colours()[ci];
    return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16;
}

// (as append() quantizes the mesh's vertices, which hold the samples: the same integers; a
// sample lies in the model's box, far inside the quantizer's range)
void Scene::quantize_samples(uint32_t from, uint32_t to) {
    const geom::Quantizer q(1.0f / unit_);
    for (uint32_t i = from; i < to; ++i) {
        const geom::Vec3 p = mem_.samples.p[i];
        int32_t* at = &mem_.sample_q[3 * i];
        if (!q(p.x, at[0]) || !q(p.y, at[1]) || !q(p.z, at[2])) at[0] = at[1] = at[2] = 0;
    }
}

void Scene::reset_mesh(bool keep_peaks) {
    for (uint32_t f = 0; f < face_count(); ++f) mem_.faces[f] = no_mesh(FaceState::Pending);
    for (const Block& b : blocks_) {
        if (!b.left_out) continue;
        for (uint32_t f = b.first_face; f < b.first_face + b.faces; ++f) mem_.faces[f].state = FaceState::Absent;
    }
    const Totals before = totals_;
    totals_ = {};
    totals_.faces = face_count() - left_out_.faces;
    vertex_top_ = triangle_top_ = 0;
    if (keep_peaks) {
        totals_.arena_peak_bytes = before.arena_peak_bytes;
        totals_.samples_peak = before.samples_peak, totals_.face_points_peak = before.face_points_peak;
        totals_.slivers_peak = before.slivers_peak, totals_.vertices_peak = before.vertices_peak;
        totals_.triangles_peak = before.triangles_peak;
    }
    if (mem_.samples.used > totals_.samples_peak) totals_.samples_peak = mem_.samples.used;
}

void Scene::mark_failed(uint32_t f) {
    if (mem_.faces[f].state == FaceState::Deferred) --totals_.deferred, ++totals_.undeferred;
    mem_.faces[f] = no_mesh(FaceState::Failed, colour_of(f));
    ++totals_.failed;
}

void Scene::bound_by_edges(uint32_t f) {
    const Block& block = block_of_face(f);
    const geom::Pack& pack = block.pack;
    const pack::Face& F = pack.faces()[f - block.first_face];
    Box box;
    for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
        const pack::Loop& L = pack.loops()[l];
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const uint32_t e = block.first_edge + pack.coedges()[c].edge();
            const uint32_t first = mem_.samples.first[e], n = mem_.samples.count[e];
            for (uint32_t k = 0; k < n; ++k) box.add(sample_q(first + k));
        }
    }
    set_edge_sphere(f, box);
}

void Scene::set_edge_sphere(uint32_t f, const Box& box) {
    FaceInfo& info = mem_.faces[f];
    info.rgb = colour_of(f);
    info.planar = surface_type(f) == uint8_t(pack::SurfaceType::Plane);
    info.radius = 0;
    if (box.empty()) return;
    // (append() bounds a mesh by half the box's edges summed, which needs no root)
    if (!sphere_around(box.lo, box.hi, info.centre, info.radius)) info.radius = 0;
}

void Scene::defer(uint32_t f) {
    if (mem_.faces[f].state == FaceState::Deferred) return;
    mem_.faces[f].state = FaceState::Deferred;
    ++totals_.deferred;
}

Result Scene::append(uint32_t f, const geom::Mesh& fm, const geom::FaceStats& stats) {
    const uint32_t v0 = vertex_top_, i0 = triangle_top_ * 3;
    if (v0 + fm.vertex_count > mem_.vertices.size() || i0 + fm.triangle_count * 3 > mem_.indices.size()) {
        return Result::fail(Status::Full, "the viewer's mesh is full (Capacity::mesh_vertices, mesh_triangles)");
    }
    if (fm.vertex_count > 0xFFFF) return Result::fail(Status::Full, "more than 65,535 vertices in one face");
    const geom::Quantizer q(1.0f / unit_), q14(16384.0f);
    for (uint32_t v = 0; v < fm.vertex_count; ++v) {
        const geom::MeshVertex& mv = fm.vertices[v];
        DrawVertex& d = mem_.vertices[v0 + v];
        if (!q(mv.p.x, d.p[0]) || !q(mv.p.y, d.p[1]) || !q(mv.p.z, d.p[2])) {
            return Result::fail(Status::OutOfRange, "a vertex lies over 1000 diagonals from the model");
        }
        int32_t n[3];
        if (!q14(mv.n.x, n[0]) || !q14(mv.n.y, n[1]) || !q14(mv.n.z, n[2])) n[0] = n[1] = n[2] = 0; // (not a number: unlit)
        d.n[0] = int16_t(n[0]), d.n[1] = int16_t(n[1]), d.n[2] = int16_t(n[2]);
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
    const bool planar = surface_type(f) == uint8_t(pack::SurfaceType::Plane);
    FaceInfo& info = mem_.faces[f];
    Totals& t = totals_;
    if (info.state == FaceState::Deferred) --t.deferred, ++t.undeferred;
    if (info.state == FaceState::Done) t.vertices -= info.vertex_count, t.triangles -= info.triangle_count; // replaced
    else mem_.done_order[t.done++] = f;
    info = {v0, fm.vertex_count, i0, fm.triangle_count, colour_of(f), {centre[0], centre[1], centre[2]}, radius, FaceState::Done, planar};
    vertex_top_ += fm.vertex_count, triangle_top_ += fm.triangle_count;
    t.vertices += fm.vertex_count;
    t.triangles += fm.triangle_count;
    const uint32_t arena = uint32_t(geom::face_arena_bytes(stats.points));
    if (arena > t.arena_peak_bytes) t.arena_peak_bytes = arena;
    if (stats.points > t.face_points_peak) t.face_points_peak = stats.points;
    if (stats.slivers > t.slivers_peak) t.slivers_peak = stats.slivers;
    if (t.vertices > t.vertices_peak) t.vertices_peak = t.vertices;
    if (t.triangles > t.triangles_peak) t.triangles_peak = t.triangles;
    return {};
}

} // namespace facet::module
