#include "geom/pack.h"
#include "geom/pack_index.h"

#include "geom/eval.h"
#include "geom/params.h"

#include "core/format.h"

#include <cmath>
#include <cstring>

namespace facet::pack {

namespace {

// The CRC of each byte value, a byte at a time (1 KB of constants): about six instructions a
// byte where the bit loop took forty.
struct CrcTable {
    uint32_t of[256];
    constexpr CrcTable() : of() {
        for (uint32_t b = 0; b < 256; ++b) {
            uint32_t c = b;
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
            of[b] = c;
        }
    }
};
constexpr CrcTable kCrc;

} // namespace

uint32_t crc32(const void* data, uint32_t size, uint32_t crc) {
    const uint8_t* p = static_cast<const uint8_t*>(data);
    crc = ~crc;
    for (uint32_t i = 0; i < size; ++i) crc = kCrc.of[(crc ^ p[i]) & 0xFFu] ^ (crc >> 8);
    return ~crc;
}

} // namespace facet::pack

namespace facet::geom {
namespace {

using namespace facet::pack;

// A value a CAD model can hold: not NaN, and within +-kMaxMagnitude (100 km in millimetres, or
// a parameter that large), so that the geometry's squares and products stay far from float's
// range and a corrupt pack cannot send the tessellation into overflow.
bool finite(float f) { return std::fabs(f) <= kMaxMagnitude; }

// A float that must hold a small non-negative integer (B-spline heads).
bool whole(float f, uint32_t max, uint32_t& out) {
    if (!finite(f) || f < 0 || f > float(max)) return false;
    out = uint32_t(f);
    return float(out) == f;
}

constexpr uint32_t kMaxPoles = 1u << 20; // kMaxDegree: geom/eval.h

uint32_t bspline_curve_count(const float* p, uint32_t avail, uint32_t dim) {
    constexpr uint32_t head_floats = float_count<BSplineCurveHead>;
    if (avail < head_floats) return 0;
    const BSplineCurveHead& h = *reinterpret_cast<const BSplineCurveHead*>(p);
    uint32_t deg, poles, knots, rational, periodic;
    if (!whole(h.degree, kMaxDegree, deg) || !whole(h.pole_count, kMaxPoles, poles) ||
        !whole(h.knot_count, kMaxPoles + kMaxDegree + 1, knots) || !whole(h.rational, 1, rational) ||
        !whole(h.periodic, 1, periodic)) {
        return 0;
    }
    if (deg < 1 || poles < 2 || poles < (periodic ? 2 : deg + 1)) return 0;
    if (knots != poles + deg + 1) return 0; // knots expanded by multiplicity (unperiodized)
    return head_floats + knots + poles * (dim + rational);
}

// A B-spline's knots never decrease and its weights are positive: what its evaluation (and the
// fixed-point patches, which divide by knot differences) relies on. Read only after the
// parameter count has been checked.
bool ordered(const float* k, int n) {
    for (int i = 1; i < n; ++i)
        if (k[i] < k[i - 1]) return false;
    return true;
}
bool positive(const float* w, int n) {
    for (int i = 0; i < n; ++i)
        if (!(w[i] > 0)) return false;
    return true;
}

bool surface_data_ok(uint8_t type, const float* p) {
    if (SurfaceType(type) != SurfaceType::BSpline) return true;
    const BSplineSurfaceView B(*reinterpret_cast<const BSplineSurfaceHead*>(p));
    return ordered(B.uk, B.ku) && ordered(B.vk, B.kv) && (!B.rational || positive(B.weights, B.nu * B.nv));
}

bool curve_data_ok(uint8_t type, uint8_t dim, const float* p) {
    if (CurveType(type) != CurveType::BSpline) return true;
    const BSplineCurveView C(*reinterpret_cast<const BSplineCurveHead*>(p), dim);
    return ordered(C.knots, C.k) && (!C.rational || positive(C.weights, C.n));
}

} // namespace

uint32_t curve_param_count(uint8_t type, uint8_t dim, const float* p, uint32_t avail) {
    switch (CurveType(type)) {
    case CurveType::Line: return dim == 3 ? float_count<Line3Params> : float_count<Line2Params>;
    case CurveType::Circle: return dim == 3 ? float_count<Circle3Params> : float_count<Circle2Params>;
    case CurveType::Ellipse: return dim == 3 ? float_count<Ellipse3Params> : float_count<Ellipse2Params>;
    case CurveType::BSpline: return bspline_curve_count(p, avail, dim);
    }
    return 0;
}

uint32_t surface_param_count(uint8_t type, const float* p, uint32_t avail) {
    switch (SurfaceType(type)) {
    case SurfaceType::Plane: return float_count<PlaneParams>;
    case SurfaceType::Cylinder: return float_count<CylinderParams>;
    case SurfaceType::Cone: return float_count<ConeParams>;
    case SurfaceType::Sphere: return float_count<SphereParams>;
    case SurfaceType::Torus: return float_count<TorusParams>;
    case SurfaceType::Revolution: return float_count<RevolutionParams>;
    case SurfaceType::Extrusion: return float_count<ExtrusionParams>;
    case SurfaceType::BSpline: {
        constexpr uint32_t head_floats = float_count<BSplineSurfaceHead>;
        if (avail < head_floats) return 0;
        const BSplineSurfaceHead& h = *reinterpret_cast<const BSplineSurfaceHead*>(p);
        uint32_t ud, vd, up, vp, uk, vk, rational, uper, vper;
        if (!whole(h.u_degree, kMaxDegree, ud) || !whole(h.v_degree, kMaxDegree, vd) || !whole(h.u_poles, kMaxPoles, up) ||
            !whole(h.v_poles, kMaxPoles, vp) || !whole(h.u_knots, kMaxPoles + kMaxDegree + 1, uk) ||
            !whole(h.v_knots, kMaxPoles + kMaxDegree + 1, vk) || !whole(h.rational, 1, rational) ||
            !whole(h.u_periodic, 1, uper) || !whole(h.v_periodic, 1, vper)) {
            return 0;
        }
        if (ud < 1 || vd < 1 || up < ud + 1 || vp < vd + 1 || uint64_t(up) * vp > kMaxPoles) return 0;
        if (uk != up + ud + 1 || vk != vp + vd + 1) return 0;
        return head_floats + uk + vk + up * vp * (3 + rational);
    }
    }
    return 0;
}

const char* section_name(uint32_t id) {
    static const char* const names[] = {"header", "Floats", "Surfaces", "Curves3", "Curves2", "Vertices", "Edges",
                                        "Coedges", "Loops", "Faces", "Shells", "Instances", "Colours",
                                        "Names", "ShellNames", "InstanceNames", "SmoothEdges"};
    if (id == uint32_t(SectionId::Needs)) return "Needs";
    return id < sizeof names / sizeof names[0] ? names[id] : "unknown";
}

Place section_place(uint32_t id, uint32_t index) {
    static const char* const kinds[] = {"header", "section Floats record", "section Surfaces record",
                                        "section Curves3 record", "section Curves2 record", "section Vertices record",
                                        "section Edges record", "section Coedges record", "section Loops record",
                                        "section Faces record", "section Shells record", "section Instances record",
                                        "section Colours record", "section Names byte", "section ShellNames record",
                                        "section InstanceNames record", "section SmoothEdges word"};
    if (id == 0) return {kinds[0]};
    if (id == uint32_t(SectionId::Needs)) return {"section Needs record", index};
    return {id < sizeof kinds / sizeof kinds[0] ? kinds[id] : "section record", index};
}

Result Pack::fail(const char* what, uint32_t section, uint32_t index) {
    *this = Pack{};
    return Result::fail(Status::Corrupt, what, section_place(section, index));
}

namespace {
template <typename T>
void rebase(std::span<const T>& view, uintptr_t from, uintptr_t to) {
    if (view.data()) view = {reinterpret_cast<const T*>(reinterpret_cast<uintptr_t>(view.data()) - from + to), view.size()};
}
} // namespace

void Pack::moved(const void* to) {
    if (!header_) return;
    const uintptr_t from = reinterpret_cast<uintptr_t>(header_), at = reinterpret_cast<uintptr_t>(to);
    header_ = static_cast<const pack::Header*>(to);
    rebase(floats_, from, at), rebase(surfaces_, from, at), rebase(curves3_, from, at), rebase(curves2_, from, at);
    rebase(vertices_, from, at), rebase(edges_, from, at), rebase(coedges_, from, at), rebase(loops_, from, at);
    rebase(faces_, from, at), rebase(shells_, from, at), rebase(instances_, from, at), rebase(colours_, from, at);
    rebase(names_, from, at), rebase(shell_names_, from, at), rebase(instance_names_, from, at), rebase(smooth_, from, at), rebase(needs_, from, at);
}

Result Pack::open(const void* data, uint32_t size) {
    *this = Pack{};
    const uint8_t* base = static_cast<const uint8_t*>(data);
    if (!data || (reinterpret_cast<uintptr_t>(data) & 3)) return fail("pack is not 4-byte aligned", 0, 0);
    if (size < sizeof(Header)) return fail("shorter than the header (truncated)", 0, 0);
    const Header* h = reinterpret_cast<const Header*>(base);
    if (std::memcmp(h->magic, kMagic, 4) != 0) return fail("not a facet pack (bad magic)", 0, 0);
    if (h->version != kVersion) return fail("unsupported version", 0, 0);
    if (h->header_bytes != sizeof(Header)) return fail("unexpected header size", 0, 0);
    // Not covered by the CRC: a later version may give them a meaning, this one requires 0.
    if (h->flags != 0 || h->reserved[0] != 0 || h->reserved[1] != 0 || h->reserved[2] != 0) {
        return fail("the header's flags or reserved fields are not 0", 0, 0);
    }
    if (h->total_bytes != size) return fail("size does not match the header (truncated or padded)", 0, 0);
    if (size > kMaxBytes) return fail("larger than the 64 MiB limit", 0, 0);
    if (h->section_count > kMaxSections) return fail("too many sections", 0, 0);
    const uint64_t table_end = sizeof(Header) + uint64_t(h->section_count) * sizeof(SectionEntry);
    if (table_end > size) return fail("section table runs past the end", 0, 0);
    if (pack::crc32(base + sizeof(Header), size - sizeof(Header)) != h->crc32) return fail("CRC mismatch", 0, 0);
    for (int i = 0; i < 3; ++i) {
        if (!finite(h->bbox_min[i]) || !finite(h->bbox_max[i]) || h->bbox_min[i] > h->bbox_max[i]) {
            return fail("bounding box is not finite, beyond +-1e8 or inverted", 0, 0);
        }
    }
    if (!finite(h->source_unit_mm) || !(h->source_unit_mm > 0)) return fail("bad source unit", 0, 0);

    const SectionEntry* table = reinterpret_cast<const SectionEntry*>(base + sizeof(Header));
    uint32_t seen = 0;
    for (uint32_t i = 0; i < h->section_count; ++i) {
        const SectionEntry& s = table[i];
        const uint32_t id = s.id;
        if (id == uint32_t(SectionId::Needs)) { // (optional: one record)
            if (seen & (1u << id)) return fail("section appears twice", id, 0);
            seen |= 1u << id;
            if (s.record_bytes != sizeof(pack::Needs) || s.count != 1 || (s.offset & 3) || s.offset < table_end ||
                uint64_t(s.offset) + sizeof(pack::Needs) > size) {
                return fail("the Needs section is not one record inside the pack", id, 0);
            }
            if (const char* why = pack::needs_problem(*reinterpret_cast<const pack::Needs*>(base + s.offset))) return fail(why, id, 0);
            needs_ = {reinterpret_cast<const pack::Needs*>(base + s.offset), 1};
            continue;
        }
        if (id < 1 || id > uint32_t(SectionId::SmoothEdges)) continue; // unknown sections are skipped
        if (seen & (1u << id)) return fail("section appears twice", id, 0);
        seen |= 1u << id;
        static const uint32_t sizes[] = {0, 4, sizeof(Surface), sizeof(Curve), sizeof(Curve), sizeof(Vertex), sizeof(Edge),
                                         sizeof(Coedge), sizeof(Loop), sizeof(pack::Face), sizeof(Shell), sizeof(Instance), sizeof(Colour),
                                         1, 4, 4, 4};
        if (s.record_bytes != sizes[id]) return fail("record size does not match this reader", id, 0);
        if (s.offset & 3) return fail("section offset is not 4-byte aligned", id, 0);
        if (s.offset < table_end || uint64_t(s.offset) + uint64_t(s.count) * s.record_bytes > size) {
            return fail("section lies outside the pack (bad offset or count)", id, 0);
        }
        const uint8_t* at = base + s.offset;
        switch (SectionId(id)) {
        case SectionId::Floats: floats_ = {reinterpret_cast<const float*>(at), s.count}; break;
        case SectionId::Surfaces: surfaces_ = {reinterpret_cast<const Surface*>(at), s.count}; break;
        case SectionId::Curves3: curves3_ = {reinterpret_cast<const Curve*>(at), s.count}; break;
        case SectionId::Curves2: curves2_ = {reinterpret_cast<const Curve*>(at), s.count}; break;
        case SectionId::Vertices: vertices_ = {reinterpret_cast<const Vertex*>(at), s.count}; break;
        case SectionId::Edges: edges_ = {reinterpret_cast<const Edge*>(at), s.count}; break;
        case SectionId::Coedges: coedges_ = {reinterpret_cast<const Coedge*>(at), s.count}; break;
        case SectionId::Loops: loops_ = {reinterpret_cast<const Loop*>(at), s.count}; break;
        case SectionId::Faces: faces_ = {reinterpret_cast<const pack::Face*>(at), s.count}; break;
        case SectionId::Shells: shells_ = {reinterpret_cast<const Shell*>(at), s.count}; break;
        case SectionId::Instances: instances_ = {reinterpret_cast<const Instance*>(at), s.count}; break;
        case SectionId::Colours: colours_ = {reinterpret_cast<const Colour*>(at), s.count}; break;
        case SectionId::Names: names_ = {reinterpret_cast<const char*>(at), s.count}; break;
        case SectionId::ShellNames: shell_names_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        case SectionId::InstanceNames: instance_names_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        case SectionId::SmoothEdges: smooth_ = {reinterpret_cast<const uint32_t*>(at), s.count}; break;
        case SectionId::Needs: break; // (above)
        }
    }
    header_ = h;
    if (Result r = check_records(); !r.ok()) return r;
    const bool has_smooth = (seen >> uint32_t(SectionId::SmoothEdges)) & 1u;
    if (has_smooth && smooth_.size() != pack::smooth_words(uint32_t(edges_.size()))) {
        return fail("one bit per edge is needed", uint32_t(SectionId::SmoothEdges), 0);
    }
    return check_names();
}

Result Pack::check_names() {
    constexpr uint32_t N = uint32_t(SectionId::Names);
    if (!names_.empty() && names_.back() != 0) return fail("the last name is not ended by a 0 byte", N, uint32_t(names_.size() - 1));
    if (names_.size() & 3) return fail("not padded to a multiple of 4 bytes", N, 0);
    // Every name starts at the pool's start or after a 0 byte, so it ends within the pool.
    const struct {
        std::span<const uint32_t> table;
        size_t count;
        SectionId id;
    } tables[] = {{shell_names_, shells_.size(), SectionId::ShellNames}, {instance_names_, instances_.size(), SectionId::InstanceNames}};
    for (const auto& t : tables) {
        if (t.table.empty()) continue;
        if (t.table.size() != t.count) return fail("one name per record of its section is needed", uint32_t(t.id), 0);
        if (const uint32_t bad = first_bad_name(names_, t.table); bad != kNoIndex) {
            return fail("the name does not start a string of Names", uint32_t(t.id), bad);
        }
    }
    return {};
}

Result Pack::check_records() {
    constexpr uint32_t F = uint32_t(SectionId::Floats);
    for (uint32_t i = 0; i < floats_.size(); ++i) {
        if (!finite(floats_[i])) return fail("a parameter is NaN, infinite or beyond +-1e8", F, i);
    }
    auto params_ok = [&](uint32_t first, uint32_t count) {
        return uint64_t(first) + count <= floats_.size();
    };
    constexpr uint32_t S = uint32_t(SectionId::Surfaces);
    for (uint32_t i = 0; i < surfaces_.size(); ++i) {
        const Surface& s = surfaces_[i];
        if (!params_ok(s.params, s.count)) return fail("parameters lie outside the float pool", S, i);
        const uint32_t need = surface_param_count(s.type, floats_.data() + s.params, s.count);
        if (need == 0) return fail("unknown surface type or bad B-spline head", S, i);
        if (need != s.count) return fail("parameter count does not match the surface type", S, i);
        if (!surface_data_ok(s.type, floats_.data() + s.params)) {
            return fail("B-spline knots decrease or a weight is not positive", S, i);
        }
        const bool swept = s.type == uint8_t(SurfaceType::Revolution) || s.type == uint8_t(SurfaceType::Extrusion);
        if (swept ? s.ref >= curves3_.size() : s.ref != kNoIndex) return fail("bad swept-curve reference", S, i);
    }
    for (int dim = 3; dim >= 2; --dim) {
        const std::span<const Curve> cs = dim == 3 ? curves3_ : curves2_;
        const uint32_t id = uint32_t(dim == 3 ? SectionId::Curves3 : SectionId::Curves2);
        for (uint32_t i = 0; i < cs.size(); ++i) {
            const Curve& c = cs[i];
            if (c.dim != dim) return fail("curve dimension does not match its section", id, i);
            if (!params_ok(c.params, c.count)) return fail("parameters lie outside the float pool", id, i);
            const uint32_t need = curve_param_count(c.type, c.dim, floats_.data() + c.params, c.count);
            if (need == 0) return fail("unknown curve type or bad B-spline head", id, i);
            if (need != c.count) return fail("parameter count does not match the curve type", id, i);
            if (!curve_data_ok(c.type, c.dim, floats_.data() + c.params)) {
                return fail("B-spline knots decrease or a weight is not positive", id, i);
            }
        }
    }
    constexpr uint32_t V = uint32_t(SectionId::Vertices);
    for (uint32_t i = 0; i < vertices_.size(); ++i) {
        for (float f : vertices_[i].p) {
            if (!finite(f)) return fail("vertex is NaN, infinite or beyond +-1e8", V, i);
        }
        for (int k = 0; k < 3; ++k) {
            const float x = vertices_[i].p[k];
            if (x < header_->bbox_min[k] || x > header_->bbox_max[k]) return fail("vertex outside the header's bounding box", V, i);
        }
    }
    constexpr uint32_t E = uint32_t(SectionId::Edges);
    for (uint32_t i = 0; i < edges_.size(); ++i) {
        const Edge& e = edges_[i];
        if (e.curve != kNoIndex && e.curve != kStraight && e.curve >= curves3_.size()) return fail("curve index out of range", E, i);
        if (e.v0 >= vertices_.size() || e.v1 >= vertices_.size()) return fail("vertex index out of range", E, i);
        if (!finite(e.t0) || !finite(e.t1) || !finite(e.max_sag) || e.max_sag < 0 || !finite(e.tolerance) || e.tolerance < 0) {
            return fail("bad parameter range, tolerance or sag limit", E, i);
        }
    }
    constexpr uint32_t C = uint32_t(SectionId::Coedges);
    for (uint32_t i = 0; i < coedges_.size(); ++i) {
        const Coedge& c = coedges_[i];
        if (c.edge() >= edges_.size()) return fail("edge index out of range", C, i);
        if (c.seam() > Seam::VHigh) return fail("bad seam side", C, i);
    }
    constexpr uint32_t L = uint32_t(SectionId::Loops);
    for (uint32_t i = 0; i < loops_.size(); ++i) {
        const Loop& l = loops_[i];
        if (l.coedge_count == 0 || uint64_t(l.first_coedge) + l.coedge_count > coedges_.size()) {
            return fail("coedge range out of range or empty", L, i);
        }
    }
    constexpr uint32_t FA = uint32_t(SectionId::Faces);
    for (uint32_t i = 0; i < faces_.size(); ++i) {
        const pack::Face& f = faces_[i];
        if (f.surface >= surfaces_.size()) return fail("surface index out of range", FA, i);
        if (f.loop_count == 0 || uint64_t(f.first_loop) + f.loop_count > loops_.size()) return fail("loop range out of range or empty", FA, i);
        if (f.colour != kNoIndex && f.colour >= colours_.size()) return fail("colour index out of range", FA, i);
        if (f.reversed > 1) return fail("bad orientation flag", FA, i);
        // Pcurves follow the face's coedges, so its loops' coedges must follow each other; only
        // elementary surfaces may leave pcurves out (they are inverted analytically).
        if (f.first_pcurve == kNoIndex) {
            if (surfaces_[f.surface].type > uint8_t(SurfaceType::Torus)) return fail("a free-form face has no pcurves", FA, i);
        } else {
            uint64_t next = loops_[f.first_loop].first_coedge;
            for (uint32_t l = f.first_loop; l < f.first_loop + f.loop_count; ++l) {
                if (loops_[l].first_coedge != next) return fail("the face's coedges are not consecutive", FA, i);
                next += loops_[l].coedge_count;
            }
            if (uint64_t(f.first_pcurve) + (next - loops_[f.first_loop].first_coedge) > curves2_.size()) {
                return fail("pcurve range out of range", FA, i);
            }
        }
        for (int k = 0; k < 2; ++k) {
            if (!finite(f.uv_min[k]) || !finite(f.uv_max[k]) || f.uv_min[k] > f.uv_max[k]) return fail("bad (u,v) bounds", FA, i);
        }
    }
    constexpr uint32_t SH = uint32_t(SectionId::Shells);
    for (uint32_t i = 0; i < shells_.size(); ++i) {
        const Shell& s = shells_[i];
        if (uint64_t(s.first_face) + s.face_count > faces_.size()) return fail("face range out of range", SH, i);
        if (s.colour != kNoIndex && s.colour >= colours_.size()) return fail("colour index out of range", SH, i);
        if (s.closed > 1) return fail("bad closed flag", SH, i);
    }
    constexpr uint32_t IN = uint32_t(SectionId::Instances);
    for (uint32_t i = 0; i < instances_.size(); ++i) {
        if (instances_[i].shell >= shells_.size()) return fail("shell index out of range", IN, i);
        if (const char* why = pack::placement_problem(instances_[i].m)) return fail(why, IN, i);
    }
    return {};
}

} // namespace facet::geom
