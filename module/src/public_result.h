#pragma once
// What leaves the module (the Viewer's calls and events, create(), model_needs() and
// library_model(), and so the C API) carries the public statuses only: Ok, OutOfRange, Full,
// Corrupt, Unsupported, NotFound, Busy and Io (the product's storage failed: facet/storage.h).
// The tessellation's own kinds are said as what they mean to a caller: geometry it refuses
// (Degenerate, Crossing) is Corrupt input. The text and the places keep the cause ("face 12:
// loops cross").
#include "core/status.h"

namespace facet::module {

constexpr bool is_public(Status s) { return s != Status::Degenerate && s != Status::Crossing; }

constexpr Status public_status(Status s) {
    switch (s) {
    case Status::Degenerate:
    case Status::Crossing: return Status::Corrupt;
    default: return s;
    }
}

constexpr Result public_result(Result r) {
    r.status = public_status(r.status);
    return r;
}

} // namespace facet::module
