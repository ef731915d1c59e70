// The workspace laid out: the Core and one face's working memory at create(), the model's
// arrays planned at load() for its counts and the room left (module/src/workspace.h: the plan),
// the pack's decoded form at the workspace's end when the application gives no pack memory,
// and what a pack needs (model_needs) and a model took (stats).
#include "core.h"
#include "geom/pack_file.h"
#include "loader.h"

#include <algorithm>
#include <new>

namespace facet {
namespace {

using module::Array;
using module::Carver;

// Room to refine the default detail: six samples an edge (it takes two to four, finer up to
// twice that); and for a part opened from a model larger than the memory, 24 mesh vertices a
// face beside them (the distinct 10 k-face assembly takes about 5.5 at its fitted view).
constexpr uint32_t kSamplesPerEdge = 6, kVerticesPerFace = 24;

constexpr size_t core_bytes() { return (sizeof(Core) + 15) / 16 * 16; }

// The workspace a capacity takes: the Core, then its arrays.
constexpr size_t layout_bytes(const Capacity& c, uint32_t patch_words = geom::kPatchCacheWords) {
    return core_bytes() + module::arrays_bytes(c, patch_words);
}

// facet/sizes.h states the workspace as a fixed part plus bytes per item of each capacity; the
// plan's arrays (packed) must take exactly those bytes per item, and the fixed part must hold
// what is left (the Core, the palettes, the patches, the alignment).
constexpr size_t packed_bytes(const Capacity& c) {
    module::Measure<true> m;
    module::workspace_plan(c, geom::kPatchCacheWords, m);
    return m.at;
}
constexpr Capacity kNothing{0, 0, 0, 0, 0, 0, 0, 0};
template <uint32_t Capacity::*kItem>
constexpr size_t bytes_per() {
    Capacity one = kNothing;
    one.*kItem = 1;
    return packed_bytes(one) - packed_bytes(kNothing);
}
static_assert(bytes_per<&Capacity::faces>() == FACET_BYTES_PER_FACE, "facet/sizes.h: FACET_BYTES_PER_FACE");
static_assert(bytes_per<&Capacity::edges>() == FACET_BYTES_PER_EDGE, "facet/sizes.h: FACET_BYTES_PER_EDGE");
static_assert(bytes_per<&Capacity::samples>() == FACET_BYTES_PER_SAMPLE, "facet/sizes.h: FACET_BYTES_PER_SAMPLE");
static_assert(bytes_per<&Capacity::face_points>() == FACET_BYTES_PER_FACE_POINT, "facet/sizes.h: FACET_BYTES_PER_FACE_POINT");
static_assert(bytes_per<&Capacity::loops>() == FACET_BYTES_PER_LOOP, "facet/sizes.h: FACET_BYTES_PER_LOOP");
static_assert(bytes_per<&Capacity::slivers>() == FACET_BYTES_PER_SLIVER, "facet/sizes.h: FACET_BYTES_PER_SLIVER");
static_assert(bytes_per<&Capacity::mesh_vertices>() == FACET_BYTES_PER_MESH_VERTEX, "facet/sizes.h: FACET_BYTES_PER_MESH_VERTEX");
static_assert(bytes_per<&Capacity::mesh_triangles>() == FACET_BYTES_PER_MESH_TRIANGLE,
              "facet/sizes.h: FACET_BYTES_PER_MESH_TRIANGLE");
// The alignment the plan's arrays can lose: under 8 bytes each, and as much inside the face's block.
constexpr size_t kAlignmentSlack = 8 * (uint32_t(Array::PaletteRgb) + 1 + uint32_t(geom::FaceArray::Patches) + 1);
static_assert(core_bytes() + packed_bytes(kNothing) + kAlignmentSlack <= FACET_WORKSPACE_FIXED_BYTES,
              "facet/sizes.h: FACET_WORKSPACE_FIXED_BYTES holds the Core, the palettes, the patches and the alignment");
// And no more than that (on the host, where the Core is largest): the formula stays within 64
// bytes of the plan (tests/viewer/plan_test.cpp).
static_assert(sizeof(void*) != 8 || FACET_WORKSPACE_FIXED_BYTES - (core_bytes() + packed_bytes(kNothing) + kAlignmentSlack) < 64,
              "facet/sizes.h: FACET_WORKSPACE_FIXED_BYTES is more than 64 bytes over what it holds");
static_assert(layout_bytes(Capacity{}) <= workspace_bytes(Capacity{}), "facet/sizes.h understates the default workspace");

// Lays the plan's arrays out in the workspace and hands each part of the viewer its own.
struct Carve {
    Carver& k;
    module::Scene::Memory scene{};
    module::Scheduler::Memory scheduler{};
    module::Painter::Memory painter{};
    std::span<module::Projected> projected;
    Result face_bound;

