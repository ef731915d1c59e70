// Edge-collapse simplification by quadric error, and the distance between meshes (simplify.h).
#include "simplify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <tuple>

namespace facet::geom {
namespace {

struct Point3 { // double, for the quadrics' sums and the distances
    double x, y, z;
};
Point3 as_point(Vec3 v) { return {v.x, v.y, v.z}; }
Point3 operator-(Point3 a, Point3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 operator+(Point3 a, Point3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Point3 operator*(Point3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Point3 a, Point3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Point3 cross(Point3 a, Point3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The sum of squared distances to weighted planes, as the symmetric 4x4 matrix of
// (x y z 1): its upper triangle row by row.
struct Quadric {
    double m[10] = {};
    void add_plane(Point3 n, double d, double weight) {
        const double v[4] = {n.x, n.y, n.z, d};
        int k = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = i; j < 4; ++j) m[k++] += weight * v[i] * v[j];
    }
    Quadric& operator+=(const Quadric& o) {
        for (int k = 0; k < 10; ++k) m[k] += o.m[k];
        return *this;
    }
    double at(Point3 p) const {
        const double v[4] = {p.x, p.y, p.z, 1};
        double sum = 0;
        int k = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = i; j < 4; ++j) sum += (i == j ? 1 : 2) * m[k++] * v[i] * v[j];
        return sum;
    }
};

// A boundary side's plane (through it, square to its triangle) weighs this many times its
// length squared: a sheet's rim keeps its place.
constexpr double kRimWeight = 16;
// A collapse may turn a triangle that stays by less than this cosine's angle (84 degrees):
// none folds over.
constexpr double kLeastTurnCosine = 0.1;

struct Collapse {
    double cost;
    uint32_t from, to;          // `from` goes into `to`, which moves to `at`
    uint32_t from_age, to_age;  // the corners' ages when it was weighed (older: weighed again)
    Point3 at;
    bool operator>(const Collapse& o) const { return cost > o.cost; }
};

class Simplifier {
  public:
    explicit Simplifier(const TriangleMesh& mesh);
    void run(uint32_t max_triangles);
    TriangleMesh result() const;

  private:
    Point3 normal_of(uint32_t t, uint32_t moved, Point3 at) const; // unnormalised, corner `moved` at `at`
    void weigh(uint32_t a, uint32_t b);
    void weigh_around(uint32_t v);
    bool allowed(const Collapse& c) const;
    void apply(const Collapse& c);
    void drop_twins(uint32_t v);

    std::vector<Point3> points_;
    std::vector<uint32_t> corners_;
    std::vector<bool> gone_;                     // per triangle
    std::vector<std::vector<uint32_t>> around_;  // per point: its triangles, none gone
    std::vector<Quadric> quadric_;
    std::vector<uint32_t> age_;
    uint32_t alive_ = 0;
    bool keep_topology_ = true;
    std::priority_queue<Collapse, std::vector<Collapse>, std::greater<>> heap_;
};

Simplifier::Simplifier(const TriangleMesh& mesh)
    : corners_(mesh.triangles), gone_(mesh.triangle_count(), false), around_(mesh.points.size()), quadric_(mesh.points.size()),
      age_(mesh.points.size(), 0), alive_(mesh.triangle_count()) {
    for (const Vec3& p : mesh.points) points_.push_back(as_point(p));
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> sides; // (a, b) undirected: the triangles on it
    for (uint32_t t = 0; t < alive_; ++t) {
        const uint32_t* c = &corners_[3 * t];
        const Point3 n = cross(points_[c[1]] - points_[c[0]], points_[c[2]] - points_[c[0]]);
        const double area2 = std::sqrt(dot(n, n));
        for (int k = 0; k < 3; ++k) around_[c[k]].push_back(t);
        if (!(area2 > 0)) continue;
        const Point3 u = n * (1 / area2);
        for (int k = 0; k < 3; ++k) {
            quadric_[c[k]].add_plane(u, -dot(u, points_[c[0]]), area2 / 2);
            ++sides[std::minmax(c[k], c[(k + 1) % 3])];
        }
    }
    for (uint32_t t = 0; t < alive_; ++t) { // the rims: sides of one triangle
        const uint32_t* c = &corners_[3 * t];
        const Point3 n = cross(points_[c[1]] - points_[c[0]], points_[c[2]] - points_[c[0]]);
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = c[k], b = c[(k + 1) % 3];
            if (sides[std::minmax(a, b)] != 1) continue;
            const Point3 side = points_[b] - points_[a];
            Point3 w = cross(side, n);
            const double len = std::sqrt(dot(w, w));
            if (!(len > 0)) continue;
            w = w * (1 / len);
            const double weight = kRimWeight * dot(side, side);
            quadric_[a].add_plane(w, -dot(w, points_[a]), weight);
            quadric_[b].add_plane(w, -dot(w, points_[a]), weight);
        }
    }
}

Point3 Simplifier::normal_of(uint32_t t, uint32_t moved, Point3 at) const {
    Point3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = corners_[3 * t + k] == moved ? at : points_[corners_[3 * t + k]];
    return cross(p[1] - p[0], p[2] - p[0]);
}

// The collapse of side (a, b) both ways, at whichever of its ends or middle costs least.
void Simplifier::weigh(uint32_t a, uint32_t b) {
    Quadric q = quadric_[a];
    q += quadric_[b];
    const Point3 choices[3] = {points_[a], points_[b], (points_[a] + points_[b]) * 0.5};
    int best = 0;
    double cost = q.at(choices[0]);
    for (int k = 1; k < 3; ++k) {
        const double c = q.at(choices[k]);
        if (c < cost) cost = c, best = k;
    }
    // (b kept, a into it; the other way round when a's end is the choice)
    if (best == 0) heap_.push({cost, b, a, age_[b], age_[a], choices[0]});
    else heap_.push({cost, a, b, age_[a], age_[b], choices[best]});
}

void Simplifier::weigh_around(uint32_t v) {
    for (uint32_t t : around_[v])
        for (int k = 0; k < 3; ++k)
            if (corners_[3 * t + k] != v) weigh(v, corners_[3 * t + k]);
}

bool Simplifier::allowed(const Collapse& c) const {
    const uint32_t a = c.from, b = c.to;
    std::vector<uint32_t> shared_far, near_a, near_b; // corners across the shared triangles; each end's neighbours
    for (uint32_t t : around_[a]) {
        const uint32_t* k = &corners_[3 * t];
        const bool both = k[0] == b || k[1] == b || k[2] == b;
        for (int i = 0; i < 3; ++i) {
            if (k[i] == a) continue;
            near_a.push_back(k[i]);
            if (both && k[i] != b) shared_far.push_back(k[i]);
        }
    }
    if (shared_far.empty()) return false; // (no longer a side)
    if (keep_topology_) {
        if (shared_far.size() > 2) return false; // a side of three sheets
        for (uint32_t t : around_[b])
            for (int i = 0; i < 3; ++i)
                if (corners_[3 * t + i] != b) near_b.push_back(corners_[3 * t + i]);
        std::sort(near_a.begin(), near_a.end());
        near_a.erase(std::unique(near_a.begin(), near_a.end()), near_a.end());
        std::sort(near_b.begin(), near_b.end());
        near_b.erase(std::unique(near_b.begin(), near_b.end()), near_b.end());
        std::vector<uint32_t> common;
        std::set_intersection(near_a.begin(), near_a.end(), near_b.begin(), near_b.end(), std::back_inserter(common));
        std::sort(shared_far.begin(), shared_far.end());
        if (common != shared_far) return false; // the link condition: it would pinch the surface
    }
    // No triangle that stays may fold over or lose its area.
    for (const uint32_t v : {a, b}) {
        for (uint32_t t : around_[v]) {
            const uint32_t* k = &corners_[3 * t];
            const int ends = (k[0] == a || k[1] == a || k[2] == a) + (k[0] == b || k[1] == b || k[2] == b);
            if (ends == 2) continue; // (goes)
            const Point3 before = normal_of(t, v, points_[v]), after = normal_of(t, v, c.at);
            const double lb = std::sqrt(dot(before, before)), la = std::sqrt(dot(after, after));
            if (!(la > 0) || !(la >= 1e-9 * lb)) return false;
            if (!(dot(before, after) > kLeastTurnCosine * lb * la)) return false;
        }
    }
    return true;
}

// Triangles around v with the same three corners: a pair wound against each other is a wall
// with no inside (both go); wound alike, one goes.
void Simplifier::drop_twins(uint32_t v) {
    auto& list = around_[v];
    for (size_t i = 0; i < list.size(); ++i) {
        const uint32_t t = list[i];
        if (gone_[t]) continue;
        std::array<uint32_t, 3> ki{corners_[3 * t], corners_[3 * t + 1], corners_[3 * t + 2]};
        std::array<uint32_t, 3> si = ki;
        std::sort(si.begin(), si.end());
        for (size_t j = i + 1; j < list.size(); ++j) {
            const uint32_t u = list[j];
            if (gone_[u]) continue;
            std::array<uint32_t, 3> su{corners_[3 * u], corners_[3 * u + 1], corners_[3 * u + 2]};
            std::sort(su.begin(), su.end());
            if (su != si) continue;
            // Alike: u's corners a turn of t's.
            const uint32_t* ku = &corners_[3 * u];
            const bool alike = (ku[0] == ki[0] && ku[1] == ki[1]) || (ku[0] == ki[1] && ku[1] == ki[2]) || (ku[0] == ki[2] && ku[1] == ki[0]);
            gone_[u] = true, --alive_;
            if (!alike) gone_[t] = true, --alive_;
            break;
        }
    }
}

void Simplifier::apply(const Collapse& c) {
    const uint32_t a = c.from, b = c.to;
    for (uint32_t t : around_[a]) {
        uint32_t* k = &corners_[3 * t];
        if (k[0] == b || k[1] == b || k[2] == b) {
            gone_[t] = true, --alive_;
            continue;
        }
        for (int i = 0; i < 3; ++i)
            if (k[i] == a) k[i] = b;
        around_[b].push_back(t);
    }
    around_[a].clear();
    points_[b] = c.at;
    quadric_[b] += quadric_[a];
    ++age_[a], ++age_[b];
    drop_twins(b);
    // Every point around b lists its triangles without the ones gone.
    std::vector<uint32_t> near;
    for (uint32_t t : around_[b])
        for (int i = 0; i < 3; ++i) near.push_back(corners_[3 * t + i]);
    near.push_back(b);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (uint32_t v : near) std::erase_if(around_[v], [&](uint32_t t) { return gone_[t]; });
    weigh_around(b);
}

void Simplifier::run(uint32_t max_triangles) {
    for (const bool keep : {true, false}) {
        keep_topology_ = keep;
        heap_ = {};
        for (uint32_t v = 0; v < points_.size(); ++v) weigh_around(v);
        while (alive_ > max_triangles && !heap_.empty()) {
            const Collapse c = heap_.top();
            heap_.pop();
            if (c.from_age != age_[c.from] || c.to_age != age_[c.to] || around_[c.from].empty() || !allowed(c)) continue;
            apply(c);
        }
        if (alive_ <= max_triangles) return;
    }
}

TriangleMesh Simplifier::result() const {
    TriangleMesh out;
    std::vector<uint32_t> number(points_.size(), UINT32_MAX);
    for (uint32_t t = 0; t < gone_.size(); ++t) {
        if (gone_[t]) continue;
        for (int k = 0; k < 3; ++k) {
            uint32_t& n = number[corners_[3 * t + k]];
            if (n == UINT32_MAX) {
                n = uint32_t(out.points.size());
                const Point3 p = points_[corners_[3 * t + k]];
                out.points.push_back({float(p.x), float(p.y), float(p.z)});
            }
            out.triangles.push_back(n);
        }
    }
    return out;
}

// The distance from p to the triangle (a, b, c): Ericson, Real-Time Collision Detection 5.1.5.
double to_triangle(Point3 p, Point3 a, Point3 b, Point3 c) {
    const Point3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    Point3 q;
    if (d1 <= 0 && d2 <= 0) {
        q = a;
    } else {
        const Point3 bp = p - b;
        const double d3 = dot(ab, bp), d4 = dot(ac, bp);
        const Point3 cp = p - c;
        const double d5 = dot(ab, cp), d6 = dot(ac, cp);
        const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
        if (d3 >= 0 && d4 <= d3) q = b;
        else if (vc <= 0 && d1 >= 0 && d3 <= 0) q = a + ab * (d1 / (d1 - d3));
        else if (d6 >= 0 && d5 <= d6) q = c;
        else if (vb <= 0 && d2 >= 0 && d6 <= 0) q = a + ac * (d2 / (d2 - d6));
        else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) q = b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
        else {
            const double sum = va + vb + vc;
            q = sum != 0 ? a + ab * (vb / sum) + ac * (vc / sum) : a;
        }
    }
    const Point3 d = p - q;
    return std::sqrt(dot(d, d));
}

} // namespace

TriangleMesh welded(const TriangleMesh& mesh) {
    TriangleMesh out;
    std::map<std::tuple<float, float, float>, uint32_t> at;
    std::vector<uint32_t> number(mesh.points.size());
    for (size_t i = 0; i < mesh.points.size(); ++i) {
        const Vec3 p = mesh.points[i];
        auto [it, fresh] = at.try_emplace({p.x, p.y, p.z}, uint32_t(out.points.size()));
        if (fresh) out.points.push_back(p);
        number[i] = it->second;
    }
    for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const uint32_t a = number[mesh.triangles[t]], b = number[mesh.triangles[t + 1]], c = number[mesh.triangles[t + 2]];
        if (a == b || b == c || a == c) continue;
        if (!(length2(cross(out.points[b] - out.points[a], out.points[c] - out.points[a])) > 0)) continue;
        out.triangles.insert(out.triangles.end(), {a, b, c});
    }
    return out;
}

