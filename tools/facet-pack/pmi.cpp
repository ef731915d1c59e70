#include "pmi.h"

#include "pmi_text.h"

#include "geom/pack.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <XCAFDimTolObjects_DatumObject.hxx>
#include <XCAFDimTolObjects_DimensionObject.hxx>
#include <XCAFDimTolObjects_GeomToleranceObject.hxx>
#include <XCAFDoc_Datum.hxx>
#include <XCAFDoc_DimTolTool.hxx>
#include <XCAFDoc_Dimension.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_GeomTolerance.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <tuple>

namespace facet::packer {
namespace {

using pack::AnnotationKind;

// The faces of the shapes at `labels` (a dimension's two sides: both).
void add_faces(const TDF_LabelSequence& labels, double scale, std::vector<FaceKey>& out) {
    for (int i = 1; i <= labels.Length(); ++i) {
        const TopoDS_Shape s = XCAFDoc_ShapeTool::GetShape(labels.Value(i));
        if (s.IsNull()) continue;
        for (TopExp_Explorer x(s, TopAbs_FACE); x.More(); x.Next()) {
            GProp_GProps props;
            BRepGProp::SurfaceProperties(x.Current(), props);
            const gp_Pnt c = props.CentreOfMass();
            out.push_back({gp_Pnt(c.X() * scale, c.Y() * scale, c.Z() * scale), props.Mass() * scale * scale});
        }
    }
}


// A polyline's points as steps in its annotation's sphere (pack::PmiStep): the first its offset
// from the centre, each next one its step from the one before, in radius / kStepUnits.
void steps(const std::vector<gp_Pnt>& line, const pack::Annotation& r, std::vector<pack::PmiStep>& out) {
    const double scale = double(pack::kStepUnits) / double(r.radius);
    int32_t before[3] = {0, 0, 0};
    for (const gp_Pnt& p : line) {
        const double xyz[3] = {p.X(), p.Y(), p.Z()};
        pack::PmiStep s;
        for (int a = 0; a < 3; ++a) {
            const int32_t q = int32_t(std::clamp<double>(std::lround((xyz[a] - double(r.centre[a])) * scale), -pack::kStepUnits, pack::kStepUnits));
            s.d[a] = int16_t(q - before[a]), before[a] = q;
        }
        out.push_back(s);
    }
}

constexpr double kPolylineTolerance = 1e-4; // of the model's diagonal
struct Tolerances {
    double fine, coarse; // mm
};

// Douglas-Peucker: the points of [first, last] a polyline keeps within `tolerance` of it.
void simplify(const std::vector<gp_Pnt>& p, size_t first, size_t last, double tolerance, std::vector<bool>& keep) {
    if (last <= first + 1) return;
    const gp_Vec along(p[first], p[last]);
    const double length2 = along.SquareMagnitude();
    size_t far = first;
    double far_d = -1;
    for (size_t k = first + 1; k < last; ++k) {
        const gp_Vec v(p[first], p[k]);
        const double d = length2 > 0 ? v.Crossed(along).Magnitude() / std::sqrt(length2) : v.Magnitude();
        if (d > far_d) far_d = d, far = k;
    }
    if (far_d <= tolerance) return;
    keep[far] = true;
    simplify(p, first, far, tolerance, keep);
    simplify(p, far, last, tolerance, keep);
}

// A presentation's edges as polylines (an edge that starts where the last ended continues it),
// its curves sampled within `deflection` (mm, before `scale`).
void add_polylines(const TopoDS_Shape& shape, double scale, double deflection, std::vector<std::vector<gp_Pnt>>& out) {
    if (shape.IsNull()) return;
    for (TopExp_Explorer x(shape, TopAbs_EDGE); x.More(); x.Next()) {
        std::vector<gp_Pnt> points;
        try {
            const BRepAdaptor_Curve c(TopoDS::Edge(x.Current()));
            if (c.GetType() == GeomAbs_Line) {
                points = {c.Value(c.FirstParameter()), c.Value(c.LastParameter())};
            } else {
                GCPnts_QuasiUniformDeflection d(c, deflection);
                if (!d.IsDone()) continue;
                for (int k = 1; k <= d.NbPoints(); ++k) points.push_back(d.Value(k));
            }
        } catch (const Standard_Failure&) {
            continue;
        }
        if (points.size() < 2) continue;
        for (gp_Pnt& p : points) p.SetXYZ(p.XYZ() * scale);
        if (!out.empty() && out.back().back().Distance(points.front()) <= 1e-9 * (1 + scale)) {
            out.back().insert(out.back().end(), points.begin() + 1, points.end());
        } else {
            out.push_back(std::move(points));
        }
    }
}

// The polylines within `tolerance` (mm) of them (Douglas-Peucker): a CAD system writes a
// glyph's strokes as polylines of many short steps (nist_ctc_02's 1,229 edges: 28 k points),
// far finer than a screen draws them.
std::vector<std::vector<gp_Pnt>> simplified(const std::vector<std::vector<gp_Pnt>>& lines, double tolerance) {
    std::vector<std::vector<gp_Pnt>> out;
    for (const auto& l : lines) {
        std::vector<bool> keep(l.size(), false);
        keep.front() = keep.back() = true;
        simplify(l, 0, l.size() - 1, tolerance, keep);
        out.emplace_back();
        for (size_t k = 0; k < l.size(); ++k)
            if (keep[k]) out.back().push_back(l[k]);
    }
    return out;
}

// The presentation's polylines (within `tolerance`, and within the coarse one), its sphere,
// its name and its plane.
template <typename Object>
void presentation(const Object& o, double scale, const Tolerances& tolerance, PmiNote& n) {
    std::vector<std::vector<gp_Pnt>> raw;
    add_polylines(o.GetPresentation(), scale, tolerance.fine / scale, raw);
    n.polylines = simplified(raw, tolerance.fine);
    n.coarse = simplified(raw, tolerance.coarse);
    Bnd_Box box;
    for (const auto& l : raw)
        for (const gp_Pnt& p : l) box.Add(p);
    if (!box.IsVoid()) {
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        const float c[3] = {float((x0 + x1) / 2), float((y0 + y1) / 2), float((z0 + z1) / 2)};
        for (int k = 0; k < 3; ++k) n.record.centre[k] = c[k];
        n.record.radius = float(std::sqrt(box.SquareExtent()) / 2 * (1 + 1e-6) + 1e-6);
    }
    std::vector<double> extents; // each polyline's: its text's strokes are most of them
    for (const auto& l : raw) {
        Bnd_Box b;
        for (const gp_Pnt& p : l) b.Add(p);
        extents.push_back(std::sqrt(b.SquareExtent()));
    }
    if (!extents.empty()) {
        std::vector<double> sorted = extents;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        n.record.stroke = float(sorted[sorted.size() / 2]);
        // Its outline first: the polylines longer than kOutlineStrokes strokes (leaders, frames,
        // a datum's triangle), then its text's strokes, which a view too far to read them leaves out.
        std::vector<size_t> order(raw.size());
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        const double longer = pack::kOutlineStrokes * double(n.record.stroke);
        std::stable_partition(order.begin(), order.end(), [&](size_t k) { return extents[k] > longer; });
        n.record.outline_count = uint32_t(std::count_if(extents.begin(), extents.end(), [&](double e) { return e > longer; }));
        auto reorder = [&](std::vector<std::vector<gp_Pnt>>& lines) {
            std::vector<std::vector<gp_Pnt>> out;
            for (size_t k : order) out.push_back(std::move(lines[k]));
            lines = std::move(out);
        };
        reorder(n.polylines), reorder(n.coarse);
    }
    if (!o.GetPresentationName().IsNull()) n.presentation = o.GetPresentationName()->ToCString();
    if (!n.polylines.empty()) n.record.flags |= pack::kPresented;
    if (o.HasPlane()) {
        const gp_Dir d = o.GetPlane().Direction();
        n.record.normal[0] = float(d.X()), n.record.normal[1] = float(d.Y()), n.record.normal[2] = float(d.Z());
        n.record.flags |= pack::kHasPlane;
    }
}

void set_anchor(PmiNote& n, bool has_point, const gp_Pnt& point, double scale) {
    gp_Pnt a;
    if (has_point) {
        a = gp_Pnt(point.XYZ() * scale);
    } else if (!n.polylines.empty()) { // the middle of its presentation's box
        Bnd_Box box;
        for (const auto& l : n.polylines)
            for (const gp_Pnt& p : l) box.Add(p);
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        a = gp_Pnt((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2);
    } else if (!n.faces.empty()) { // no presentation: at its first face
        a = n.faces.front().centre;
    }
    n.record.anchor[0] = float(a.X()), n.record.anchor[1] = float(a.Y()), n.record.anchor[2] = float(a.Z());
}


// "Datum Target B1 (76)" -> "Datum Target B1"; what a presentation alone says it is.
AnnotationKind kind_of_presentation(const std::string& name) {
    if (name.rfind("Datum", 0) == 0) return AnnotationKind::Datum;
    if (name.find("Feature Control Frame") != std::string::npos) return AnnotationKind::Tolerance;
    if (name.find("Dimension") != std::string::npos) return AnnotationKind::Dimension;
    return AnnotationKind::Note;
}

} // namespace

void read_pmi(const Handle(TDocStd_Document)& doc, double scale, Pmi& out) {
    out = {};
    const Handle(XCAFDoc_DimTolTool) tool = XCAFDoc_DocumentTool::DimTolTool(doc->Main());
    if (tool.IsNull()) return;
    TDF_LabelSequence dimensions, tolerances, datums;
    tool->GetDimensionLabels(dimensions);
    tool->GetGeomToleranceLabels(tolerances);
    tool->GetDatumLabels(datums);
    out.dimensions = uint32_t(dimensions.Length()), out.tolerances = uint32_t(tolerances.Length()), out.datums = uint32_t(datums.Length());
    if (dimensions.IsEmpty() && tolerances.IsEmpty() && datums.IsEmpty()) return;
    // The presentations' polylines within a ten-thousandth of the model's size (a 1 m part:
    // 0.1 mm; zoomed in until a glyph fills the screen, still under its pixels).
    Bnd_Box model;
    TDF_LabelSequence roots;
    XCAFDoc_DocumentTool::ShapeTool(doc->Main())->GetFreeShapes(roots);
    for (int r = 1; r <= roots.Length(); ++r) BRepBndLib::Add(XCAFDoc_ShapeTool::GetShape(roots.Value(r)), model);
    const double diagonal = model.IsVoid() ? 1.0 : std::sqrt(model.SquareExtent()) * scale;
    const Tolerances tolerance{kPolylineTolerance * diagonal, double(pack::kCoarsePolylines) * diagonal};
    std::vector<PmiNote> graphic; // presentations alone: after the semantic ones
    auto refs = [&](const TDF_Label& label, PmiNote& n) {
        TDF_LabelSequence first, second;
        tool->GetRefShapeLabel(label, first, second);
        add_faces(first, scale, n.faces);
        add_faces(second, scale, n.faces);
    };
    for (int i = 1; i <= dimensions.Length(); ++i) {
        Handle(XCAFDoc_Dimension) attr;
        if (!dimensions.Value(i).FindAttribute(XCAFDoc_Dimension::GetID(), attr)) continue;
        const Handle(XCAFDimTolObjects_DimensionObject) o = attr->GetObject();
        if (o.IsNull()) continue;
        PmiNote n;
        refs(dimensions.Value(i), n);
        presentation(*o, scale, tolerance, n);
        set_anchor(n, o->HasTextPoint(), o->GetPointTextAttach(), scale);
        const XCAFDimTolObjects_DimensionType type = o->GetType();
        if (type == XCAFDimTolObjects_DimensionType_CommonLabel || type == XCAFDimTolObjects_DimensionType_DimensionPresentation) {
            n.record.kind = uint8_t(type == XCAFDimTolObjects_DimensionType_CommonLabel ? AnnotationKind::Note : kind_of_presentation(n.presentation));
            const size_t cut = n.presentation.rfind(" (");
            n.text = n.presentation.substr(0, cut);
            if (n.text.empty()) n.text = n.record.kind == uint8_t(AnnotationKind::Note) ? "Note" : "";
            graphic.push_back(std::move(n));
            continue;
        }
        n.record.kind = uint8_t(AnnotationKind::Dimension);
        n.record.flags |= pack::kSemantic;
        n.text = dimension_text(*o, n.record);
        out.notes.push_back(std::move(n));
    }
    for (int i = 1; i <= tolerances.Length(); ++i) {
        Handle(XCAFDoc_GeomTolerance) attr;
        if (!tolerances.Value(i).FindAttribute(XCAFDoc_GeomTolerance::GetID(), attr)) continue;
        const Handle(XCAFDimTolObjects_GeomToleranceObject) o = attr->GetObject();
        if (o.IsNull()) continue;
        PmiNote n;
        n.record.kind = uint8_t(AnnotationKind::Tolerance);
        n.record.flags |= pack::kSemantic;
        refs(tolerances.Value(i), n);
        presentation(*o, scale, tolerance, n);
        set_anchor(n, o->HasPointText(), o->GetPointTextAttach(), scale);
        n.text = tolerance_text(*o, n.record) + datum_system(tool, tolerances.Value(i));
        out.notes.push_back(std::move(n));
    }
    for (int i = 1; i <= datums.Length(); ++i) {
        Handle(XCAFDoc_Datum) attr;
        if (!datums.Value(i).FindAttribute(XCAFDoc_Datum::GetID(), attr)) continue;
        const Handle(XCAFDimTolObjects_DatumObject) o = attr->GetObject();
        if (o.IsNull()) continue;
        PmiNote n;
        n.record.kind = uint8_t(AnnotationKind::Datum);
        n.record.flags |= pack::kSemantic;
        n.record.type = uint8_t(o->IsDatumTarget() ? pack::DatumType::Target : pack::DatumType::Feature);
        refs(datums.Value(i), n);
        presentation(*o, scale, tolerance, n);
        set_anchor(n, o->HasPointText(), o->GetPointTextAttach(), scale);
        n.text = o->GetName().IsNull() ? "" : o->GetName()->ToCString();
        if (o->IsDatumTarget()) n.text += std::to_string(o->GetDatumTargetNumber());
        out.notes.push_back(std::move(n));
    }
    for (PmiNote& n : graphic) out.notes.push_back(std::move(n));
    for (PmiNote& n : out.notes) n.text = geom::cut_utf8(n.text, pack::kMaxAnnotationText);
}

geom::AnnotationTables pmi_tables(const Pmi& pmi, const geom::Pack& pack, const std::vector<TopoDS_Shape>& packed_faces,
                                  uint32_t& missed) {
    geom::AnnotationTables t;
    missed = 0;
    // Each packed face's centre and area in its shell's coordinates, when some note has faces.
    std::vector<FaceKey> packed;
    const bool any_faces = std::any_of(pmi.notes.begin(), pmi.notes.end(), [](const PmiNote& n) { return !n.faces.empty(); });
    if (any_faces) {
        for (const TopoDS_Shape& f : packed_faces) {
            GProp_GProps props;
            BRepGProp::SurfaceProperties(f, props);
            packed.push_back({props.CentreOfMass(), props.Mass()});
        }
    }
    const pack::Header& h = pack.header();
    double diag2 = 0;
    for (int k = 0; k < 3; ++k) diag2 += double(h.bbox_max[k] - h.bbox_min[k]) * (h.bbox_max[k] - h.bbox_min[k]);
    const double near = 1e-4 * std::sqrt(diag2) + 1e-3; // mm: a face's centre moved by healing no more than this
    auto find = [&](const FaceKey& key) {
        uint32_t best = pack::kNoIndex;
        double best_d = near;
        for (const pack::Instance& in : pack.instances()) {
            const pack::Shell& s = pack.shells()[in.shell];
            for (uint32_t f = s.first_face; f < s.first_face + s.face_count && f < packed.size(); ++f) {
                if (std::fabs(packed[f].area - key.area) > 0.02 * key.area + 1e-9) continue;
                const gp_Pnt& c = packed[f].centre;
                const float* m = in.m;
                const gp_Pnt placed(m[0] * c.X() + m[1] * c.Y() + m[2] * c.Z() + m[3], m[4] * c.X() + m[5] * c.Y() + m[6] * c.Z() + m[7],
                                    m[8] * c.X() + m[9] * c.Y() + m[10] * c.Z() + m[11]);
                if (const double d = placed.Distance(key.centre); d <= best_d) best_d = d, best = f;
            }
        }
        return best;
    };
    // A presentation given again (the same name and the same points): drawn by the first.
    using Key = std::tuple<std::string, size_t, long long, long long, long long>;
    std::map<Key, uint32_t> drawn;
    for (const PmiNote& n : pmi.notes) {
        pack::Annotation r = n.record;
        const uint32_t index = uint32_t(t.records.size());
        r.text = uint32_t(t.text.size());
        t.text.insert(t.text.end(), n.text.begin(), n.text.end());
        t.text.push_back(0);
        r.first_face = uint32_t(t.faces.size());
        for (const FaceKey& k : n.faces) {
            const uint32_t f = find(k);
            if (f == pack::kNoIndex) {
                ++missed;
            } else if (std::find(t.faces.begin() + r.first_face, t.faces.end(), f) == t.faces.end()) {
                t.faces.push_back(f);
            }
        }
        r.face_count = uint32_t(t.faces.size()) - r.first_face;
        for (const pack::Annotation& o : t.records) { // the same kind, text and faces as an earlier one: a repeat
            if (o.kind == r.kind && o.face_count == r.face_count && std::strcmp(t.text.data() + o.text, t.text.data() + r.text) == 0 &&
                std::equal(t.faces.begin() + o.first_face, t.faces.begin() + o.first_face + o.face_count, t.faces.begin() + r.first_face)) {
                r.flags |= pack::kRepeat;
                break;
            }
        }
        r.drawn_by = pack::kNoIndex;
        if (!n.polylines.empty()) {
            size_t points = 0;
            for (const auto& l : n.polylines) points += l.size();
            const gp_Pnt& p = n.polylines.front().front();
            const Key key{n.presentation, points, std::llround(p.X() * 1e3), std::llround(p.Y() * 1e3), std::llround(p.Z() * 1e3)};
            if (const auto [it, fresh] = drawn.insert({key, index}); !fresh) r.drawn_by = it->second;
        }
        auto add = [&](const std::vector<std::vector<gp_Pnt>>& lines, uint32_t& first, uint32_t& count) {
            first = uint32_t(t.polylines.size());
            if (r.drawn_by == pack::kNoIndex) { // (one drawn by another keeps none of its own)
                for (const auto& l : lines) {
                    t.polylines.push_back({uint32_t(t.points.size()), uint32_t(l.size())});
                    steps(l, r, t.points);
                }
            }
            count = uint32_t(t.polylines.size()) - first;
        };
        add(n.polylines, r.first_polyline, r.polyline_count);
        add(n.coarse, r.first_coarse, r.coarse_count);
        if (r.drawn_by != pack::kNoIndex) r.outline_count = 0; // (it has no polylines of its own)
        t.records.push_back(r);
    }
    return t;
}

} // namespace facet::packer
