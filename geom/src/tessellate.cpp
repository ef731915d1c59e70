#include "geom/tessellate.h"
#include "geom/patches.h"

#include "geom/elementary.h"
#include "face_internal.h"
#include "geom/fmath.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <new>
#include <type_traits>

namespace facet::geom {

using namespace facet::pack;
using detail::FaceScratch;
using detail::Sliver;

// What a job works in besides the caller's memory: its CDT (over the storage's arena) and the
// builder that fills it, the storage's arrays by type, the face's grid and refinement's state.
struct FaceJob::Engine {
    FaceScratch sc{};
    const uint8_t* cut_from = nullptr; // the storage sc was cut from, and its capacity
    FaceCapacity cut_for{};
    cdt::Cdt<uint16_t> cdt{{}};
    cdt::FaceBuilder<uint16_t> builder{cdt};
    detail::Grid grid;
    detail::RefineState refine;
};

FaceJob::FaceJob() {
    static_assert(sizeof(Engine) <= kEngineBytes && alignof(Engine) <= 8, "FaceJob::kEngineBytes holds the Engine");
    static_assert(std::is_trivially_destructible_v<Engine>, "a job's engine needs no destructor");
    new (engine_) Engine();
}

FaceJob::Engine& FaceJob::engine() { return *std::launder(reinterpret_cast<Engine*>(engine_)); }

cdt::Point detail::Grid::to_grid(Vec2 uv) const {
    return {int32_t(std::lround((uv.x * su - x0) * q)) - kGridHalf, int32_t(std::lround((uv.y * sv - y0) * q)) - kGridHalf};
}

Vec2 detail::Grid::to_uv(cdt::Point g) const {
    return {(float(g.x + kGridHalf) / q + x0) / su, (float(g.y + kGridHalf) / q + y0) / sv};
}

float default_tolerance(const float box_min[3], const float box_max[3]) {
    const Vec3 d{box_max[0] - box_min[0], box_max[1] - box_min[1], box_max[2] - box_min[2]};
    const float diag = length(d);
    return diag > 0 ? diag * 0.001f : 0.01f;
}

float default_tolerance(const Pack& pack) { return default_tolerance(pack.header().bbox_min, pack.header().bbox_max); }

namespace {

// Unit normals of one face, flipped on a reversed face: in closed form from the 3D point on
// planes, cylinders, cones and spheres (elementary.h: no trigonometry, no square root: on a
// soft-float core these are the bulk of a vertex's cost), from the surface's derivatives
// elsewhere.
class FaceNormals {
public:
    FaceNormals(const Pack& pack, const Surface& S, const pack::Face& F, std::span<uint32_t> patches)
        : pack_(pack), S_(S), F_(F), elementary_(is_elementary(S)), flip_(F.reversed ? -1.0f : 1.0f), patches_(pack, S, patches) {
        if (elementary_) closed_ = Elementary(pack, S).normals(flip_);
    }

    // What a vertex's normal costs, in eighths of a work unit: closed form, from a B-spline's
    // fixed-point patch (about four thousand ARM926 instructions), from float derivatives.
    uint32_t vertex_cost() const { return elementary_ ? 1 : patches_.usable() ? 6 : 48; }

    Vec3 at(Vec3 p, Vec2 uv) const {
        Vec3 n;
        return closed_.at(p, n) ? n : from_derivatives(uv); // (none unless elementary)
    }

private:
    // At a pole (du x dv vanishes) it looks a little toward the middle of the face.
    Vec3 from_derivatives(Vec2 uv) const {
        auto eval = [&](float u, float v) { // a B-spline's from its fixed-point patch
            return patches_.usable() ? patches_.point_and_derivatives(u, v) : eval_surface(pack_, S_, u, v);
        };
        SurfacePoint sp = eval(uv.x, uv.y);
        Vec3 n = cross(sp.du, sp.dv);
        if (length2(n) < 1e-24f) {
            const float um = 0.5f * (F_.uv_min[0] + F_.uv_max[0]), vm = 0.5f * (F_.uv_min[1] + F_.uv_max[1]);
            sp = eval(uv.x + 1e-3f * (um - uv.x), uv.y + 1e-3f * (vm - uv.y));
            n = cross(sp.du, sp.dv);
        }
        return normalized(n) * flip_;
    }