TriangleMesh simplified(const TriangleMesh& mesh, uint32_t max_triangles) {
    Simplifier s(mesh);
    s.run(max_triangles);
    return s.result();
}

float farthest(const TriangleMesh& from, const TriangleMesh& to) {
    if (to.triangles.empty()) return from.points.empty() ? 0.0f : INFINITY;
    std::vector<Point3> samples;
    for (const Vec3& p : from.points) samples.push_back(as_point(p));
    for (size_t t = 0; t + 2 < from.triangles.size(); t += 3) {
        const Point3 a = as_point(from.points[from.triangles[t]]), b = as_point(from.points[from.triangles[t + 1]]),
                     c = as_point(from.points[from.triangles[t + 2]]);
        samples.push_back((a + b + c) * (1.0 / 3));
        samples.push_back((a + b) * 0.5), samples.push_back((b + c) * 0.5), samples.push_back((c + a) * 0.5);
    }
    // Each sample's nearest triangle, the previous sample's first: samples come in order, so it
    // is often near enough to show the sample cannot be the farthest, and the search stops.
    auto distance = [&](const Point3& p, size_t t) {
        return to_triangle(p, as_point(to.points[to.triangles[t]]), as_point(to.points[to.triangles[t + 1]]),
                           as_point(to.points[to.triangles[t + 2]]));
    };
    double most = 0;
    size_t near = 0;
    for (const Point3& p : samples) {
        double least = distance(p, near);
        for (size_t t = 0; t + 2 < to.triangles.size() && least > most; t += 3) {
            const double d = distance(p, t);
            if (d < least) least = d, near = t;
        }
        most = std::max(most, least);
    }
    return float(most);
}

} // namespace facet::geom
