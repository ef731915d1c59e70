// facet-measure: a face's exact surface and the exact distance and angle between two faces,
// from a pack, with the device's own code (geom/measure.h) — what the viewer shows when a
// face is picked, for scripts and tests.
//
//   facet-measure MODEL.fpk --face N[@I] [--face M[@J]] [--json]
//   facet-measure MODEL.fpk --all          every face of every shell as placed by its first instance (JSON lines)
//
// N: a face index (facet-mesh --faces and the viewer's pick name them); @I: the instance that
// places it (default: the first instance of the face's shell). Values in the STEP file's
// unit; --json: in millimetres and in that unit. Exit 0, 1 (an unreadable pack), 2 (usage: a
// face or instance that does not exist).
#include "geom/measure.h"
#include "pack_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::geom;

namespace {

struct Pick {
    uint32_t face = 0, instance = ~0u;
    FaceGeometry g;
};

int usage(const char* why) {
    if (why) std::fprintf(stderr, "facet-measure: error: %s\n", why);
    std::fprintf(stderr, "usage: facet-measure MODEL.fpk --face N[@I] [--face M[@J]] [--json] | --all\n");
    return 2;
}

bool parse_index(const char* s, uint32_t& out) {
    char* end = nullptr;
    const unsigned long v = std::strtoul(s, &end, 10);
    if (end == s || (*end && *end != '@') || v > 0xFFFFFFF) return false;
    out = uint32_t(v);
    return true;
}

const char* unit_name(float mm) {
    struct U { float mm; const char* name; };
    static const U kUnits[] = {{1, "mm"}, {10, "cm"}, {1000, "m"}, {25.4f, "in"}, {304.8f, "ft"}, {0.001f, "um"}};
    for (const U& u : kUnits)
        if (std::fabs(mm - u.mm) <= 1e-6f * u.mm) return u.name;
    return nullptr;
}

// Decimals of a length: the digits the pack's float32 positions hold, no more (a position
// 400 mm from the origin is good to about 5e-5 mm: 4 decimals), 6 at most.
int g_decimals = 4;
void set_decimals(const Pack& pack, double unit_mm) {
    const pack::Header& h = pack.header();
    double reach = 0;
    for (int k = 0; k < 3; ++k) reach = std::max(reach, std::max(std::fabs(double(h.bbox_min[k])), std::fabs(double(h.bbox_max[k]))));
    const double step = std::max(reach, 1e-3) * 4.8e-7 / unit_mm; // 4 float32 steps, in the file's unit
    g_decimals = std::clamp(int(std::ceil(-std::log10(step))), 0, 6);
}

// A length in the file's unit.
std::string length(double mm, double unit_mm, const char* unit) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f %s", g_decimals, mm / unit_mm, unit);
    return buf;
}
std::string degrees(double rad) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f deg", rad * 57.29577951308232);
    return buf;
}
std::string vec(const D3& v, double scale = 1) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x / scale, v.y / scale, v.z / scale);
    return buf;
}
std::string jvec(const D3& v) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "[%.9g, %.9g, %.9g]", v.x, v.y, v.z);
    return buf;
}

std::string describe(const Pick& p, double u, const char* un) {
    const FaceGeometry& g = p.g;
    std::string s = "face " + std::to_string(p.face) + " (instance " + std::to_string(p.instance) + "): " + surface_name(g.type);
    using T = pack::SurfaceType;
    switch (g.type) {
    case T::Plane: s += ", normal " + vec(g.axis) + ", offset " + length(g.offset, u, un) + " (through " + vec(g.origin, u) + ")"; break;
    case T::Cylinder:
        s += std::string(g.hole ? " (hole)" : " (boss)") + ", diameter " + length(2 * g.radius, u, un) + ", radius " + length(g.radius, u, un) +
             ", axis through " + vec(g.origin, u) + " along " + vec(g.axis);
        break;
    case T::Cone:
        s += std::string(g.hole ? " (hole)" : " (boss)") + ", half-angle " + degrees(g.half_angle) + ", radius " + length(g.radius, u, un) +
             " at " + vec(g.origin, u) + ", axis along " + vec(g.axis);
        break;
    case T::Sphere: s += ", radius " + length(g.radius, u, un) + ", centre " + vec(g.origin, u); break;
    case T::Torus:
        s += ", major radius " + length(g.radius, u, un) + ", minor radius " + length(g.minor, u, un) + ", centre " + vec(g.origin, u) +
             ", axis along " + vec(g.axis);
        break;
    case T::BSpline:
        s += std::string(g.rational ? " (rational)" : "") + ", degrees " + std::to_string(g.u_degree) + " x " + std::to_string(g.v_degree) +
             ", " + std::to_string(g.u_poles) + " x " + std::to_string(g.v_poles) + " poles" +
             (g.u_periodic || g.v_periodic ? std::string(" (periodic in ") + (g.u_periodic ? (g.v_periodic ? "u and v" : "u") : "v") +
                                                 ": one period, unrolled)"
                                           : "");
        break;
    case T::Revolution: s += ", axis through " + vec(g.origin, u) + " along " + vec(g.axis); break;
    case T::Extrusion: s += ", along " + vec(g.axis); break;
    }
    return s;
}

