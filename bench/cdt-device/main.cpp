// facet-cdt-bench: the CDT on the device. Triangulates the paper's face and the 10k plate
// (bench/inputs, the same faces as the host benchmark) in the 16-bit device arena, each inside
// an instruction-count region ("cdt_paper", "cdt_plate10k"; "..._paper_order" for the paper's
// insertion order), then runs the independent checker
// on the result (outside the region) and reports. Exits non-zero if anything fails.
#include "cdt/check.h"
#include "cdt/face.h"
#include "cdt_inputs.h"
#include "hal/board.h"
#include "hal/measure.h"
#include "hal/print.h"
#include "hal/report.h"

namespace {

using namespace facet;

constexpr size_t kMaxPoints = 10240;          // enough for plate10k (10,000 segments)
constexpr size_t kVertices = kMaxPoints + 16; // + box corners
constexpr size_t kScratchWords = 160 * 1024;  // the checker's, measured need for plate10k ~70k

__attribute__((section(".arena"))) cdt::Arena<uint16_t, kVertices> arena;
__attribute__((section(".arena"))) cdt::Point loop_points[kMaxPoints];
__attribute__((section(".arena"))) cdt::Point interior[kMaxPoints];
__attribute__((section(".arena"))) uint32_t loop_sizes[1024];
__attribute__((section(".arena"))) uint32_t scratch[kScratchWords];
__attribute__((section(".arena"))) cdt::Segment segments[kMaxPoints];

bool run(hal::Board& board, const char* name, const char* region, cdt::LocateMode mode) {
    hal::Console& con = board.console;
    bench::Input in;
    const bench::InputBuffers buf{loop_points, kMaxPoints, loop_sizes, 1024, interior, kMaxPoints};
    if (!bench::make_input(name, buf, in)) {
        print(con, "cdt-bench: input {} does not fit the buffers\n", name);
        return false;
    }
    cdt::Cdt<uint16_t> cdt(arena.view());
    hal::measure_begin(con, region);
    const Result s = cdt::triangulate_face(cdt, in.face, mode);
    hal::measure_end(con, region);
    if (!s.ok()) {
        print(con, "cdt-bench: {} failed: {} ({})\n", name, s, s.status);
        return false;
    }
    // The checker needs the constraint list.
    size_t ns = 0, first = 0;
    for (uint32_t size : in.face.loop_sizes) {
        for (uint32_t j = 0; j < size; ++j) {
            segments[ns++] = {in.face.loop_points[first + j], in.face.loop_points[first + (j + 1) % size]};
        }
        first += size;
    }
    const std::span<const cdt::Segment> segs(segments, ns);
    const size_t need = cdt::check_scratch_words(cdt.vertex_count(), cdt.triangle_count(), segs);
    if (need > kScratchWords) {
        print(con, "cdt-bench: checker needs {} words, has {}\n", need, kScratchWords);
        return false;
    }
    const Result r = cdt::check(cdt, segs, true, std::span<uint32_t>(scratch, kScratchWords));
    const cdt::CdtStats& st = cdt.stats();
    print(con, "@cdt {} points {} segments {} vertices {} triangles {} inner {} flips {} walk {} checker {}\n",
          region, in.points(), in.segments, cdt.vertex_count() - cdt::kBoxVertices, cdt.triangle_count(),
          cdt.inner_count(), st.flips, st.walk_steps, r);
    print(con, "@vertices {} {}\n", region, in.points());
    return r.ok();
}

} // namespace

int facet_main(hal::Board& board) {
    hal::report_board(board);
    print(board.console, "cdt-bench: arena {} bytes for {} vertices ({} bytes per triangle)\n",
          sizeof arena, kVertices, sizeof(cdt::Triangle<uint16_t>));
    // facet's default order, then the paper's own order (each point, then its segment).
    const bool a = run(board, "paper", "cdt_paper", cdt::kDefaultLocateMode);
    const bool b = run(board, "plate10k", "cdt_plate10k", cdt::kDefaultLocateMode);
    const bool c = run(board, "paper", "cdt_paper_paper_order", cdt::LocateMode::Sequential);
    const bool d = run(board, "plate10k", "cdt_plate10k_paper_order", cdt::LocateMode::Sequential);
    return a && b && c && d ? 0 : 1;
}
