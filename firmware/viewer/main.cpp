// facet-viewer, first cut: the pack from its load address, validated, tessellated face by face
// on the device (geom/ + cdt/), drawn shaded through the span rasterizer, captured.
//
// Regions for the instruction counter: "tessellate" (every distinct part, all faces) and
// "frame" (one full redraw). A face that cannot be tessellated is reported ("@face N failed:
// reason") and left out; the rest of the model is drawn. Still to come (issue 5): the
// wireframe first and faces filling in, interaction, level of detail.
#include "facet_board_config.h"
#include "geom/pack.h"
#include "geom/tessellate.h"
#include "hal/board.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "render/raster.h"
#include "report.h"

#include <cmath>

namespace {

using namespace facet;

constexpr uint32_t kPixels = uint32_t(board_config::kDisplayWidth) * board_config::kDisplayHeight;
constexpr size_t kEdges = 8192;
constexpr size_t kSamples = 65536;
constexpr size_t kFaceVertices = 12000; // per face, in the 16-bit CDT arena
constexpr size_t kMeshVertices = 98304;
constexpr size_t kMeshTriangles = 131072;

#define ARENA __attribute__((section(".arena")))
ARENA uint16_t depth[kPixels];
hal::Rgb565 line[board_config::kDisplayWidth];

ARENA uint32_t edge_first[kEdges];
ARENA uint16_t edge_count[kEdges];
ARENA float sample_t[kSamples];
ARENA geom::Vec3 sample_p[kSamples];

ARENA cdt::Arena<uint16_t, kFaceVertices> arena;
ARENA cdt::Point loop_points[kFaceVertices];
ARENA cdt::Point interior[kFaceVertices];
ARENA uint32_t loop_sizes[512];
ARENA geom::Vec2 face_uv[kFaceVertices];
ARENA uint8_t pinned[kFaceVertices];
ARENA geom::Vec3 face_xyz[kFaceVertices];
ARENA uint32_t mesh_of[kFaceVertices];

ARENA geom::MeshVertex mesh_vertices[kMeshVertices];
ARENA uint32_t mesh_indices[3 * kMeshTriangles];
ARENA uint32_t vertex_colour[kMeshVertices];
ARENA render::ScreenVertex screen[kMeshVertices];
ARENA uint32_t shell_first_triangle[1024], shell_triangles[1024];
ARENA uint32_t shell_first_vertex[1024], shell_vertices[1024];

struct Camera {
    float m[9];   // world -> view rotation (rows)
    float c[3];   // the model's centre
    float distance, focal, near, far, cx, cy;
};

Camera fit(const pack::Header& h, uint16_t w, uint16_t hgt, float yaw, float pitch) {
    Camera cam{};
    float r2 = 0;
    for (int k = 0; k < 3; ++k) {
        cam.c[k] = 0.5f * (h.bbox_min[k] + h.bbox_max[k]);
        const float e = 0.5f * (h.bbox_max[k] - h.bbox_min[k]);
        r2 += e * e;
    }
    const float r = r2 > 0 ? std::sqrt(r2) : 1.0f;
    const float cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
    // Rotate about z (yaw), then tilt about x (pitch): CAD models are usually z-up.
    const float m[9] = {cy, -sy, 0, sy * cp, cy * cp, -sp, sy * sp, cy * sp, cp};
    for (int i = 0; i < 9; ++i) cam.m[i] = m[i];
    cam.distance = 3 * r;
    cam.near = cam.distance - r;
    cam.far = cam.distance + r;
    const float half = 0.5f * float(w < hgt ? w : hgt);
    cam.focal = 1.25f * half * (cam.distance - r) / r; // the silhouette is well inside the bounding sphere
    cam.cx = 0.5f * w;
    cam.cy = 0.5f * hgt;
    return cam;
}

// Transforms and lights one instance's vertices into `screen`.
void project(const Camera& cam, const pack::Instance& inst, uint32_t first, uint32_t count) {
    const float light[3] = {-0.38f, 0.5f, 0.78f};
    for (uint32_t i = first; i < first + count; ++i) {
        const geom::MeshVertex& v = mesh_vertices[i];
        const float* t = inst.m;
        const float p[3] = {t[0] * v.p.x + t[1] * v.p.y + t[2] * v.p.z + t[3] - cam.c[0],
                            t[4] * v.p.x + t[5] * v.p.y + t[6] * v.p.z + t[7] - cam.c[1],
                            t[8] * v.p.x + t[9] * v.p.y + t[10] * v.p.z + t[11] - cam.c[2]};
        const float n0[3] = {t[0] * v.n.x + t[1] * v.n.y + t[2] * v.n.z, t[4] * v.n.x + t[5] * v.n.y + t[6] * v.n.z,
                             t[8] * v.n.x + t[9] * v.n.y + t[10] * v.n.z};
        float q[3], n[3];
        for (int k = 0; k < 3; ++k) {
            q[k] = cam.m[3 * k] * p[0] + cam.m[3 * k + 1] * p[1] + cam.m[3 * k + 2] * p[2];
            n[k] = cam.m[3 * k] * n0[0] + cam.m[3 * k + 1] * n0[1] + cam.m[3 * k + 2] * n0[2];
        }
        // View: x right, y up, q[2] toward the viewer; depth along -z from the camera.
        const float d = cam.distance - q[2];
        render::ScreenVertex& s = screen[i];
        s.x = int32_t((cam.cx + cam.focal * q[0] / d) * 16.0f);
        s.y = int32_t((cam.cy - cam.focal * q[1] / d) * 16.0f);
        float zr = (d - cam.near) / (cam.far - cam.near);
        zr = zr < 0 ? 0 : (zr > 1 ? 1 : zr);
        s.z = uint16_t(zr * 65535.0f);
        float lit = n[0] * light[0] + n[1] * light[1] + n[2] * light[2];
        lit = lit < 0 ? -lit * 0.6f : lit; // two-sided: open shells show their back too
        const float k = 0.3f + 0.7f * lit;
        const uint32_t c = vertex_colour[i];
        s.r = uint8_t(float(c & 255) * k);
        s.g = uint8_t(float((c >> 8) & 255) * k);
        s.b = uint8_t(float((c >> 16) & 255) * k);
    }
}

} // namespace

