#include "viewer.h"

#include "geom/fmath.h"
#include "geom/pack_file.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "render/fixed.h"

#include <cmath>

namespace facet::viewer {
namespace {

constexpr float kUnitsPerDiagonal = 1048576.0f; // 2^20: mesh quantum = diagonal / 2^20
constexpr float kViewPerDiagonal = 65536.0f;    // 2^16: camera-space unit = diagonal / 2^16
constexpr int32_t kRadiusV = 32768;             // the bounding sphere's radius in view units
constexpr uint16_t kLineBias = 384;             // depth units edges are pulled toward the eye
constexpr hal::Rgb565 kEdgeColour = hal::rgb565(28, 30, 38);
constexpr uint32_t kDefaultRgb = 0x00CDBEB4;   // light warm grey (B,G,R bytes)
constexpr float kStep = 0.2617993878f;          // 15 degrees

constexpr uint8_t kOutNear = 1, kOutGuard = 2;
constexpr uint32_t kNoColour = 0xFF000000u; // no palette in the slot (colours are 24-bit)

// X / d for d >= 1, to about 2^-15 relative, without dividing (render/fixed.h).
inline int32_t divide(int64_t x, int32_t d) { return render::divide(x, render::reciprocal(uint32_t(d))); }

inline int32_t round_to_int(float v) { return int32_t(v + (v >= 0 ? 0.5f : -0.5f)); }

} // namespace

Memory Storage::memory(std::span<uint16_t> depth0, std::span<uint16_t> depth1, std::span<hal::Rgb565> line) {
    return Memory{
        {depth0, depth1},
        line,
        geom::EdgeSamples{edge_first, edge_count, sample_t, sample_p},
        sample_q,
        geom::FaceScratch{arena.view(), loop_points, loop_sizes, face_uv, pinned, face_xyz, mesh_of, measured, slivers},
        geom::Mesh{face_vertices, face_indices, {}},
        mesh_vertices,
        mesh_indices,
        faces,
        done_order,
        projected,
        edge_drawn,
        palettes,
        palette_rgb,
    };
}

// One instance under the current camera: view = (a P >> 30) + b, all fixed point.
struct Viewer::Instance {
    int32_t a[9];
    int32_t b[3];
    int32_t light[3]; // Q14, in shell coordinates
    bool mirrored;
    bool closed;
    int32_t dist, near, f16, cx16, cy16, guard;
    int64_t zk; // depth scale: z16 = (d - near) * zk >> 16
};

Viewer::Viewer(hal::Board& board, Memory& memory, CaptureFn capture, void* capture_context)
    : board_(board), mem_(memory), capture_(capture), capture_context_(capture_context),
      raster_{{board.display, memory.depth[0], memory.line},
              {board.display, memory.depth[1].empty() ? memory.depth[0] : memory.depth[1], memory.line}} {
    buffers_ = board.display.info().buffers >= 2 && !memory.depth[1].empty() ? 2 : 1;
    for (uint32_t& rgb : mem_.palette_rgb) rgb = kNoColour;
}

const render::Palette& Viewer::palette(uint32_t rgb) {
    for (uint32_t i = 0; i < mem_.palette_rgb.size(); ++i)
        if (mem_.palette_rgb[i] == rgb) return mem_.palettes[i];
    const uint32_t i = next_palette_;
    next_palette_ = (next_palette_ + 1) % uint32_t(mem_.palettes.size());
    mem_.palette_rgb[i] = rgb;
    render::make_palette(mem_.palettes[i], uint8_t(rgb & 255), uint8_t((rgb >> 8) & 255), uint8_t((rgb >> 16) & 255));
    return mem_.palettes[i];
}

Status Viewer::open(uint8_t* region, uint32_t capacity) {
    hal::Console& con = board_.console;
    if (!ok(raster_[0].check()) || !ok(raster_[1].check())) {
        print(con, "viewer: the z-buffer is smaller than the display\n");
        return Status::OutOfRange;
    }
    pack_file_bytes_ = geom::pack_file_bytes(region, capacity);
    uint32_t bytes = 0;
    const char* why = "";
    const bool deflated = geom::pack_file_kind(region, capacity) == geom::PackFileKind::Deflated;
    if (deflated) hal::measure_begin(con, "unpack");
    const Status unpacked = geom::unpack_in_place(region, capacity, capacity, bytes, why);
    if (deflated) hal::measure_end(con, "unpack");
    if (!ok(unpacked)) {
        print(con, "viewer: no valid pack: {}\n", why);
        return unpacked;
    }
    pack_bytes_ = bytes;
    geom::PackProblem problem;
    if (!ok(pack_.open(region, bytes, problem))) {
        print(con, "viewer: no valid pack: {}\n", problem.message);
        return Status::Corrupt;
    }
    if (pack_.faces().size() > mem_.faces.size() || pack_.edges().size() > mem_.edge_drawn.size() ||
        pack_.edges().size() > mem_.samples.first.size()) {
        print(con, "viewer: the model has {} faces and {} edges; this build holds {} and {}\n", pack_.faces().size(),
              pack_.edges().size(), mem_.faces.size(), mem_.edge_drawn.size());
        return Status::Full;
    }
    const pack::Header& h = pack_.header();
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        centre_[k] = 0.5f * (h.bbox_min[k] + h.bbox_max[k]);
        const float e = 0.5f * (h.bbox_max[k] - h.bbox_min[k]);
        r2 += e * e;
    }
    radius_ = r2 > 0 ? std::sqrt(r2) : 1.0f;
    unit_ = 2 * radius_ / kUnitsPerDiagonal;
    default_tolerance_ = geom::default_tolerance(pack_);
    opt_.tolerance = default_tolerance_;
    yaw_ = 0.6f, pitch_ = -0.95f, zoom_ = 1, pan_x_ = pan_y_ = 0;
    print(con, "@model faces {} edges {} shells {} instances {} bytes {} file_bytes {}\n", pack_.faces().size(),
          pack_.edges().size(), pack_.shells().size(), pack_.instances().size(), bytes, pack_file_bytes_);
    help();
    if (Status s = restart(); !ok(s)) return s;
    (void)capture_(capture_context_, "wireframe");
    return Status::Ok;
}

