// facet-bench-cdt: facet's sequential CDT side by side with CGAL 5.5's
// Constrained_Delaunay_triangulation_2 (Epick, with its domain-marking step) on the same inputs,
// in the same run. Google Benchmark does the timing; a reporter collects the figures and prints
// ns per inserted vertex and the ratio to CGAL per input; --csv FILE writes one row per input
// and implementation. facet16/facet32 insert in facet's default order (all points along a
// Hilbert curve, then the loops); facet32-paper-order interleaves each loop point with its
// segment as the paper does; facet32-kdtree and facet32-random are the paper's Fig. 17
// alternatives (kd-tree-nearest Locate, random order).
//
//   facet-bench-cdt [--csv FILE] [--inputs a,b,...] [--quick] [benchmark flags]
#include "cdt/check.h"
#include "cdt/face.h"
#include "cdt_inputs.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#ifdef FACET_HAVE_CGAL
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <list>
#endif

using namespace facet;

namespace {

struct OwnedInput {
    std::vector<cdt::Point> loop_points, interior;
    std::vector<uint32_t> loop_sizes;
    bench::Input input;
};

std::unique_ptr<OwnedInput> load(const char* name) {
    bench::InputSize size;
    if (!bench::input_size(name, size)) return nullptr;
    auto in = std::make_unique<OwnedInput>();
    in->loop_points.resize(size.loop_points);
    in->loop_sizes.resize(size.loops);
    in->interior.resize(size.interior);
    const bench::InputBuffers buf{in->loop_points.data(), in->loop_points.size(), in->loop_sizes.data(),
                                  in->loop_sizes.size(), in->interior.data(), in->interior.size()};
    if (!bench::make_input(name, buf, in->input)) return nullptr;
    return in;
}

template <typename Index>
struct HostArena {
    std::vector<cdt::Vertex<Index>> v;
    std::vector<cdt::Triangle<Index>> t;
    std::vector<Index> work, order, minseq, ins;
    std::vector<uint32_t> keys;
    explicit HostArena(size_t n)
        : v(n), t(cdt::triangles_for(n)), work(cdt::work_for(n)), order(n), minseq(n), ins(n), keys(n) {}
    cdt::ArenaView<Index> view() { return {v, t, work, order, minseq, ins, keys}; }
};

struct Result {
    double ns_per_vertex = 0;
    uint64_t vertices = 0, triangles = 0;
};
std::map<std::string, Result> results; // key: input|impl

template <typename Index>
void run_facet(benchmark::State& state, const OwnedInput* in, cdt::LocateMode mode, const std::string& key) {
    HostArena<Index> arena(in->input.points() + cdt::kBoxVertices + 8);
    cdt::Cdt<Index> cdt(arena.view());
    for (auto _ : state) {
        const facet::Result s = cdt::triangulate_face(cdt, in->input.face, mode);
        if (!s.ok()) {
            state.SkipWithError(status_name(s.status));
            return;
        }
        benchmark::DoNotOptimize(cdt.triangle_count());
    }
    const uint64_t v = in->input.points();
    const uint32_t inner = cdt.inner_count();
    state.counters["vertices"] = double(v);
    state.counters["triangles"] = inner;
    results[key] = {0, v, inner};
}

#ifdef FACET_HAVE_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
    int nesting = -1;
    bool in_domain() const { return nesting % 2 == 1; }
};
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Nesting levels by breadth-first search from the infinite face, crossing one constraint per
// level: faces at odd levels are inside the domain (CGAL's documented polygon recipe).
uint64_t mark_domain(CDT& cdt) {
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
    std::list<CDT::Face_handle> border{cdt.infinite_face()};
    uint64_t inside = 0;
    for (int level = 0; !border.empty(); ++level) {
        std::list<CDT::Face_handle> next;
        while (!border.empty()) {
            CDT::Face_handle start = border.front();
            border.pop_front();
            if (start->info().nesting != -1) continue;
            std::list<CDT::Face_handle> queue{start};
            start->info().nesting = level;
            while (!queue.empty()) {
                CDT::Face_handle f = queue.front();
                queue.pop_front();
                if (level % 2 == 1 && !cdt.is_infinite(f)) ++inside;
                for (int i = 0; i < 3; ++i) {
                    CDT::Face_handle n = f->neighbor(i);
                    if (n->info().nesting != -1) continue;
                    if (cdt.is_constrained(CDT::Edge(f, i))) next.push_back(n);
                    else {
                        n->info().nesting = level;
                        queue.push_back(n);
                    }
                }
            }
        }
        border.swap(next);
    }
    return inside;
}

void run_cgal(benchmark::State& state, const OwnedInput* in, const std::string& key) {
    std::vector<K::Point_2> interior;
    for (const cdt::Point& p : in->input.face.interior) interior.emplace_back(p.x, p.y);
    std::vector<std::vector<K::Point_2>> loops;
    size_t first = 0;
    for (uint32_t n : in->input.face.loop_sizes) {
        std::vector<K::Point_2> loop;
        for (uint32_t j = 0; j < n; ++j) loop.emplace_back(in->input.face.loop_points[first + j].x, in->input.face.loop_points[first + j].y);
        loops.push_back(std::move(loop));
        first += n;
    }
    uint64_t inside = 0;
    for (auto _ : state) {
        CDT cdt;
        for (const auto& loop : loops) cdt.insert_constraint(loop.begin(), loop.end(), true);
        cdt.insert(interior.begin(), interior.end());
        inside = mark_domain(cdt);
        benchmark::DoNotOptimize(inside);
    }
    results[key] = {0, in->input.points(), inside};
}
#endif

