// The text of an annotation as a drawing writes it (pmi_text.h).
#include "pmi_text.h"

#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <XCAFDimTolObjects_DatumObject.hxx>
#include <XCAFDoc_Datum.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace facet::packer {
namespace {

// The symbols drawings use (UTF-8; facet's font draws each: tools/font/make_font.py).
constexpr const char* kDiameter = "\u2300";
constexpr const char* kPlusMinus = "\u00B1";
constexpr const char* kDegree = "\u00B0";
constexpr const char* kToleranceSymbols[pack::kToleranceTypes] = {
    "",       "\u2220", "\u2197", "\u25CB", "\u25CE", "\u25CE", "\u232D", "\u23E5",
    "\u2225", "\u27C2", "\u2316", "\u2312", "\u2313", "\u23E4", "\u232F", "\u2330",
};
constexpr const char* kMaximumMaterial = "\u24C2", *kLeastMaterial = "\u24C1", *kProjected = "\u24C5";

// A value as a drawing writes it: `decimals` places when the file says (else up to four, no
// trailing zeros).
std::string number(double v, int decimals = -1) {
    char s[48];
    if (decimals >= 0 && decimals <= 6) {
        std::snprintf(s, sizeof s, "%.*f", decimals, v);
        return s;
    }
    std::snprintf(s, sizeof s, "%.4f", v);
    std::string t = s;
    while (t.back() == '0') t.pop_back();
    if (t.back() == '.') t.pop_back();
    return t == "-0" ? "0" : t;
}

pack::DimensionType dimension_type(XCAFDimTolObjects_DimensionType t) {
    using D = pack::DimensionType;
    switch (t) {
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromCenterToOuter:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromCenterToInner:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromOuterToCenter:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromOuterToOuter:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromOuterToInner:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromInnerToCenter:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromInnerToOuter:
    case XCAFDimTolObjects_DimensionType_Location_LinearDistance_FromInnerToInner: return D::Linear;
    case XCAFDimTolObjects_DimensionType_Size_Diameter:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalMinorDiameter:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalMajorDiameter:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalHighMajorDiameter:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalLowMajorDiameter: return D::Diameter;
    case XCAFDimTolObjects_DimensionType_Size_Radius:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalMinorRadius:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalMajorRadius:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalHighMajorRadius:
    case XCAFDimTolObjects_DimensionType_Size_ToroidalLowMajorRadius: return D::Radius;
    case XCAFDimTolObjects_DimensionType_Location_Angular:
    case XCAFDimTolObjects_DimensionType_Size_Angular: return D::Angle;
    case XCAFDimTolObjects_DimensionType_Size_SphericalDiameter: return D::SphericalDiameter;
    case XCAFDimTolObjects_DimensionType_Size_SphericalRadius: return D::SphericalRadius;
    case XCAFDimTolObjects_DimensionType_Size_CurveLength:
    case XCAFDimTolObjects_DimensionType_Size_Thickness:
    case XCAFDimTolObjects_DimensionType_Size_WithPath: return D::Length;
    default: return D::Location;
    }
}

// A fit class: "H7" (a hole: capitals), "g6" (a shaft).
std::string fit_class(bool hole, XCAFDimTolObjects_DimensionFormVariance v, XCAFDimTolObjects_DimensionGrade g) {
    static const char* const letters[] = {"", "a", "b", "c", "cd", "d", "e", "ef", "f", "fg", "g", "h", "js", "j", "k",
                                          "m", "n", "p", "r", "s", "t", "u", "v", "x", "y", "z", "za", "zb", "zc"};
    std::string s = size_t(v) < std::size(letters) ? letters[v] : "";
    if (hole)
        for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    const int grade = int(g) - 1; // IT01, IT0, IT1, ...
    return s + (grade < 0 ? "01" : std::to_string(grade));
}

} // namespace