Status Viewer::restart() {
    hal::Console& con = board_.console;
    hal::measure_begin(con, "edges");
    Status st = geom::sample_edges(pack_, opt_, mem_.samples);
    if (ok(st) && mem_.samples.used * 3 > mem_.sample_q.size()) st = Status::Full;
    if (ok(st)) {
        const float inv = 1.0f / unit_;
        for (uint32_t i = 0; i < mem_.samples.used; ++i) {
            const geom::Vec3 p = mem_.samples.p[i];
            mem_.sample_q[3 * i] = round_to_int(p.x * inv);
            mem_.sample_q[3 * i + 1] = round_to_int(p.y * inv);
            mem_.sample_q[3 * i + 2] = round_to_int(p.z * inv);
        }
    }
    hal::measure_end(con, "edges");
    if (!ok(st)) {
        print(con, "viewer: sampling the edges at tolerance {} um needs more than the pool's {} samples\n",
              uint32_t(opt_.tolerance * 1000), mem_.samples.t.size());
        return st;
    }
    for (uint32_t f = 0; f < pack_.faces().size(); ++f) mem_.faces[f] = {0, 0, 0, 0, 0, {0, 0, 0}, 0, FaceState::Pending, false};
    const Totals before = totals_;
    totals_ = {};
    totals_.faces = uint32_t(pack_.faces().size());
    if (pass_ > 0) { // the session's peaks carry over
        totals_.arena_peak_bytes = before.arena_peak_bytes;
        totals_.samples_peak = before.samples_peak, totals_.face_points_peak = before.face_points_peak;
        totals_.slivers_peak = before.slivers_peak, totals_.vertices_peak = before.vertices_peak;
        totals_.triangles_peak = before.triangles_peak;
    }
    if (mem_.samples.used > totals_.samples_peak) totals_.samples_peak = mem_.samples.used;
    next_face_ = 0;
    half_shot_ = false;
    applied_[0] = applied_[1] = 0;
    stale_[0] = stale_[1] = true;
    print(con, "@lod tolerance_um {} samples {}\n", uint32_t(opt_.tolerance * 1000 + 0.5f), mem_.samples.used);
    present();
    return Status::Ok;
}

bool Viewer::step() {
    if (next_face_ >= pack_.faces().size()) return false;
    const uint32_t f = next_face_++;
    tessellate(f);
    const uint32_t finished = totals_.done + totals_.failed;
    const bool last = finished == totals_.faces;
    if (last) stale_[0] = stale_[1] = true; // the final frames lose the progress bar
    present();
    if (pass_ == 0 && !half_shot_ && 2 * finished >= totals_.faces) {
        half_shot_ = true;
        (void)capture_(capture_context_, "half");
    }
    if (last) {
        hal::Console& con = board_.console;
        print(con, "@{} faces {} failed {} triangles {} vertices {} mesh_bytes {} arena_peak {} tolerance_um {}\n",
              pass_ == 0 ? "tessellation" : "retessellation", totals_.faces, totals_.failed, totals_.triangles,
              totals_.vertices, totals_.mesh_bytes, totals_.arena_peak_bytes, uint32_t(opt_.tolerance * 1000 + 0.5f));
        if (pass_ == 0) (void)capture_(capture_context_, "done");
    }
    return true;
}

