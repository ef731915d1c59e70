#pragma once
// Open CASCADE curves and surfaces as pack records (Surfaces, Curves3, Curves2 and their
// floats): the elementary kinds as they are, the others as B-splines (exact where Open CASCADE
// converts them, else within 1e-4 mm), each conversion counted in Stats::converted.
#include "occt_to_pack.h"

#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>

#include <cstdint>

namespace facet::packer {

// A 3D curve over [t0, t1] as a Curves3 record: its index, or pack::kNoIndex.
uint32_t add_curve3(geom::PackWriter& w, const Handle(Geom_Curve)& curve, double t0, double t1, Stats& st);
// A face's pcurve over [t0, t1] on `surface` as a Curves2 record: its index, or pack::kNoIndex.
uint32_t add_curve2(geom::PackWriter& w, const Handle(Geom2d_Curve)& curve, double t0, double t1,
                    const Handle(Geom_Surface)& surface, Stats& st);
// A surface as a Surfaces record: its index, or pack::kNoIndex when it cannot be converted.
uint32_t add_surface(geom::PackWriter& w, const Handle(Geom_Surface)& surface, Stats& st);

} // namespace facet::packer