    const Pack& pack_;
    const Surface& S_;
    const pack::Face& F_;
    bool elementary_;
    float flip_;
    Elementary::Normals closed_;
    mutable PatchCache patches_;
};

// How much the surface bends along u and along v at (u, v): the normal curvatures of the
// parameter directions (1/mm; magnitudes). Exact on the elementary surfaces; on the others
// from the turn of the unit normal over a small step each way (a B-spline's points from its
// fixed-point patches).
void bending(const Pack& pack, const Surface& S, const pack::Face& F, float u, float v, PatchCache& patches, float& ku,
             float& kv) {
    if (is_elementary(S)) return Elementary(pack, S).bending(v, ku, kv);
    auto turn = [&](float du, float dv) { // |n(+) - n(-)| / |S(+) - S(-)|
        auto eval = [&](float x, float y) { return patches.usable() ? patches.point_and_derivatives(x, y) : eval_surface(pack, S, x, y); };
        const SurfacePoint a = eval(u + du, v + dv), b = eval(u - du, v - dv);
        const Vec3 na = normalized(cross(a.du, a.dv)), nb = normalized(cross(b.du, b.dv));
        const float d = length(a.p - b.p);
        return d > 0 ? length(na - nb) / d : 0.0f;
    };
    ku = turn(0.01f * (F.uv_max[0] - F.uv_min[0]), 0);
    kv = turn(0, 0.01f * (F.uv_max[1] - F.uv_min[1]));
}

// Appends a vertex (the caller checked the room).
uint32_t add_vertex(const FaceNormals& normals, Mesh& mesh, Vec3 p, Vec2 uv) {
    mesh.vertices[mesh.vertex_count] = {p, normals.at(p, uv)};
    if (mesh.vertex_count < mesh.uv.size()) mesh.uv[mesh.vertex_count] = uv;
    return mesh.vertex_count++;
}

// Appends a triangle wound as the face's normal (the caller checked the room).
void add_triangle(const pack::Face& F, Mesh& mesh, const uint32_t id[3], FaceStats& stats) {
    uint32_t* out = &mesh.indices[mesh.triangle_count * 3];
    out[0] = id[0];
    out[1] = F.reversed ? id[2] : id[1];
    out[2] = F.reversed ? id[1] : id[2];
    ++mesh.triangle_count;
    ++stats.triangles;
}

// The CDT's inner triangles and their vertices, each vertex once, in the order first used.
// sc.mesh_of maps CDT vertices to points on the way in and to mesh vertices on the way out.
// From triangle `next` on, until about `units` are spent (a new vertex costs `vertex_cost`
// eighths of a unit: its normal): Busy, and `next` says where to go on.
Status emit_triangles(const FaceNormals& normals, const pack::Face& F, const cdt::Cdt<uint16_t>& cdt, FaceScratch& sc,
                      Mesh& mesh, FaceStats& stats, uint32_t& next, uint32_t units, uint32_t vertex_cost) {
    constexpr uint32_t kAssigned = 0x80000000u; // mesh_of[v]: a mesh vertex, not a point
    auto position = [&](uint16_t v) {
        const uint32_t m = sc.mesh_of[v];
        return m & kAssigned ? mesh.vertices[m & ~kAssigned].p : sc.xyz[m];
    };
    uint32_t spent = 0;
    for (uint32_t t = next; t < cdt.triangle_count(); ++t) {
        if (spent / 8 >= units) { // in eighths of a unit
            next = t;
            return Status::Busy;
        }
        spent += 1;
        const cdt::Triangle<uint16_t>& T = cdt.triangle(uint16_t(t));
        if (!T.inner()) continue;
        // A triangle with two corners at one point (a pole or apex is a segment in (u,v)) has
        // no area: its two other edges are one edge in 3D, which would count twice. Its
        // neighbours close the mesh without it.
        const Vec3 p0 = position(T.v[0]), p1 = position(T.v[1]), p2 = position(T.v[2]);
        if (same_point(p0, p1) || same_point(p1, p2) || same_point(p2, p0)) continue;
        if ((mesh.triangle_count + 1) * 3 > mesh.indices.size()) return Status::Full;
        uint32_t id[3];
        for (int k = 0; k < 3; ++k) {
            uint32_t& m = sc.mesh_of[T.v[k]];
            if (!(m & kAssigned)) {
                if (mesh.vertex_count >= mesh.vertices.size()) return Status::Full;
                m = kAssigned | add_vertex(normals, mesh, sc.xyz[m], sc.uv[m]);
                spent += vertex_cost;
            }
            id[k] = m & ~kAssigned;
        }
        add_triangle(F, mesh, id, stats);
    }
    next = cdt.triangle_count();
    return Status::Ok;
}

} // namespace

void FaceJob::start(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt, FaceStorage& storage,
                    Mesh& mesh) {
    pack_ = &pack, edges_ = &edges, opt_ = opt, mesh_ = &mesh, face_ = face;
    stage_ = Stage::Map;
    np_ = nl_ = 0;
    base_vertex_ = mesh.vertex_count, base_triangle_ = mesh.triangle_count;
    Engine& E = engine();
    E.grid = {};
    E.refine = {};
    next_loop_ = next_triangle_ = 0;
    stats_ = {};
    result_ = Result::fail(Status::Busy, "tessellating");
    if (!storage.bound()) {
        E.sc = {};
        E.cut_from = nullptr;
        stage_ = Stage::Failed;
        result_ = Result::fail(Status::OutOfRange, "the face storage is not bound to memory", {"face", face});
        return;
    }
    const FaceCapacity& c = storage.capacity();
    if (E.cut_from != storage.memory() || E.cut_for.points != c.points || E.cut_for.loops != c.loops ||
        E.cut_for.slivers != c.slivers || E.cut_for.patch_words != c.patch_words) {
        E.sc = detail::scratch_of(storage);
        E.cut_from = storage.memory(), E.cut_for = c;
    }
    E.cdt = cdt::Cdt<uint16_t>(E.sc.arena);
    PatchCache::forget(E.sc.patches); // they may be another pack's
}

Result FaceJob::fail(Result r) {
    stage_ = Stage::Failed;
    mesh_->vertex_count = base_vertex_;
    mesh_->triangle_count = base_triangle_;
    result_ = r.within({"face", face_});
    return result_;
}

// Steps 2 and 3 (once the loops are in (u,v)): the metric, the CDT grid.
Result FaceJob::prepare() {
    const Pack& pack = *pack_;
    FaceScratch& sc = engine().sc;
    const pack::Face& F = pack.faces()[face_];
    const Surface& S = pack.surfaces()[F.surface];
    if (!(opt_.tolerance > 0 && opt_.tolerance <= pack::kMaxMagnitude) || !(opt_.max_angle > 0)) {
        return Result::fail(Status::OutOfRange, "the tolerance and the angle must be positive");
    }

    // 2. Metric scale at the middle of the face: |Su| and |Sv|, so that distances in the scaled
    //    (u,v) are distances on the surface, then each direction weighted by the square root
    //    of the surface's bending along it, so that equal distances mean equal deviations of a
    //    chord: Delaunay triangles are then stretched along the flatter direction (a torus
    //    fillet's triangles run around its ring), as the deviation allows.
    detail::Grid& grid = engine().grid;
    const float um = 0.5f * (F.uv_min[0] + F.uv_max[0]), vm = 0.5f * (F.uv_min[1] + F.uv_max[1]);
    PatchCache patches(pack, S, sc.patches); // (the patches stay for refinement and normals)
    const SurfacePoint mid = patches.usable() ? patches.point_and_derivatives(um, vm) : eval_surface(pack, S, um, vm);
    grid.su = length(mid.du), grid.sv = length(mid.dv);
    if (!(grid.su > 1e-9f)) grid.su = 1;
    if (!(grid.sv > 1e-9f)) grid.sv = 1;
    float ku, kv;
    bending(pack, S, F, um, vm, patches, ku, kv);
    const float kmax = std::max(ku, kv);
    if (kmax > 0) {
        constexpr float kMinWeight = 0.125f; // at most 8:1 stretch
        grid.su *= std::max(sqrt_f(ku / kmax), kMinWeight);
        grid.sv *= std::max(sqrt_f(kv / kmax), kMinWeight);
    }

    // 3. Quantize to the CDT grid: the loops' extent spans 2^15 units, inside the CDT's
    //    fastest predicate tier. Every point refinement adds lies inside the loops.
    float x1 = -1e30f, y1 = -1e30f;
    grid.x0 = grid.y0 = 1e30f;
    for (uint32_t i = 0; i < np_; ++i) {
        grid.x0 = std::min(grid.x0, sc.uv[i].x * grid.su), x1 = std::max(x1, sc.uv[i].x * grid.su);
        grid.y0 = std::min(grid.y0, sc.uv[i].y * grid.sv), y1 = std::max(y1, sc.uv[i].y * grid.sv);
    }
    const float extent = std::max(x1 - grid.x0, y1 - grid.y0);
    if (!(extent > 0) || !std::isfinite(extent)) return Result::fail(Status::Degenerate, "the face has no extent in (u,v)");
    grid.q = float(2 * detail::kGridHalf) / extent;
    for (uint32_t i = 0; i < np_; ++i) sc.loop_points[i] = grid.to_grid(sc.uv[i]);
    return detail::clean_loops(sc, np_, nl_, stats_.slivers);
}

Result FaceJob::run(uint32_t units) {
    if (stage_ == Stage::Done || stage_ == Stage::Failed) return result_;
    const Pack& pack = *pack_;
    Engine& E = engine();
    FaceScratch& sc = E.sc;
    Mesh& mesh = *mesh_;
    const pack::Face& F = pack.faces()[face_];
    const Result busy = Result::fail(Status::Busy, "tessellating");
    uint32_t spent = 0;
    if (stage_ == Stage::Map) {
        // 1. Loops into (u,v), a few loops at a time (a unit: a point).
        const uint32_t np0 = np_;
        const Result m = detail::map_loops(pack, face_, *edges_, sc, np_, nl_, next_loop_, units);
        spent += np_ - np0;
        if (m.status == Status::Busy) return busy;
        if (!m.ok()) return fail(m);
        if (detail::retraces(sc, np_, nl_)) { // no area at this tolerance: no triangle
            np_ = nl_ = 0;
            stage_ = Stage::Emit;
            stats_ = {};
        } else if (Result r = prepare(); !r.ok()) {
            return fail(r);
        }
        spent += 1 + np_ / 16;
        stats_.points = np_;
        if (stage_ == Stage::Emit) {
            // no area (above)
        } else if (nl_ == 0) {
            stage_ = Stage::Emit; // slivers alone
        } else {
            // 4. Triangulate the loops.
            const cdt::FaceInput in{{sc.loop_points.data(), np_}, {sc.loop_sizes.data(), nl_}, {}};
            if (Result r = E.builder.start(in, cdt::kDefaultLocateMode); !r.ok()) return fail(r);
            spent += 1 + np_ / 16;
            stage_ = Stage::Triangulate;
        }
        if (spent >= units) return busy;
    }
    if (stage_ == Stage::Triangulate) {
        Result r = E.builder.run(units - spent);
        // Loops that cross (a B-rep's artefact, or features closer than the grid): the smaller
        // piece goes as slivers and the loops are triangulated anew, a few times at most.
        while (r.status == Status::Crossing && stats_.untangled < kMaxUntangles) {
            const cdt::FaceBuilder<uint16_t>::Segment s = E.builder.refused();
            const uint32_t slivers0 = stats_.slivers;
            if (!detail::untangle(sc, np_, nl_, stats_.slivers, s.from, s.to).ok()) break;
            if (Result c = detail::clean_loops(sc, np_, nl_, stats_.slivers); !c.ok()) return fail(c);
            ++stats_.untangled;
            spent += E.builder.used() + 1 + np_ / 8 + (stats_.slivers - slivers0);
            stats_.points = np_;
            if (nl_ == 0) { // slivers alone
                r = {};
                stage_ = Stage::Emit;
                break;
            }
            const cdt::FaceInput in{{sc.loop_points.data(), np_}, {sc.loop_sizes.data(), nl_}, {}};
            if (Result st = E.builder.start(in, cdt::kDefaultLocateMode); !st.ok()) return fail(st);
            if (spent >= units) return busy;
            r = E.builder.run(units - spent);
        }
        if (r.status == Status::Busy) return busy;
        if (stage_ == Stage::Emit) {
            // nothing left to triangulate
        } else if (!r.ok()) {
            if (r.status == Status::Crossing && stats_.untangled > 0) {
                return fail(Result::fail(Status::Crossing, "loops cross, and still do after their smaller pieces went",
                                         {"pieces", stats_.untangled}));
            }
            return fail(r);
        } else {
            spent += E.builder.used() + np_ / 32;
            if (sc.mesh_of.size() < E.cdt.vertex_capacity()) {
                return fail(Result::fail(Status::Full, "more vertices than the face scratch holds"));
            }
            for (uint32_t v = 0; v < E.cdt.vertex_count(); ++v) sc.mesh_of[v] = UINT32_MAX;
            for (uint32_t i = 0; i < np_; ++i) { // point -> vertex after triangulation; repeats keep the first
                const uint32_t v = sc.arena.keys[i];
                if (v < E.cdt.vertex_count() && sc.mesh_of[v] == UINT32_MAX) sc.mesh_of[v] = i;
            }
            if (Result st = detail::stitch(sc, np_, nl_, E.cdt, stats_.slivers); !st.ok()) return fail(st);
            E.refine = {};
            E.refine.total = E.refine.loop_points = np_;
            stage_ = Stage::Refine;
        }
        if (spent >= units) return busy;
    }
    if (stage_ == Stage::Refine) {
        // 5. Refine until every inner triangle is within the tolerance.
        uint32_t used = 0;
        const Result r = detail::refine(pack, face_, opt_, E.grid, E.cdt, sc, E.refine, units - spent, used);
        if (r.status == Status::Busy) return busy;
        if (!r.ok()) return fail(r);
        spent += used;
        stats_.points = E.refine.total;
        stage_ = Stage::Emit;
        if (spent >= units) return busy;
    }
    // 6. Output: the inner triangles and their vertices (each once, in the order first used).
    //    Loop points keep their edge sample's 3D point, shared with the neighbour.
    const Surface& S = pack.surfaces()[F.surface];
    const FaceNormals normals(pack, S, F, sc.patches);
    if (nl_ > 0) {
        const Status e = emit_triangles(normals, F, E.cdt, sc, mesh, stats_, next_triangle_, units - std::min(units, spent),
                                        normals.vertex_cost());
        if (e == Status::Busy) return busy;
        if (!ok(e)) return fail(Result::fail(Status::Full, "the mesh is full"));
    }
    // The slivers of collapsed loop points (their own vertices; none with two equal corners).
    for (uint32_t k = 0; k < stats_.slivers; ++k) {
        const Sliver& v = sc.slivers[k];
        if (same_point(v.p[0], v.p[1]) || same_point(v.p[1], v.p[2]) || same_point(v.p[2], v.p[0])) continue;
        if (mesh.vertex_count + 3 > mesh.vertices.size() || (mesh.triangle_count + 1) * 3 > mesh.indices.size()) {
            return fail(Result::fail(Status::Full, "the mesh is full"));
        }
        uint32_t id[3];
        for (int c = 0; c < 3; ++c) id[c] = add_vertex(normals, mesh, v.p[c], v.uv[c]);
        add_triangle(F, mesh, id, stats_);
    }
    stage_ = Stage::Done;
    result_ = {};
    return result_;
}

Result tessellate_face(const Pack& pack, uint32_t face, const EdgeSamples& edges, const TessOptions& opt, FaceStorage& storage,
                       Mesh& mesh, FaceStats& stats) {
    FaceJob job;
    job.start(pack, face, edges, opt, storage, mesh);
    Result r;
    while ((r = job.run(UINT32_MAX)).status == Status::Busy) {
    }
    stats = job.stats();
    return r;
}

} // namespace facet::geom
