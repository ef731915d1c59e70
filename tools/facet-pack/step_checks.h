#pragma once
// What a STEP file says is wrong with itself, and what Open CASCADE lost reading it: the checks
// read_step() (step_reader.cpp) makes before and after the transfer, each naming the entity.
#include "step_reader.h"

#include <StepData_StepModel.hxx>
#include <XSControl_Reader.hxx>

#include <string>
#include <vector>

namespace facet::packer {

// The first geometric number of the file no part can hold: not finite (1E400 reads as infinity)
// or beyond +-1e10 in the file's unit (a point at 1E308, a radius of -1E308). Open CASCADE's
// healing loops on such a shape for as long as one cares to wait. Empty when there is none.
std::string out_of_range_number(const Handle(StepData_StepModel)& m);

// The entities whose transfer failed outright (an exception inside Open CASCADE: a malformed
// entity, a dangling reference; a signal it raised counts as one, OSD::SetSignal): "#74
// VERTEX_POINT: ..." each into model.failed, the first few. What they held is lost with them.
void account_failures(XSControl_Reader& reader, StepModel& model);

// The faces of the file Open CASCADE lost: a face entity of a shell that was transferred, with
// no face among the transferred shapes (into model.lost, counted in model.face_entities). A
// face of a shell nothing transferred (construction geometry beside the part) is not lost,
// only left out (model.faces_outside).
void account_faces(XSControl_Reader& reader, const std::vector<TopoDS_Shape>& top, StepModel& model);

} // namespace facet::packer
