#pragma once
// The product and manufacturing information (PMI) of an AP242 file as Open CASCADE reads it
// (XCAFDoc_DimTolTool: dimensions, geometric tolerances, datums, with their presentations),
// made into a pack's annotations (geom/pmi_format.h).
#include "pack_writer.h"

#include <TDocStd_Document.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include <string>
#include <vector>

namespace facet::geom {
class Pack;
}

namespace facet::packer {

// A face an annotation applies to, as the file gives it (placed in the model, mm): found among
// the packed faces by where it lies and its area, as healing makes new faces of the file's.
struct FaceKey {
    gp_Pnt centre;
    double area;
};

struct PmiNote {
    pack::Annotation record{}; // its kind, type, flags, material, values, anchor and normal (the rest: pmi_tables)
    std::string text;          // UTF-8
    std::vector<FaceKey> faces;
    std::vector<std::vector<gp_Pnt>> polylines; // its presentation (mm)
    std::vector<std::vector<gp_Pnt>> coarse;    // the same within pack::kCoarsePolylines
    std::string presentation;                   // the presentation's name in the file ("Feature Control Frame (18)")
};

struct Pmi {
    std::vector<PmiNote> notes; // semantic ones first (dimensions, tolerances, datums), then presentations alone
    // As Open CASCADE counts them: dimension labels (graphic-only ones included), geometric
    // tolerances and datums.
    uint32_t dimensions = 0, tolerances = 0, datums = 0;
};

// Reads the document's PMI (a reader with GDT and view modes on). `scale`: the factor the
// shapes were scaled by to millimetres (a file with no unit read as another), applied here too.
void read_pmi(const Handle(TDocStd_Document)& doc, double scale, Pmi& out);

// The notes as a pack's tables: each face found among the pack's (`packed_faces` in pack order,
// in their shells' coordinates, placed by every instance), a presentation drawn again marked as
// drawn by the first. `missed`: faces no packed face matched (their annotation keeps the rest).
geom::AnnotationTables pmi_tables(const Pmi& pmi, const geom::Pack& pack, const std::vector<TopoDS_Shape>& packed_faces,
                                  uint32_t& missed);

} // namespace facet::packer