void Viewer::tessellate(uint32_t f) {
    hal::Console& con = board_.console;
    FaceInfo& info = mem_.faces[f];
    const pack::Face& F = pack_.faces()[f];
    uint32_t shell = 0;
    while (shell + 1 < pack_.shells().size() && f >= pack_.shells()[shell].first_face + pack_.shells()[shell].face_count) ++shell;
    const uint32_t ci = F.colour != pack::kNoIndex ? F.colour : pack_.shells()[shell].colour;
    uint32_t rgb = kDefaultRgb;
    if (ci != pack::kNoIndex) {
        const pack::Colour c = pack_.colours()[ci];
        rgb = uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16;
    }

    hal::measure_begin(con, "face");
    geom::Mesh& fm = mem_.face_mesh;
    fm.vertex_count = fm.triangle_count = 0;
    const geom::FaceResult r = geom::tessellate_face(pack_, f, mem_.samples, opt_, mem_.scratch, fm);
    const char* why = r.reason;
    Status st = r.status;
    const uint32_t v0 = totals_.vertices, i0 = totals_.triangles * 3;
    if (ok(st) && (v0 + fm.vertex_count > mem_.vertices.size() || i0 + fm.triangle_count * 3 > mem_.indices.size())) {
        st = Status::Full;
        why = "the viewer's mesh is full";
    }
    if (ok(st) && fm.vertex_count > mem_.projected.size()) {
        st = Status::Full;
        why = "more vertices than the viewer projects per face";
    }
    if (ok(st)) {
        const float inv = 1.0f / unit_, limit = float(1 << 30);
        for (uint32_t v = 0; v < fm.vertex_count && ok(st); ++v) {
            const geom::MeshVertex& mv = fm.vertices[v];
            DrawVertex& d = mem_.vertices[v0 + v];
            const float q[3] = {mv.p.x * inv, mv.p.y * inv, mv.p.z * inv};
            for (int k = 0; k < 3; ++k) {
                if (!(std::fabs(q[k]) < limit)) {
                    st = Status::OutOfRange;
                    why = "a vertex lies over 1000 diagonals from the model";
                }
                d.p[k] = ok(st) ? round_to_int(q[k]) : 0;
            }
            d.n[0] = int16_t(round_to_int(mv.n.x * 16384.0f));
            d.n[1] = int16_t(round_to_int(mv.n.y * 16384.0f));
            d.n[2] = int16_t(round_to_int(mv.n.z * 16384.0f));
            d.pad = 0;
        }
        for (uint32_t i = 0; i < fm.triangle_count * 3; ++i) mem_.indices[i0 + i] = uint16_t(fm.indices[i]);
    }
    hal::measure_end(con, "face");

    if (!ok(st)) {
        info = {0, 0, 0, 0, rgb, {0, 0, 0}, 0, FaceState::Failed, false};
        ++totals_.failed;
        print(con, "@face {} failed: {} ({}); it stays wireframe\n", f, why, status_name(st));
        return;
    }
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
    const bool planar = pack_.surfaces()[F.surface].type == uint8_t(pack::SurfaceType::Plane);
    info = {v0, fm.vertex_count, i0, fm.triangle_count, rgb, {centre[0], centre[1], centre[2]}, radius, FaceState::Done, planar};
    mem_.done_order[totals_.done++] = f;
    totals_.vertices += fm.vertex_count;
    totals_.triangles += fm.triangle_count;
    totals_.mesh_bytes = totals_.vertices * uint32_t(sizeof(DrawVertex)) + totals_.triangles * 3 * uint32_t(sizeof(uint16_t));
    const uint32_t arena = uint32_t(cdt::arena_bytes<uint16_t>(r.points + 4));
    if (arena > totals_.arena_peak_bytes) totals_.arena_peak_bytes = arena;
    if (r.points > totals_.face_points_peak) totals_.face_points_peak = r.points;
    if (r.slivers > totals_.slivers_peak) totals_.slivers_peak = r.slivers;
    if (totals_.vertices > totals_.vertices_peak) totals_.vertices_peak = totals_.vertices;
    if (totals_.triangles > totals_.triangles_peak) totals_.triangles_peak = totals_.triangles;
    print(con, "@progress {}/{} triangles {}\n", totals_.done + totals_.failed, totals_.faces, totals_.triangles);
}