std::string dimension_text(const XCAFDimTolObjects_DimensionObject& o, pack::Annotation& r) {
    const pack::DimensionType type = dimension_type(o.GetType());
    r.type = uint8_t(type);
    int left = 0, right = -1;
    o.GetNbOfDecimalPlaces(left, right);
    const int places = right > 0 ? right : -1;
    std::string s;
    switch (type) {
    case pack::DimensionType::Diameter: s = kDiameter; break;
    case pack::DimensionType::SphericalDiameter: s = std::string("S") + kDiameter; break;
    case pack::DimensionType::Radius: s = "R"; break;
    case pack::DimensionType::SphericalRadius: s = "SR"; break;
    default: break;
    }
    const double nominal = o.GetValue();
    r.value = float(nominal);
    const char* unit = type == pack::DimensionType::Angle ? kDegree : "";
    if (o.IsDimWithRange()) { // limits: the lower, then the upper
        r.lower = float(o.GetLowerBound() - nominal), r.upper = float(o.GetUpperBound() - nominal);
        return s + number(o.GetLowerBound(), places) + unit + "-" + number(o.GetUpperBound(), places) + unit;
    }
    s += number(nominal, places) + unit;
    if (o.IsDimWithPlusMinusTolerance()) {
        // Open CASCADE gives the deviation below the nominal as its size.
        const double below = std::fabs(o.GetLowerTolValue()), above = o.GetUpperTolValue();
        r.lower = float(-below), r.upper = float(above);
        if (below == above) s += " " + std::string(kPlusMinus) + number(above);
        else s += " +" + number(above) + "/-" + number(below);
    }
    if (o.IsDimWithClassOfTolerance()) {
        Standard_Boolean hole = false;
        XCAFDimTolObjects_DimensionFormVariance variance = XCAFDimTolObjects_DimensionFormVariance_None;
        XCAFDimTolObjects_DimensionGrade grade = XCAFDimTolObjects_DimensionGrade_IT01;
        if (o.GetClassOfTolerance(hole, variance, grade)) s += " " + fit_class(hole, variance, grade);
    }
    return s;
}

// The datums a tolerance refers to, primary first ("A B C").
std::string datum_system(const Handle(XCAFDoc_DimTolTool)& tool, const TDF_Label& tolerance) {
    TDF_LabelSequence labels;
    if (!tool->GetDatumWithObjectOfTolerLabels(tolerance, labels)) return "";
    std::vector<std::pair<int, std::string>> refs;
    for (int i = 1; i <= labels.Length(); ++i) {
        Handle(XCAFDoc_Datum) d;
        if (!labels.Value(i).FindAttribute(XCAFDoc_Datum::GetID(), d)) continue;
        const Handle(XCAFDimTolObjects_DatumObject) o = d->GetObject();
        if (o.IsNull() || o->GetName().IsNull()) continue;
        refs.push_back({o->GetPosition(), o->GetName()->ToCString()});
    }
    std::stable_sort(refs.begin(), refs.end());
    std::string s;
    for (const auto& [position, name] : refs) s += " " + name;
    return s;
}

std::string tolerance_text(const XCAFDimTolObjects_GeomToleranceObject& o, pack::Annotation& r) {
    const int type = int(o.GetType());
    r.type = uint8_t(type >= 0 && type < pack::kToleranceTypes ? type : 0);
    r.value = float(o.GetValue());
    std::string s = kToleranceSymbols[r.type];
    s += " ";
    if (o.GetTypeOfValue() == XCAFDimTolObjects_GeomToleranceTypeValue_Diameter) s += kDiameter;
    if (o.GetTypeOfValue() == XCAFDimTolObjects_GeomToleranceTypeValue_SphericalDiameter) s += std::string("S") + kDiameter;
    s += number(o.GetValue());
    switch (o.GetMaterialRequirementModifier()) {
    case XCAFDimTolObjects_GeomToleranceMatReqModif_M: s += std::string(" ") + kMaximumMaterial, r.material = uint8_t(pack::Material::Maximum); break;
    case XCAFDimTolObjects_GeomToleranceMatReqModif_L: s += std::string(" ") + kLeastMaterial, r.material = uint8_t(pack::Material::Least); break;
    default: break;
    }
    if (o.GetZoneModifier() == XCAFDimTolObjects_GeomToleranceZoneModif_Projected) s += std::string(" ") + kProjected + number(o.GetValueOfZoneModifier());
    return s;
}

} // namespace facet::packer