class Collect : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
            auto it = results.find(r.run_name.function_name);
            if (it == results.end()) continue;
            it->second.ns_per_vertex = r.GetAdjustedRealTime() * 1e6 / double(it->second.vertices); // ms -> ns
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

} // namespace

int main(int argc, char** argv) {
    std::string csv, only;
    bool quick = false;
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
        else if (!std::strcmp(argv[i], "--inputs") && i + 1 < argc) only = "," + std::string(argv[++i]) + ",";
        else if (!std::strcmp(argv[i], "--quick")) quick = true;
        else rest.push_back(argv[i]);
    }
    std::vector<std::string> names;
    for (size_t i = 0; i < bench::kInputCount; ++i) {
        const std::string n = bench::kInputNames[i];
        if (!only.empty() && only.find("," + n + ",") == std::string::npos) continue;
        if (quick && (n.find("1M") != std::string::npos || n.find("100k") != std::string::npos)) continue;
        names.push_back(n);
    }
    std::vector<std::unique_ptr<OwnedInput>> inputs;
    for (const std::string& n : names) {
        inputs.push_back(load(n.c_str()));
        const OwnedInput* in = inputs.back().get();
        if (!in) {
            std::fprintf(stderr, "facet-bench-cdt: cannot build input %s\n", n.c_str());
            return 2;
        }
        const bool device = in->input.points() + cdt::kBoxVertices + 8 <= 32768;
        const bool big = in->input.points() > 200000;
        auto reg = [&](const std::string& impl, auto fn) {
            const std::string key = n + "|" + impl;
            auto* b = benchmark::RegisterBenchmark(key.c_str(), [=](benchmark::State& s) { fn(s, key); });
            b->Unit(benchmark::kMillisecond)->UseRealTime();
            if (big) b->Iterations(1);
            else b->MinTime(0.2);
        };
        if (device) reg("facet16", [in](benchmark::State& s, const std::string& k) { run_facet<uint16_t>(s, in, cdt::LocateMode::HilbertFirst, k); });
        reg("facet32", [in](benchmark::State& s, const std::string& k) { run_facet<uint32_t>(s, in, cdt::LocateMode::HilbertFirst, k); });
#ifdef FACET_HAVE_CGAL
        reg("cgal", [in](benchmark::State& s, const std::string& k) { run_cgal(s, in, k); });
#endif
        // Insertion orders: the paper's (each point, then its segment) on every input, and for
        // the paper's Fig. 17, kd-tree-nearest and random-order Locate on a few.
        if (!big || n.find("grid") == std::string::npos) {
            reg("facet32-paper-order", [in](benchmark::State& s, const std::string& k) { run_facet<uint32_t>(s, in, cdt::LocateMode::Sequential, k); });
        }
        if (n == "paper" || n == "plate10k" || n == "plate10k+grid" || n == "plate100k+grid") {
            reg("facet32-kdtree", [in](benchmark::State& s, const std::string& k) { run_facet<uint32_t>(s, in, cdt::LocateMode::KdTreeNearest, k); });
            reg("facet32-random", [in](benchmark::State& s, const std::string& k) { run_facet<uint32_t>(s, in, cdt::LocateMode::RandomOrder, k); });
        }
    }
    int rargc = int(rest.size());
    benchmark::Initialize(&rargc, rest.data());
    Collect reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    std::printf("\n%-16s %-16s %10s %10s %14s %14s\n", "input", "impl", "vertices", "triangles", "ns/vertex", "ratio_to_cgal");
    FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
    if (out) std::fprintf(out, "input,impl,vertices,triangles,ns_per_vertex,ratio_to_cgal\n");
    for (const std::string& n : names) {
        const auto cg = results.find(n + "|cgal");
        for (const auto& [key, r] : results) {
            if (key.compare(0, n.size() + 1, n + "|") != 0) continue;
            const std::string impl = key.substr(n.size() + 1);
            const double ratio = cg != results.end() && cg->second.ns_per_vertex > 0 ? r.ns_per_vertex / cg->second.ns_per_vertex : 0;
            std::printf("%-16s %-16s %10llu %10llu %14.1f %14.3f\n", n.c_str(), impl.c_str(), (unsigned long long)r.vertices,
                        (unsigned long long)r.triangles, r.ns_per_vertex, ratio);
            if (out) std::fprintf(out, "%s,%s,%llu,%llu,%.2f,%.4f\n", n.c_str(), impl.c_str(), (unsigned long long)r.vertices,
                                  (unsigned long long)r.triangles, r.ns_per_vertex, ratio);
        }
    }
    if (out) std::fclose(out);
    return 0;
}
