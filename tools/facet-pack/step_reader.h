#pragma once
// Reading a STEP file into healed parts, shared by facet-pack and the mesh benchmark.
#include <TopoDS_Shape.hxx>
#include <XCAFDoc_ColorTool.hxx>

#include "pmi.h"

#include <string>
#include <vector>

namespace facet::packer {

struct Part {
    TopoDS_Shape shape; // a solid, an open shell or a lone face, healed, with its placement
    bool closed;        // a solid whose faces share every edge (after healing and sewing)
    std::string name;     // the part (product) that holds it, from the file ("" if unnamed)
    std::string instance; // its occurrence in the assembly, when the file names it
    uint32_t node = UINT32_MAX; // the deepest sub-assembly (StepModel::nodes) it is in; none: not in an assembly
};

// A sub-assembly of the product structure (the file's NEXT_ASSEMBLY_USAGE_OCCURRENCEs, as the
// XCAF tree holds them), in depth-first order: node 0 the top product.
struct TreeNode {
    uint32_t parent;        // an earlier node; UINT32_MAX for node 0
    std::string name;       // its product's
    std::string occurrence; // its occurrence's in its parent, when the file names it
};

struct StepModel {
    std::vector<Part> parts;
    Handle(XCAFDoc_ColorTool) colours; // null when the file has no product structure
    float unit_mm = 1.0f;              // the file's length unit (coordinates are converted to mm)
    uint32_t open_solids = 0;          // solids with gaps healing could not close
    // Faces: FACE_SURFACE/ADVANCED_FACE entities of the file's shells, and those of them Open
    // CASCADE made no face of although their shell was read: lost on the way in, each with
    // what is known ("#28 ADVANCED_FACE: Unresolved Reference ... (Id.#96)").
    uint32_t face_entities = 0;
    std::vector<std::string> lost;
    uint32_t faces_outside = 0; // faces of shells no shape uses (construction planes): left out
    // Entities whose transfer failed outright ("#74 VERTEX_POINT: ..."): what they held is lost.
    std::vector<std::string> failed;
    std::string name;                    // the model's: its top product's (or the file's stem)
    std::string notes;                   // how the file was read when it was out of the ordinary (no product, no unit)
    Pmi pmi;                             // its PMI (AP242), as Open CASCADE reads it
    std::vector<TreeNode> nodes;         // its assembly tree (none: a part, or no product structure)
};

// The length unit to assume when the file gives none (a file with no unit context).
enum class UnitGuess { BySize, Millimetre, Centimetre, Metre, Inch, Foot };

// Reads and heals; on failure returns false with a message for the user.
bool read_step(const std::string& path, StepModel& model, std::string& error, bool quiet,
               UnitGuess no_unit = UnitGuess::BySize);

// A line of progress on stderr, with the seconds since the first: "facet-pack: 12.3 s: healing".
void progress(const char* what);

// "mm", "cm", "m", "in", "ft" (or "size": guess from the part's size); false for other text.
bool parse_unit(const std::string& text, UnitGuess& unit);

} // namespace facet::packer
