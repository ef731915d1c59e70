#pragma once
// What a model takes on a device (pack::Needs), measured by loading its pack into the module as
// a device would: facet::model_needs() sizes a workspace from it without decoding the pack.
#include "geom/pack_format.h"

#include <cstdint>
#include <string>
#include <vector>

namespace facet::packer {

// The pack's edge samples, mesh vertices and mesh triangles at the model's default level of
// detail and at pack::kCoarsestFirst times its tolerance, every face at the one tolerance (no
// view-dependent detail). False, with `error`, when the module cannot show the model at all.
bool measure_needs(const std::vector<uint8_t>& pack, pack::Needs& out, std::string& error);

} // namespace facet::packer
