#include "clearance.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet::packer {
namespace {

constexpr int kSamples = 32;          // segments per edge for the distance estimate
constexpr double kShare = 0.4;        // of the clearance, for each side's sag

struct Polyline {
    std::vector<gp_Pnt> p;
    Bnd_Box box;
    TopoDS_Vertex a, b;
};

double segment_distance(const gp_Pnt& x, const gp_Pnt& a, const gp_Pnt& b) {
    const gp_Vec ab(a, b), ax(a, x);
    const double len2 = ab.SquareMagnitude();
    const double t = len2 > 0 ? std::clamp(ab.Dot(ax) / len2, 0.0, 1.0) : 0.0;
    return x.Distance(a.Translated(ab * t));
}

// The smallest distance between the polylines, from each one's points to the other's segments.
double polyline_distance(const Polyline& u, const Polyline& v) {
    double best = std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2; ++pass) {
        const Polyline& x = pass == 0 ? u : v;
        const Polyline& y = pass == 0 ? v : u;
        for (const gp_Pnt& p : x.p)
            for (size_t k = 0; k + 1 < y.p.size(); ++k) best = std::min(best, segment_distance(p, y.p[k], y.p[k + 1]));
    }
    return best;
}

bool share_vertex(const Polyline& u, const Polyline& v) {
    auto same = [](const TopoDS_Vertex& a, const TopoDS_Vertex& b) { return !a.IsNull() && !b.IsNull() && a.IsSame(b); };
    return same(u.a, v.a) || same(u.a, v.b) || same(u.b, v.a) || same(u.b, v.b);
}

} // namespace

std::vector<float> edge_sag_limits(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& edge_map) {
    const int n = edge_map.Extent();
    std::vector<Polyline> lines(n + 1);
    std::vector<bool> made(n + 1, false);
    auto polyline = [&](int i) -> const Polyline& {
        if (!made[i]) {
            made[i] = true;
            const TopoDS_Edge e = TopoDS::Edge(edge_map(i));
            TopExp::Vertices(e, lines[i].a, lines[i].b);
            if (!BRep_Tool::Degenerated(e)) {
                try {
                    BRepAdaptor_Curve c(e);
                    const double t0 = c.FirstParameter(), t1 = c.LastParameter();
                    for (int k = 0; k <= kSamples; ++k) {
                        const gp_Pnt p = c.Value(t0 + (t1 - t0) * k / kSamples);
                        lines[i].p.push_back(p);
                        lines[i].box.Add(p);
                    }
                } catch (const Standard_Failure&) {
                    lines[i].p.clear();
                }
            }
        }
        return lines[i];
    };
    std::vector<double> clearance(n + 1, std::numeric_limits<double>::infinity());
    for (TopExp_Explorer fx(shape, TopAbs_FACE); fx.More(); fx.Next()) {
        std::vector<int> edges;
        for (TopExp_Explorer ex(fx.Current(), TopAbs_EDGE); ex.More(); ex.Next()) {
            const int i = edge_map.FindIndex(ex.Current());
            if (i > 0 && std::find(edges.begin(), edges.end(), i) == edges.end() && !polyline(i).p.empty()) edges.push_back(i);
        }
        for (size_t x = 0; x < edges.size(); ++x) {
            for (size_t y = x + 1; y < edges.size(); ++y) {
                const int i = edges[x], j = edges[y];
                const Polyline &u = lines[i], &v = lines[j];
                if (share_vertex(u, v)) continue;
                if (u.box.Distance(v.box) >= std::max(clearance[i], clearance[j])) continue; // nothing nearer
                const double d = polyline_distance(u, v);
                clearance[i] = std::min(clearance[i], d);
                clearance[j] = std::min(clearance[j], d);
            }
        }
    }
    std::vector<float> limits(n + 1, 0.0f);
    for (int i = 1; i <= n; ++i)
        if (std::isfinite(clearance[i])) limits[i] = float(kShare * clearance[i]);
    return limits;
}

} // namespace facet::packer
