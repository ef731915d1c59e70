#pragma once
// A pack's annotations: the product and manufacturing information (PMI) of an AP242 file, its
// dimensions, geometric tolerances, datums and notes, each with its values as text, the faces
// it applies to and its presentation (polylines: leaders, frames, the CAD system's stroked
// text). Optional sections of a whole pack (a reader that does not know them skips them; a
// pack without them reads as before). Written by tools/facet-pack (pmi.cpp), read in place by
// geom::Annotations (geom/pmi.h); docs/pack-format.md, "Annotations".
#include "geom/pack_format.h"

#include <cstdint>

namespace facet::pack {

enum class PmiSectionId : uint32_t {
    Annotations = 26,  // Annotation records
    PmiText = 27,      // UTF-8 texts, each ended by a 0 byte, padded with 0s to 4 bytes
    PmiFaces = 28,     // uint32 face indices (the pack's Faces), each annotation's run
    PmiPolylines = 29, // Polyline records, each annotation's run
    PmiPoints = 30,    // PmiStep records, each polyline's run (its annotation's sphere in 2 x kStepUnits steps)
};

// What an annotation is; its `type` says which within the kind.
enum class AnnotationKind : uint8_t { Dimension = 0, Tolerance = 1, Datum = 2, Note = 3 };
constexpr uint32_t kAnnotationKinds = 4;
constexpr uint32_t kind_bit(AnnotationKind k) { return 1u << uint32_t(k); }
constexpr uint32_t kAllKinds = (1u << kAnnotationKinds) - 1;

// A dimension's type.
enum class DimensionType : uint8_t {
    Location = 0,          // a distance or location of no type below
    Linear = 1,            // a linear distance between two features
    Diameter = 2,          // ⌀
    Radius = 3,            // R
    Angle = 4,             // an angle (degrees)
    SphericalDiameter = 5, // S⌀
    SphericalRadius = 6,   // SR
    Length = 7,            // a curve's length, a thickness or another size
};
constexpr uint8_t kDimensionTypes = 8;

// A geometric tolerance's type (ISO 1101's characteristics; 0: none read).
enum class ToleranceType : uint8_t {
    None = 0, Angularity, CircularRunout, Circularity, Coaxiality, Concentricity, Cylindricity, Flatness,
    Parallelism, Perpendicularity, Position, ProfileOfLine, ProfileOfSurface, Straightness, Symmetry, TotalRunout,
};
constexpr uint8_t kToleranceTypes = 16;

// A datum's type.
enum class DatumType : uint8_t { Feature = 0, Target = 1 };

// Annotation::flags.
constexpr uint8_t kSemantic = 1;    // its values come from the file's semantic PMI (else: presentation only)
constexpr uint8_t kPresented = 2;   // the file gives its presentation (polylines); else it is placed at its faces
constexpr uint8_t kHasPlane = 4;    // `normal` holds the plane its presentation lies in
constexpr uint8_t kRepeat = 8;      // an earlier one has its kind, text and faces (the file gives a datum once per
                                    // tolerance that refers to it): a list shows that one alone
constexpr uint8_t kAnnotationFlags = 15;

// Annotation::material: a tolerance's material condition.
enum class Material : uint8_t { None = 0, Maximum = 1, Least = 2 }; // Ⓜ, Ⓛ

struct Annotation {
    uint8_t kind;     // AnnotationKind
    uint8_t type;     // DimensionType, ToleranceType or DatumType (0 for a note)
    uint8_t flags;    // kSemantic | kPresented | kHasPlane | kRepeat
    uint8_t material; // Material (tolerances)
    uint32_t text;    // byte of PmiText where its text starts ("⌀52 ±0.15", "⌖ ⌀1 Ⓜ A B C", "A")
    uint32_t first_face, face_count;         // its faces: a run of PmiFaces
    uint32_t first_polyline, polyline_count; // its presentation: a run of PmiPolylines
    uint32_t first_coarse, coarse_count;     // the same within kCoarsePolylines: what a view far off draws
    // kNoIndex, or an annotation earlier in the table whose presentation is the same drawing
    // (the file gives a tolerance's frame again as a graphic, or a datum once per reference):
    // drawn once, by that one (this one has no polylines of its own).
    uint32_t drawn_by;
    // The values read (mm, or degrees for an angle; 0 where the kind has none): a dimension's
    // nominal and its deviations below and above it (a limit dimension: its limits less the
    // nominal), a tolerance's zone.
    float value, lower, upper;
    float anchor[3]; // where its text sits (mm)
    float normal[3]; // its presentation's plane (kHasPlane): the side it reads from
    float centre[3], radius; // a sphere holding its presentation (mm; radius 0: none)
    // The size of its strokes (mm: the median extent of its polylines; 0: none): about its
    // text's height, what says whether a view can read it.
    float stroke;
    // Its first polylines (fine and coarse alike) are its outline: leaders, frames, symbols'
    // shapes, each longer than kOutlineStrokes strokes; the rest its text's strokes.
    uint32_t outline_count;
};
static_assert(sizeof(Annotation) == 96, "pack::Annotation is 96 bytes");
constexpr float kOutlineStrokes = 3;

// The coarse polylines stray from the presentation by up to this part of the pack's box
// diagonal (a pixel of a view that fits the model on a screen some 500 pixels across): a view
// whose pixel at the annotation spans more than that draws them, not the fine ones (which keep
// within a ten-thousandth of it).
constexpr float kCoarsePolylines = 2e-3f;

// An annotation's polylines follow one another in PmiPolylines (its fine ones, then its coarse
// ones), and their points in PmiPoints.
struct Polyline {
    uint32_t first_point, point_count; // a run of PmiPoints, at least 2
};
static_assert(sizeof(Polyline) == 8, "pack::Polyline is 8 bytes");

// A point of a polyline in its annotation's sphere: the first, its offset from the centre, each
// next one its step from the one before, in units of radius / kStepUnits (a 300 mm leader:
// 0.02 mm); a point is where the steps up to it add up to, at most kStepUnits from the centre on
// each axis. Six bytes where three floats take twelve, and steps compress: nist_ctc_02_ap242's
// annotations take half the pack bytes floats would.
struct PmiStep {
    int16_t d[3];
};
static_assert(sizeof(PmiStep) == 6, "pack::PmiStep is 6 bytes");
constexpr int32_t kStepUnits = 16383;

// Bounds a reader holds a pack's annotations to.
constexpr uint32_t kMaxAnnotations = 1u << 16;
constexpr uint32_t kMaxAnnotationText = 255; // bytes of one annotation's text, without its 0

} // namespace facet::pack
