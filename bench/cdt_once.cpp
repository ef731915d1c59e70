// facet-cdt-once: triangulates one named benchmark input once and prints what happened.
// Deterministic, for profiling under callgrind:  facet-cdt-once plate10k [sequential|kdtree|random|hilbert]
#include "cdt/face.h"
#include "cdt_inputs.h"

#include <cstdio>
#include <cstring>
#include <vector>

using namespace facet;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s INPUT [sequential|kdtree|random|hilbert]\n", argv[0]);
        return 2;
    }
    cdt::LocateMode mode = cdt::LocateMode::Sequential;
    if (argc > 2 && !std::strcmp(argv[2], "kdtree")) mode = cdt::LocateMode::KdTreeNearest;
    if (argc > 2 && !std::strcmp(argv[2], "random")) mode = cdt::LocateMode::RandomOrder;
    if (argc > 2 && !std::strcmp(argv[2], "hilbert")) mode = cdt::LocateMode::HilbertFirst;
    bench::InputSize size;
    if (!bench::input_size(argv[1], size)) {
        std::fprintf(stderr, "unknown input %s\n", argv[1]);
        return 2;
    }
    std::vector<cdt::Point> lp(size.loop_points), ip(size.interior);
    std::vector<uint32_t> ls(size.loops);
    bench::Input in;
    if (!bench::make_input(argv[1], {lp.data(), lp.size(), ls.data(), ls.size(), ip.data(), ip.size()}, in)) return 2;
    const size_t v = in.points() + cdt::kBoxVertices + 8;
    std::vector<cdt::Vertex<uint32_t>> vert(v);
    std::vector<cdt::Triangle<uint32_t>> tri(cdt::triangles_for(v));
    std::vector<uint32_t> work(cdt::work_for(v)), order(v), minseq(v), ins(v), keys(v);
    cdt::Cdt<uint32_t> cdt({vert, tri, work, order, minseq, ins, keys});
    const Status s = cdt::triangulate_face(cdt, in.face, mode).status;
    const cdt::CdtStats& st = cdt.stats();
    std::printf("%s: %s, %u vertices, %u inner triangles, walk steps %llu, flips %llu, cavities %llu (%llu triangles)\n",
                argv[1], status_name(s), cdt.vertex_count(), cdt.inner_count(), (unsigned long long)st.walk_steps,
                (unsigned long long)st.flips, (unsigned long long)st.cavities, (unsigned long long)st.cavity_triangles);
    return ok(s) ? 0 : 1;
}