    // The array as the plan states it, of the type the part takes (the same size and alignment).
    template <typename T>
    std::span<T> as(size_t count, size_t bytes, size_t align) {
        FACET_ASSERT("module", bytes == sizeof(T) && align == alignof(T));
        void* p = k.take(count * bytes, align);
        return p ? std::span<T>(static_cast<T*>(p), count) : std::span<T>();
    }
    void array(Array what, size_t count, size_t bytes, size_t align) {
        switch (what) {
        case Array::EdgeFirst: scene.samples.first = as<uint32_t>(count, bytes, align); break;
        case Array::EdgeCount: scene.samples.count = as<uint16_t>(count, bytes, align); break;
        case Array::EdgeDrawn: painter.edge_drawn = as<uint8_t>(count, bytes, align); break;
        case Array::SampleT: scene.samples.t = as<float>(count, bytes, align); break;
        case Array::SampleP: scene.samples.p = as<geom::Vec3>(count, bytes, align); break;
        case Array::SampleQ: scene.sample_q = as<int32_t>(count, bytes, align); break;
        case Array::FaceStorage: break; // face()
        case Array::FaceVertices: scheduler.face_mesh.vertices = as<geom::MeshVertex>(count, bytes, align); break;
        case Array::FaceIndices: scheduler.face_mesh.indices = as<uint32_t>(count, bytes, align); break;
        case Array::MeshVertices: scene.vertices = as<module::DrawVertex>(count, bytes, align); break;
        case Array::MeshIndices: scene.indices = as<uint16_t>(count, bytes, align); break;
        case Array::Faces: scene.faces = as<module::FaceInfo>(count, bytes, align); break;
        case Array::DoneOrder: scene.done_order = as<uint32_t>(count, bytes, align); break;
        case Array::Projected: projected = painter.projected = as<module::Projected>(count, bytes, align); break;
        case Array::PointCache: painter.points = as<module::ProjectedPoint>(count, bytes, align); break;
        case Array::Palettes: painter.palettes = as<render::Palette>(count, bytes, align); break;
        case Array::PaletteRgb: painter.palette_rgb = as<uint32_t>(count, bytes, align); break;
        }
    }
    void face(const geom::FaceCapacity& f) {
        const size_t bytes = geom::face_storage_bytes(f);
        if (void* p = k.take(bytes, 8)) {
            face_bound = scheduler.storage.bind(p, bytes, f);
            scheduler.scratch = {static_cast<uint8_t*>(p), geom::face_scratch_bytes(f)};
        } else {
            face_bound = Result::fail(Status::Full, "no room for a face's storage");
        }
    }
};

} // namespace

uint32_t pack_memory_bytes(const void* file, uint32_t file_bytes) { return module::pack_memory_need(file, file_bytes); }

namespace {

// model_needs() before its status is made public.
Result needs_of(const void* file, uint32_t file_bytes, ModelNeeds& needs) {
    needs = {};
    const geom::PackFileKind kind = file ? geom::pack_file_kind(file, file_bytes) : geom::PackFileKind::Unknown;
    pack::Needs measured{};
    bool has_measured = false;
    if (kind == geom::PackFileKind::Blocked) {
        geom::PackIndex index;
        if (reinterpret_cast<uintptr_t>(file) & 3) return Result::fail(Status::OutOfRange, "a blocked pack must lie 4-byte aligned");
        if (Result r = index.open(file, file_bytes); !r.ok()) return r;
        for (const pack::Part& p : index.parts()) needs.faces += p.face_count, needs.edges += p.edge_count;
        needs.parts = uint32_t(index.parts().size());
        if (index.needs()) measured = *index.needs(), has_measured = true;
    } else if (kind != geom::PackFileKind::Unknown) {
        geom::LzmaProbs probs; // (about 10 KB of stack, for an LZMA pack's head)
        geom::PackCounts n;
        if (Result r = geom::stored_pack_counts(file, file_bytes, n, probs); !r.ok()) return r;
        needs.faces = n.faces, needs.edges = n.edges, needs.parts = n.shells;
        measured = n.needs, has_measured = n.has_needs;
    } else {
        return Result::fail(Status::Corrupt, "no pack here (neither FPK1, FPX1, FPZ1 nor FPB1)");
    }
    if (has_measured) {
        if (const char* why = pack::needs_problem(measured)) return Result::fail(Status::Corrupt, why);
    }
    needs.pack_memory_bytes = module::pack_memory_need(file, file_bytes);
    const size_t base = layout_bytes(Capacity{});
    // (+ the alignment the base's end and the model's arrays may lose, to 8 bytes)
    needs.least_workspace_bytes = (base + module::plan_model(needs.faces, needs.edges, 0, Capacity{}).need + 64 + 7) / 8 * 8;
    size_t roomy = base + module::model_room_bytes(needs.faces, needs.edges, kSamplesPerEdge, 0);
    if (has_measured) {
        // What the packer measured: the coarsest first level whole (every face meshed), and the
        // default level.
        const size_t least = base + module::model_room_for(needs.faces, needs.edges, measured.coarse_samples,
                                                           measured.coarse_vertices, measured.coarse_triangles);
        needs.least_workspace_bytes = std::max(needs.least_workspace_bytes, (least + 7) / 8 * 8);
        roomy = base + module::model_room_for(needs.faces, needs.edges, measured.samples, measured.mesh_vertices,
                                              measured.mesh_triangles);
    }
    // (never under what create() takes: facet/sizes.h's formula)
    needs.least_workspace_bytes = std::max(needs.least_workspace_bytes, workspace_bytes(Capacity{}));
    needs.workspace_bytes = std::max((roomy + 7) / 8 * 8, needs.least_workspace_bytes);
    return {};
}
} // namespace

Result model_needs(const void* file, uint32_t file_bytes, ModelNeeds& needs) {
    return module::public_result(needs_of(file, file_bytes, needs));
}

Core::Core(const Config& config, Carver& k, uint8_t* end)
    : config_(config), emitter_{relay, this}, painter_(scene_, raster_), scheduler_(scene_, emitter_),
      presenter_(scene_, camera_, painter_, raster_, emitter_, {config.now_us, config.clock_user}),
      judge_(scene_, camera_, scheduler_, config_), detail_(scene_, scheduler_, judge_, config.screen_error_px),
      swapper_(scene_, scheduler_, presenter_, detail_, emitter_),
      sectioning_(scene_, camera_, presenter_, config.interface == Interface::Full),
      picks_(scene_, painter_, presenter_, config.interface == Interface::Full) {
    Carve c{k, {}, {}, {}, {}, {}};
    module::base_plan(config.capacity, geom::kPatchCacheWords, c);
    carved_ = k.fits() && c.face_bound.ok();
    if (!carved_) return;
    model_start_ = k.next();
    end_ = end;
    c.scheduler.max_face_vertices = uint32_t(c.projected.size());
    scheduler_.init(c.scheduler);
    scheduler_.set_filter({&module::FaceJudge::wants, &judge_});
    scheduler_.set_block_tolerance({&module::Detail::block_tolerance, &detail_});
    scheduler_.set_block_order({&module::Detail::block_order, &detail_});
    swapper_.set_left_out({&Core::blocks_left_out, this});
    painter_.init(c.painter);
    projected_ = c.projected;
    controls_.set_screen(config.display.width, config.display.height);
    controls_.set_overlay(&presenter_.overlay());
    presenter_.overlay().set_scene(&scene_);
}

// Without pack memory of its own, the pack takes the workspace's end: what it decodes to, and
// the file itself when it lies there (the model's arrays come before both: up to model_end).
Result Core::place_pack(const void* file, uint32_t file_size, uint32_t need, void*& memory, uint32_t& memory_bytes,
                        uint8_t*& model_end) const {
    model_end = end_;
    const auto* in = static_cast<const uint8_t*>(file);
    const bool file_inside = in && in >= model_start_ && in < end_;
    if (!memory) {
        if (need && file_inside) need += file_size + 8; // decoded in front of it (moved to 8-byte alignment)
        uintptr_t start = need <= uintptr_t(end_ - model_start_) ? (reinterpret_cast<uintptr_t>(end_) - need) & ~uintptr_t(7) : 0;
        if (file_inside) start = std::min(start, reinterpret_cast<uintptr_t>(in) & ~uintptr_t(7));
        if (start < reinterpret_cast<uintptr_t>(model_start_)) {
            return Result::fail(Status::Full, "the workspace cannot hold the pack's decoded blocks", {"bytes needed", need});
        }
        model_end = reinterpret_cast<uint8_t*>(start);
        if (need) memory = model_end, memory_bytes = uint32_t(end_ - model_end);
    } else if (static_cast<uint8_t*>(memory) < end_ && static_cast<uint8_t*>(memory) + memory_bytes > model_start_) {
        return Result::fail(Status::OutOfRange, "the pack memory overlaps the workspace (give none: the pack then takes the workspace's end)");
    } else if (file_inside) {
        model_end = reinterpret_cast<uint8_t*>(reinterpret_cast<uintptr_t>(in) & ~uintptr_t(7));
    }
    return {};
}

// The largest blocks that fit: decoded where place_pack() puts them, and their arrays in the
// room left with room for their samples and meshes (kSamplesPerEdge, kVerticesPerFace; the
// whole model needs only the least that opens it). By bisection: on the size above which all
// are kept, then on the last block kept among those of the next size (copies of a part have
// equal boxes).
module::BlockCut Core::cut_blocks(const void* file, uint32_t file_bytes, uint32_t file_size, void* memory, uint32_t memory_bytes,
                                  const module::Reader* reader) const {
    geom::PackIndex index;
    if ((reinterpret_cast<uintptr_t>(file) & 3) || !index.open(file, file_bytes, reader ? reader->bytes() : file_bytes).ok()) {
        return {}; // (load() says why)
    }
    uint32_t all_faces, all_edges;
    module::kept_counts(index, {}, all_faces, all_edges);
    auto fits = [&](const module::BlockCut& cut) {
        void* mem = memory;
        uint32_t mem_bytes = memory_bytes;
        uint8_t* model_end = nullptr;
        const uint32_t need = module::pack_memory_need(index, cut);
        if (!place_pack(file, file_size, need, mem, mem_bytes, model_end).ok()) return false;
        if (memory && need > memory_bytes) return false;
        // Every face and edge has its place in the arrays (a block left out may come in later);
        // the room for samples and meshes is the kept blocks'.
        uint32_t faces, edges;
        module::kept_counts(index, cut, faces, edges);
        const size_t room = model_end > model_start_ ? size_t(model_end - model_start_) : 0;
        const size_t numbered = module::model_bytes({all_faces, all_edges, 0, 0, 0}) - module::model_bytes({faces, edges, 0, 0, 0});
        return module::plan_model(all_faces, all_edges, room, config_.capacity, edges).fits &&
               (cut.above <= 0 || room >= numbered + module::model_room_bytes(faces, edges, kSamplesPerEdge, kVerticesPerFace));
    };
    if (fits({})) return {}; // the whole model
    float lo = 0, hi = 0; // lo: too many kept; hi: fits
    for (const pack::Block& b : index.blocks()) hi = std::max(hi, module::block_size(b));
    hi = hi * 1.001f + 1e-6f;
    for (int k = 0; k < 40 && hi - lo > hi * 1e-4f; ++k) {
        const float mid = 0.5f * (lo + hi);
        (fits({mid, mid, 0}) ? hi : lo) = mid;
    }
    // The blocks between lo and hi across (equal ones): the first of them, as many as fit.
    uint32_t none = 0, some = uint32_t(index.blocks().size()); // `none` kept through block none - 1 fits
    while (some - none > 1) {
        const uint32_t mid = (none + some) / 2;
        (fits({hi, lo, mid - 1}) ? none : some) = mid;
    }
    return none ? module::BlockCut{hi, lo, none - 1} : module::BlockCut{hi, hi, 0};
}

Result Core::plan(uint32_t faces, uint32_t edges, uint32_t sampled_edges, uint8_t* end) {
    const size_t room = end > model_start_ ? size_t(end - model_start_) : 0;
    const module::ModelPlan p = module::plan_model(faces, edges, room, config_.capacity, sampled_edges);
    if (!p.fits) {
        return Result::fail(Status::Full, "the workspace is too small for this model's faces, edges and their samples",
                            {"bytes needed", uint32_t(p.need > room ? p.need - room : 0)});
    }
    Carver k(model_start_, room);
    Carve c{k, {}, {}, {}, {}, {}};
    module::model_plan(p.capacity, c);
    if (!k.fits()) return Result::fail(Status::Full, "the workspace is too small for this model's arrays");
    painter_.set_edges(c.painter.edge_drawn);
    return scene_.attach(c.scene);
}

Viewer* Viewer::create(const Config& config, void* workspace, size_t bytes, Result* why) {
    return create_viewer(config, workspace, bytes, workspace_bytes(config.capacity), why);
}

Viewer* create_viewer(const Config& config, void* workspace, size_t bytes, size_t least, Result* why) {
    auto refuse = [&](Result r) -> Viewer* {
        if (why) *why = module::public_result(r);
        return nullptr;
    };
    if (!workspace || (reinterpret_cast<uintptr_t>(workspace) & 7)) {
        return refuse(Result::fail(Status::OutOfRange, "the workspace must be 8-byte aligned", {"workspace"}));
    }
    if (bytes > SIZE_MAX - reinterpret_cast<uintptr_t>(workspace)) {
        return refuse(Result::fail(Status::OutOfRange, "the workspace's size runs past the end of memory", {"workspace"}));
    }
    const Capacity& c = config.capacity;
    if (c.face_points < 8 || c.face_points > 32760 || c.loops == 0) {
        return refuse(Result::fail(Status::OutOfRange, "a capacity is out of range (face_points 8 to 32,760, loops above 0)", {"capacity"}));
    }
    if (bytes < least || bytes < layout_bytes(c)) {
        return refuse(Result::fail(Status::Full, "the workspace is smaller than workspace_bytes(capacity)",
                                   {"bytes needed", uint32_t(std::max(least, layout_bytes(c)))}));
    }
    Carver k(static_cast<uint8_t*>(workspace) + core_bytes(), bytes - core_bytes());
    Core* core = new (workspace) Core(config, k, static_cast<uint8_t*>(workspace) + bytes);
    if (!core->carved()) return refuse(Result::fail(Status::Full, "the workspace is smaller than workspace_bytes(capacity)"));
    if (Result r = core->configure(); !r.ok()) return refuse(r);
    if (why) *why = {};
    return core;
}

Stats Core::stats() const {
    const module::Totals& t = scene_.totals();
    // The plan at this model's peaks (the patches only for a model with free-form surfaces).
    const Capacity used{scene_.face_count(), scene_.edge_count(), t.samples_peak,   t.face_points_peak,
                        config_.capacity.loops, t.slivers_peak,   t.vertices_peak, t.triangles_peak};
    bool free_form = false;
    for (uint32_t b = 0; scene_.loaded() && b < scene_.block_count(); ++b) {
        for (const pack::Surface& s : scene_.block(b).pack.surfaces()) free_form = free_form || s.type == uint8_t(pack::SurfaceType::BSpline);
    }
    const uint64_t peak = scene_.loaded() ? layout_bytes(used, free_form ? geom::kPatchCacheWords : 0) : core_bytes();
    return {t.faces, t.done, t.failed, t.deferred, t.triangles, t.vertices, scheduler_.pass(), t.mesh_bytes(), t.arena_peak_bytes,
            pack_bytes_, pack_file_bytes_, uint32_t(peak), scheduler_.tolerance(), painter_.refused()};
}



} // namespace facet