uint32_t Viewer::storage_in_use() const {
    const uint64_t edges = pack_.edges().size(), faces = pack_.faces().size();
    const uint64_t points = totals_.face_points_peak + cdt::kBoxVertices, triangles = cdt::triangles_for(points);
    const uint64_t bytes =
        edges * (sizeof(uint32_t) + sizeof(uint16_t) + sizeof(uint8_t)) +              // per-edge sample index, drawn mark
        uint64_t(totals_.samples_peak) * (sizeof(float) + sizeof(geom::Vec3) + 3 * sizeof(int32_t)) + // samples
        cdt::arena_bytes<uint16_t>(points) +                                            // one face's CDT
        points * (sizeof(cdt::Point) + sizeof(geom::Vec2) + 1 + sizeof(geom::Vec3) + sizeof(uint32_t) +
                  sizeof(geom::MeshVertex) + sizeof(Projected)) +                       // one face's points
        triangles * (sizeof(geom::TriangleMeasure) + 3 * sizeof(uint32_t)) +            // its triangles
        uint64_t(totals_.slivers_peak) * sizeof(geom::Sliver) + capacity::kLoops * sizeof(uint32_t) +
        uint64_t(totals_.vertices_peak) * sizeof(DrawVertex) + uint64_t(totals_.triangles_peak) * 3 * sizeof(uint16_t) +
        faces * (sizeof(FaceInfo) + sizeof(uint32_t)) +                                 // per face
        capacity::kPalettes * (sizeof(render::Palette) + sizeof(uint32_t));
    return uint32_t(bytes);
}

Viewer::Instance Viewer::instance_transform(uint32_t index) const {
    const pack::Instance& inst = pack_.instances()[index];
    Instance in{};
    float sy, cy, sp, cp;
    geom::sincos_f(yaw_, sy, cy);
    geom::sincos_f(pitch_, sp, cp);
    // Rotate about z (yaw), then tilt about x (pitch): CAD models are usually z-up.
    const float R[9] = {cy, -sy, 0, sy * cp, cy * cp, -sp, sy * sp, cy * sp, cp};
    const float* m = inst.m;
    float A[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[3 * i + j] = R[3 * i] * m[j] + R[3 * i + 1] * m[4 + j] + R[3 * i + 2] * m[8 + j];
    const float v_per_mm = kViewPerDiagonal / (2 * radius_);
    const float t[3] = {m[3] - centre_[0], m[7] - centre_[1], m[11] - centre_[2]};
    const float pan[3] = {pan_x_, pan_y_, 0};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) in.a[3 * i + j] = round_to_int(A[3 * i + j] * 67108864.0f); // 2^30 / 16
        in.b[i] = round_to_int((R[3 * i] * t[0] + R[3 * i + 1] * t[1] + R[3 * i + 2] * t[2] + pan[i]) * v_per_mm);
    }
    // The light, fixed in view space (upper left, toward the viewer), into shell coordinates.
    const float L[3] = {-0.38f, 0.5f, 0.78f};
    for (int j = 0; j < 3; ++j) in.light[j] = round_to_int((A[j] * L[0] + A[3 + j] * L[1] + A[6 + j] * L[2]) * 16384.0f);
    const float det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
    in.mirrored = det < 0;
    in.closed = pack_.shells()[inst.shell].closed != 0;

    const hal::DisplayInfo d = board_.display.info();
    const float half = 0.5f * float(d.width < d.height ? d.width : d.height);
    in.dist = round_to_int(3.0f * kRadiusV * zoom_);
    in.near = kRadiusV / 64;
    in.f16 = round_to_int(16 * 2.5f * half); // the bounding sphere fills 80% of the short side when fitted
    in.cx16 = int32_t(d.width) * 8;
    in.cy16 = int32_t(d.height) * 8;
    in.guard = render::kGuardBand - (in.cx16 > in.cy16 ? in.cx16 : in.cy16) - 64;
    const int32_t far = in.dist + kRadiusV;
    in.zk = (int64_t(65535) << 16) / (far - in.near > 1 ? far - in.near : 1);
    return in;
}