std::string json_face(const Pick& p) {
    const FaceGeometry& g = p.g;
    char buf[1024];
    std::snprintf(buf, sizeof buf,
                  "{\"face\": %u, \"instance\": %u, \"type\": \"%s\", \"reversed\": %s, \"origin\": %s, \"axis\": %s, \"offset\": %.12g, "
                  "\"radius\": %.12g, \"minor_radius\": %.12g, \"half_angle\": %.12g, \"hole\": %s, \"u_degree\": %d, \"v_degree\": %d, "
                  "\"u_poles\": %d, \"v_poles\": %d, \"rational\": %s, \"u_periodic\": %s, \"v_periodic\": %s}",
                  p.face, p.instance, surface_name(g.type), g.reversed ? "true" : "false", jvec(g.origin).c_str(), jvec(g.axis).c_str(),
                  g.offset, g.radius, g.minor, g.half_angle, g.hole ? "true" : "false", g.u_degree, g.v_degree, g.u_poles, g.v_poles,
                  g.rational ? "true" : "false", g.u_periodic ? "true" : "false", g.v_periodic ? "true" : "false");
    return buf;
}

const char* relation_name(Relation::Kind k) {
    switch (k) {
    case Relation::Kind::None: return "none";
    case Relation::Kind::Planes: return "planes";
    case Relation::Kind::PlaneAxis: return "plane_axis";
    case Relation::Kind::Axes: return "axes";
    case Relation::Kind::PlanePoint: return "plane_point";
    case Relation::Kind::AxisPoint: return "axis_point";
    case Relation::Kind::Points: return "points";
    }
    return "none";
}

} // namespace

