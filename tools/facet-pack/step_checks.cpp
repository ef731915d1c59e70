#include "step_checks.h"

#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_EntityIterator.hxx>
#include <Interface_Graph.hxx>
#include <StepGeom_CartesianPoint.hxx>
#include <StepGeom_Circle.hxx>
#include <StepGeom_ConicalSurface.hxx>
#include <StepGeom_CylindricalSurface.hxx>
#include <StepGeom_Direction.hxx>
#include <StepGeom_Ellipse.hxx>
#include <StepGeom_SphericalSurface.hxx>
#include <StepGeom_ToroidalSurface.hxx>
#include <StepGeom_Vector.hxx>
#include <StepShape_AdvancedFace.hxx>
#include <StepShape_FaceSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <cmath>
#include <cstdio>
#include <unordered_set>

namespace facet::packer {
namespace {

// What the file says is wrong with entity i: its own check and the file-wide one naming it.
std::string entity_problem(const Handle(StepData_StepModel)& m, int i) {
    std::string why;
    const Handle(Standard_Transient)& e = m->Value(i);
    const Handle(Interface_Check)& check = m->Check(i, true);
    for (int k = 1; !check.IsNull() && k <= check->NbFails() && k <= 2; ++k) why += std::string(why.empty() ? "" : "; ") + check->CFail(k);
    const std::string mark = "Ent.Id.#" + std::to_string(m->IdentLabel(e)) + " ";
    const Handle(Interface_Check)& global = m->GlobalCheck();
    for (int k = 1; !global.IsNull() && k <= global->NbFails(); ++k)
        if (std::string(global->CFail(k)).find(mark) != std::string::npos) why += std::string(why.empty() ? "" : "; ") + global->CFail(k);
    return why;
}

} // namespace

std::string out_of_range_number(const Handle(StepData_StepModel)& m) {
    constexpr double kMost = 1e10;
    const auto bad = [](double v) { return !(std::fabs(v) <= kMost); };
    for (int i = 1; !m.IsNull() && i <= m->NbEntities(); ++i) {
        const Handle(Standard_Transient)& e = m->Value(i);
        double v = 0;
        bool found = false;
        if (const auto p = Handle(StepGeom_CartesianPoint)::DownCast(e); !p.IsNull()) {
            for (int k = 1; k <= p->NbCoordinates() && !found; ++k) found = bad(v = p->CoordinatesValue(k));
        } else if (const auto d = Handle(StepGeom_Direction)::DownCast(e); !d.IsNull()) {
            for (int k = 1; k <= d->NbDirectionRatios() && !found; ++k) found = bad(v = d->DirectionRatiosValue(k));
        } else if (const auto c = Handle(StepGeom_Circle)::DownCast(e); !c.IsNull()) {
            found = bad(v = c->Radius());
        } else if (const auto el = Handle(StepGeom_Ellipse)::DownCast(e); !el.IsNull()) {
            found = bad(v = el->SemiAxis1()) || bad(v = el->SemiAxis2());
        } else if (const auto cy = Handle(StepGeom_CylindricalSurface)::DownCast(e); !cy.IsNull()) {
            found = bad(v = cy->Radius());
        } else if (const auto co = Handle(StepGeom_ConicalSurface)::DownCast(e); !co.IsNull()) {
            found = bad(v = co->Radius()) || bad(v = co->SemiAngle());
        } else if (const auto sp = Handle(StepGeom_SphericalSurface)::DownCast(e); !sp.IsNull()) {
            found = bad(v = sp->Radius());
        } else if (const auto to = Handle(StepGeom_ToroidalSurface)::DownCast(e); !to.IsNull()) {
            found = bad(v = to->MajorRadius()) || bad(v = to->MinorRadius());
        } else if (const auto ve = Handle(StepGeom_Vector)::DownCast(e); !ve.IsNull()) {
            found = bad(v = ve->Magnitude());
        }
        if (found) {
            char text[200];
            std::snprintf(text, sizeof text, "#%d %s holds %g: no part's geometry (a number beyond +-1e10, or not finite)",
                          m->IdentLabel(e), m->TypeName(e, false), v);
            return text;
        }
    }
    return {};
}

void account_failures(XSControl_Reader& reader, StepModel& model) {
    const Handle(XSControl_WorkSession) ws = reader.WS();
    const Handle(StepData_StepModel) m = Handle(StepData_StepModel)::DownCast(reader.Model());
    if (m.IsNull() || ws.IsNull() || ws->TransferReader().IsNull()) return;
    const Handle(Transfer_TransientProcess) tp = ws->TransferReader()->TransientProcess();
    if (tp.IsNull()) return;
    const Interface_CheckIterator checks = tp->CheckList(false);
    for (checks.Start(); checks.More(); checks.Next()) {
        const Handle(Interface_Check)& c = checks.Value();
        if (c.IsNull() || !c->HasFailed()) continue;
        const Handle(Standard_Transient) e = c->Entity();
        const int n = e.IsNull() ? 0 : m->Number(e);
        const std::string what = n > 0 ? "#" + std::to_string(m->IdentLabel(e)) + " " + m->TypeName(e, false) : std::string("an entity");
        model.failed.push_back(what + ": " + c->CFail(1));
    }
    // What the reader found wrong in the file itself (a syntax error, a reference to nothing),
    // which is where such a failure starts.
    const Handle(Interface_Check)& global = m->GlobalCheck();
    for (int k = 1; !model.failed.empty() && !global.IsNull() && k <= global->NbFails() && k <= 3; ++k) {
        model.failed.push_back(std::string("the file: ") + global->CFail(k));
    }
    for (int i = 1; !model.failed.empty() && i <= m->NbEntities(); ++i) {
        const Handle(Interface_Check)& c = m->Check(i, true);
        if (!c.IsNull() && c->HasFailed()) model.failed.push_back("#" + std::to_string(m->IdentLabel(m->Value(i))) + ": " + c->CFail(1));
    }
}

void account_faces(XSControl_Reader& reader, const std::vector<TopoDS_Shape>& top, StepModel& model) {
    const Handle(XSControl_WorkSession) ws = reader.WS();
    const Handle(StepData_StepModel) m = Handle(StepData_StepModel)::DownCast(reader.Model());
    if (m.IsNull() || ws.IsNull() || ws->TransferReader().IsNull()) return;
    const Handle(Transfer_TransientProcess) tp = ws->TransferReader()->TransientProcess();
    if (tp.IsNull()) return;
    const Interface_Graph& graph = ws->Graph();
    std::unordered_set<const void*> made;
    for (const TopoDS_Shape& s : top)
        for (TopExp_Explorer x(s, TopAbs_FACE); x.More(); x.Next()) made.insert(x.Current().TShape().get());
    for (int i = 1; i <= m->NbEntities(); ++i) {
        const Handle(Standard_Transient)& e = m->Value(i);
        if (!e->IsKind(STANDARD_TYPE(StepShape_FaceSurface))) continue;
        bool shell_read = false;
        for (Interface_EntityIterator it = graph.Sharings(e); it.More(); it.Next()) shell_read = shell_read || tp->IsBound(it.Value());
        if (!shell_read) {
            ++model.faces_outside;
            continue;
        }
        ++model.face_entities;
        bool found = false;
        const TopoDS_Shape result = TransferBRep::ShapeResult(tp, e);
        for (TopExp_Explorer x(result, TopAbs_FACE); x.More() && !found; x.Next()) found = made.count(x.Current().TShape().get()) > 0;
        if (found) continue;
        std::string why = entity_problem(m, i);
        model.lost.push_back("#" + std::to_string(m->IdentLabel(e)) + " " +
                             (e->IsKind(STANDARD_TYPE(StepShape_AdvancedFace)) ? "ADVANCED_FACE" : "FACE_SURFACE") + ": " +
                             (why.empty() ? "Open CASCADE made no face of it" : why));
    }
}

} // namespace facet::packer