void Viewer::project(const Instance& in, const int32_t p[3], Projected& o) const {
    const int64_t x = int64_t(in.a[0]) * p[0] + int64_t(in.a[1]) * p[1] + int64_t(in.a[2]) * p[2];
    const int64_t y = int64_t(in.a[3]) * p[0] + int64_t(in.a[4]) * p[1] + int64_t(in.a[5]) * p[2];
    const int64_t z = int64_t(in.a[6]) * p[0] + int64_t(in.a[7]) * p[1] + int64_t(in.a[8]) * p[2];
    o.x = int32_t(x >> 30) + in.b[0];
    o.y = int32_t(y >> 30) + in.b[1];
    o.d = in.dist - (int32_t(z >> 30) + in.b[2]);
    o.out = 0;
    if (o.d < in.near) {
        o.out = kOutNear;
        return;
    }
    const int64_t X = int64_t(o.x) * in.f16, Y = int64_t(o.y) * in.f16, G = int64_t(in.guard) * o.d;
    if (X > G || -X > G || Y > G || -Y > G) {
        o.out = kOutGuard;
        return;
    }
    const render::Reciprocal r = render::reciprocal(uint32_t(o.d)); // the perspective: x and y over one depth
    o.s.x = in.cx16 + render::divide(X, r);
    o.s.y = in.cy16 - render::divide(Y, r);
    const int64_t zz = (int64_t(o.d - in.near) * in.zk) >> 16;
    o.s.z = uint16_t(zz > 65535 ? 65535 : zz);
}

// Whether a face's bounding sphere may touch the screen: false only when it lies wholly
// behind the near plane or beyond one side of the view (each test conservative: the sphere's
// distance to a side plane is compared with its radius times a bound on the plane normal's
// length).
bool Viewer::on_screen(const Instance& in, const FaceInfo& face) const {
    if (face.radius <= 0) return true;
    const int32_t* p = face.centre;
    const int64_t x = int64_t(in.a[0]) * p[0] + int64_t(in.a[1]) * p[1] + int64_t(in.a[2]) * p[2];
    const int64_t y = int64_t(in.a[3]) * p[0] + int64_t(in.a[4]) * p[1] + int64_t(in.a[5]) * p[2];
    const int64_t z = int64_t(in.a[6]) * p[0] + int64_t(in.a[7]) * p[1] + int64_t(in.a[8]) * p[2];
    const int64_t cx = int32_t(x >> 30) + in.b[0], cy = int32_t(y >> 30) + in.b[1];
    const int64_t d = in.dist - (int32_t(z >> 30) + in.b[2]);
    // Mesh units are 16 view units (kUnitsPerDiagonal / kViewPerDiagonal); an eighth more for
    // the rounding of the fixed-point rotation.
    const int64_t r = face.radius / 16 + face.radius / 128 + 2;
    if (d + r < in.near) return false;
    const int64_t f = in.f16, w = in.cx16, h = in.cy16;
    if (cx * f - w * d > r * (f + w) || -cx * f - w * d > r * (f + w)) return false;
    if (cy * f - h * d > r * (f + h) || -cy * f - h * d > r * (f + h)) return false;
    return true;
}

// Whether a planar face of a closed shell turns its back to the eye (then every triangle of
// it would be culled, and its edges are drawn by its neighbours if they are seen).
bool Viewer::faces_away(const Instance& in, const FaceInfo& face) const {
    if (!face.planar || !in.closed || face.vertex_count == 0) return false;
    const DrawVertex& v = mem_.vertices[face.first_vertex];
    const int32_t* p = v.p;
    const int64_t x = (int64_t(in.a[0]) * p[0] + int64_t(in.a[1]) * p[1] + int64_t(in.a[2]) * p[2]) >> 30;
    const int64_t y = (int64_t(in.a[3]) * p[0] + int64_t(in.a[4]) * p[1] + int64_t(in.a[5]) * p[2]) >> 30;
    const int64_t z = (int64_t(in.a[6]) * p[0] + int64_t(in.a[7]) * p[1] + int64_t(in.a[8]) * p[2]) >> 30;
    // The normal in view space (the rotation, scaled by 2^26, keeps it outward even mirrored).
    const int64_t nx = (int64_t(in.a[0]) * v.n[0] + int64_t(in.a[1]) * v.n[1] + int64_t(in.a[2]) * v.n[2]) >> 14;
    const int64_t ny = (int64_t(in.a[3]) * v.n[0] + int64_t(in.a[4]) * v.n[1] + int64_t(in.a[5]) * v.n[2]) >> 14;
    const int64_t nz = (int64_t(in.a[6]) * v.n[0] + int64_t(in.a[7]) * v.n[1] + int64_t(in.a[8]) * v.n[2]) >> 14;
    // The eye sits at (0, 0, dist) in view space (depth d = dist - z); the face looks at it
    // when n . (eye - p) > 0.
    const int64_t to_eye_x = -(x + in.b[0]), to_eye_y = -(y + in.b[1]), to_eye_z = in.dist - (z + in.b[2]);
    return nx * to_eye_x + ny * to_eye_y + nz * to_eye_z < 0;
}