int main(int argc, char** argv) {
    std::string path;
    std::vector<Pick> picks;
    bool json = false, all = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--face") {
            if (i + 1 >= argc) return usage("--face takes a face index (N or N@INSTANCE)");
            Pick p;
            const char* s = argv[++i];
            if (!parse_index(s, p.face)) return usage((std::string("--face ") + s + ": a face index, N or N@INSTANCE").c_str());
            if (const char* at = std::strchr(s, '@'); at && !parse_index(at + 1, p.instance))
                return usage((std::string("--face ") + s + ": the instance after @ is a number").c_str());
            picks.push_back(p);
        } else if (a == "--json") {
            json = true;
        } else if (a == "--all") {
            all = true;
        } else if (a == "-h" || a == "--help") {
            return usage(nullptr), 0;
        } else if (!a.empty() && a[0] == '-') {
            return usage(("unknown option " + a).c_str());
        } else if (path.empty()) {
            path = a;
        } else {
            return usage("one pack at a time");
        }
    }
    if (path.empty()) return usage("no pack given");
    if (!all && (picks.empty() || picks.size() > 2)) return usage("one or two --face");
    if (all && !picks.empty()) return usage("--all or --face, not both");
    LoadedPack lp;
    std::string error;
    if (!load_pack_file(path, lp, error)) {
        std::fprintf(stderr, "facet-measure: error: %s\n", error.c_str());
        return 1;
    }
    Pack pack;
    if (Result r = pack.open(lp.data(), lp.bytes); !r.ok()) {
        std::fprintf(stderr, "facet-measure: error: %s: %s\n", path.c_str(), r.what);
        return 1;
    }
    const auto shells = pack.shells();
    const auto instances = pack.instances();
    if (all) {
        for (uint32_t s = 0; s < shells.size(); ++s) {
            uint32_t inst = ~0u;
            for (uint32_t i = 0; i < instances.size() && inst == ~0u; ++i)
                if (instances[i].shell == s) inst = i;
            if (inst == ~0u) continue;
            for (uint32_t f = shells[s].first_face; f < shells[s].first_face + shells[s].face_count; ++f) {
                Pick p{f, inst, {}};
                if (Result r = describe_face(pack, f, instances[inst].m, p.g); !r.ok()) return usage(r.what);
                std::printf("%s\n", json_face(p).c_str());
            }
        }
        return 0;
    }
    for (Pick& p : picks) {
        if (p.face >= pack.faces().size())
            return usage(("face " + std::to_string(p.face) + ": the pack has " + std::to_string(pack.faces().size()) + " faces (0 to " +
                          std::to_string(pack.faces().size() - 1) + ")").c_str());
        uint32_t shell = 0;
        while (shell + 1 < shells.size() && p.face >= shells[shell].first_face + shells[shell].face_count) ++shell;
        if (p.instance == ~0u) {
            for (uint32_t i = 0; i < instances.size() && p.instance == ~0u; ++i)
                if (instances[i].shell == shell) p.instance = i;
            if (p.instance == ~0u) return usage(("face " + std::to_string(p.face) + " belongs to a shell no instance places").c_str());
        }
        if (p.instance >= instances.size() || instances[p.instance].shell != shell)
            return usage(("instance " + std::to_string(p.instance) + " does not place face " + std::to_string(p.face) + "'s shell").c_str());
        if (Result r = describe_face(pack, p.face, instances[p.instance].m, p.g); !r.ok()) return usage(r.what);
    }
    const double u = pack.header().source_unit_mm > 0 ? pack.header().source_unit_mm : 1.0;
    set_decimals(pack, u);
    const char* named = unit_name(float(u));
    char other[32];
    std::snprintf(other, sizeof other, "x %.6g mm", u);
    const char* un = named ? named : other;
    Relation rel;
    if (picks.size() == 2) rel = relate(picks[0].g, picks[1].g);
    if (json) {
        std::printf("{\"unit_mm\": %.12g, \"unit\": \"%s\", \"faces\": [", u, un);
        for (size_t i = 0; i < picks.size(); ++i) std::printf("%s%s", i ? ", " : "", json_face(picks[i]).c_str());
        std::printf("]");
        if (picks.size() == 2) {
            std::printf(", \"relation\": {\"kind\": \"%s\", \"angle\": %.12g, \"parallel\": %s, \"distance\": ", relation_name(rel.kind), rel.angle,
                        rel.parallel ? "true" : "false");
            if (rel.has_distance) std::printf("%.12g}", rel.distance);
            else std::printf("null}");
        }
        std::printf("}\n");
        return 0;
    }
    for (const Pick& p : picks) std::printf("%s\n", describe(p, u, un).c_str());
    if (picks.size() == 2) {
        std::string s = "faces " + std::to_string(picks[0].face) + " and " + std::to_string(picks[1].face) + ": ";
        switch (rel.kind) {
        case Relation::Kind::None: s += "no exact relation (a free-form surface)"; break;
        case Relation::Kind::Planes:
            s += rel.parallel ? "parallel planes, distance " + length(rel.distance, u, un) : "planes at " + degrees(rel.angle);
            break;
        case Relation::Kind::PlaneAxis:
            s += rel.parallel ? "axis parallel to the plane, distance " + length(rel.distance, u, un)
                              : "axis at " + degrees(rel.angle) + " to the plane";
            break;
        case Relation::Kind::Axes:
            s += rel.parallel ? "parallel axes, distance " + length(rel.distance, u, un)
                              : "axes at " + degrees(rel.angle) + ", closest " + length(rel.distance, u, un) + " apart";
            break;
        case Relation::Kind::PlanePoint: s += "centre " + length(rel.distance, u, un) + " from the plane"; break;
        case Relation::Kind::AxisPoint: s += "centre " + length(rel.distance, u, un) + " from the axis"; break;
        case Relation::Kind::Points: s += "centres " + length(rel.distance, u, un) + " apart"; break;
        }
        std::printf("%s\n", s.c_str());
    }
    return 0;
}
