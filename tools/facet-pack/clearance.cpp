#include "clearance.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepLProp_CLProps.hxx>
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
#include <cstdint>
#include <cstring>
#include <limits>

namespace facet::packer {
namespace {

constexpr int kSamples = 32;          // segments per edge for the distance estimate
constexpr double kShare = 0.4;        // of the clearance, for each side's sag

struct Polyline {
    std::vector<gp_Pnt> p; // at t0 + (t1 - t0) k / kSamples
    Bnd_Box box;
    TopoDS_Vertex a, b;
    TopoDS_Edge edge;
    double t0 = 0, t1 = 0;
};

// Where two polylines come nearest: the distance, and each one's parameter there.
struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    double tu = 0, tv = 0;
};

// The point of segment ab nearest x, as its fraction along ab.
double segment_fraction(const gp_Pnt& x, const gp_Pnt& a, const gp_Pnt& b) {
    const gp_Vec ab(a, b), ax(a, x);
    const double len2 = ab.SquareMagnitude();
    return len2 > 0 ? std::clamp(ab.Dot(ax) / len2, 0.0, 1.0) : 0.0;
}

// The nearest points of the polylines, from each one's points to the other's segments.
Nearest polyline_nearest(const Polyline& u, const Polyline& v) {
    Nearest best;
    for (int pass = 0; pass < 2; ++pass) {
        const Polyline& x = pass == 0 ? u : v;
        const Polyline& y = pass == 0 ? v : u;
        for (size_t i = 0; i < x.p.size(); ++i)
            for (size_t k = 0; k + 1 < y.p.size(); ++k) {
                const double f = segment_fraction(x.p[i], y.p[k], y.p[k + 1]);
                const double d = x.p[i].Distance(y.p[k].Translated(gp_Vec(y.p[k], y.p[k + 1]) * f));
                if (d >= best.distance) continue;
                const double tx = x.t0 + (x.t1 - x.t0) * double(i) / kSamples;
                const double ty = y.t0 + (y.t1 - y.t0) * (double(k) + f) / kSamples;
                best = {d, pass == 0 ? tx : ty, pass == 0 ? ty : tx};
            }
    }
    return best;
}

// Whether `toward` lies on the concave side of the edge's curve at t: where the curve's chords
// sag to. A straight curve has no such side; a chord of a curve never leaves its convex side.
bool concave_toward(const Polyline& line, double t, const gp_Pnt& toward) {
    try {
        BRepAdaptor_Curve c(line.edge);
        BRepLProp_CLProps props(c, t, 2, 1e-9);
        if (!props.IsTangentDefined() || !(props.Curvature() > 1e-12)) return false;
        gp_Dir n;
        props.Normal(n); // towards the centre of curvature
        return gp_Vec(props.Value(), toward).Dot(gp_Vec(n)) > 0;
    } catch (const Standard_Failure&) {
        return true; // unknown: keep the limit
    }
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
            lines[i].edge = e;
            if (!BRep_Tool::Degenerated(e)) {
                try {
                    BRepAdaptor_Curve c(e);
                    const double t0 = c.FirstParameter(), t1 = c.LastParameter();
                    lines[i].t0 = t0, lines[i].t1 = t1;
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
    auto reach = [&](int i) { return lines[i].box.IsVoid() ? 0.0 : std::sqrt(lines[i].box.SquareExtent()); };
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
                // What could lower either's clearance: nearer than it, and within the edge's reach
                // (a chord never sags further from its curve than the curve's own box is wide).
                const double reach_i = std::min(clearance[i], reach(i)), reach_j = std::min(clearance[j], reach(j));
                if (u.box.Distance(v.box) >= std::max(reach_i, reach_j)) continue;
                const Nearest near = polyline_nearest(u, v);
                if (!(near.distance < std::max(reach_i, reach_j))) continue;
                // Each edge's chords sag towards its concave side only: two holes side by side
                // never reach each other however coarse their circles, a rounded corner's arc
                // reaches the hole near it.
                const gp_Pnt pu = BRepAdaptor_Curve(u.edge).Value(near.tu), pv = BRepAdaptor_Curve(v.edge).Value(near.tv);
                if (near.distance < reach_i && concave_toward(u, near.tu, pv)) clearance[i] = near.distance;
                if (near.distance < reach_j && concave_toward(v, near.tv, pu)) clearance[j] = near.distance;
            }
        }
    }
    // Each limit to 8 significant bits, rounded down (a limit still, within 0.8%): the low half
    // of the float is then 0, and a pack's edges compress to about 2 bytes less each.
    std::vector<float> limits(n + 1, 0.0f);
    for (int i = 1; i <= n; ++i) {
        if (!std::isfinite(clearance[i])) continue;
        uint32_t bits;
        const float limit = float(kShare * clearance[i]);
        std::memcpy(&bits, &limit, sizeof bits);
        bits &= 0xFFFF0000u;
        std::memcpy(&limits[i], &bits, sizeof bits);
    }
    return limits;
}

} // namespace facet::packer