void Viewer::draw_triangle(int buffer, const Instance& in, const Projected& a, const Projected& b, const Projected& c,
                           const render::Palette& pal, render::Cull cull) {
    render::Rasterizer& r = raster_[buffer];
    if (!(a.out | b.out | c.out)) {
        (void)r.draw(a.s, b.s, c.s, pal, cull);
        return;
    }
    if (a.out & b.out & c.out & kOutNear) return;
    // Clip against the near plane and the guard band (camera space, float: this path is rare).
    struct V {
        float x, y, d, shade;
    };
    const float near = float(in.near), f16 = float(in.f16);
    const float G = float(in.guard) * 0.98f; // inside the band after rounding
    V poly[9], tmp[9];
    int n = 3;
    const Projected* src[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i)
        poly[i] = {float(src[i]->x), float(src[i]->y), float(src[i]->d), float(src[i]->s.shade)};
    auto plane = [&](const V& v, int k) {
        switch (k) {
        case 0: return v.d - near * 1.01f;
        case 1: return G * v.d - f16 * v.x;
        case 2: return G * v.d + f16 * v.x;
        case 3: return G * v.d - f16 * v.y;
        default: return G * v.d + f16 * v.y;
        }
    };
    for (int k = 0; k < 5 && n >= 3; ++k) {
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const V& p = poly[i];
            const V& q = poly[(i + 1) % n];
            const float dp = plane(p, k), dq = plane(q, k);
            if (dp >= 0) tmp[m++] = p;
            if ((dp >= 0) != (dq >= 0)) {
                const float t = dp / (dp - dq);
                tmp[m++] = {p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t, p.d + (q.d - p.d) * t, p.shade + (q.shade - p.shade) * t};
            }
        }
        n = m;
        for (int i = 0; i < n; ++i) poly[i] = tmp[i];
    }
    if (n < 3) return;
    render::ScreenVertex s[9];
    for (int i = 0; i < n; ++i) {
        const int32_t d = round_to_int(poly[i].d) > in.near ? round_to_int(poly[i].d) : in.near;
        s[i].x = in.cx16 + divide(int64_t(round_to_int(poly[i].x)) * in.f16, d);
        s[i].y = in.cy16 - divide(int64_t(round_to_int(poly[i].y)) * in.f16, d);
        const int64_t zz = (int64_t(d - in.near) * in.zk) >> 16;
        s[i].z = uint16_t(zz > 65535 ? 65535 : zz);
        s[i].shade = uint8_t(poly[i].shade);
    }
    for (int i = 1; i + 1 < n; ++i) (void)r.draw(s[0], s[i], s[i + 1], pal, cull);
}

void Viewer::draw_face(int buffer, uint32_t f, const Instance& in, bool with_edges) {
    const FaceInfo& F = mem_.faces[f];
    if (F.state != FaceState::Done || !on_screen(in, F) || faces_away(in, F)) return;
    Projected* P = mem_.projected.data();
    const render::Palette& pal = palette(F.rgb);
    const bool two_sided = !in.closed;
    for (uint32_t v = 0; v < F.vertex_count; ++v) {
        const DrawVertex& dv = mem_.vertices[F.first_vertex + v];
        Projected& o = P[v];
        project(in, dv.p, o);
        int32_t lit = (int32_t(dv.n[0]) * in.light[0] + int32_t(dv.n[1]) * in.light[1] + int32_t(dv.n[2]) * in.light[2]) >> 14;
        if (lit < 0) lit = two_sided ? (-lit * 154) >> 8 : 0; // the back of an open sheet, a little darker
        if (lit > 16384) lit = 16384;
        o.s.shade = uint8_t(77 + ((178 * lit) >> 14)); // ambient 0.3 + diffuse 0.7, of 255
    }
    const render::Cull cull = in.closed ? render::Cull::Back : render::Cull::None;
    const uint16_t* id = &mem_.indices[F.first_index];
    for (uint32_t t = 0; t < F.triangle_count; ++t, id += 3) {
        if (in.mirrored) draw_triangle(buffer, in, P[id[0]], P[id[2]], P[id[1]], pal, cull);
        else draw_triangle(buffer, in, P[id[0]], P[id[1]], P[id[2]], pal, cull);
    }
    if (with_edges) draw_face_edges(buffer, f, in, false);
}

