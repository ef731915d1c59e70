#pragma once
// Reading a STEP file into healed parts, shared by facet-pack and the mesh benchmark.
#include <TopoDS_Shape.hxx>
#include <XCAFDoc_ColorTool.hxx>

#include <string>
#include <vector>

namespace facet::packer {

struct Part {
    TopoDS_Shape shape; // a solid, an open shell or a lone face, healed, with its placement
    bool closed;        // a solid whose faces share every edge (after healing and sewing)
};

struct StepModel {
    std::vector<Part> parts;
    Handle(XCAFDoc_ColorTool) colours; // null when the file has no product structure
    float unit_mm = 1.0f;              // the file's length unit (OCCT converts to mm)
    uint32_t open_solids = 0;          // solids with gaps healing could not close
};

// Reads and heals; on failure returns false with a message for the user.
bool read_step(const std::string& path, StepModel& model, std::string& error, bool quiet);

} // namespace facet::packer