int facet_main(hal::Board& board) {
    hal::Console& con = board.console;
    fw::report_board(board);
    const auto* header = reinterpret_cast<const pack::Header*>(board_config::kPackAddress);
    const uint32_t size = header->total_bytes <= board_config::kPackBytes ? header->total_bytes : 0;
    geom::Pack pack;
    geom::PackProblem problem;
    if (size == 0 || pack.open(header, size, problem) != Status::Ok) {
        print(con, "viewer: no valid pack at {}: {}\n", hex(board_config::kPackAddress),
              size == 0 ? "nothing loaded (run.py --load MODEL.fpk@ADDR)" : problem.message);
        return 1;
    }
    print(con, "@model faces {} edges {} shells {} instances {} bytes {}\n", pack.faces().size(), pack.edges().size(),
          pack.shells().size(), pack.instances().size(), size);
    if (pack.edges().size() > kEdges || pack.shells().size() > 1024) {
        print(con, "viewer: the model has more edges or parts than this build holds\n");
        return 1;
    }

    geom::TessOptions opt;
    opt.tolerance = geom::default_tolerance(pack);
    geom::EdgeSamples samples{edge_first, edge_count, sample_t, sample_p};
    geom::FaceScratch scratch{arena.view(), loop_points, loop_sizes, interior, face_uv, pinned, face_xyz, mesh_of};
    geom::Mesh mesh{mesh_vertices, mesh_indices, {}};
    uint32_t failed = 0;

    hal::measure_begin(con, "tessellate");
    Status st = geom::sample_edges(pack, opt, samples);
    for (uint32_t s = 0; s < pack.shells().size() && ok(st); ++s) {
        const pack::Shell& sh = pack.shells()[s];
        shell_first_triangle[s] = mesh.triangle_count;
        shell_first_vertex[s] = mesh.vertex_count;
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            const uint32_t v0 = mesh.vertex_count;
            const geom::FaceResult r = geom::tessellate_face(pack, f, samples, opt, scratch, mesh);
            if (!ok(r.status)) {
                ++failed;
                continue;
            }
            const pack::Face& F = pack.faces()[f];
            const uint32_t ci = F.colour != pack::kNoIndex ? F.colour : sh.colour;
            uint32_t rgb = 0x00CDBEB4; // a light warm grey (B,G,R bytes)
            if (ci != pack::kNoIndex) {
                const pack::Colour c = pack.colours()[ci];
                rgb = uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16;
            }
            for (uint32_t v = v0; v < mesh.vertex_count; ++v) vertex_colour[v] = rgb;
        }
        shell_triangles[s] = mesh.triangle_count - shell_first_triangle[s];
        shell_vertices[s] = mesh.vertex_count - shell_first_vertex[s];
    }
    hal::measure_end(con, "tessellate");
    if (!ok(st)) {
        print(con, "viewer: edge sampling failed: {}\n", status_name(st));
        return 1;
    }
    print(con, "@tessellation faces {} failed {} triangles {} vertices {} mesh_bytes {} tolerance_um {}\n",
          pack.faces().size(), failed, mesh.triangle_count, mesh.vertex_count,
          mesh.vertex_count * sizeof(geom::MeshVertex) + mesh.triangle_count * 12, uint32_t(opt.tolerance * 1000));

    render::Rasterizer raster(board.display, depth, line);
    const hal::DisplayInfo d = board.display.info();
    const Camera cam = fit(pack.header(), d.width, d.height, 0.6f, -0.95f);
    hal::measure_begin(con, "frame");
    for (uint16_t y = 0; y < d.height; ++y) {
        const uint32_t t = uint32_t(y) * 255 / (d.height > 1 ? d.height - 1 : 1);
        (void)board.display.fill_span(0, y, d.width, hal::rgb565(uint8_t(40 + t * 150 / 255), uint8_t(48 + t * 150 / 255), uint8_t(70 + t * 140 / 255)));
    }
    raster.clear_depth();
    uint32_t drawn = 0;
    for (const pack::Instance& inst : pack.instances()) {
        const uint32_t first = shell_first_triangle[inst.shell], count = shell_triangles[inst.shell];
        if (!count) continue;
        project(cam, inst, shell_first_vertex[inst.shell], shell_vertices[inst.shell]);
        for (uint32_t t = first; t < first + count; ++t) {
            const uint32_t* id = &mesh_indices[3 * t];
            if (ok(raster.draw(screen[id[0]], screen[id[1]], screen[id[2]], render::Cull::None))) ++drawn;
        }
    }
    hal::measure_end(con, "frame");
    (void)board.display.flip();
    print(con, "@frame triangles {} pixels {}\n", drawn, raster.stats.pixels);
    return ok(hal::capture("model")) ? 0 : 1;
}