void Viewer::draw_face_edges(int buffer, uint32_t f, const Instance& in, bool once) {
    // Its edges lie in its sphere; a plane facing away hides them unless a neighbour shows them.
    if (!on_screen(in, mem_.faces[f]) || faces_away(in, mem_.faces[f])) return;
    const pack::Face& F = pack_.faces()[f];
    for (uint32_t l = F.first_loop; l < F.first_loop + F.loop_count; ++l) {
        const pack::Loop& L = pack_.loops()[l];
        for (uint32_t c = L.first_coedge; c < L.first_coedge + L.coedge_count; ++c) {
            const pack::Coedge& C = pack_.coedges()[c];
            if (C.seam() != pack::Seam::None) continue; // a periodic surface's seam is no B-rep edge to the eye
            const uint32_t e = C.edge();
            if (once) {
                if (mem_.edge_drawn[e]) continue;
                mem_.edge_drawn[e] = 1;
            }
            draw_edge(buffer, e, in);
        }
    }
}

void Viewer::draw_edge(int buffer, uint32_t e, const Instance& in) {
    const pack::Edge& E = pack_.edges()[e];
    if (E.curve == pack::kNoIndex) return; // a pole: nothing to draw
    const uint32_t first = mem_.samples.first[e], n = mem_.samples.count[e];
    Projected prev{}, cur{};
    for (uint32_t k = 0; k < n; ++k) {
        project(in, &mem_.sample_q[3 * (first + k)], cur);
        // Segments that leave the view volume are left out (edges are not clipped).
        if (k > 0 && !(prev.out | cur.out)) (void)raster_[buffer].line(prev.s, cur.s, kEdgeColour, kLineBias);
        prev = cur;
    }
}

void Viewer::draw_progress() {
    const hal::DisplayInfo d = board_.display.info();
    const uint32_t finished = totals_.done + totals_.failed;
    const uint16_t w = uint16_t(totals_.faces ? uint32_t(d.width) * finished / totals_.faces : d.width);
    for (uint16_t y = uint16_t(d.height - 4); y < d.height; ++y) {
        if (w) (void)board_.display.fill_span(0, y, w, hal::rgb565(40, 110, 220));
        if (w < d.width) (void)board_.display.fill_span(w, y, uint16_t(d.width - w), hal::rgb565(70, 74, 84));
    }
}

void Viewer::draw_full(int buffer) {
    const hal::DisplayInfo d = board_.display.info();
    // A CAD-style background: light at the top, darker toward the bottom (16.16 steps per row).
    const int32_t rows = d.height > 1 ? d.height - 1 : 1;
    const int32_t dr = (80 << 16) / rows, dg = (78 << 16) / rows, db = (64 << 16) / rows;
    int32_t r = 214 << 16, g = 222 << 16, b = 234 << 16;
    for (uint16_t y = 0; y < d.height; ++y, r -= dr, g -= dg, b -= db) {
        (void)board_.display.fill_span(0, y, d.width, hal::rgb565(uint8_t(r >> 16), uint8_t(g >> 16), uint8_t(b >> 16)));
    }
    raster_[buffer].clear_depth();
    for (uint32_t i = 0; i < pack_.instances().size(); ++i) {
        const Instance in = instance_transform(i);
        const pack::Shell& sh = pack_.shells()[pack_.instances()[i].shell];
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) draw_face(buffer, f, in, false);
        // Each edge once per instance (an edge has two faces).
        for (uint8_t& drawn : mem_.edge_drawn.first(pack_.edges().size())) drawn = 0;
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) draw_face_edges(buffer, f, in, true);
    }
}

void Viewer::present() {
    hal::Console& con = board_.console;
    const int b = buffers_ == 2 ? back_ : 0;
    if (stale_[b]) {
        raster_[b].stats = {};
        hal::measure_begin(con, "frame");
        draw_full(b);
        hal::measure_end(con, "frame");
        const render::RasterStats& st = raster_[b].stats;
        print(con, "@frame triangles {} culled {} spans {} pixels {}\n", st.triangles, st.culled, st.spans, st.pixels);
        stale_[b] = false;
    } else {
        // The faces finished since this buffer was last shown, in every instance of their shell.
        for (uint32_t i = 0; i < pack_.instances().size() && applied_[b] < totals_.done; ++i) {
            const pack::Shell& sh = pack_.shells()[pack_.instances()[i].shell];
            bool any = false;
            Instance in;
            for (uint32_t k = applied_[b]; k < totals_.done; ++k) {
                const uint32_t f = mem_.done_order[k];
                if (f < sh.first_face || f >= sh.first_face + sh.face_count) continue;
                if (!any) in = instance_transform(i), any = true;
                draw_face(b, f, in, true);
            }
        }
    }
    applied_[b] = totals_.done;
    if (totals_.done + totals_.failed < totals_.faces) draw_progress();
    (void)board_.display.flip();
    if (buffers_ == 2) back_ ^= 1;
}

