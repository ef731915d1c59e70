#pragma once
// Open CASCADE shapes to pack records: topology, colours and placements (the surfaces, curves
// and pcurves: occt_geometry.h).
#include "pack_blocks.h"
#include "pack_writer.h"

#include <TopoDS_Shape.hxx>
#include <XCAFDoc_ColorTool.hxx>

#include <map>
#include <vector>
#include <string>

namespace facet::packer {

struct Stats {
    uint32_t solids = 0, shells = 0, faces = 0, edges = 0, instances = 0;
    uint32_t smooth_edges = 0; // whose two faces meet tangentially (pack::SectionId::SmoothEdges)
    std::map<std::string, uint32_t> surface_types, converted; // converted: "offset -> B-spline"
    uint32_t faces_skipped = 0;
    uint32_t empty_parts = 0; // parts every face of which was skipped: left out with their occurrences
    std::string first_problem;
};

class Packer {
public:
    Packer(geom::PackWriter& w, Handle(XCAFDoc_ColorTool) colours, Stats& stats)
        : w_(w), colours_(colours), stats_(stats) {}

    // Adds one shell (a solid's, or a surface model's) placed by its location, sharing the
    // geometry of earlier occurrences of the same shell.
    // The shell is named after its part (the first occurrence's name), the instance after the
    // occurrence (names from the file; "" for none).
    void add_occurrence(const TopoDS_Shape& shell_or_solid, bool closed, const std::string& name = "",
                        const std::string& instance = "");

    // Every packed face, in pack order (prototype coordinates): for measuring a mesh against
    // the exact surfaces.
    std::vector<TopoDS_Shape> packed_faces;
    // The prototype shape of each shell, in pack order.
    std::vector<TopoDS_Shape> prototypes;

private:
    uint32_t add_prototype(const TopoDS_Shape& shape, bool closed);
    uint32_t colour_of(const TopoDS_Shape& s);

    geom::PackWriter& w_;
    Handle(XCAFDoc_ColorTool) colours_;
    Stats& stats_;
    std::map<const void*, uint32_t> prototypes_; // TShape -> Shells index
    std::map<uint32_t, uint32_t> colour_index_;  // packed RGBA -> Colours index
    std::map<std::string, uint32_t> types_before_; // the surface types counted before the face being packed
};

// Each prototype's box (its own coordinates, mm): Open CASCADE's tight box of its faces, grown
// by a thousandth of its size and a micrometre (float rounding, the B-rep's tolerances).
std::vector<geom::PartBox> part_boxes(const std::vector<TopoDS_Shape>& prototypes);

} // namespace facet::packer
