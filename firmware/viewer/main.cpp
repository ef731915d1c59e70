// facet-viewer: the handheld viewer. The pack comes from the board's pack address; the viewer
// (viewer.h) shows its wireframe, fills in the faces one by one, and then follows the keys on
// the UART and the mouse (versatilepb's PL050) until 'q'.
//
// UART protocol for the host runner: "@idle" when the viewer waits for input (the runner sends
// its next scripted entry then, ending with ENQ), "@progress", "@tessellation", "@view" status lines,
// and the instruction-count regions "edges", "face" (one per face) and "frame" (a full
// redraw).
#include "facet_board_config.h"
#include "hal/board.h"
#include "hal/print.h"
#include "report.h"
#include "viewer.h"

namespace {

using namespace facet;

constexpr uint32_t kPixels = uint32_t(board_config::kDisplayWidth) * board_config::kDisplayHeight;
using namespace viewer::capacity;

#define ARENA __attribute__((section(".arena")))
__attribute__((section(".zbuffer"))) uint16_t depth[2][kPixels]; // one per display buffer
hal::Rgb565 line[board_config::kDisplayWidth];

ARENA uint32_t edge_first[kEdges];
ARENA uint16_t edge_count[kEdges];
ARENA uint8_t edge_drawn[kEdges];
ARENA float sample_t[kSamples];
ARENA geom::Vec3 sample_p[kSamples];
ARENA int32_t sample_q[3 * kSamples];

ARENA cdt::Arena<uint16_t, kFaceVertices> arena;
ARENA cdt::Point loop_points[kFaceVertices];
ARENA cdt::Point interior[kFaceVertices];
ARENA uint32_t loop_sizes[kLoops];
ARENA geom::Vec2 face_uv[kFaceVertices];
ARENA uint8_t pinned[kFaceVertices];
ARENA geom::Vec3 face_xyz[kFaceVertices];
ARENA uint32_t mesh_of[kFaceVertices];
ARENA uint64_t passed[cdt::triangles_for(kFaceVertices)];
ARENA geom::MeshVertex face_vertices[kFaceVertices];
ARENA uint32_t face_indices[3 * cdt::triangles_for(kFaceVertices)];

ARENA viewer::DrawVertex mesh_vertices[kMeshVertices];
ARENA uint16_t mesh_indices[3 * kMeshTriangles];
ARENA viewer::FaceInfo faces[kFaces];
ARENA uint32_t done_order[kFaces];
ARENA viewer::Projected projected[kFaceVertices];

Status capture(void*, const char* name) { return hal::capture(name); }

} // namespace

int facet_main(hal::Board& board) {
    hal::Console& con = board.console;
    fw::report_board(board);
    viewer::Memory mem{
        {depth[0], depth[1]},
        line,
        geom::EdgeSamples{edge_first, edge_count, sample_t, sample_p},
        sample_q,
        geom::FaceScratch{arena.view(), loop_points, loop_sizes, interior, face_uv, pinned, face_xyz, mesh_of, passed},
        geom::Mesh{face_vertices, face_indices, {}},
        mesh_vertices,
        mesh_indices,
        faces,
        done_order,
        projected,
        edge_drawn,
    };
    static viewer::Viewer v(board, mem, capture, nullptr);
    const auto* header = reinterpret_cast<const pack::Header*>(board_config::kPackAddress);
    const uint32_t size = header->total_bytes <= board_config::kPackBytes ? header->total_bytes : 0;
    if (!ok(v.open(header, size))) {
        print(con, "viewer: nothing to show (load a pack with run.py --load MODEL.fpk@{})\n", hex(board_config::kPackAddress));
        return 1;
    }
    // "@idle" once the viewer has nothing left to do, then again after each ENQ (0x05) from
    // the host runner: a scripted session sends its next entry only then.
    bool prompt = true;
    while (!v.quit()) {
        hal::InputEvent e;
        while (!v.quit() && board.input.poll(e)) {
            if (e.kind == hal::InputEvent::Kind::Key && e.key == 0x05) prompt = true;
            else v.handle(e);
        }
        if (v.quit()) break;
        if (v.step()) continue;
        if (prompt) {
            print(con, "@idle\n");
            prompt = false;
        }
    }
    const viewer::Totals& t = v.totals();
    print(con, "viewer: {} faces ({} failed), {} triangles; bye\n", t.faces, t.failed, t.triangles);
    return 0;
}