void Viewer::view_changed() {
    stale_[0] = stale_[1] = true;
    present();
    print(board_.console, "@view yaw {} pitch {} zoom_pct {}\n", round_to_int(yaw_ * 57.29578f), round_to_int(pitch_ * 57.29578f),
          round_to_int(100.0f / zoom_));
}

void Viewer::help() {
    print(board_.console,
          "keys: a/d turn, w/s tilt, +/- zoom, i/j/k/l pan, f fit, [/] coarser/finer detail, h help, q quit;\n"
          "      !shot NAME<enter> takes a screenshot; mouse: left drag turns, right drag pans, middle drag zooms\n");
}

void Viewer::command(const char* text) {
    auto starts = [&](const char* p) {
        uint32_t i = 0;
        for (; p[i]; ++i)
            if (text[i] != p[i]) return false;
        return true;
    };
    if (starts("shot ") && text[5]) {
        (void)capture_(capture_context_, text + 5);
        return;
    }
    print(board_.console, "viewer: unknown command '{}'\n", text);
}

void Viewer::key(uint8_t k) {
    const float pan = 0.1f * radius_;
    switch (k) {
    case 'a': yaw_ -= kStep; break;
    case 'd': yaw_ += kStep; break;
    case 'w': pitch_ -= kStep; break;
    case 's': pitch_ += kStep; break;
    case '+': case '=': zoom_ *= 0.8f; break;
    case '-': zoom_ *= 1.25f; break;
    case 'j': pan_x_ -= pan; break;
    case 'l': pan_x_ += pan; break;
    case 'i': pan_y_ += pan; break;
    case 'k': pan_y_ -= pan; break;
    case 'f': yaw_ = 0.6f, pitch_ = -0.95f, zoom_ = 1, pan_x_ = pan_y_ = 0; break;
    case '[': case ']': {
        const float t = k == '[' ? opt_.tolerance * 2 : opt_.tolerance * 0.5f;
        if (t > default_tolerance_ * 16.01f || t < default_tolerance_ / 8.01f) {
            print(board_.console, "viewer: level of detail at its limit ({} um)\n", uint32_t(opt_.tolerance * 1000 + 0.5f));
            return;
        }
        opt_.tolerance = t;
        ++pass_;
        (void)restart();
        return;
    }
    case 'h': case '?': help(); return;
    case 'q': quit_ = true; return;
    case '\r': case '\n': case ' ': return;
    default: print(board_.console, "viewer: unknown key {} (h for help)\n", uint32_t(k)); return;
    }
    if (zoom_ < 0.05f) zoom_ = 0.05f;
    if (zoom_ > 20.0f) zoom_ = 20.0f;
    view_changed();
}

void Viewer::handle(const hal::InputEvent& e) {
    using Kind = hal::InputEvent::Kind;
    switch (e.kind) {
    case Kind::Key:
        if (in_line_) {
            if (e.key == '\n' || e.key == '\r') {
                line_[line_len_] = 0;
                in_line_ = false;
                command(line_);
            } else if (line_len_ + 1 < sizeof line_) {
                line_[line_len_++] = char(e.key);
            }
            return;
        }
        if (e.key == '!') {
            in_line_ = true;
            line_len_ = 0;
            return;
        }
        key(e.key);
        return;
    case Kind::PointerDown:
    case Kind::PointerUp: buttons_ = e.buttons; return;
    case Kind::PointerMove: {
        if (!e.buttons) return;
        if (e.buttons & 1) { // turn: 0.5 degree per pixel
            yaw_ += float(e.dx) * 0.00872665f;
            pitch_ += float(e.dy) * 0.00872665f;
        } else if (e.buttons & 2) { // pan: the model follows the pointer at its centre's depth
            const hal::DisplayInfo d = board_.display.info();
            const float px = 2 * radius_ * 3 * zoom_ / (2.5f * 0.5f * float(d.width < d.height ? d.width : d.height));
            pan_x_ += float(e.dx) * px / 2;
            pan_y_ -= float(e.dy) * px / 2;
        } else if (e.buttons & 4) {
            zoom_ *= 1.0f + float(e.dy) * 0.01f;
            if (zoom_ < 0.05f) zoom_ = 0.05f;
            if (zoom_ > 20.0f) zoom_ = 20.0f;
        }
        view_changed();
        return;
    }
    }
}

} // namespace facet::viewer
