#pragma once
// Builds a pack in memory on the host (tools/facet-pack, tests). Not for the device: it
// allocates. The matching reader is geom/pack.h.
#include "geom/pack_format.h"
#include "geom/pmi_format.h"
#include "geom/tree_format.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace facet::geom {

// A pack's annotations (geom/pmi_format.h), as facet-pack builds them: each table one section.
struct AnnotationTables {
    std::vector<pack::Annotation> records;
    std::vector<char> text; // 0-ended texts (finish() pads the pool to 4 bytes)
    std::vector<uint32_t> faces;
    std::vector<pack::Polyline> polylines;
    std::vector<pack::PmiStep> points;
};

// UTF-8 text cut to at most `bytes`, on a character's boundary (names, annotations' texts).
std::string cut_utf8(const std::string& text, size_t bytes);

// The frame at (x, y, z) along the world's axes (right-handed): an elementary surface's record's head.
inline pack::Frame axes_at(float x, float y, float z) { return {{x, y, z}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }

class PackWriter {
public:
    // A block of parameters; returns its first index. A block equal bit for bit to one added
    // before is not stored again (the halves of a hole share their cylinder, say).
    uint32_t add_floats(const std::vector<float>& values);
    // Surfaces and curves from their records (pack_format.h): each record's type goes with it.
    // Returns the surface's (the curve's, among those of its dimension) index.
    uint32_t add_surface(const pack::PlaneParams& p) { return add_record(pack::SurfaceType::Plane, p); }
    uint32_t add_surface(const pack::CylinderParams& p) { return add_record(pack::SurfaceType::Cylinder, p); }
    uint32_t add_surface(const pack::ConeParams& p) { return add_record(pack::SurfaceType::Cone, p); }
    uint32_t add_surface(const pack::SphereParams& p) { return add_record(pack::SurfaceType::Sphere, p); }
    uint32_t add_surface(const pack::TorusParams& p) { return add_record(pack::SurfaceType::Torus, p); }
    // The curve swept (a 3D curve's index).
    uint32_t add_surface(const pack::RevolutionParams& p, uint32_t curve) { return add_record(pack::SurfaceType::Revolution, p, curve); }
    uint32_t add_surface(const pack::ExtrusionParams& p, uint32_t curve) { return add_record(pack::SurfaceType::Extrusion, p, curve); }
    uint32_t add_curve(const pack::Line3Params& p) { return add_record(pack::CurveType::Line, 3, p); }
    uint32_t add_curve(const pack::Circle3Params& p) { return add_record(pack::CurveType::Circle, 3, p); }
    uint32_t add_curve(const pack::Ellipse3Params& p) { return add_record(pack::CurveType::Ellipse, 3, p); }
    uint32_t add_curve(const pack::Line2Params& p) { return add_record(pack::CurveType::Line, 2, p); }
    uint32_t add_curve(const pack::Circle2Params& p) { return add_record(pack::CurveType::Circle, 2, p); }
    uint32_t add_curve(const pack::Ellipse2Params& p) { return add_record(pack::CurveType::Ellipse, 2, p); }
    // B-splines: the head (BSplineSurfaceHead, BSplineCurveHead) and what follows it, as
    // pack_format.h lays them out; the writer takes the floats as they are (the reader checks).
    uint32_t add_bspline_surface(const std::vector<float>& record) { return add_surface_record(pack::SurfaceType::BSpline, record); }
    uint32_t add_bspline_curve(uint8_t dim, const std::vector<float>& record) { return add_curve_record(pack::CurveType::BSpline, dim, record); }
    // A record of a stated type as its floats (one pack's records copied into another: pack_blocks).
    uint32_t add_surface_record(pack::SurfaceType type, const std::vector<float>& params, uint32_t ref = pack::kNoIndex);
    uint32_t add_curve_record(pack::CurveType type, uint8_t dim, const std::vector<float>& params);
    uint32_t add_vertex(float x, float y, float z);
    uint32_t add_edge(const pack::Edge& e);
    // Edge e's two faces meet tangentially (pack::SectionId::SmoothEdges).
    void set_smooth_edge(uint32_t e);
    uint32_t add_coedge(const pack::Coedge& c);
    uint32_t add_loop(const pack::Loop& l);
    uint32_t add_face(const pack::Face& f);
    uint32_t add_shell(const pack::Shell& s);
    uint32_t add_instance(const pack::Instance& i);
    uint32_t add_colour(pack::Colour c);
    // Names (UTF-8; "" leaves the record unnamed; cut at pack::kMaxNameBytes on a character
    // boundary). The Names sections are written only when something is named.
    void set_model_name(const std::string& name);
    void name_shell(uint32_t shell, const std::string& name);
    void name_instance(uint32_t instance, const std::string& name);

    uint32_t coedge_count() const { return uint32_t(coedges_.size()); }
    uint32_t curve2_count() const { return uint32_t(curves2_.size()); }
    uint32_t loop_count() const { return uint32_t(loops_.size()); }
    uint32_t face_count() const { return uint32_t(faces_.size()); }

    void set_source_unit_mm(float unit) { unit_mm_ = unit; }
    // What the model takes on a device (pack::Needs), written first after the table.
    void set_needs(const pack::Needs& needs) { needs_ = needs, has_needs_ = true; }
    // The model's assembly tree (geom/tree_format.h; written when it has a node): each node's
    // names as strings (the writer puts them in the Names pool), an InstanceNode per instance.
    struct TreeNodeNames {
        std::string name, occurrence;
    };
    void set_tree(std::vector<pack::Node> nodes, std::vector<TreeNodeNames> names, std::vector<pack::InstanceNode> instances);
    // The model's annotations (written when there is one).
    void set_annotations(AnnotationTables tables) { annotations_ = std::move(tables); }
    const AnnotationTables& annotations() const { return annotations_; }
    // The finished pack: header with bounding box and CRC, section table, sections.
    std::vector<uint8_t> finish() const;
    // Bytes per section, for the packer's summary.
    std::string summary() const;

private:
    template <typename Params>
    static std::vector<float> floats_of(const Params& p) {
        static_assert(sizeof(Params) % sizeof(float) == 0, "a record is floats");
        const float* f = reinterpret_cast<const float*>(&p);
        return std::vector<float>(f, f + sizeof(Params) / sizeof(float));
    }
    template <typename Params>
    uint32_t add_record(pack::SurfaceType type, const Params& p, uint32_t ref = pack::kNoIndex) {
        return add_surface_record(type, floats_of(p), ref);
    }
    template <typename Params>
    uint32_t add_record(pack::CurveType type, uint8_t dim, const Params& p) {
        return add_curve_record(type, dim, floats_of(p));
    }

    std::vector<float> floats_;
    std::map<std::string, uint32_t> blocks_; // a block's bytes -> its first index
    std::vector<pack::Surface> surfaces_;
    std::vector<pack::Curve> curves3_, curves2_;
    std::vector<pack::Vertex> vertices_;
    std::vector<pack::Edge> edges_;
    std::vector<bool> smooth_; // per edge, as far as set
    pack::Needs needs_{};
    bool has_needs_ = false;
    AnnotationTables annotations_;
    std::vector<pack::Node> tree_; // (names: offsets into names_, before finish() puts the model's first)
    std::vector<pack::InstanceNode> tree_instances_;
    std::vector<pack::Coedge> coedges_;
    std::vector<pack::Loop> loops_;
    std::vector<pack::Face> faces_;
    std::vector<pack::Shell> shells_;
    std::vector<pack::Instance> instances_;
    std::vector<pack::Colour> colours_;
    uint32_t add_name(const std::string& name);
    std::string model_name_;
    std::vector<char> names_; // the other names (the pool puts the model's first)
    std::map<std::string, uint32_t> name_at_;
    std::vector<uint32_t> shell_names_, instance_names_;
    float unit_mm_ = 1.0f;
};

} // namespace facet::geom
